"""The kept field of a solver (private; methods of ``vtp_geodesics.Solver``): after ``distances(...,
keep_field=True)``, the exact distance and the nearest source at any vertex or point of the surface (the C++
``Geodesic_distance_solver::field_distance()`` and ``field_nearest_source()``)."""

from ._arguments import vertices_or_points


class Field:
    """The queries of the kept field of ``Solver`` (which holds the compiled solver ``_core``)."""

    def field_distance(self, points, *, return_labels=False):
        """The exact distance from the nearest source at any vertex or point of the surface, from the field that
        the last ``distances(..., keep_field=True)`` kept (no new propagation).

        The field is every window of the exact run that crossed a face (about the memory of the windows
        propagated: ``field_bytes``); the distance inside a face is the least, over its corners, the sources
        in it and these windows, of the length of a straight path in their unfolding, which is the exact
        geodesic distance, not an interpolation of the vertex values. It is kept until the next computation
        of the solver: ``distances()``, ``distance()``, ``path()``, ``isolines()``, ``cell_borders()``,
        ``cell_areas()``, ``log_map()`` and ``farthest_point_sampling()`` replace it; ``matrix()``,
        ``polar_patches()``, ``trace()``, ``locate()`` and the ``field_*`` queries do not.

        Parameters
        ----------
        points : int or array-like of int (k,), (faces, barycentric), or array-like (k, 3) of floats
            Vertex indices (rows of V); or points of the surface: a pair of arrays, face indices (k,) and
            barycentric coordinates (k, 3) with respect to the corners F[f, 0], F[f, 1], F[f, 2]
            (non-negative, sum 1); or xyz positions (k, 3), each replaced by the nearest point of the surface
            (see ``locate``). Integer arrays are vertex indices: give positions as floats.
        return_labels : bool, default False
            Also return the nearest source of each point (as ``field_nearest_source()``).

        Returns
        -------
        distances : ndarray float64 (k,)
            ``inf`` where no source reaches, or beyond the ``max_distance`` of the run. At a vertex, the
            distance of the run (``distances()`` gave the same); one point gives shape (1,).
        labels : ndarray int64 (k,), only with ``return_labels=True``
            The index of the nearest source, numbered as ``distances(..., return_labels=True)`` numbers them
            (the ``sources`` vertices first, then the ``points``); -1 where the distance is ``inf``. Where
            two sources are equally near, either.

        Raises
        ------
        ValueError
            If the solver holds no kept field (no ``distances(..., keep_field=True)`` yet, or another
            computation since); a vertex or face index out of range, invalid barycentric coordinates, a
            non-finite position. TypeError for arrays that are not numbers.

        Examples
        --------
        >>> import numpy as np, vtp_geodesics
        >>> V = np.array([[0., 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
        >>> s = vtp_geodesics.Solver(V, [[0, 1, 2], [0, 2, 3]])
        >>> d = s.distances([0, 2], keep_field=True)
        >>> d, labels = s.field_distance([[0.5, 0.25, 0.0]], return_labels=True)
        >>> print(round(float(d[0]), 12), int(labels[0]))
        0.559016994375 0
        """
        v, f, b = vertices_or_points(points, self._core.locate)
        d, labels = self._core.field_query(v, f, b, bool(return_labels))
        return (d, labels) if return_labels else d

    def field_nearest_source(self, points):
        """The nearest source at each vertex or point of the surface, from the kept field: int64 (k,), numbered
        as ``distances(..., return_labels=True)`` numbers them, -1 where no source reaches (or beyond the
        limit of the run). ``points`` and errors as ``field_distance()``."""
        v, f, b = vertices_or_points(points, self._core.locate)
        return self._core.field_query(v, f, b, True)[1]

    @property
    def has_kept_field(self):
        """Whether the solver holds the field of a ``distances(..., keep_field=True)`` (its last computation)."""
        return self._core.has_kept_field

    @property
    def field_bytes(self):
        """The bytes that the kept field holds (0 without one); also ``statistics["field_bytes"]`` and
        ``statistics["field_pieces"]`` (the windows kept) after the run."""
        return self._core.field_bytes
