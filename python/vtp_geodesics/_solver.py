"""The solver of one mesh (private; see ``vtp_geodesics.Solver``): its construction and properties here, its
queries by topic in ``_queries`` (distances, paths, one distance, locating points), ``_field`` (the kept field of
a run), ``_matrices`` (distance matrices), ``_sampling`` (farthest-point sampling), ``_curves`` (isolines, cell
borders and areas) and ``_patches`` (polar patches)."""

import warnings as _warnings

from . import _core
from ._arguments import check_threads, mesh_arrays
from ._log_map import LogMap
from ._curves import Curves
from ._field import Field
from ._matrices import Matrices
from ._patches import Patches
from ._queries import Queries
from ._sampling import Sampling


class Solver(Queries, Field, Matrices, Sampling, LogMap, Curves, Patches):
    """Geodesic distances on one triangle mesh: ``Solver(V, F, *, threads=0, repair=True, through_pinches=False)``.

    The constructor checks the mesh and does the per-mesh preprocessing once; every query then runs
    from there, any number of times, with the GIL released (other Python threads keep running).

    Parameters
    ----------
    V : array-like (n, 3) of numbers
        Vertex coordinates (any real dtype, any memory order; converted to float64).
    F : array-like (m, 3) of integers
        Triangles as 0-based vertex indices (any integer dtype). Boundaries, several components and
        vertices in no face are fine; faces that do not form a manifold, consistently oriented triangle
        mesh are repaired (see ``repair``).
    threads : int, keyword only
        Threads of the preprocessing and the default of the parallel methods and of ``matrix()``; 0 (the
        default) means all cores (OpenMP's default).
    repair : bool, keyword only, default True
        If V and F do not form a valid mesh (a non-manifold vertex or edge, a face with a repeated vertex,
        duplicate faces, coincident vertices, inconsistent orientation), repair them as the command-line
        tool repairs a file, and say what was done in a ``UserWarning``: coincident vertices merged,
        degenerate and duplicate faces removed, faces reoriented, the surface cut at non-manifold edges and
        vertices (their vertices split into copies). **Every index stays the caller's**: results are given
        on the rows of V and F, a split vertex gets the least distance of its copies (and that copy's
        label), a vertex the repair dropped (in no face) gets ``inf`` (label -1) unless it is a source (0);
        a split vertex given as a source or a target is all its copies; faces given or returned are rows
        of F (a face removed as degenerate cannot be given). A valid mesh costs nothing more: the repair
        runs only when the check fails. The default is True because the tool and ``read_mesh()`` repair by
        default, and arrays from scanners and converters often need it; ``repair=False`` raises
        ``ValueError`` naming the problem instead.
    through_pinches : bool, keyword only, default False
        What a vertex split by the repair (a pinch: a non-manifold vertex, or the end of a non-manifold
        edge) means for distances. False (the default, as the tool and MMP/gdist): its copies are apart, no
        geodesic passes through the pinch from one sheet to another. True (as CGAL's
        Surface_mesh_shortest_path and the reference VTP on the same arrays): paths may pass through it;
        the copies are joined by runs from the distances already known, one per split vertex that a
        source reaches, each costing the region it lowers (a path crossing a non-manifold edge still
        passes through its end points only). With True, ``distances()`` and ``distance()`` join;
        ``path()``, ``matrix()`` and ``farthest_point_sampling()`` raise ``ValueError`` on a mesh with
        split vertices; with a limit or targets, the whole field is computed, then limited.

    Raises
    ------
    ValueError
        Wrong shapes, no vertex or no face, a NaN or infinite coordinate, a vertex index out of range
        (with a hint when the faces look 1-indexed), faces that the repair cannot make a mesh (no face
        left); with ``repair=False``, a face with a repeated vertex, a non-manifold vertex or edge,
        inconsistent orientation. The message names the vertex or face.

    Warns
    -----
    UserWarning
        When V and F were repaired, saying what was done (also in ``repairs``).
    TypeError
        Non-numeric arrays, or F not of an integer dtype.

    Methods
    -------
    distances(sources=0, *, points=None, max_distance=inf, targets=None, method="vtp", lam=recommended_lambda,
              return_labels=False, threads=0, keep_field=False)
        distances from the nearest of several sources (vertices and surface points), float64 (n,); with
        keep_field=True the solver keeps the field of the run for the field_* queries.
    field_distance(points, *, return_labels=False), field_nearest_source(points)
        the exact distance and the nearest source at any vertex or point of the surface, from the kept field.
    field_isolines(levels), field_cell_borders(), field_cell_areas()
        isolines at any levels, cell borders and cell areas of the kept field, with no new run.
    isolines(levels, *, sources=0), cell_borders(sources), cell_areas(sources)
        the same from one run of the given sources (lists of Curve namedtuples; CellAreas).
    path(target, *, sources=0, points=None, return_locations=False)
        the geodesic path from the nearest source to a target, (k, 3) points, source first (with
        return_locations: a SurfacePolyline).
    distance(a, b)
        the distance between two vertices or surface points, stopping once it is known.
    matrix(sources=None, *, targets=None, max_distance=inf, dtype=numpy.float64, threads=0, progress=False)
        one row per source, on all cores: dense ndarray, or scipy.sparse.csr_matrix with a finite limit.
    locate(xyz)
        the nearest surface points of (k, 3) positions, as (faces, barycentric).
    log_map(sources=0, *, points=None, max_distance=inf, reference_direction=None, log_map_strict=False,
            return_via=False)
        geodesic polar coordinates around the nearest source, float64 (n, 2) rho * (cos theta, sin theta)
        (reference= and strict= are kept as aliases).
    straightest_geodesic(start, *, direction, length, threads=0)
        straightest geodesics (the exp map), a StraightestGeodesic (trace(start, direction, length): alias).
    polar_patches(centres, *, radius, points=None, threads=0, log_map_strict=False)
        the log map around many centres cut at a radius, PolarPatches CSR arrays.
    statistics
        the library's statistics of the last computation, as a dict.
    """

    def __init__(self, V, F, *, threads=0, repair=True, through_pinches=False):
        V, F = mesh_arrays(V, F)
        self._threads = check_threads(threads)
        self._core = _core.Solver(V, F, self._threads, bool(repair), bool(through_pinches))
        self._n = V.shape[0]
        self._m = F.shape[0]
        if self._core.repairs:
            _warnings.warn("Solver(V, F): the faces do not form a valid triangle mesh and were repaired as the "
                           "tool repairs a file: %s; the results are on the rows of V and F (a split vertex gets "
                           "the least distance of its copies, a vertex in no face inf)" % self._core.repairs,
                           UserWarning, stacklevel=2)

    @property
    def repairs(self):
        """What the repair did to V and F (as in the warning), or "" if they form a valid mesh."""
        return self._core.repairs

    def vertex_copies(self):
        """The mesh vertices of each vertex of V: ``(begin int64 (n + 1,), copies int64)``, the copies of vertex
        i being ``copies[begin[i]:begin[i + 1]]`` (one each for a valid mesh; several for a vertex the repair
        split, none for one it dropped). The mesh vertices are those of the repaired mesh (internal)."""
        return self._core.vertex_copies()

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

        Keys: ``vtp_geodesics.statistics_keys``, in order: the library's statistics, named as in the tool's
        ``--stats-json`` and the C++ ``Propagation_statistics`` (one description of them, ``vtp_support/statistics.h``;
        ``seconds`` is the propagation, wall clock), then the stages below, then mesh_build_seconds (the
        constructor's checks of V and F and building of the mesh). After ``matrix()``, the sums over the rows
        (peaks are maxima).

        The stages from the file (or the arrays) to the answer, with the names of the tool's ``--stats-json``:
        read_seconds, repair_seconds, preprocessing_seconds, propagation_seconds (= seconds), write_seconds
        (0: the outputs are the caller's), other_seconds (0), total_seconds (their sum) and
        outside_propagation_ratio ((total - propagation) / propagation). When V and F are the arrays that the
        last ``read_mesh()`` returned (the same faces and number of vertices; the first Solver built on them),
        read_seconds is that reading and repair_seconds adds its check of the faces (which the Solver then
        does not repeat) to mesh_build_seconds; otherwise read_seconds is 0 (the caller read the arrays) and
        repair_seconds = mesh_build_seconds.
        """
        return self._core.statistics()

    def __repr__(self):
        return "vtp_geodesics.Solver(%d vertices, %d faces)" % (self._n, self._m)
