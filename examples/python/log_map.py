"""The log map (geodesic polar coordinates): one exact run gives, with the distances, for every vertex the angle theta
at which its geodesic leaves the source, as rho (cos theta, sin theta) in the source's tangent frame. Around a
vertex, then around a point inside a face, within a radius. Checks that rho is the distance at every vertex.

    PYTHONPATH=build/python python3 examples/python/log_map.py [mesh.off]
"""
import os
import sys

import numpy as np

import vtp_geodesics

here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")

V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
errors = 0


def report(around, log, via, d):
    """Prints the coordinates of the run and checks that their radius is the distance; returns the errors."""
    reached = np.isfinite(d)
    rho = np.linalg.norm(log[reached], axis=1)
    theta = np.degrees(np.arctan2(log[reached, 1], log[reached, 0]))
    print("%s: %d vertices, largest rho %.6f, %d behind a saddle or border vertex"
          % (around, reached.sum(), rho.max(), np.count_nonzero(via[reached] >= 0)))
    for v, r, t in list(zip(np.flatnonzero(reached), rho, theta))[1:4]:
        print("  vertex %d: rho %.6f, theta %.2f degrees" % (v, r, t))
    worst = np.max(np.abs(rho - d[reached]))
    print("  largest |rho - distance|: %.3g" % worst)
    return int(worst > 1e-12 * (1 + d[reached].max())) + int(np.any(np.isfinite(log[~reached])))


# around a vertex: theta = 0 along the library's reference edge, angles scaled by 2 pi / the angle sum there
log, via = solver.log_map(0, return_via=True)
errors += report("around vertex 0", log, via, solver.distances(0))
errors += int(np.any(log[0] != 0))

# around the centroid of face 0, within a radius: theta = 0 along F[0][0] -> F[0][1], unscaled
centroid = ([0], [[1 / 3, 1 / 3, 1 / 3]])
radius = 0.25 * solver.distances(0).max()
log, via = solver.log_map(points=centroid, max_distance=radius, return_via=True)
errors += report("around the centroid of face 0 (radius %.4f)" % radius, log, via,
                 solver.distances(points=centroid, max_distance=radius))

if errors:
    sys.exit("%d check(s) failed" % errors)
