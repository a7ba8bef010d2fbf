"""The queries of a solver (private; methods of ``vtp_geodesics.Solver``): distances from several sources, a
geodesic path, the distance between two points, the nearest surface points, straightest geodesics."""

import collections as _collections
import math as _math

import numpy as _np

from ._arguments import (SOURCE_DEFAULT, check_float, check_method, check_threads, one_point, query_sources,
                         recommended_lambda, surface_points, trace_directions, trace_starts, vertex_list, xyz_rows,
                         xyz_rows_named)


#: A polyline on the surface: ``path(..., return_locations=True)`` (the C++ ``Surface_polyline``).
SurfacePolyline = _collections.namedtuple("SurfacePolyline", ["points", "faces", "barycentric"],
                                          module="vtp_geodesics")
SurfacePolyline.__doc__ = """A polyline on the surface (the C++ ``Surface_polyline``): its points and the same points
as face locations. ``Curve`` (isolines, cell borders) has these three fields first.

points : ndarray float64 (k, 3)
faces : ndarray int64 (k,)
barycentric : ndarray float64 (k, 3)
    With respect to the corners F[face, 0], F[face, 1], F[face, 2].
"""

#: The result of ``Solver.straightest_geodesic()``.
StraightestGeodesic = _collections.namedtuple(
    "StraightestGeodesic", ["points", "end", "end_direction", "length", "reached_border"], module="vtp_geodesics")
StraightestGeodesic.__doc__ = """The result of ``Solver.straightest_geodesic()`` (the C++ ``Straightest_geodesic``;
a batch: each field holds the values of every walk).

points : ndarray float64 (k, 3) (a batch: a list of them)
    The points from the start to the end: the start, each edge crossed, each vertex passed, the end.
end : (face int, barycentric ndarray (3,)) (a batch: faces int64 (n,), barycentric float64 (n, 3))
    The end point, with respect to F[face].
end_direction : ndarray float64 (3,) (a batch: (n, 3))
    The unit direction of the walk at its end, tangent to the end's face.
length : float (a batch: (n,))
    The length walked: the length asked for, or less if the walk stopped on the border.
reached_border : bool (a batch: (n,))
    Whether the walk stopped on the border before its length.
"""


