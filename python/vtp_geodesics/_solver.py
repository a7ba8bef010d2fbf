"""The solver of one mesh (private; see ``vtp_geodesics.Solver``): its construction and properties here, its
queries by topic in ``_queries`` (distances, paths, one distance, locating points), ``_matrices`` (distance
matrices) and ``_sampling`` (farthest-point sampling)."""

from . import _core
from ._arguments import check_threads, mesh_arrays
from ._matrices import Matrices
from ._queries import Queries
from ._sampling import Sampling


class Solver(Queries, Matrices, Sampling):
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
    distances(sources=0, *, points=None, max_distance=inf, targets=None, method="vtp", lam=recommended_lambda,
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
        V, F = mesh_arrays(V, F)
        self._threads = check_threads(threads)
        self._core = _core.Solver(V, F, self._threads)
        self._n = V.shape[0]
        self._m = F.shape[0]

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

        Keys: method, threads, vertices, faces, sources, windows_created, windows_propagated,
        peak_live_windows, peak_window_bytes, vertices_processed, pseudo_sources, resets, stopped_early,
        rounds, parallel_rounds, round_selection_seconds, round_propagation_seconds, round_merge_seconds (the
        stages of the parallel rounds), reached_vertices, max_distance, seconds (the propagation, wall clock),
        output_seconds, preprocessing_seconds (the library's preprocessing in the constructor) and
        mesh_build_seconds (the constructor's checks of V and F and building of the mesh). After
        ``matrix()``, the sums over the rows (peaks are maxima).

        The stages from the arrays to the answer, with the names of the tool's ``--stats-json``: read_seconds
        and write_seconds (0: ``read_mesh()`` and the caller's outputs are timed by the caller),
        repair_seconds (= mesh_build_seconds), preprocessing_seconds, propagation_seconds (= seconds),
        other_seconds (0), total_seconds (their sum) and outside_propagation_ratio ((total - propagation) /
        propagation).
        """
        return self._core.statistics()

    def __repr__(self):
        return "vtp_geodesics.Solver(%d vertices, %d faces)" % (self._n, self._m)
