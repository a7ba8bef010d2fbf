"""Isolines and cell borders as curves on the surface (the C++ geodesic_curves.h; the manual's page on curves)."""

import math as _math

import numpy as _np

from ._arguments import SOURCE_DEFAULT, check_float, source_vertices, surface_points


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
    def isolines(self, levels, sources=SOURCE_DEFAULT, *, points=None, step=None, chord_tolerance=None,
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
            Also return each curve's face locations.

        Returns
        -------
        list of dict
            One per curve: ``points`` (k, 3), ``closed`` (bool), ``level``; with ``return_locations``,
            ``faces`` (k,) int64 and ``barycentric`` (k, 3). Two consecutive points lie in a common face; a
            closed curve does not repeat its first point.
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
        ``points``), as connected curves: a list of dict with ``points`` (k, 3), ``closed``, ``cells`` (i, j)
        (the two source indices, i < j) and, with ``return_locations``, ``faces`` and ``barycentric``."""
        return self._curves(_np.zeros(0), True, sources, points, chord_tolerance, 0, return_locations)

    def _curves(self, levels, borders, sources, points, chord_tolerance, exact_refinement, return_locations):
        tol, refine = _options(chord_tolerance, exact_refinement)
        src = source_vertices(sources, points)
        pf, pb = surface_points(points, self._core.locate)
        if src.size == 0 and pf.size == 0:
            raise ValueError("no source: sources is empty and no points are given")
        out = []
        for P, F, B, closed, level, i, j in self._core.curves(src, pf, pb, levels, borders, tol, refine):
            c = {"points": P, "closed": bool(closed)}
            if borders:
                c["cells"] = (int(i), int(j))
            else:
                c["level"] = float(level)
            if return_locations:
                c["faces"] = F
                c["barycentric"] = B
            out.append(c)
        return out
