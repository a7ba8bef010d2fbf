# Polar patches of the Python module: Solver.polar_patches() against distances() with the same max_distance (rho
# bitwise, the same vertices), the plane (rho and theta Euclidean), threads = one thread, strict, a repaired mesh,
# bad input; centres at points of faces (rows = the single log_map() and distances() runs from the point); Ctrl-C.

import math
import os

import numpy as np
import pytest

import vtp_geodesics
from conftest import assert_interrupt_stops, data_file, plane_grid


def test_rows_equal_single_runs(elephant):
    V, F, solver = elephant
    largest = solver.distances(0).max()
    radius = 0.07 * largest
    centres = np.arange(0, V.shape[0], 37)
    p = solver.polar_patches(centres, radius=radius)
    assert isinstance(p, vtp_geodesics.PolarPatches)
    assert p.indptr.dtype == np.int64 and p.indices.dtype == np.int64
    assert p.rho.dtype == np.float64 and p.theta.dtype == np.float64
    assert p.indptr.shape == (centres.size + 1,) and p.indptr[0] == 0 and p.indptr[-1] == p.indices.size
    for i, c in enumerate(centres):
        d = solver.distances(int(c), max_distance=radius)
        row = slice(p.indptr[i], p.indptr[i + 1])
        idx = p.indices[row]
        assert np.array_equal(idx, np.flatnonzero(np.isfinite(d)))  # ascending, every vertex within the radius
        assert np.array_equal(p.rho[row], d[idx])  # bitwise
        assert (p.theta[row] >= 0).all() and (p.theta[row] < 2 * np.pi).all()
        k = np.flatnonzero(idx == c)
        assert k.size == 1 and p.rho[row][k[0]] == 0 and p.theta[row][k[0]] == 0


def test_threads_and_strict(elephant):
    V, F, solver = elephant
    radius = 0.05 * solver.distances(0).max()
    centres = np.arange(V.shape[0])
    for strict in (False, True):
        a = solver.polar_patches(centres, radius=radius, threads=1, strict=strict)
        b = solver.polar_patches(centres, radius=radius, threads=2, strict=strict)
        for x, y in zip(a, b):
            assert np.array_equal(x, y)
    # strict and default agree on rho and on the vertices
    c = solver.polar_patches(centres, radius=radius, strict=True)
    assert np.array_equal(a.indices, c.indices) and np.array_equal(a.rho, c.rho)


def test_plane_is_euclidean():
    V, F = plane_grid(15, 15, jitter=0.3, seed=3)
    solver = vtp_geodesics.Solver(V, F)
    radius = 0.3
    centres = [7 * 15 + 7, 5 * 15 + 9, 7]  # two inside, one on the border (angles scaled by pi / pi)
    p = solver.polar_patches(centres, radius=radius)
    for i, c in enumerate(centres):
        row = slice(p.indptr[i], p.indptr[i + 1])
        e = np.hypot(V[:, 0] - V[c, 0], V[:, 1] - V[c, 1])
        inside = np.flatnonzero(e < radius - 1e-12)
        assert set(inside) <= set(p.indices[row]) <= set(np.flatnonzero(e <= radius + 1e-12))
        assert np.allclose(p.rho[row], e[p.indices[row]], rtol=0, atol=1e-12)
        # theta: the Euclidean angle from the reference edge (from c to the source of its halfedge), which the
        # log map of the same centre gives as rho (cos theta, sin theta); here checked through its invariance:
        # angle differences between vertices are Euclidean angle differences
        d = V[p.indices[row], :2] - V[c, :2]
        far = p.rho[row] > 1e-9
        phi = np.arctan2(d[far, 1], d[far, 0])
        t = p.theta[row][far]
        gap = np.remainder((t - t[0]) - (phi - phi[0]) + np.pi, 2 * np.pi) - np.pi
        assert np.abs(gap).max() < 1e-12


