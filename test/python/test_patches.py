# Polar patches of the Python module: Solver.polar_patches() against distances() with the same max_distance (rho
# bitwise, the same vertices), the plane (rho and theta Euclidean), threads = one thread, strict, a repaired mesh,
# bad input.

import math
import os

import numpy as np
import pytest

import vtp_geodesics
from conftest import data_file, plane_grid


def test_rows_equal_single_runs(elephant):
    V, F, solver = elephant
    largest = solver.distances(0).max()
    radius = 0.07 * largest
    centres = np.arange(0, V.shape[0], 37)
    p = solver.polar_patches(centres, radius)
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
        a = solver.polar_patches(centres, radius, threads=1, strict=strict)
        b = solver.polar_patches(centres, radius, threads=2, strict=strict)
        for x, y in zip(a, b):
            assert np.array_equal(x, y)
    # strict and default agree on rho and on the vertices
    c = solver.polar_patches(centres, radius, strict=True)
    assert np.array_equal(a.indices, c.indices) and np.array_equal(a.rho, c.rho)


def test_plane_is_euclidean():
    V, F = plane_grid(15, 15, jitter=0.3, seed=3)
    solver = vtp_geodesics.Solver(V, F)
    radius = 0.3
    centres = [7 * 15 + 7, 5 * 15 + 9, 7]  # two inside, one on the border (angles scaled by pi / pi)
    p = solver.polar_patches(centres, radius)
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
    p = solver.polar_patches(good, math.inf)
    for i, c in enumerate(good):
        row = slice(p.indptr[i], p.indptr[i + 1])
        d = solver.distances(c)
        assert np.array_equal(p.indices[row], np.flatnonzero(np.isfinite(d)))  # split vertices once
        assert np.array_equal(p.rho[row], d[p.indices[row]])  # the least over the copies
    for c in split:
        with pytest.raises(ValueError, match="split by the repair"):
            solver.polar_patches([c], 1.0)


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
        solver.polar_patches(centres, radius)


def test_empty_and_infinite(elephant):
    V, F, solver = elephant
    p = solver.polar_patches([], 0.1)
    assert p.indptr.tolist() == [0] and p.indices.size == 0
    p = solver.polar_patches(3, math.inf)
    d = solver.distances(3)
    assert np.array_equal(p.rho, d[p.indices]) and p.indices.size == np.isfinite(d).sum()
