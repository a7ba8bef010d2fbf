"""Isolines and cell borders as curves on the surface, and the areas of the cells (the C++ geodesic_curves.h; the
manual's page on curves): from one run of the given sources, or from the field that ``distances(...,
keep_field=True)`` kept (the ``field_*`` methods)."""

import collections as _collections
import math as _math

import numpy as _np

from ._arguments import SOURCE_DEFAULT, check_float, query_sources


class Curve(_collections.namedtuple("Curve", ["points", "faces", "barycentric", "closed", "level", "cells"],
                                    module="vtp_geodesics")):
    """A curve of ``Solver.isolines()`` or ``Solver.cell_borders()`` (the C++ ``Geodesic_curve``, a surface
    polyline: points and their face locations).

    points : ndarray float64 (k, 3)
        The points of the curve, in order. Two consecutive points lie in a common face; a closed curve does not
        repeat its first point.
    faces, barycentric : ndarray int64 (k,), float64 (k, 3)
        The same points as face locations (barycentric coordinates with respect to F[face]), as ``path()`` gives
        them.
    closed : bool
        Whether the last point is joined to the first.
    level : float
        The level of an isoline (``nan`` for a border).
    cells : (int, int) or None
        The two source indices (i < j) of a border (``None`` for an isoline).

    ``curve["points"]`` (the keys of the dicts of versions before 1.x) is kept as a documented alias of
    ``curve.points``, for every field above.
    """
    __slots__ = ()

    def __getitem__(self, key):
        if isinstance(key, str):
            if key not in self._fields:
                raise KeyError(key)
            return getattr(self, key)
        return super().__getitem__(key)


#: The result of ``Solver.cell_areas()`` and ``Solver.field_cell_areas()``.
CellAreas = _collections.namedtuple("CellAreas", ["areas", "uncertainty"], module="vtp_geodesics")
CellAreas.__doc__ = """The result of ``Solver.cell_areas()``: the areas of the geodesic Voronoi cells of the sources.

areas : ndarray float64 (s,)
    One per source, in the order of the labels of ``distances(..., return_labels=True)``.
uncertainty : ndarray float64 (s,)
    A bound of ``|areas[i] - the true area of cell i|`` (the one meaning of the C++ ``Voronoi_cell_areas``): the
    chord tolerance times the length of the cell's border, which holds where the borders are exact.
"""


def _levels(levels):
    a = _np.asarray(levels, dtype=_np.float64).reshape(-1)
    if a.size and not (_np.all(_np.isfinite(a)) and _np.all(a >= 0.0)):
        raise ValueError("every level must be finite and >= 0")
    return _np.ascontiguousarray(a)


def _options(chord_tolerance, exact_refinement):
    tol = 0.0 if chord_tolerance is None else check_float(chord_tolerance, "chord_tolerance")
    if chord_tolerance is not None and not (tol > 0.0 and _math.isfinite(tol)):
        raise ValueError("chord_tolerance must be positive and finite")
    if isinstance(exact_refinement, bool) or not isinstance(exact_refinement, (int, _np.integer)) \
            or not 0 <= int(exact_refinement) <= 10:
        raise ValueError("exact_refinement must be an int between 0 and 10")
    return tol, int(exact_refinement)


