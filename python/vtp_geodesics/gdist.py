"""Drop-in replacement for the ``gdist`` package (The Virtual Brain's tvb-gdist), on vtp_geodesics.

Change one line::

    import gdist                                  # before
    from vtp_geodesics import gdist               # after

The functions have gdist's names, argument names and order, defaults and return types:
``compute_gdist``, ``local_gdist_matrix`` and ``distance_matrix_of_selected_points``. gdist requires float64
vertices and int32 triangles; those are accepted, and so is anything convertible (other real and integer
dtypes, lists, non-contiguous views).

Where this module deliberately differs from gdist:

- a mesh that is not a valid manifold mesh (non-manifold vertices or edges, duplicate, degenerate or flipped
  triangles) is repaired as ``vtp_geodesics.Solver`` repairs it, with a ``UserWarning`` saying what was done,
  and every index stays the caller's (a vertex the repair split gets the least distance of its copies, a
  vertex in no face ``inf``), where gdist crashes or gives wrong numbers;
- bad input raises ``ValueError`` or ``TypeError`` naming the problem (a triangle index out of range, a
  negative index, a NaN coordinate, wrong shapes), where gdist crashes the interpreter or returns wrong
  numbers silently;
- the distances are exact (VTP) where gdist's MMP code fails on some real meshes;
- ``local_gdist_matrix`` is symmetric (each pair holds the smaller of its two computed distances, which
  differ by rounding only) and every stored entry is ``<= max_distance``; the rows are computed on all
  cores;
- ``distance_matrix_of_selected_points`` stores only the pairs within ``max_distance`` (gdist stores ``inf``
  for the others), symmetric as well;
- ``is_one_indexed`` applies to ``triangles`` only, as in gdist: vertex indices given as sources, targets or
  points are always 0-based.
"""

import numpy
import scipy.sparse

from . import Solver as _Solver
from . import _core

__all__ = ["compute_gdist", "local_gdist_matrix", "distance_matrix_of_selected_points"]


def _solver(vertices, triangles, is_one_indexed):
    if not isinstance(is_one_indexed, (bool, numpy.bool_)):
        raise TypeError("is_one_indexed must be a bool, got %r" % (is_one_indexed,))
    F = numpy.asarray(triangles)
    if F.dtype.kind not in "iu" or F.dtype == numpy.bool_:
        raise TypeError("triangles must hold integer indices, got dtype %s" % F.dtype)
    F = F.astype(numpy.int64)
    if is_one_indexed:
        if F.size and F.min() < 1:
            raise ValueError("is_one_indexed=True, but triangles hold the index %d (one-indexed triangles start at 1)"
                             % F.min())
        F = F - 1
    try:
        return _Solver(vertices, F)
    except ValueError as e:
        if is_one_indexed or "numbered from 1?" not in str(e):
            raise
        # the gdist functions take one-indexed triangles with their own argument
        raise ValueError(str(e).replace("pass F - 1", "pass is_one_indexed=True")) from None


def _indices(x, name, n):
    a = numpy.asarray(x)
    if a.dtype.kind not in "iu" or a.dtype == numpy.bool_:
        if not (a.size == 0 and a.dtype.kind == "f"):
            raise TypeError("%s must hold integer vertex indices, got dtype %s" % (name, a.dtype))
    a = a.astype(numpy.int64).reshape(-1) if a.ndim <= 1 else None
    if a is None:
        raise ValueError("%s must be 1-dimensional" % name)
    if a.size and (a.min() < 0 or a.max() >= n):
        bad = a[(a < 0) | (a >= n)][0]
        raise ValueError("%s: vertex index %d out of range [0, %d)" % (name, bad, n))
    return a


