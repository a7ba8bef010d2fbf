"""Exact geodesic distances on triangle meshes (VTP, PVTP, AVTP, PAVTP), from numpy arrays.

    import vtp_geodesics
    V, F = vtp_geodesics.read_mesh("elephant.off")      # V float64 (n, 3), F int64 (m, 3)
    solver = vtp_geodesics.Solver(V, F)                  # per-mesh preprocessing, once
    d = solver.distances(0)                              # float64 (n,): distances from vertex 0
    d, labels = solver.distances([0, 99], return_labels=True)
    path = solver.path(500, sources=0)                   # (k, 3) points, from the source to vertex 500
    M = solver.matrix(max_distance=0.1)                  # scipy.sparse.csr_matrix, rows on all cores
    fps = solver.farthest_point_sampling(100)            # samples, radii, distances, labels (Voronoi cells)

Distances are exact (up to double rounding) for the methods "vtp" and "pvtp", lengths of real surface paths
for "avtp" and "pavtp". Unreachable vertices, and vertices beyond a distance limit, get ``inf``. Every
computation releases the GIL and may run on all cores; bad input raises ValueError or TypeError naming the
problem. The drop-in modules ``vtp_geodesics.gdist`` and ``vtp_geodesics.pygeodesic`` take the arguments of
the packages of the same names.
"""

import collections as _collections
import math as _math
import os as _os
import warnings as _warnings

import numpy as _np

from . import _core

__all__ = ["Solver", "FarthestPointSamples", "read_mesh", "methods", "recommended_lambda"]

#: The result of ``Solver.farthest_point_sampling()``.
FarthestPointSamples = _collections.namedtuple(
    "FarthestPointSamples", ["samples", "radii", "distances", "labels", "cell_areas", "cell_area_uncertainty"])
FarthestPointSamples.__doc__ = """The result of ``Solver.farthest_point_sampling()``.

samples : ndarray int64 (s,)
    The sample vertices, in the order they were taken.
radii : ndarray float64 (s,)
    ``radii[i]``: the covering radius once ``samples[:i + 1]`` are taken (the largest distance of a vertex to
    its nearest sample; ``inf`` while a connected component has no sample). Non-increasing.
distances : ndarray float64 (n,)
    The distance of every vertex to its nearest sample.
labels : ndarray int64 (n,)
    The index (into ``samples``) of the nearest sample of every vertex: its geodesic Voronoi cell; -1 for a
    vertex no sample reaches.
cell_areas : ndarray float64 (s,)
    The area of the part of the surface nearest to each sample. A face whose corners are in different cells
    is split where the two distances, extended straight along its edges, are equal.
cell_area_uncertainty : ndarray float64 (s,)
    The area of the faces each cell shares with other cells, where its border is estimated: a bound of the
    error of ``cell_areas``.
"""

#: The methods of the library (names for ``method=``), from its method table.
methods = tuple(m["name"] for m in _core.method_table() if m["available"])

#: The window-reset step (in mean edge lengths) recommended for the approximate methods.
recommended_lambda = _core.recommended_lambda


# ------------------------------------------------------------------------------------------------------------
# conversions of user input (everything that is not an array of numbers of the right kind is refused here)
# ------------------------------------------------------------------------------------------------------------
class _VertexZero(int):
    """The default of ``sources``: vertex 0, unless ``points`` are given (then no vertex)."""

    def __repr__(self):
        return "0"


_SOURCE_DEFAULT = _VertexZero(0)


def _source_vertices(sources, points):
    if sources is _SOURCE_DEFAULT and points is not None:
        return _np.zeros(0, dtype=_np.int64)
    return _vertex_list(sources, "sources")


def _as_float_array(x, name):
    try:
        a = _np.asarray(x)
    except Exception as e:  # ragged lists and the like
        raise ValueError("%s cannot be read as an array of numbers: %s" % (name, e)) from None
    if a.dtype.kind not in "fiu" or a.dtype == _np.bool_:
        raise TypeError("%s must hold real numbers, got dtype %s" % (name, a.dtype))
    return _np.ascontiguousarray(a, dtype=_np.float64)