class Curves:
    def isolines(self, levels, *, sources=SOURCE_DEFAULT, points=None, step=None, chord_tolerance=None,
                 exact_refinement=0, return_locations=False):
        """The isolines of the distance from the sources at ``levels``, as connected curves on the exact
        distance inside the faces (not a linear interpolation of vertex values).

        Parameters
        ----------
        levels : array-like of float (>= 0), or None with ``step``
            The levels.
        sources, points
            As in ``distances()``.
        step : float, optional
            With ``levels=None``: the levels step, 2 step, ... up to the largest distance.
        chord_tolerance : float, optional
            Largest distance of a chord to its arc (default: 1e-3 times the mean edge length).
        exact_refinement : int, default 0
            Exact runs with the curve points as targets, each moving the points onto their level.
        return_locations : bool, default False
            Kept for compatibility: every ``Curve`` now holds its face locations.

        Returns
        -------
        list of Curve
            One per curve (a namedtuple: ``points`` (k, 3), ``faces`` (k,), ``barycentric`` (k, 3), ``closed``,
            ``level``, ``cells`` None). Two consecutive points lie in a common face; a closed curve does not repeat
            its first point.
        """
        if levels is None:
            s = check_float(step, "step") if step is not None else _math.nan
            if not (s > 0.0 and _math.isfinite(s)):
                raise ValueError("the isoline step must be positive and finite")
            d = self.distances(sources, points=points)
            d = d[0] if isinstance(d, tuple) else d
            top = float(_np.max(d[_np.isfinite(d)])) if _np.any(_np.isfinite(d)) else 0.0
            levels = [s * k for k in range(1, int(top / s) + 1)]
        return self._curves(_levels(levels), False, sources, points, chord_tolerance, exact_refinement,
                            return_locations)

    def cell_borders(self, sources=SOURCE_DEFAULT, *, points=None, chord_tolerance=None, return_locations=False):
        """The borders between the geodesic Voronoi cells of the sources (vertices of ``sources``, then
        ``points``), as connected curves: a list of ``Curve`` (``points`` (k, 3), ``faces``, ``barycentric``,
        ``closed``, ``cells`` (i, j) the two source indices, i < j, ``level`` nan; ``return_locations`` is kept for
        compatibility, the locations are always there). From one
        exact run that keeps its field: a border point is where the exact distances of its two sources are
        equal (but for the junctions of three cells, see the manual's page on curves)."""
        return self._curves(_np.zeros(0), True, sources, points, chord_tolerance, 0, return_locations)

    def cell_areas(self, sources=SOURCE_DEFAULT, *, points=None, chord_tolerance=None):
        """The areas of the geodesic Voronoi cells of the sources (the part of the surface nearest to each), the
        faces cut along the borders of ``cell_borders()``: from one exact run that keeps its field.

        Parameters
        ----------
        sources, points
            As in ``distances()``.
        chord_tolerance : float, optional
            Largest distance of a chord of a border to its arc (default: 1e-3 times the mean edge length).

        Returns
        -------
        areas : ndarray float64 (s,)
            One per source, in the order of ``distances(..., return_labels=True)``'s labels (the ``sources``
            vertices, then the ``points``). They add up to the area of the faces whose corners are all reached.
        uncertainty : ndarray float64 (s,)
            ``chord_tolerance`` times the length of the cell's border: a bound of |``areas[i]`` - the true area|
            (the area between the chords and the borders; the areas are exact where the borders are straight in
            their faces, as on a plane).

        The two arrays come as a ``CellAreas`` namedtuple (``areas, uncertainty = ...`` still works).
        """
        tol, _ = _options(chord_tolerance, 0)
        src, pf, pb = self._sources(sources, points)
        return CellAreas(*self._core.cell_areas(src, pf, pb, tol, False))

    def field_isolines(self, levels, *, chord_tolerance=None, exact_refinement=0, return_locations=False):
        """The isolines at ``levels`` (chosen after the run) of the field that ``distances(..., keep_field=True)``
        kept, without a new propagation; as ``isolines()`` (``levels``, the options and the result), exact at
        every level. Raises ValueError if the solver holds no kept field (see ``field_distance()``)."""
        return self._curves(_levels(levels), False, None, None, chord_tolerance, exact_refinement, return_locations,
                            from_field=True)

    def field_cell_borders(self, *, chord_tolerance=None, return_locations=False):
        """The borders between the cells of the sources of the kept field (``distances(..., keep_field=True)``),
        as ``cell_borders()`` (``cells`` numbered as that run's labels), without a new propagation."""
        return self._curves(_np.zeros(0), True, None, None, chord_tolerance, 0, return_locations, from_field=True)

    def field_cell_areas(self, *, chord_tolerance=None):
        """The areas of the cells of the sources of the kept field (``distances(..., keep_field=True)``) and their
        uncertainty, as ``cell_areas()``, without a new propagation."""
        tol, _ = _options(chord_tolerance, 0)
        empty = _np.zeros(0, dtype=_np.int64)
        return CellAreas(*self._core.cell_areas(empty, empty, _np.zeros((0, 3)), tol, True))

    def _sources(self, sources, points):
        src, pf, pb = query_sources(sources, points, self._core.locate)
        return src, pf, pb

    def _curves(self, levels, borders, sources, points, chord_tolerance, exact_refinement, return_locations,
                from_field=False):
        tol, refine = _options(chord_tolerance, exact_refinement)
        if from_field:
            src = pf = _np.zeros(0, dtype=_np.int64)
            pb = _np.zeros((0, 3))
        else:
            src, pf, pb = self._sources(sources, points)
        del return_locations  # (the locations are always returned)
        return [Curve(P, F, B, bool(closed), _math.nan if borders else float(level),
                      (int(i), int(j)) if borders else None)
                for P, F, B, closed, level, i, j in self._core.curves(src, pf, pb, levels, borders, tol, refine,
                                                                        from_field)]
