"""Polar patches: the log map around many centres, cut at a radius (private; ``vtp_geodesics.Solver.polar_patches``)."""

import collections as _collections

from ._arguments import check_float, check_threads, merge_alias, surface_points, vertex_list

#: The result of ``Solver.polar_patches()``.
PolarPatches = _collections.namedtuple("PolarPatches", ["indptr", "indices", "rho", "theta"], module="vtp_geodesics")
PolarPatches.__doc__ = """The result of ``Solver.polar_patches()``: the arrays of compressed sparse rows (CSR), one row
per centre.

indptr : ndarray int64 (k + 1,)
    Patch i is the entries ``indptr[i]:indptr[i + 1]`` of the three arrays below.
indices : ndarray int64 (nnz,)
    The vertices (rows of V) of each patch, ascending within a patch.
rho : ndarray float64 (nnz,)
    Their geodesic distance to the centre (exact), at most the radius; 0 at the centre itself.
theta : ndarray float64 (nnz,)
    Their angle at the centre, in [0, 2 pi), in the tangent frame of ``log_map()`` (0 at the centre itself).

``scipy.sparse.csr_matrix((p.rho, p.indices, p.indptr), shape=(k, n))`` (and the same with ``p.theta``) gives
sparse matrices; but a theta of 0 (the centre, and vertices along the reference direction) is a real value there,
which scipy would drop in ``eliminate_zeros()`` and which ``toarray()`` does not tell from an absent vertex: keep
``indices`` for membership.
"""


class Patches:
    """The polar patches of ``Solver``."""

    def polar_patches(self, centres=None, *, radius=None, points=None, threads=0, log_map_strict=False, strict=None):
        """Geodesic polar coordinates around many centres: for each centre, every vertex whose geodesic distance to
        it is at most ``radius``, with its ``rho`` (the exact distance) and ``theta`` (the angle at which its
        geodesic leaves the centre), the patches of a geodesic CNN. Each patch is bit for bit the log map of one
        run from its centre with ``max_distance=radius`` (``log_map()``'s coordinates are
        ``rho * (cos theta, sin theta)``); each run stops at the radius and costs what its patch reaches, not the
        mesh. The centres are shared among the threads; the result does not depend on their number. Ctrl-C
        (KeyboardInterrupt) stops the computation: no new patch starts, the patches under way finish, and
        KeyboardInterrupt is raised; no thread is left running.

        Parameters
        ----------
        centres : int or array-like (k,) of vertex indices, optional
            The vertex centres, one patch each, in this order (they may repeat).
        radius : float >= 0
            The radius of every patch (``inf``: whole log maps); required.
        points : (faces, barycentric) or array-like (m, 3), optional
            Centres at points of the surface, as in ``log_map(points=...)``: ``(faces, barycentric)`` arrays
            (barycentric coordinates with respect to the corners as given in F) or xyz rows (their nearest
            surface points, ``locate()``). Their patches come after those of ``centres``, in this order; the
            patch of a point is that of ``log_map(points=(face, barycentric), max_distance=radius)``, theta in
            the same frame (0 along F[face][0] -> F[face][1]; theta to rounding, as the frame is turned
            after the run in both).
        threads : int, default 0 (the solver's)
        log_map_strict : bool, default False
            (``strict``: its alias, kept for compatibility.) The strict polyhedral theta behind saddle and border vertices (every vertex in the shadow of a vertex
            gets that vertex's theta) instead of the default continuation (see ``log_map()``).

        Returns
        -------
        PolarPatches
            ``(indptr, indices, rho, theta)``, one row per centre (``centres``, then ``points``): NumPy arrays
            of CSR rows, not a scipy matrix, so that membership stays explicit (a theta or a rho of 0 is a
            value) and the arrays go as they are to scipy or to a framework's sparse tensors (see
            ``PolarPatches``).

        Raises
        ------
        ValueError
            A centre out of range, in no face, or split by the repair (a non-manifold vertex has no tangent plane);
            a point with a face out of range or invalid barycentric coordinates; a negative or NaN radius.
        TypeError
            No radius.
        KeyboardInterrupt
            Ctrl-C during the computation.
        """
        strict = merge_alias(log_map_strict, False, strict, "log_map_strict", "strict")
        c = vertex_list(centres, "centres")
        pf, pb = surface_points(points, self._core.locate)
        if radius is None:
            raise TypeError("polar_patches() needs a radius")
        r = check_float(radius, "radius")
        if not r >= 0:
            raise ValueError("radius must be >= 0 (inf for whole log maps), got %r" % (radius,))
        if not isinstance(strict, bool):
            raise TypeError("log_map_strict must be a bool, got %r" % (strict,))
        return PolarPatches(*self._core.polar_patches(c, pf, pb, r, strict, check_threads(threads)))