class Queries:
    """The queries of ``Solver`` (which holds the compiled solver ``_core``)."""

    def distances(self, sources=SOURCE_DEFAULT, *, points=None, curves=None, source_border=False, signed=False,
                  max_distance=_math.inf, targets=None, method="vtp", lam=recommended_lambda, return_labels=False,
                  threads=0, keep_field=False):
        """Geodesic distances from the nearest source to every vertex.

        Parameters
        ----------
        sources : int or array-like of int, default 0
            Source vertices (indices into V). The default is vertex 0 when no ``points``, ``curves`` or
            ``source_border`` are given, no vertex when some are.
        points : (faces, barycentric) or array-like (k, 3), optional
            Sources at points of the surface: a pair of arrays, face indices (k,) and barycentric
            coordinates (k, 3) with respect to the corners F[f, 0], F[f, 1], F[f, 2] (non-negative, sum 1);
            or xyz positions (k, 3), each replaced by the nearest point of the surface (see ``locate``).
        curves : list of curves, optional
            Sources that are curves drawn on the surface, each one source (one label): a curve is xyz positions
            (k, 3), located as ``points`` are (a position farther from the surface than 1e-6 of the diagonal of
            the mesh's bounding box raises ValueError), or ``(faces, barycentric)`` arrays; at least two distinct
            points. Consecutive points in one face are joined straight inside it, points that share no face by the
            shortest geodesic between them; a curve whose last point is its first is closed. The tool's
            ``--source-curve``.
        source_border : bool, default False
            The border of the mesh (every border loop) as one more source, after the curves (ValueError if the
            mesh has no border). The tool's ``--source-border``.
        signed : bool, default False
            Signed distances (needs ``curves`` or ``source_border``): negative on the left of the curves (left =
            face normal x direction of travel: inside a counter-clockwise loop on the plane z = 0 seen from above;
            the border runs with the surface on its left, so every value is <= 0). ValueError when every curve
            is closed and some part of the surface lies on the left of a piece and on the right of another
            (curves not oriented consistently). For open curves: negative where the nearest point is inside a
            piece and on its left, when the curves do not separate the surface (see the manual). The tool's
            ``--signed``.
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
        lam : float, default ``vtp_geodesics.recommended_lambda``
            Reset step of the approximate methods (ignored by the exact ones).
        return_labels : bool, default False
            Also return the nearest source of each vertex.
        threads : int, default 0
            Threads of the parallel methods (0: the solver's ``threads``).
        keep_field : bool, default False
            Keep the field of this run in the solver (every window that crossed a face; exact methods "vtp"
            and "pvtp" only, not with ``targets``), until its next computation: ``field_distance()``,
            ``field_nearest_source()``, ``field_isolines()``, ``field_cell_borders()`` and
            ``field_cell_areas()`` then answer from it, exactly, at any point and any level, without a new
            propagation. Its memory: ``field_bytes`` (about that of the windows propagated). From curves (and
            the border) too: ``field_isolines()`` then gives their geodesic offset curves; the field is the
            unsigned distance (also after ``signed=True``), and ``field_cell_borders()`` / ``field_cell_areas()``
            raise ValueError (not available for sources that are curves yet).

        Returns
        -------
        distances : ndarray float64 (n,)
            The distance of each vertex to its nearest source (signed with ``signed=True``: negative on the left
            of the curves, and the tool's ``--signed`` values bit for bit); ``inf`` for vertices no source reaches
            or beyond ``max_distance``.
        labels : ndarray int64 (n,), only with ``return_labels=True``
            Index of the nearest source in the order: the ``sources`` vertices first, then the ``points``, then
            the ``curves`` (one index each), then the border (``source_border=True``: the last index), as the
            tool's ``--labels``; -1 where the distance is ``inf``. Where two sources are equally near, either.

        Raises
        ------
        ValueError
            No source, an index out of range, invalid barycentric coordinates, a negative limit, an
            unknown method; ``keep_field=True`` with an approximate method or with ``targets``; a curve of fewer
            than two distinct points or with a point off the surface, ``source_border=True`` on a mesh without
            border, ``signed=True`` without a curve or with closed curves not oriented consistently. TypeError
            for non-integer indices.
        """
        if curves is not None or source_border or signed:
            return self._curve_distances(sources, points, curves, source_border, signed, max_distance, targets,
                                         method, lam, return_labels, threads, keep_field)
        src, pf, pb = query_sources(sources, points, self._core.locate)
        tgt = vertex_list(targets, "targets")
        d, labels, _ = self._core.distances(src, pf, pb, check_float(max_distance, "max_distance"), tgt,
                                            check_method(method), check_float(lam, "lam"),
                                            check_threads(threads), bool(return_labels), bool(keep_field))
        return (d, labels) if return_labels else d

    def _curve_distances(self, sources, points, curves, source_border, signed, max_distance, targets, method, lam,
                         return_labels, threads, keep_field):
        """``distances()`` with curves, the border or ``signed``."""
        curves = [] if curves is None else curves
        if isinstance(curves, _np.ndarray) or (isinstance(curves, tuple) and len(curves) == 2
                                                and _np.ndim(curves[0]) == 1):
            raise TypeError("curves must be a list of curves (each an (k, 3) array or a (faces, barycentric) pair), "
                            "got one curve: wrap it in a list")
        if sources is SOURCE_DEFAULT and (points is not None or len(curves) > 0 or source_border):
            src = _np.zeros(0, dtype=_np.int64)
        else:
            src = vertex_list(sources, "sources")
        pf, pb = surface_points(points, self._core.locate)
        faces, bary, xyz, offsets = [], [], [], [0]
        for k, c in enumerate(curves):
            name = "curves[%d]" % k
            if isinstance(c, tuple) and len(c) == 2:
                f, b = surface_points(c, self._core.locate, name)
                x = _np.full((f.shape[0], 3), _np.nan)
            else:
                x = xyz_rows_named(c, name)
                f, b = self._core.locate(x)
            faces.append(f)
            bary.append(b)
            xyz.append(x)
            offsets.append(offsets[-1] + f.shape[0])
        cat = lambda arrays, empty: _np.ascontiguousarray(_np.concatenate(arrays)) if arrays else empty
        cf = cat(faces, _np.zeros(0, dtype=_np.int64))
        cb = cat(bary, _np.zeros((0, 3)))
        cx = cat(xyz, _np.zeros((0, 3)))
        tgt = vertex_list(targets, "targets")
        d, labels = self._core.curve_distances(src, pf, pb, cf, cb, cx, _np.asarray(offsets, dtype=_np.int64),
                                               bool(source_border), bool(signed),
                                               check_float(max_distance, "max_distance"), tgt, check_method(method),
                                               check_float(lam, "lam"), check_threads(threads), bool(return_labels),
                                               bool(keep_field))
        return (d, labels) if return_labels else d

    def path(self, target, *, sources=SOURCE_DEFAULT, points=None, max_distance=_math.inf, return_locations=False):
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
            The same points as face locations (a vertex as a corner of one of its faces); the three then come
            as a ``SurfacePolyline`` namedtuple (``P, faces, bary = ...`` still works).

        Raises
        ------
        ValueError
            If no source reaches the target (or it is beyond ``max_distance``), or bad input as in
            ``distances()``.
        """
        src, pf, pb = query_sources(sources, points, self._core.locate)
        tv, tf, tb = one_point(target, self._core.locate, "target")
        P, faces, bary, _d = self._core.path(tv, tf, tb, src, pf, pb, check_float(max_distance, "max_distance"))
        return SurfacePolyline(P, faces, bary) if return_locations else P

    def distance(self, a, b, *, method="vtp", lam=recommended_lambda):
        """The geodesic distance between ``a`` and ``b`` (each a vertex index, a (face, barycentric) pair or
        an xyz position, as ``target`` of ``path()``). The propagation from ``a`` stops as soon as the
        distance of ``b`` is final. Returns a float (``inf`` if ``b`` is not reachable from ``a``)."""
        av, af, ab = one_point(a, self._core.locate, "a")
        bv, bf, bb = one_point(b, self._core.locate, "b")
        return self._core.distance(av, af, ab, bv, bf, bb, check_method(method), check_float(lam, "lam"))

    def locate(self, xyz):
        """The nearest points of the surface to positions ``xyz`` (k, 3): ``(faces int64 (k,), barycentric
        float64 (k, 3))``, barycentric coordinates with respect to F[face]. An AABB tree of the faces is
        built on the first call."""
        return self._core.locate(xyz_rows(xyz))

    def straightest_geodesic(self, start, *, direction, length, threads=0):
        """Straightest geodesics (the exponential map; the C++ ``straightest_geodesic()``, the tool's
        ``--straightest-geodesic``): from ``start``, walk straight along the surface in ``direction`` for
        ``length``. Inside a face the walk is a segment; across an edge it goes on in the unfolded next face;
        through a vertex it leaves with half the vertex's angle sum on each side (Polthier and Schmies' straightest
        geodesics); it ends exactly on the border if it reaches it (or at a border vertex).

        Parameters
        ----------
        start : int, (face, barycentric), xyz, or a batch of them
            A vertex index, a point of the surface as a face index and 3 barycentric coordinates (with respect
            to F[face]), or a position (3,) replaced by the nearest surface point; a batch: an int array (n,),
            ``(faces (n,), barycentric (n, 3))`` arrays, or positions (n, 3).
        direction : (2,) or (3,), or one per start (n, 2) or (n, 3)
            2D: in the tangent frame of the start, that of ``log_map()`` (at a vertex: angles from the edge to
            ``source(halfedge(v))``, counter-clockwise, scaled by 2 pi / the vertex's angle sum, pi / sum at the
            border; at a point of a face: x along F[face][0] -> F[face][1], y towards F[face][2]), so that
            ``straightest_geodesic(c, direction=log[v] / rho[v], length=rho[v])`` ends at v where
            ``log_map(c, return_via=True)`` gives ``via[v] == -1`` (its geodesic passes through no vertex). 3D:
            projected onto the tangent plane.
        length : float >= 0, or one per start (n,)
        threads : int, default 0 (the solver's)
            The walks of a batch are shared among the threads.

        Returns
        -------
        StraightestGeodesic
            ``(points, end, end_direction, length, reached_border)``: see ``vtp_geodesics.StraightestGeodesic``.

        Raises
        ------
        ValueError
            A start that is not a vertex or a point of a face, a zero or non-finite direction (or one orthogonal
            to the tangent plane), a negative or non-finite length.
        """
        return StraightestGeodesic(*self._walk(start, direction, length, threads, True))

    def trace(self, start, direction, length, *, threads=0, return_details=False):
        """Alias of ``straightest_geodesic()`` (its former name), kept with its former signature and result:
        ``direction`` and ``length`` positional, and a tuple ``(points, end, end_direction)``, with
        ``return_details=True`` also ``(walked, border)`` (the ``length`` and ``reached_border`` of
        ``StraightestGeodesic``)."""
        return self._walk(start, direction, length, threads, return_details)

    def _walk(self, start, direction, length, threads, return_details):
        batch, sv, sf, sb = trace_starts(start, self._core.locate)
        d, lengths = trace_directions(direction, length, sv.shape[0], batch)
        P, offsets, faces, bary, end_dir, walked, border = self._core.trace(sv, sf, sb, d, lengths,
                                                                            check_threads(threads))
        paths = [P[offsets[i]:offsets[i + 1]] for i in range(sv.shape[0])]
        if batch:
            result = (paths, (faces, bary), end_dir)
            details = (walked, border)
        else:
            result = (paths[0], (int(faces[0]), bary[0]), end_dir[0])
            details = (float(walked[0]), bool(border[0]))
        return result + details if return_details else result
