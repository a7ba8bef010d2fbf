"""Drop-in replacement for ``pygeodesic.geodesic`` (the exact algorithm class), on vtp_geodesics.

Change one line::

    import pygeodesic.geodesic as geodesic        # before
    from vtp_geodesics import pygeodesic as geodesic   # after

    geoalg = geodesic.PyGeodesicAlgorithmExact(points, faces)
    distance, path = geoalg.geodesicDistance(source_index, target_index)
    distances, best_source = geoalg.geodesicDistances(source_indices, target_indices)

Where this module deliberately differs from pygeodesic:

- a mesh that is not a valid manifold mesh (non-manifold vertices or edges, duplicate, degenerate or flipped
  faces) is repaired as ``vtp_geodesics.Solver`` repairs it, with a ``UserWarning``, on the caller's indices;
- bad input (indices out of range, wrong shapes, NaN coordinates) raises ``ValueError`` or ``TypeError``;
  pygeodesic prints an error and returns ``(None, None)``, or clamps indices into range;
- the distances are exact (VTP) on meshes where pygeodesic's MMP code crashes;
- ``geodesicDistance`` returns ``(inf, empty (0, 3) array)`` when the target is not reachable.
"""

import numpy

from . import Solver as _Solver

__all__ = ["PyGeodesicAlgorithmExact"]


def _index(x, name, n):
    if isinstance(x, (bool, numpy.bool_)) or not isinstance(x, (int, numpy.integer)):
        a = numpy.asarray(x)
        if a.ndim != 0 or a.dtype.kind not in "iu":
            raise TypeError("%s must be a vertex index (int), got %r" % (name, x))
        x = a
    i = int(x)
    if i < 0 or i >= n:
        raise ValueError("%s %d out of range [0, %d)" % (name, i, n))
    return i


class PyGeodesicAlgorithmExact:
    """Exact geodesic distances and paths on the mesh ``(points, faces)``.

    Args:
        points: (N, 3) vertex coordinates (any real dtype).
        faces: (M, 3) vertex indices of the triangles, 0-based (any integer dtype).

    A mesh that is not a valid manifold mesh is repaired (``UserWarning``; indices stay the caller's). Raises
    ValueError / TypeError if the mesh cannot be used (pygeodesic prints an error instead).
    """

    def __init__(self, points, faces):
        self._solver = _Solver(points, faces)
        self._n = self._solver.number_of_vertices

    def geodesicDistance(self, sourceIndex, targetIndex):
        """Distance and path between two vertices: ``(distance float, path ndarray (k, 3))``.

        The path runs from the target to the source (the target first), as in pygeodesic; its length is
        the distance. ``(inf, empty (0, 3) array)`` if the target is not reachable.
        """
        s = _index(sourceIndex, "sourceIndex", self._n)
        t = _index(targetIndex, "targetIndex", self._n)
        d = self._solver.distance(s, t)
        if not numpy.isfinite(d):
            return float("inf"), numpy.zeros((0, 3))
        path = self._solver.path(t, sources=s)
        return float(d), numpy.ascontiguousarray(path[::-1])

    def geodesicDistances(self, source_indices=None, target_indices=None, max_distance=numpy.inf):
        """Distance of each target vertex from the nearest source vertex.

        Args:
            source_indices: source vertices (default: vertex 0).
            target_indices: target vertices (default: every vertex).
            max_distance: distance limit (beyond it: ``inf``).

        Returns:
            ``(distances float64 (len(targets),), best_source int32 (len(targets),))``, ``best_source``
            being the index into ``source_indices`` of the nearest source (-1 where the distance is ``inf``).
        """
        sources = numpy.zeros(1, dtype=numpy.int64) if source_indices is None else numpy.asarray(source_indices)
        if sources.ndim == 0:
            sources = sources.reshape(1)
        if sources.size == 0:
            raise ValueError("source_indices is empty")
        d, labels = self._solver.distances(sources, max_distance=max_distance, targets=target_indices,
                                           return_labels=True)
        if target_indices is None:
            return d, labels.astype(numpy.int32)
        t = numpy.asarray(target_indices).astype(numpy.int64).reshape(-1)
        return d[t], labels[t].astype(numpy.int32)