def _as_index_array(x, name, ndim=None):
    try:
        a = _np.asarray(x)
    except Exception as e:
        raise ValueError("%s cannot be read as an array of indices: %s" % (name, e)) from None
    if a.size == 0 and a.dtype.kind == "f":  # an empty list comes out as float64
        a = a.astype(_np.int64)
    if a.dtype.kind not in "iu" or a.dtype == _np.bool_:
        raise TypeError("%s must hold integer indices, got dtype %s" % (name, a.dtype))
    if a.dtype.kind == "u" and a.size and a.max() > _np.iinfo(_np.int64).max:
        raise ValueError("%s: index out of range" % name)
    a = _np.ascontiguousarray(a, dtype=_np.int64)
    if ndim is not None and a.ndim != ndim:
        raise ValueError("%s must be %d-dimensional, got shape %s" % (name, ndim, a.shape))
    return a


def _vertex_list(x, name):
    """An int or an array-like of vertex indices -> int64 (k,)."""
    if x is None:
        return _np.zeros(0, dtype=_np.int64)
    if isinstance(x, (bool, _np.bool_)):
        raise TypeError("%s must be a vertex index or an array of them, got a bool" % name)
    a = _as_index_array(x, name)
    if a.ndim == 0:
        a = a.reshape(1)
    if a.ndim != 1:
        raise ValueError("%s must be a vertex index or a 1-dimensional array of them, got shape %s" % (name, a.shape))
    return a


def _check_float(x, name):
    if isinstance(x, (bool, _np.bool_)):
        raise TypeError("%s must be a number, got a bool" % name)
    try:
        return float(x)
    except (TypeError, ValueError):
        raise TypeError("%s must be a number, got %r" % (name, x)) from None


def _check_threads(threads):
    if isinstance(threads, (bool, _np.bool_)) or not isinstance(threads, (int, _np.integer)):
        raise TypeError("threads must be an int, got %r" % (threads,))
    if threads < 0:
        raise ValueError("threads must be >= 0 (0: all cores), got %d" % threads)
    return int(threads)


def _check_method(method):
    if not isinstance(method, str):
        raise TypeError("method must be a string (one of %s), got %r" % (", ".join(methods), method))
    return method.lower()


def read_mesh(path, *, threads=0):
    """Reads a mesh file with the readers of the command-line tools: ``read_mesh(path) -> (V, F)``.

    Reads OFF, OBJ, PLY, STL and GOCAD TS files (the format comes from the extension). A file that is not a
    valid triangle mesh is repaired as ``vtp_geodesics`` (the tool) repairs it: polygons triangulated,
    duplicate points merged, degenerate faces removed, faces reoriented, non-manifold vertices duplicated;
    what was done is reported as a ``UserWarning``, and the vertices are then those of the repaired mesh.

    Returns ``V``, float64 array (n, 3) of vertex coordinates, and ``F``, int64 array (m, 3) of vertex
    indices (0-based) of the triangles. Raises FileNotFoundError if there is no such file, ValueError if the
    file cannot be read or used (the message names the problem).
    """
    path = _os.fspath(path)
    if not _os.path.exists(path):
        raise FileNotFoundError("no such file: '%s'" % path)
    V, F, repairs, _reader, _direct = _core.read_mesh(path, _check_threads(threads))
    if repairs:
        _warnings.warn("read_mesh('%s'): the file is not a valid triangle mesh and was repaired: %s"
                       % (path, repairs), UserWarning, stacklevel=2)
    return V, F


