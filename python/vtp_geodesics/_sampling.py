"""Farthest-point sampling and the geodesic Voronoi cells of the samples (private;
``vtp_geodesics.Solver.farthest_point_sampling``)."""

import collections as _collections

import numpy as _np

from ._arguments import check_float, check_method, check_threads, recommended_lambda

#: The result of ``Solver.farthest_point_sampling()``.
FarthestPointSamples = _collections.namedtuple(
    "FarthestPointSamples", ["samples", "radii", "distances", "labels", "cell_areas", "cell_area_uncertainty"],
    module="vtp_geodesics")
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
    The area of the part of the surface nearest to each sample. Exact methods ("vtp", "pvtp"): the faces are
    cut along the exact borders of the cells (those of ``cell_borders(samples)``), from one more run from the
    samples that keeps its field (as ``cell_areas(samples)``). Approximate methods (and
    ``exact_cell_areas=False``): from the vertex values; a face whose corners are in different cells is split
    where the two distances, extended straight along its edges, are equal (an estimate).
cell_area_uncertainty : ndarray float64 (s,)
    A bound of the error of ``cell_areas``. Exact methods: the chord tolerance of the borders (1e-3 times the
    mean edge length) times the length of the cell's border, a bound of the area between the chords and the
    borders (the areas are exact where the borders are straight in their faces, as on a plane).
    Approximate methods (and ``exact_cell_areas=False``): the area of the faces each cell shares with other
    cells, where its border is estimated.
"""


class Sampling:
    """The farthest-point sampling of ``Solver`` (which holds the compiled solver ``_core``)."""

    def farthest_point_sampling(self, k, *, first=None, radius=0.0, method="vtp", lam=recommended_lambda,
                                threads=0, exact_cell_areas=True):
        """Farthest-point sampling with geodesic distances, and the geodesic Voronoi cells of the samples.

        Takes up to ``k`` sample vertices: ``first`` (default: the vertex farthest from vertex 0), then each
        time the vertex farthest from the samples taken so far (ties: the lowest index), until ``k`` samples or
        until every vertex is within ``radius`` of a sample. Each sample costs only the region it wins (the
        propagation starts from the distances already known), so ``k`` samples cost about ``log k`` full
        computations, not ``k``. The samples, radii, distances and labels are those of a full computation from
        all the samples so far at every step. With the exact methods, the cell areas come from one more run from
        the samples (keeping its field, about the memory of the windows it propagates) and are exact; with the
        approximate ones they are estimated from the vertex values (see ``FarthestPointSamples``).

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
        lam : float, default ``vtp_geodesics.recommended_lambda``
            Reset step of the approximate methods.
        threads : int, default 0
            Threads of "pvtp" / "pavtp" / "pvsp" / "pvsp2" (0: the solver's ``threads``).
        exact_cell_areas : bool, default True
            With "vtp" or "pvtp": the cell areas from the exact borders, at the cost of one more run from the
            samples that keeps its field (its memory, about that of the windows it propagates, e.g. 31-62 MB on
            44,000 vertices, is held until the next computation of the solver). False: the estimate from the
            vertex values, as the approximate methods (no extra run). Ignored by the approximate methods.

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
        result = self._core.farthest_point_sampling(min(int(k), self._n), first_index, check_float(radius, "radius"),
                                                    check_method(method), check_float(lam, "lam"),
                                                    check_threads(threads), bool(exact_cell_areas))
        return FarthestPointSamples(*result)
