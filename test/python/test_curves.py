# Isolines and cell borders of the Python module (Solver.isolines(), Solver.cell_borders(); the C++
# geodesic_curves.h): circles and a straight bisector on the plane, face locations that give the points back,
# the elephant refined by exact runs against the distances of the points, bad input.

import numpy as np
import pytest

import vtp_geodesics
from conftest import plane_grid


def test_plane_circles_and_bisector():
    V, F = plane_grid(21, 21, jitter=0.3, seed=3)
    s = vtp_geodesics.Solver(V, F)
    c = 10 * 21 + 10  # the vertex nearest to the centre
    curves = s.isolines([0.1, 0.3], sources=c, chord_tolerance=1e-6, return_locations=True)
    assert len(curves) == 2
    for k in curves:
        assert k["closed"]
        r = np.linalg.norm(k["points"] - V[c], axis=1)
        assert np.abs(r - k["level"]).max() < 1e-9
        # the face locations give the same points
        q = np.einsum("ij,ijk->ik", k["barycentric"], V[F[k["faces"]]])
        assert np.abs(q - k["points"]).max() < 1e-12
    a, b = 5 * 21 + 10, 15 * 21 + 10
    borders = s.cell_borders([a, b])
    assert len(borders) == 1 and borders[0]["cells"] == (0, 1) and not borders[0]["closed"]
    p = borders[0]["points"]
    assert np.abs(np.linalg.norm(p - V[a], axis=1) - np.linalg.norm(p - V[b], axis=1)).max() < 1e-9


def test_elephant_refined_by_exact_runs(elephant):
    V, F, s = elephant
    d = s.distances(0)
    top = d[np.isfinite(d)].max()
    curves = s.isolines([0.2 * top, 0.6 * top], sources=0, exact_refinement=2, return_locations=True)
    assert curves
    errors = []
    for k in curves:
        for f, b in zip(k["faces"], k["barycentric"]):
            errors.append(abs(s.distance(0, (int(f), b)) - k["level"]))
    errors = np.array(errors)
    assert np.mean(errors <= 1e-9 * top) >= 0.95
    assert errors.max() <= 1e-2 * top


def test_step_and_bad_input():
    V, F = plane_grid(6, 6)
    s = vtp_geodesics.Solver(V, F)
    assert [round(k["level"], 12) for k in s.isolines(None, sources=0, step=0.5)] == [0.5, 1.0]
    with pytest.raises(ValueError):
        s.isolines([-0.1], sources=0)
    with pytest.raises(ValueError):
        s.isolines([float("nan")], sources=0)
    with pytest.raises(ValueError):
        s.isolines(None, sources=0, step=0.0)
    with pytest.raises(ValueError):
        s.isolines([0.1], sources=0, chord_tolerance=0.0)
    with pytest.raises(ValueError):
        s.isolines([0.1], sources=0, exact_refinement=-1)