class Solver:
    """Geodesic distances on one triangle mesh: ``Solver(V, F, *, threads=0)``.

    The constructor checks the mesh and does the per-mesh preprocessing once; every query then runs
    from there, any number of times, with the GIL released (other Python threads keep running).

    Parameters
    ----------
    V : array-like (n, 3) of numbers
        Vertex coordinates (any real dtype, any memory order; converted to float64).
    F : array-like (m, 3) of integers
        Triangles as 0-based vertex indices (any integer dtype). Faces must form a manifold triangle mesh
        with a consistent orientation (boundaries, several components and isolated vertices are fine).
    threads : int, keyword only
        Threads of the preprocessing and the default of the parallel methods and of ``matrix()``; 0 (the
        default) means all cores (OpenMP's default).

    Raises
    ------
    ValueError
        Wrong shapes, no vertex or no face, a NaN or infinite coordinate, a vertex index out of range
        (with a hint when the faces look 1-indexed), a face with a repeated vertex, a non-manifold vertex
        or edge, inconsistent orientation; the message names the vertex or face.
    TypeError
        Non-numeric arrays, or F not of an integer dtype.

    Methods
    -------
    distances(sources=0, *, points=None, max_distance=inf, targets=None, method="vtp", lam=8.0,
              return_labels=False, threads=0)
        distances from the nearest of several sources (vertices and surface points), float64 (n,).
    path(target, sources=0, *, points=None, return_locations=False)
        the geodesic path from the nearest source to a target, (k, 3) points, source first.
    distance(a, b)
        the distance between two vertices or surface points, stopping once it is known.
    matrix(sources=None, targets=None, *, max_distance=inf, dtype=numpy.float64, threads=0, progress=False)
        one row per source, on all cores: dense ndarray, or scipy.sparse.csr_matrix with a finite limit.
    locate(xyz)
        the nearest surface points of (k, 3) positions, as (faces, barycentric).
    statistics
        the library's statistics of the last computation, as a dict.
    """

    def __init__(self, V, F, *, threads=0):
        V = _as_float_array(V, "V")
        F = _as_index_array(F, "F")
        if V.ndim != 2 or V.shape[1] != 3:
            raise ValueError("V must have shape (n, 3), got shape %s" % (V.shape,))
        if F.ndim != 2 or F.shape[1] != 3:
            raise ValueError("F must have shape (m, 3) (triangles), got shape %s" % (F.shape,))
        self._threads = _check_threads(threads)
        self._core = _core.Solver(V, F, self._threads)
        self._n = V.shape[0]
        self._m = F.shape[0]

    # -- properties -------------------------------------------------------------------------------------------
    @property
    def number_of_vertices(self):
        """Number of vertices n (rows of V)."""
        return self._n

    @property
    def number_of_faces(self):
        """Number of faces m (rows of F)."""
        return self._m

    @property
    def mean_edge_length(self):
        """Mean edge length h of the mesh (the unit of ``lam``)."""
        return self._core.mean_edge_length

    @property
    def statistics(self):
        """The library's statistics of the last computation, as a dict.

        Keys: vertices, faces, sources, method, threads, windows_created, windows_propagated,
        peak_live_windows, peak_window_bytes, vertices_processed, pseudo_sources, resets, stopped_early,
        rounds, parallel_rounds, selection_seconds, propagation_seconds, merge_seconds, reached_vertices,
        max_distance, seconds (the propagation, wall clock), output_seconds, preprocessing_seconds (the
        library's preprocessing in the constructor) and mesh_build_seconds (the constructor's checks of V and F
        and building of the mesh). After ``matrix()``, the sums over the rows (peaks are maxima).
        """
        return self._core.statistics()

    # -- helpers ----------------------------------------------------------------------------------------------
    def _points(self, points, name="points"):
        """points -> (faces int64 (k,), barycentric float64 (k, 3)) in the order given."""
        if points is None:
            return _np.zeros(0, dtype=_np.int64), _np.zeros((0, 3), dtype=_np.float64)
        if isinstance(points, tuple) and len(points) == 2:
            faces = _as_index_array(points[0], name + " faces")
            bary = _as_float_array(points[1], name + " barycentric coordinates")
            if faces.ndim == 0:
                faces = faces.reshape(1)
            if bary.ndim == 1:
                bary = bary.reshape(1, -1)
            if faces.ndim != 1 or bary.ndim != 2 or bary.shape != (faces.shape[0], 3):
                raise ValueError("%s: (faces, barycentric) must have shapes (k,) and (k, 3), got %s and %s"
                                 % (name, faces.shape, bary.shape))
            return faces, bary
        xyz = _as_float_array(points, name)
        if xyz.ndim == 1:
            xyz = xyz.reshape(1, -1)
        if xyz.ndim != 2 or xyz.shape[1] != 3:
            raise ValueError("%s must be (faces, barycentric) arrays or xyz rows of shape (k, 3), got shape %s"
                             % (name, xyz.shape))
        return self._core.locate(xyz)

    def _one_point(self, x, name):
        """A vertex index, a (face, barycentric) pair or an xyz position -> (vertex, face, bary)."""
        if isinstance(x, (bool, _np.bool_)):
            raise TypeError("%s must be a vertex index or a point, got a bool" % name)
        if isinstance(x, (int, _np.integer)):
            return int(x), -1, _np.zeros((0, 3))
        if isinstance(x, tuple) and len(x) == 2 and _np.ndim(x[0]) == 0:
            faces, bary = self._points((_np.asarray([x[0]]), _np.asarray(x[1], dtype=float).reshape(1, -1)), name)
        else:
            a = _np.asarray(x)
            if a.ndim == 0 and a.dtype.kind in "iu":
                return int(a), -1, _np.zeros((0, 3))
            faces, bary = self._points(a, name)
            if faces.shape[0] != 1:
                raise ValueError("%s must be one vertex or one point, got %d points" % (name, faces.shape[0]))
        if int(faces[0]) < 0:
            raise ValueError("%s: face index %d out of range [0, %d)" % (name, int(faces[0]), self._m))
        return -1, int(faces[0]), bary.reshape(1, 3)

    # -- queries ----------------------------------------------------------------------------------------------
    def distances(self, sources=_SOURCE_DEFAULT, *, points=None, max_distance=_math.inf, targets=None, method="vtp",
                  lam=8.0, return_labels=False, threads=0):
        """Geodesic distances from the nearest source to every vertex.

        Parameters
        ----------
        sources : int or array-like of int, default 0
            Source vertices (indices into V). The default is vertex 0 when no ``points`` are given, no vertex
            when some are.
        points : (faces, barycentric) or array-like (k, 3), optional
            Sources at points of the surface: a pair of arrays, face indices (k,) and barycentric
            coordinates (k, 3) with respect to the corners F[f, 0], F[f, 1], F[f, 2] (non-negative, sum 1);
            or xyz positions (k, 3), each replaced by the nearest point of the surface (see ``locate``).
        max_distance : float, default inf
            Distance limit: vertices farther get ``inf``; the work is that of the region within it.
        targets : array-like of int, optional
            Target vertices: the propagation stops as soon as their distances are final; the other vertices
            then have their distance where it is already final and ``inf`` elsewhere.
        method : str, default "vtp"
            One of ``vtp_geodesics.methods``: "vtp" (exact, one thread), "pvtp" (exact, parallel), "avtp",
            "pavtp" (approximate: window resets every ``lam`` mean edge lengths; never below the exact
            distances), "vsp", "pvsp" (one virtual source per vertex: the fastest, an upper bound, mean
            error about 0.2-0.4%), "vsp2", "pvsp2" (two per vertex: about half the error, 1.3-2x the time).
        lam : float, default 8.0
            Reset step of the approximate methods (ignored by the exact ones).
        return_labels : bool, default False
            Also return the nearest source of each vertex.
        threads : int, default 0
            Threads of the parallel methods (0: the solver's ``threads``).

        Returns
        -------
        distances : ndarray float64 (n,)
            ``inf`` for vertices no source reaches or beyond ``max_distance``.
        labels : ndarray int64 (n,), only with ``return_labels=True``
            Index of the nearest source in the order given: the ``sources`` vertices first, then the
            ``points``; -1 where the distance is ``inf``. Where two sources are equally near, either.

        Raises
        ------
        ValueError
            No source, an index out of range, invalid barycentric coordinates, a negative limit, an
            unknown method. TypeError for non-integer indices.
        """
        src = _source_vertices(sources, points)
        pf, pb = self._points(points)
        if src.size == 0 and pf.size == 0:
            raise ValueError("no source: sources is empty and no points are given")
        tgt = _vertex_list(targets, "targets")
        d, labels, _ = self._core.distances(src, pf, pb, _check_float(max_distance, "max_distance"), tgt,
                                            _check_method(method), _check_float(lam, "lam"),
                                            _check_threads(threads), bool(return_labels))
        return (d, labels) if return_labels else d

    def path(self, target, sources=_SOURCE_DEFAULT, *, points=None, max_distance=_math.inf, return_locations=False):
        """The geodesic path from the nearest source to ``target``.

        Parameters
        ----------
        target : int, (face, barycentric) or xyz
            A vertex index, a point of the surface as a face index and 3 barycentric coordinates (with
            respect to F[face]), or a position (3,) replaced by the nearest surface point.
        sources, points, max_distance
            As in ``distances()``.
        return_locations : bool, default False
            Also return the path as face locations.

        Returns
        -------
        points : ndarray float64 (k, 3)
            The path **from the source to the target**: the source first, the target last, with the edge
            crossings and the saddle or boundary vertices it turns at in between. Its length equals the
            distance of the target (up to rounding).
        faces, barycentric : ndarray int64 (k,), float64 (k, 3), only with ``return_locations=True``
            The same points as face locations (a vertex as a corner of one of its faces).

        Raises
        ------
        ValueError
            If no source reaches the target (or it is beyond ``max_distance``), or bad input as in
            ``distances()``.
        """
        src = _source_vertices(sources, points)
        pf, pb = self._points(points)
        if src.size == 0 and pf.size == 0:
            raise ValueError("no source: sources is empty and no points are given")
        tv, tf, tb = self._one_point(target, "target")
        if tb.size == 0:
            tb = _np.zeros((1, 3))
        P, faces, bary, _d = self._core.path(tv, tf, tb, src, pf, pb, _check_float(max_distance, "max_distance"))
        return (P, faces, bary) if return_locations else P

    def distance(self, a, b, *, method="vtp", lam=8.0):
        """The geodesic distance between ``a`` and ``b`` (each a vertex index, a (face, barycentric) pair or
        an xyz position, as ``target`` of ``path()``). The propagation from ``a`` stops as soon as the
        distance of ``b`` is final. Returns a float (``inf`` if ``b`` is not reachable from ``a``)."""
        av, af, ab = self._one_point(a, "a")
        bv, bf, bb = self._one_point(b, "b")
        if ab.size == 0:
            ab = _np.zeros((1, 3))
        if bb.size == 0:
            bb = _np.zeros((1, 3))
        return self._core.distance(av, af, ab, bv, bf, bb, _check_method(method), _check_float(lam, "lam"))

    def farthest_point_sampling(self, k, *, first=None, radius=0.0, method="vtp", lam=8.0, threads=0):
        """Farthest-point sampling with geodesic distances, and the geodesic Voronoi cells of the samples.

        Takes up to ``k`` sample vertices: ``first`` (default: the vertex farthest from vertex 0), then each
        time the vertex farthest from the samples taken so far (ties: the lowest index), until ``k`` samples or
        until every vertex is within ``radius`` of a sample. Each sample costs only the region it wins (the
        propagation starts from the distances already known), so ``k`` samples cost about ``log k`` full
        computations, not ``k``. The samples, radii, distances and labels are those of a full computation from
        all the samples so far at every step.

        Parameters
        ----------
        k : int
            The number of samples wanted (fewer once every vertex is a sample).
        first : int, optional
            The first sample.
        radius : float, default 0.0
            Stop once the covering radius is at most ``radius``.
        method : str, default "vtp"
            "vtp" or "pvtp" (exact), "avtp" or "pavtp" (approximate, with ``lam``), "vsp" or "pvsp"
            (one virtual source per vertex: the fastest; the samples are then the farthest by these
            distances, upper bounds of the exact ones), "vsp2" or "pvsp2" (two per vertex: closer to the
            exact distances, slower).
        lam : float, default 8.0
            Reset step of the approximate methods.
        threads : int, default 0
            Threads of "pvtp" / "pavtp" / "pvsp" / "pvsp2" (0: the solver's ``threads``).

        Returns
        -------
        FarthestPointSamples
            ``(samples, radii, distances, labels, cell_areas, cell_area_uncertainty)``, see its docstring.

        Raises
        ------
        ValueError
            A negative ``k`` or ``radius``, ``first`` out of range, an unknown method.
        """
        if isinstance(k, (bool, _np.bool_)) or not isinstance(k, (int, _np.integer)):
            raise TypeError("k must be an integer, got %r" % (k,))
        if first is None:
            first_index = -1
        else:
            if isinstance(first, (bool, _np.bool_)) or not isinstance(first, (int, _np.integer)):
                raise TypeError("first must be an integer vertex index, got %r" % (first,))
            if first < 0 or first >= self._n:
                raise ValueError("first must be a vertex index in [0, %d), got %d" % (self._n, first))
            first_index = int(first)
        if k < 0:
            raise ValueError("k must be >= 0, got %d" % k)
        # more samples than vertices are never taken: a k beyond 64 bits is as good as the number of vertices
        result = self._core.farthest_point_sampling(min(int(k), self._n), first_index, _check_float(radius, "radius"),
                                                    _check_method(method), _check_float(lam, "lam"),
                                                    _check_threads(threads))
        return FarthestPointSamples(*result)

    def locate(self, xyz):
        """The nearest points of the surface to positions ``xyz`` (k, 3): ``(faces int64 (k,), barycentric
        float64 (k, 3))``, barycentric coordinates with respect to F[face]. An AABB tree of the faces is
        built on the first call."""
        xyz = _as_float_array(xyz, "xyz")
        if xyz.ndim == 1:
            xyz = xyz.reshape(1, -1)
        return self._core.locate(xyz)

    def matrix(self, sources=None, targets=None, *, max_distance=_math.inf, dtype=_np.float64, threads=0,
               progress=False, method="vtp", lam=8.0):
        """Distance matrix, one row per source, rows computed in parallel on all cores.

        Parameters
        ----------
        sources : array-like of int, optional
            Row sources (vertex indices; may repeat). Default: every vertex (an n x n matrix).
        targets : array-like of int, optional
            Columns (vertex indices). Default: every vertex.
        max_distance : float, default inf
            With a finite limit, each row's propagation stops at it and the result is a
            ``scipy.sparse.csr_matrix`` holding exactly the entries <= max_distance (including the 0 of a
            source in its own column); without, a dense ndarray.
        dtype : numpy.float64 or numpy.float32
            Type of the entries. float32 is written directly (no float64 copy of the matrix is made):
            each entry is the float64 distance rounded to float32.
        threads : int, default 0
            Rows computed at the same time (0: the solver's ``threads``, all cores by default).
        progress : bool, default False
            Write "rows done / total" to stderr about five times a second.
        method : "vtp" or "avtp", default "vtp"
            Each row is computed on one thread; "pvtp" and "pavtp" give the same rows as "vtp" and "avtp".
        lam : float, default 8.0
            Reset step of "avtp".

        Returns
        -------
        ndarray (len(sources), len(targets)) of ``dtype`` with ``inf`` where unreachable, or
        scipy.sparse.csr_matrix of that shape and dtype when ``max_distance`` is finite. Row i is bitwise
        the result of ``distances(sources[i])`` (restricted to the targets).

        Ctrl-C (KeyboardInterrupt) stops the computation: no new row starts, the rows under way finish
        (within about one row's time), and KeyboardInterrupt is raised; no thread is left running.
        """
        src = _np.arange(self._n, dtype=_np.int64) if sources is None else _vertex_list(sources, "sources")
        all_columns = targets is None
        cols = _np.zeros(0, dtype=_np.int64) if all_columns else _vertex_list(targets, "targets")
        dt = _np.dtype(dtype)
        if dt not in (_np.dtype(_np.float64), _np.dtype(_np.float32)):
            raise TypeError("dtype must be numpy.float64 or numpy.float32, got %s" % dt)
        single = dt == _np.dtype(_np.float32)
        limit = _check_float(max_distance, "max_distance")
        method = _check_method(method)
        if method in ("pvtp", "pavtp"):
            method = method[1:]
        if limit < 0 or limit != limit:
            raise ValueError("max_distance must be >= 0 (inf for none), got %r" % max_distance)
        args = (src, cols, all_columns, limit, single, method, _check_float(lam, "lam"), _check_threads(threads),
                bool(progress))
        ncols = self._n if all_columns else cols.shape[0]
        if limit < _math.inf:
            import scipy.sparse
            data, indices, indptr = self._core.matrix_sparse(*args)
            return scipy.sparse.csr_matrix((data, indices, indptr), shape=(src.shape[0], ncols), copy=False)
        return self._core.matrix_dense(*args)

    def __repr__(self):
        return "vtp_geodesics.Solver(%d vertices, %d faces)" % (self._n, self._m)
