# Bad input raises ValueError or TypeError naming the problem, and never crashes the interpreter; Ctrl-C during
# a matrix stops it.

import os

import numpy as np
import pytest

import vtp_geodesics
from vtp_geodesics import gdist, pygeodesic
from conftest import assert_interrupt_stops, plane_grid

V0, F0 = plane_grid(6, 6)


@pytest.mark.parametrize("V,F,exc,match", [
    (V0[:, :2], F0, ValueError, r"shape \(n, 3\)"),
    (V0, F0[:, :2], ValueError, r"shape \(m, 3\)"),
    (V0.ravel(), F0, ValueError, "shape"),
    (np.zeros((0, 3)), np.zeros((0, 3), dtype=int), ValueError, "no vertices"),
    (V0, np.zeros((0, 3), dtype=int), ValueError, "no faces"),
    (np.where(np.arange(V0.size).reshape(V0.shape) == 7, np.nan, V0), F0, ValueError, "vertex 2 .*non-finite"),
    (np.where(np.arange(V0.size).reshape(V0.shape) == 7, np.inf, V0), F0, ValueError, "non-finite"),
    (V0, np.where(F0 == 5, 36, F0), ValueError, "out of range"),
    (V0, np.where(F0 == 5, -1, F0), ValueError, "-1, out of range"),
    (V0, F0 + 1, ValueError, "numbered from 1"),
    (V0, F0.astype(float), TypeError, "integer"),
    (V0.astype(str), F0, TypeError, "real numbers"),
    ([[0, 0, 0], [1, 0]], F0, ValueError, ""),
    (V0, np.array([[0, 1, 1]] + F0.tolist()), ValueError, "repeated vertex"),
])
def test_bad_mesh(V, F, exc, match):
    with pytest.raises(exc, match=match):
        vtp_geodesics.Solver(V, F, repair=False)
    if match == "repeated vertex":                               # repaired by default (test_repair.py)
        with pytest.warns(UserWarning, match="removed 1 degenerate"):
            vtp_geodesics.Solver(V, F)
    else:
        with pytest.raises(exc, match=match):
            vtp_geodesics.Solver(V, F)


def test_non_manifold():
    # the error with repair=False; by default, the repair and its warning (test_repair.py checks the results)
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=float)
    fin = np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])         # three faces on edge 0-1
    with pytest.raises(ValueError, match="manifold|oriented"):
        vtp_geodesics.Solver(V, fin, repair=False)
    with pytest.warns(UserWarning, match="non-manifold edge"):
        vtp_geodesics.Solver(V, fin)
    Vb = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [-1, 0, 0], [-1, -1, 0]], dtype=float)
    bowtie = np.array([[0, 1, 2], [0, 3, 4]])                 # two fans at vertex 0
    with pytest.raises(ValueError, match="not manifold.*repair=True"):
        vtp_geodesics.Solver(Vb, bowtie, repair=False)
    with pytest.warns(UserWarning, match="non-manifold vertex"):
        vtp_geodesics.Solver(Vb, bowtie)
    flipped = np.array(F0)
    flipped[0] = flipped[0, ::-1]                              # inconsistent orientation
    with pytest.raises(ValueError, match="manifold|oriented"):
        vtp_geodesics.Solver(V0, flipped, repair=False)
    with pytest.warns(UserWarning, match="reoriented"):
        vtp_geodesics.Solver(V0, flipped)


