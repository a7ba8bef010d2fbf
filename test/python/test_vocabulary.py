# One vocabulary (issue 46) in the Python module: the results as namedtuples with named fields (Curve, CellAreas,
# SurfacePolyline, StraightestGeodesic), the names of the C++ named parameters and of the tool's flags
# (straightest_geodesic, reference_direction, log_map_strict) with the former names kept as aliases (trace,
# reference, strict, curve["points"]), and the arguments after the first keyword-only.

import math

import numpy as np
import pytest

import vtp_geodesics


def test_curves_are_namedtuples_with_their_locations(elephant):
    V, F, s = elephant
    d = s.distances(0)
    level = 0.3 * float(d[np.isfinite(d)].max())
    curves = s.isolines([level], sources=0)
    assert curves and all(isinstance(c, vtp_geodesics.Curve) for c in curves)
    for c in curves:
        assert c._fields == ("points", "faces", "barycentric", "closed", "level", "cells")
        assert c.points.shape == (len(c.faces), 3) and c.barycentric.shape == (len(c.faces), 3)
        assert c.level == level and c.cells is None
        # each point is its face location
        assert np.allclose(np.einsum("ij,ijk->ik", c.barycentric, V[F[c.faces]]), c.points, rtol=0, atol=1e-12)
        # the keys of the former dicts are aliases of the fields
        assert c["points"] is c.points and c["closed"] == c.closed and c["level"] == c.level
        assert c[0] is c.points
        with pytest.raises(KeyError):
            c["nothing"]
    borders = s.cell_borders([0, 2000])
    assert borders and all(math.isnan(b.level) and b.cells == (0, 1) for b in borders)
    # return_locations is kept (the locations are always there)
    again = s.cell_borders([0, 2000], return_locations=True)
    assert all(np.array_equal(a.points, b.points) and np.array_equal(a.faces, b.faces) for a, b in zip(again, borders))


def test_cell_areas_and_paths_are_namedtuples(elephant):
    V, F, s = elephant
    r = s.cell_areas([0, 2000])
    assert isinstance(r, vtp_geodesics.CellAreas)
    areas, uncertainty = r
    assert areas is r.areas and uncertainty is r.uncertainty and (uncertainty > 0).all()
    p = s.path(500, sources=0, return_locations=True)
    assert isinstance(p, vtp_geodesics.SurfacePolyline)
    P, faces, bary = p
    assert np.array_equal(P, s.path(500, sources=0)) and p.faces is faces and p.barycentric is bary
    assert np.allclose(np.einsum("ij,ijk->ik", bary, V[F[faces]]), P, rtol=0, atol=1e-12)


def test_straightest_geodesic_and_its_alias_trace(elephant):
    V, F, s = elephant
    w = s.straightest_geodesic(5, direction=[1.0, 0.0, 0.0], length=0.2)
    assert isinstance(w, vtp_geodesics.StraightestGeodesic)
    P, end, end_direction, walked, border = s.trace(5, [1.0, 0.0, 0.0], 0.2, return_details=True)
    assert np.array_equal(w.points, P) and w.end[0] == end[0] and np.array_equal(w.end[1], end[1])
    assert np.array_equal(w.end_direction, end_direction) and w.length == walked and w.reached_border == border
    assert len(s.trace(5, [1.0, 0.0, 0.0], 0.2)) == 3  # the alias keeps its former result
    batch = s.straightest_geodesic([5, 6], direction=[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], length=[0.2, 0.1])
    assert len(batch.points) == 2 and batch.length.shape == (2,)
    with pytest.raises(TypeError):
        s.straightest_geodesic(5, [1.0, 0.0, 0.0], 0.2)


def test_log_map_names_of_the_cpp_parameters_and_their_aliases(elephant):
    V, F, s = elephant
    ref = [0.0, 1.0, 0.0]
    new = s.log_map(0, reference_direction=ref, log_map_strict=True, max_distance=0.3)
    old = s.log_map(0, reference=ref, strict=True, max_distance=0.3)
    assert np.array_equal(new, old, equal_nan=True)
    assert not np.array_equal(new, s.log_map(0, max_distance=0.3), equal_nan=True)
    with pytest.raises(TypeError, match="both given"):
        s.log_map(0, reference_direction=ref, reference=ref)
    with pytest.raises(TypeError, match="both given"):
        s.log_map(0, log_map_strict=True, strict=True)
    with pytest.raises(TypeError, match="log_map_strict must be a bool"):
        s.log_map(0, log_map_strict=1)
    a = s.polar_patches([0, 7], radius=0.2, log_map_strict=True)
    b = s.polar_patches([0, 7], radius=0.2, strict=True)
    assert all(np.array_equal(x, y) for x, y in zip(a, b))


def test_arguments_after_the_first_are_keywords(elephant):
    V, F, s = elephant
    for call in (lambda: s.isolines([0.1], 0), lambda: s.path(5, 0), lambda: s.matrix([0], [1, 2]),
                 lambda: s.polar_patches([0], 0.1)):
        with pytest.raises(TypeError):
            call()
    assert s.matrix([0], targets=[1, 2]).shape == (1, 2)
