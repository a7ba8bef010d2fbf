"""Exact geodesic distances on triangle meshes (VTP, PVTP, AVTP, PAVTP), from numpy arrays.

    import vtp_geodesics
    V, F = vtp_geodesics.read_mesh("elephant.off")      # V float64 (n, 3), F int64 (m, 3)
    solver = vtp_geodesics.Solver(V, F)                  # per-mesh preprocessing, once
    d = solver.distances(0)                              # float64 (n,): distances from vertex 0
    d, labels = solver.distances([0, 99], return_labels=True)
    path = solver.path(500, sources=0)                   # (k, 3) points, from the source to vertex 500
                                                         # (arguments after the first are keywords)
    M = solver.matrix(max_distance=0.1)                  # scipy.sparse.csr_matrix, rows on all cores
    fps = solver.farthest_point_sampling(100)            # samples, radii, distances, labels (Voronoi cells)

Distances are exact (up to double rounding) for the methods "vtp" and "pvtp", lengths of real surface paths
for "avtp" and "pavtp". Unreachable vertices, and vertices beyond a distance limit, get ``inf``. Every
computation releases the GIL and may run on all cores; bad input raises ValueError or TypeError naming the
problem. The drop-in modules ``vtp_geodesics.gdist`` and ``vtp_geodesics.pygeodesic`` take the arguments of
the packages of the same names.
"""

# The package by topic, in private modules: _arguments (conversions and checks of the arguments, the method
# names, recommended_lambda), _io (read_mesh), _solver (Solver: construction, properties, statistics) with its
# queries in _queries, _field, _matrices, _sampling, _curves, _log_map and _patches; _core is the compiled layer
# (python/src/).
from . import _core
from ._arguments import methods, recommended_lambda
from ._curves import CellAreas, Curve
from ._io import read_mesh
from ._patches import PolarPatches
from ._queries import StraightestGeodesic, SurfacePolyline
from ._sampling import FarthestPointSamples
from ._solver import Solver

statistics_keys = _core.statistics_keys  # the keys of Solver.statistics, in order

__all__ = ["Solver", "FarthestPointSamples", "PolarPatches", "SurfacePolyline", "Curve", "CellAreas",
           "StraightestGeodesic", "read_mesh", "methods", "recommended_lambda", "statistics_keys"]

# the public names are vtp_geodesics.<name> (in help(), reprs and pickles), wherever they are defined
Solver.__module__ = read_mesh.__module__ = Curve.__module__ = __name__