def test_repaired_mesh():
    # two fans of triangles pinched at vertex 0 (a non-manifold vertex, split by the repair)
    V, F = plane_grid(5, 5, seed=2)
    W = V + np.array([0., 0., 1.])
    V = np.vstack([V, W])
    F = np.vstack([F, F + V.shape[0] // 2])
    F[F == V.shape[0] // 2] = 0  # the corner (0, 0, 1) of the second grid becomes vertex 0
    with pytest.warns(UserWarning):
        solver = vtp_geodesics.Solver(V, F)
    begin, _ = solver.vertex_copies()
    split = [i for i in range(V.shape[0]) if begin[i + 1] - begin[i] > 1]
    assert split  # the pinched vertex
    good = [i for i in range(V.shape[0]) if begin[i + 1] - begin[i] == 1]
    p = solver.polar_patches(good, radius=math.inf)
    for i, c in enumerate(good):
        row = slice(p.indptr[i], p.indptr[i + 1])
        d = solver.distances(c)
        assert np.array_equal(p.indices[row], np.flatnonzero(np.isfinite(d)))  # split vertices once
        assert np.array_equal(p.rho[row], d[p.indices[row]])  # the least over the copies
    for c in split:
        with pytest.raises(ValueError, match="split by the repair"):
            solver.polar_patches([c], radius=1.0)
    # centres at points of faces of the repaired mesh: the rows of the single runs from each point
    faces = np.array([0, 7, F.shape[0] - 1])
    bary = np.array([[0.2, 0.3, 0.5], [1 / 3, 1 / 3, 1 / 3], [0.6, 0.2, 0.2]])
    p = solver.polar_patches(points=(faces, bary), radius=math.inf)
    for i in range(faces.size):
        point = (faces[i:i + 1], bary[i:i + 1])
        d = solver.distances(points=point)
        lm = solver.log_map(points=point)
        row = slice(p.indptr[i], p.indptr[i + 1])
        idx = p.indices[row]
        assert np.array_equal(idx, np.flatnonzero(np.isfinite(d)))
        assert np.array_equal(p.rho[row], d[idx])
        gap = np.remainder(p.theta[row] - np.arctan2(lm[idx, 1], lm[idx, 0]) + np.pi, 2 * np.pi) - np.pi
        assert np.abs(gap[p.rho[row] > 1e-9]).max() < 1e-12


@pytest.mark.parametrize("centres, radius, error, message", [
    ([0, 100000], 0.1, ValueError, "out of range"),
    ([-1], 0.1, ValueError, "out of range"),
    ([0], -0.1, ValueError, "radius"),
    ([0], float("nan"), ValueError, "radius"),
    ([0.5], 0.1, TypeError, "integer"),
    ([0], "a", TypeError, "radius"),
])
def test_bad_input(elephant, centres, radius, error, message):
    V, F, solver = elephant
    with pytest.raises(error, match=message):
        solver.polar_patches(centres, radius=radius)


def test_empty_and_infinite(elephant):
    V, F, solver = elephant
    p = solver.polar_patches([], radius=0.1)
    assert p.indptr.tolist() == [0] and p.indices.size == 0
    p = solver.polar_patches(3, radius=math.inf)
    d = solver.distances(3)
    assert np.array_equal(p.rho, d[p.indices]) and p.indices.size == np.isfinite(d).sum()


def _face_points(solver, V, F, count, seed):
    rng = np.random.default_rng(seed)
    faces = rng.integers(0, F.shape[0], count)
    bary = rng.random((count, 3)) + 0.05
    bary /= bary.sum(axis=1, keepdims=True)
    bary[0] = [1 / 3, 1 / 3, 1 / 3]
    bary[1] = [0.5, 0.5, 0.]  # on an edge
    return faces, bary


def test_point_rows_equal_single_log_maps(elephant):
    # each row of a point centre: the vertices and rho of distances(points=..., max_distance=radius) (bitwise),
    # theta that of log_map(points=..., max_distance=radius) from the same point (its frame: F[face][0] ->
    # F[face][1]), to rounding
    V, F, solver = elephant
    radius = 0.07 * solver.distances(0).max()
    faces, bary = _face_points(solver, V, F, 12, seed=5)
    p = solver.polar_patches(points=(faces, bary), radius=radius)
    assert p.indptr.shape == (faces.size + 1,) and p.indptr[-1] == p.indices.size
    for i in range(faces.size):
        point = (faces[i:i + 1], bary[i:i + 1])
        d = solver.distances(points=point, max_distance=radius)
        lm = solver.log_map(points=point, max_distance=radius)
        row = slice(p.indptr[i], p.indptr[i + 1])
        idx = p.indices[row]
        assert idx.size > 3
        assert np.array_equal(idx, np.flatnonzero(np.isfinite(d)))
        assert np.array_equal(idx, np.flatnonzero(np.isfinite(lm[:, 0])))
        assert np.array_equal(p.rho[row], d[idx])
        assert np.abs(np.hypot(lm[idx, 0], lm[idx, 1]) - p.rho[row]).max() < 1e-12 * radius + 1e-15
        assert (p.theta[row] >= 0).all() and (p.theta[row] < 2 * np.pi).all()
        t = np.arctan2(lm[idx, 1], lm[idx, 0])
        gap = np.remainder(p.theta[row] - t + np.pi, 2 * np.pi) - np.pi
        assert np.abs(gap[p.rho[row] > 1e-9 * radius]).max() < 1e-12


def test_vertices_then_points(elephant):
    # one call with both: the vertex rows, then the point rows, each as in a call of its own; xyz points are
    # located as locate() does; the threads do not change a bit
    V, F, solver = elephant
    radius = 0.05 * solver.distances(0).max()
    faces, bary = _face_points(solver, V, F, 6, seed=9)
    centres = [5, 900, 5]
    both = solver.polar_patches(centres, radius=radius, points=(faces, bary))
    a = solver.polar_patches(centres, radius=radius)
    b = solver.polar_patches(points=(faces, bary), radius=radius)
    assert np.array_equal(both.indptr, np.concatenate([a.indptr, b.indptr[1:] + a.indptr[-1]]))
    for k in ("indices", "rho", "theta"):
        assert np.array_equal(getattr(both, k), np.concatenate([getattr(a, k), getattr(b, k)]))
    xyz = np.einsum("kj,kjd->kd", bary, V[F[faces]])
    lf, lb = solver.locate(xyz)
    c = solver.polar_patches(points=xyz, radius=radius)
    d = solver.polar_patches(points=(lf, lb), radius=radius)
    for x, y in zip(c, d):
        assert np.array_equal(x, y)
    for strict in (False, True):
        one = solver.polar_patches(centres, radius=radius, points=(faces, bary), threads=1, strict=strict)
        two = solver.polar_patches(centres, radius=radius, points=(faces, bary), threads=2, strict=strict)
        for x, y in zip(one, two):
            assert np.array_equal(x, y)


def test_points_on_the_plane():
    # a point inside a face of a flat grid: rho the Euclidean distance, theta the Euclidean angle from
    # F[face][0] -> F[face][1]
    V, F = plane_grid(15, 15, jitter=0.3, seed=3)
    solver = vtp_geodesics.Solver(V, F)
    face = 200
    bary = np.array([[0.2, 0.3, 0.5]])
    x = bary @ V[F[face]]
    p = solver.polar_patches(points=([face], bary), radius=0.3)
    e = V[p.indices, :2] - x[0, :2]
    assert np.allclose(p.rho, np.hypot(e[:, 0], e[:, 1]), rtol=0, atol=1e-12)
    axis = V[F[face, 1], :2] - V[F[face, 0], :2]
    if np.cross(V[F[face, 1]] - V[F[face, 0]], V[F[face, 2]] - V[F[face, 0]])[2] < 0:
        e[:, 1] = -e[:, 1]  # the faces' orientation points down: angles counter-clockwise seen from below
        axis[1] = -axis[1]
    phi = np.arctan2(e[:, 1], e[:, 0]) - np.arctan2(axis[1], axis[0])
    gap = np.remainder(p.theta - phi + np.pi, 2 * np.pi) - np.pi
    assert np.abs(gap).max() < 1e-12


@pytest.mark.parametrize("kwargs, error, message", [
    (dict(points=([100000], [[1., 0., 0.]]), radius=0.1), ValueError, "out of range"),
    (dict(points=([0], [[0.5, 0.6, 0.]]), radius=0.1), ValueError, "barycentric"),
    (dict(points=([0], [[0.5, 0.5]]), radius=0.1), ValueError, "shape"),
    (dict(points=([0], [[1., 0., 0.]])), TypeError, "radius"),
])
def test_bad_points(elephant, kwargs, error, message):
    V, F, solver = elephant
    with pytest.raises(error, match=message):
        solver.polar_patches(**kwargs)


def test_keyboard_interrupt_stops_the_patches():
    # whole log maps around every vertex of a 4900-vertex grid, four times: several seconds at least
    V, F = plane_grid(70, 70, jitter=0.3)
    solver = vtp_geodesics.Solver(V, F, threads=2)
    centres = np.tile(np.arange(len(V)), 4)
    assert_interrupt_stops(
        lambda: solver.polar_patches(centres, radius=math.inf, points=([0], [[1 / 3, 1 / 3, 1 / 3]])), "patches")
    # and the solver still works
    p = solver.polar_patches([3], radius=math.inf)
    assert np.array_equal(p.rho, solver.distances(3)[p.indices])
