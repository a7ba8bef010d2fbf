"""The log map of a solver (private; ``vtp_geodesics.Solver.log_map``): geodesic polar coordinates around the
nearest source, in one run of VTP or PVTP."""

import math as _math

import numpy as _np

from ._arguments import (SOURCE_DEFAULT, as_float_array, check_float, check_method, check_threads, merge_alias,
                         query_sources)


class LogMap:
    """The log map of ``Solver`` (which holds the compiled solver ``_core``)."""

    def log_map(self, sources=SOURCE_DEFAULT, *, points=None, max_distance=_math.inf, reference_direction=None,
                log_map_strict=False, return_via=False, method="vtp", threads=0, reference=None, strict=None):
        """Geodesic polar coordinates (the discrete logarithmic map) around the nearest source: for every vertex,
        ``rho * (cos theta, sin theta)``, rho its exact geodesic distance and theta the angle at which its
        geodesic leaves its nearest source, in that source's tangent frame. One propagation (no trace-back of
        paths): about the time of ``distances()``.

        Parameters
        ----------
        sources : int or array-like of int, default 0
            Source vertices (indices into V); the default is vertex 0 when no ``points`` are given.
        points : (faces, barycentric) or array-like (k, 3), optional
            Sources at points of the surface, as in ``distances()``.
        max_distance : float, default inf
            Distance limit (local patches): vertices farther get ``inf``; the work is that of the region within.
        reference_direction : array-like (3,), optional
            The direction of theta = 0, projected onto the tangent plane of each source (the name of the C++
            named parameter and of the tool's ``--reference-direction``; ``reference``: its alias, kept). By
            default: at a vertex v, the edge from v to ``source(halfedge(v))`` of the library (the frame of
            ``straightest_geodesic()`` at a vertex); at a point of a face, F[face][0] -> F[face][1] (its frame
            there), so that ``trace(c, log[v] / rho[v], rho[v])`` walks from the source c towards v.
        log_map_strict : bool, default False
            (The name of the C++ named parameter and of the tool's ``--log-map-strict``; ``strict``: its alias,
            kept.) False: behind a saddle or boundary vertex s, the coordinates go on from those of s, turned at s
            as a straightest geodesic (a wedge of directions stays a wedge). True: the strict polyhedral angle,
            every vertex behind s gets the theta of s.
        return_via : bool, default False
            Also return, for every vertex, the last vertex its geodesic passes through (-1: none).
        method : str, default "vtp"
            "vtp" or "pvtp" (the same coordinates on several threads); the other methods carry no direction.
        threads : int, default 0
            Threads of "pvtp" (0: the solver's ``threads``).

        Returns
        -------
        coordinates : ndarray float64 (n, 2)
            ``rho * (cos theta, sin theta)``; ``(inf, inf)`` where unreached (or beyond ``max_distance``);
            ``(0, 0)`` at a source vertex. With several sources, relative to the nearest (in its frame).
            Angles grow counter-clockwise seen from the side the faces' normals point to; at a vertex source
            they are scaled by 2 pi / its angle sum (pi / sum at a boundary vertex).
        via : ndarray int64 (n,), only with ``return_via=True``
            The last vertex of the geodesic before the vertex (a saddle or boundary vertex it turns at), -1 if
            it passes through none.

        Raises
        ------
        ValueError
            No source, an index out of range, invalid barycentric coordinates, a negative limit, a method other
            than vtp / pvtp, a zero or non-finite reference or one orthogonal to a source's tangent plane, a
            source vertex whose faces do not form one fan.
        """
        reference = merge_alias(reference_direction, None, reference, "reference_direction", "reference")
        strict = merge_alias(log_map_strict, False, strict, "log_map_strict", "strict")
        src, pf, pb = query_sources(sources, points, self._core.locate)
        if reference is None:
            ref = _np.zeros(0)
        else:
            ref = as_float_array(reference, "reference_direction").reshape(-1)
            if ref.shape != (3,):
                raise ValueError("reference_direction must be a 3D direction (3,), got shape %s"
                                 % (_np.shape(reference),))
        if not isinstance(strict, (bool, _np.bool_)):
            raise TypeError("log_map_strict must be a bool, got %r" % (strict,))
        x, via = self._core.log_map(src, pf, pb, check_float(max_distance, "max_distance"), ref, bool(strict),
                                    check_method(method), check_threads(threads))
        return (x, via) if return_via else x