def test_bad_queries():
    solver = vtp_geodesics.Solver(V0, F0)
    with pytest.raises(ValueError, match="out of range"):
        solver.distances(36)
    with pytest.raises(ValueError, match="out of range"):
        solver.distances(-1)
    with pytest.raises(ValueError, match="no source"):
        solver.distances([])
    with pytest.raises(TypeError):
        solver.distances(1.5)
    with pytest.raises(TypeError):
        solver.distances("0")
    with pytest.raises(ValueError, match="method"):
        solver.distances(0, method="dijkstra")
    with pytest.raises(ValueError, match="max_distance"):
        solver.distances(0, max_distance=-1)
    with pytest.raises(ValueError, match="out of range"):
        solver.distances(0, targets=[99])
    with pytest.raises(ValueError, match="barycentric"):
        solver.distances(points=(np.array([0]), np.array([[0.5, 0.6, 0.1]])))
    with pytest.raises(ValueError, match="face index"):
        solver.distances(points=(np.array([50]), np.array([[1, 0, 0]])))
    with pytest.raises(ValueError, match="non-finite"):
        solver.distances(points=np.array([[np.nan, 0, 0]]))
    with pytest.raises(ValueError, match="out of range"):
        solver.matrix([0, 40])
    with pytest.raises(TypeError, match="dtype"):
        solver.matrix([0], dtype=np.int32)
    with pytest.raises(ValueError):
        solver.path(5, sources=[])
    with pytest.raises(ValueError, match="threads"):
        vtp_geodesics.Solver(V0, F0, threads=-2)
    # unreachable: a second component
    V2 = np.vstack([V0, V0 + [5, 0, 0]])
    F2 = np.vstack([F0, F0 + len(V0)])
    s2 = vtp_geodesics.Solver(V2, F2)
    d = s2.distances(0)
    assert np.all(np.isinf(d[len(V0):])) and np.all(np.isfinite(d[:len(V0)]))
    with pytest.raises(ValueError, match="reach"):
        s2.path(len(V0) + 3, sources=0)
    assert s2.distance(0, len(V0) + 3) == np.inf


def test_one_indexed_faces_hint():
    # Solver takes no is_one_indexed argument: its message says what to pass; the gdist functions name their flag
    with pytest.raises(ValueError, match=r"numbered from 1\? pass F - 1\)$") as e:
        vtp_geodesics.Solver(V0, F0 + 1)
    assert "is_one_indexed" not in str(e.value)
    assert vtp_geodesics.Solver(V0, (F0 + 1) - 1).distances(0)[0] == 0        # the hint, followed, works
    with pytest.raises(ValueError, match=r"numbered from 1\? pass is_one_indexed=True\)$"):
        gdist.compute_gdist(V0, (F0 + 1).astype(np.int32))
    d = gdist.compute_gdist(V0, (F0 + 1).astype(np.int32), is_one_indexed=True)
    assert d.shape == (len(V0),) and d[0] == 0


def test_dropins_bad_input():
    with pytest.raises(ValueError, match="out of range"):
        gdist.compute_gdist(V0, np.where(F0 == 5, 99, F0).astype(np.int32))
    with pytest.raises(ValueError, match="numbered from 1"):
        gdist.compute_gdist(V0, (F0 + 1).astype(np.int32))            # one-indexed triangles without the flag
    with pytest.raises(ValueError, match="one-indexed"):
        gdist.compute_gdist(V0, F0.astype(np.int32), is_one_indexed=True)  # zero-indexed with the flag
    with pytest.raises(ValueError, match="non-finite"):
        gdist.local_gdist_matrix(np.where(V0 == V0[3, 0], np.nan, V0), F0.astype(np.int32), 0.5)
    with pytest.raises(ValueError, match="source_indices"):
        gdist.compute_gdist(V0, F0.astype(np.int32), source_indices=np.array([-3], dtype=np.int32))
    with pytest.raises(ValueError, match="empty"):
        gdist.compute_gdist(V0, F0.astype(np.int32), source_indices=np.array([], dtype=np.int32))
    with pytest.raises(TypeError):
        gdist.compute_gdist(V0, F0.astype(np.float64))
    alg = pygeodesic.PyGeodesicAlgorithmExact(V0, F0)
    with pytest.raises(ValueError, match="out of range"):
        alg.geodesicDistance(0, 36)
    with pytest.raises(ValueError, match="out of range"):
        alg.geodesicDistances([0], [40])
    with pytest.raises(ValueError):
        pygeodesic.PyGeodesicAlgorithmExact(V0, F0[:, :2])


def test_keyboard_interrupt_stops_a_matrix():
    # a matrix of ~20000 rows of a 4900-vertex mesh: several seconds at least, on any machine
    V, F = plane_grid(70, 70, jitter=0.3)
    solver = vtp_geodesics.Solver(V, F, threads=2)
    sources = np.tile(np.arange(len(V)), 4)
    assert_interrupt_stops(lambda: solver.matrix(sources, dtype=np.float32), "matrix")
    # and the solver still works
    assert np.array_equal(solver.matrix([3])[0], solver.distances(3))
