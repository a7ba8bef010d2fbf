# The drop-in modules vtp_geodesics.gdist and vtp_geodesics.pygeodesic: types, shapes, symmetry, the limit, and
# the same distances as the module.

import numpy as np
import scipy.sparse

import vtp_geodesics
from vtp_geodesics import gdist, pygeodesic


def test_compute_gdist(elephant):
    V, F, solver = elephant
    Vg, Fg = V.astype(np.float64), F.astype(np.int32)   # as gdist requires
    d = gdist.compute_gdist(Vg, Fg)
    assert d.dtype == np.float64 and d.shape == (len(V),)
    assert np.array_equal(d, solver.distances(0))
    src, tgt = np.array([10, 20], dtype=np.int32), np.array([5, 6, 7, 2000], dtype=np.int32)
    dt = gdist.compute_gdist(Vg, Fg, src, tgt)
    assert dt.shape == (4,) and np.array_equal(dt, solver.distances([10, 20])[tgt])
    dl = gdist.compute_gdist(Vg, Fg, source_indices=src, max_distance=0.1)
    full = solver.distances([10, 20])
    assert np.array_equal(dl[full <= 0.1], full[full <= 0.1]) and np.all(np.isinf(dl[full > 0.1]))
    d1 = gdist.compute_gdist(Vg, Fg + 1, is_one_indexed=True)
    assert np.array_equal(d1, d)


def test_local_gdist_matrix(elephant):
    V, F, solver = elephant
    R = 0.05
    M = gdist.local_gdist_matrix(V, F.astype(np.int32), R)
    n = len(V)
    assert isinstance(M, scipy.sparse.csc_matrix) and M.shape == (n, n) and M.dtype == np.float64
    assert M.nnz > n
    assert np.all(M.data <= R) and np.all(M.diagonal() == 0)
    assert (M != M.T).nnz == 0                                  # symmetric
    rows = [0, 100, 1000]
    for r in rows:
        d = solver.distances(r)
        inside = np.flatnonzero(d <= R)
        inside = inside[inside != r]
        col = M[:, [r]].toarray().ravel()
        assert np.array_equal(np.flatnonzero(col), inside)
        assert np.allclose(col[inside], d[inside], rtol=1e-12, atol=1e-14)


def test_distance_matrix_of_selected_points(elephant):
    V, F, solver = elephant
    pts = np.array([4, 400, 1400, 2400], dtype=np.int32)
    M = gdist.distance_matrix_of_selected_points(V, F.astype(np.int32), pts)
    assert isinstance(M, scipy.sparse.csc_matrix) and M.shape == (len(V), len(V))
    assert M.nnz == 12 and (M != M.T).nnz == 0
    for p in pts:
        d = solver.distances(int(p))
        for q in pts:
            if q != p:
                assert abs(M[p, q] - d[q]) <= 1e-12
    R = float(np.median(M.data))
    ML = gdist.distance_matrix_of_selected_points(V, F.astype(np.int32), pts, max_distance=R)
    assert 0 < ML.nnz < 12 and np.all(ML.data <= R) and (ML != ML.T).nnz == 0


def test_pygeodesic(elephant):
    V, F, solver = elephant
    alg = pygeodesic.PyGeodesicAlgorithmExact(V, F)
    dist, path = alg.geodesicDistance(3, 1500)
    assert isinstance(dist, float) and path.ndim == 2 and path.shape[1] == 3
    assert np.array_equal(path[0], V[1500]) and np.array_equal(path[-1], V[3])  # target first, as pygeodesic
    assert abs(np.linalg.norm(np.diff(path, axis=0), axis=1).sum() - dist) <= 1e-9
    assert abs(dist - solver.distances(3)[1500]) <= 1e-12
    d, best = alg.geodesicDistances()
    assert d.dtype == np.float64 and best.dtype == np.int32 and np.array_equal(d, solver.distances(0))
    src, tgt = np.array([8, 1600]), np.array([1, 2, 3, 2500])
    d, best = alg.geodesicDistances(src, tgt)
    assert d.shape == (4,) and best.shape == (4,)
    single = np.array([solver.distances(int(s))[tgt] for s in src])
    assert np.allclose(d, single.min(axis=0), rtol=0, atol=1e-12)
    assert np.allclose(single[best, np.arange(4)], d, rtol=0, atol=1e-12)