def compute_gdist(vertices, triangles, source_indices=None, target_indices=None, max_distance=numpy.inf,
                  is_one_indexed=False):
    """Geodesic distance from the nearest of ``source_indices`` to each of ``target_indices``.

    Args:
        vertices: (N, 3) coordinates (float64, or anything convertible).
        triangles: (M, 3) vertex indices of the triangles (int32, or any integer type).
        source_indices: source vertices (default: vertex 0).
        target_indices: target vertices (default: every vertex). With targets, the propagation stops once
            their distances are final.
        max_distance: distance limit; targets beyond it get ``inf`` (the propagation stops there).
        is_one_indexed: the triangles are numbered from 1.

    Returns:
        numpy.ndarray float64 (len(target_indices),), or (N,) without targets: exact geodesic distances,
        ``inf`` beyond ``max_distance`` or where unreachable.

    Raises ValueError / TypeError on bad input (gdist crashes or returns wrong values instead).
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    n = solver.number_of_vertices
    sources = numpy.zeros(1, dtype=numpy.int64) if source_indices is None else _indices(source_indices,
                                                                                          "source_indices", n)
    if sources.size == 0:
        raise ValueError("source_indices is empty")
    if target_indices is None:
        return solver.distances(sources, max_distance=max_distance)
    targets = _indices(target_indices, "target_indices", n)
    d = solver.distances(sources, max_distance=max_distance, targets=targets)
    return d[targets]


def _symmetric_csc(M, n):
    """min(M, M^T) over the union of both patterns, as a csc_matrix (a symmetric CSR is its own CSC)."""
    M = M.tocsr()
    M.sort_indices()
    data, indices, indptr = _core.symmetric_min_csr(M.data.astype(numpy.float64), M.indices.astype(numpy.int64),
                                                    M.indptr.astype(numpy.int64))
    return scipy.sparse.csc_matrix((data, indices, indptr), shape=(n, n))


def local_gdist_matrix(vertices, triangles, max_distance=numpy.inf, is_one_indexed=False):
    """Geodesic distances from every vertex to every vertex within ``max_distance``.

    Returns:
        scipy.sparse.csc_matrix (N, N) float64, **symmetric**, holding the pairs of distinct vertices at
        distance ``<= max_distance`` (the diagonal is not stored). Rows are computed on all cores; with
        ``max_distance=inf`` every pair is stored (N^2 entries: mind the memory).

    Raises ValueError / TypeError on bad input.
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    n = solver.number_of_vertices
    limit = float(max_distance)
    if not limit >= 0:
        raise ValueError("max_distance must be >= 0, got %r" % (max_distance,))
    if limit < numpy.inf:
        M = solver.matrix(max_distance=limit)
    else:
        M = scipy.sparse.csr_matrix(solver.matrix())
    M = _drop_diagonal(M)
    return _symmetric_csc(M, n)


def _drop_diagonal(M):
    C = M.tocoo()
    keep = (C.row != C.col) & numpy.isfinite(C.data)
    C = scipy.sparse.coo_matrix((C.data[keep], (C.row[keep], C.col[keep])), shape=C.shape)
    return C.tocsr()


def distance_matrix_of_selected_points(vertices, triangles, points, max_distance=numpy.inf, is_one_indexed=False):
    """Pairwise geodesic distances among the vertices ``points``, within ``max_distance``.

    Returns:
        scipy.sparse.csc_matrix (N, N) float64 (N: number of vertices), symmetric, holding d(p, q) for the
        pairs p != q of ``points`` at distance ``<= max_distance`` (gdist also stores ``inf`` for the pairs
        beyond the limit; this one does not).

    Raises ValueError / TypeError on bad input.
    """
    solver = _solver(vertices, triangles, is_one_indexed)
    n = solver.number_of_vertices
    pts = numpy.unique(_indices(points, "points", n))
    limit = float(max_distance)
    if not limit >= 0:
        raise ValueError("max_distance must be >= 0, got %r" % (max_distance,))
    if pts.size == 0:
        return scipy.sparse.csc_matrix((n, n), dtype=numpy.float64)
    D = solver.matrix(pts, targets=pts, max_distance=limit)
    D = scipy.sparse.coo_matrix(D) if limit == numpy.inf else D.tocoo()
    keep = (D.row != D.col) & numpy.isfinite(D.data) & (D.data <= limit)
    M = scipy.sparse.csr_matrix((D.data[keep], (pts[D.row[keep]], pts[D.col[keep]])), shape=(n, n))
    return _symmetric_csc(M, n)
