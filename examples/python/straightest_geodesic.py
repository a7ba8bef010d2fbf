"""Straightest geodesics (the exponential map) undo the log map: from the centroid of a face, the log map gives each
nearby vertex v its distance rho and direction theta; the walk (``trace``) from the centroid in the direction theta
for the length rho ends at v, when the geodesic to v passes through no vertex (via = -1). Checks every such walk
within four mean edge lengths: it goes its whole length, and if it meets no other vertex on its way, it ends at its
vertex. (A walk that meets a vertex goes on from it by the straightest rule: where the geodesic to v grazes a vertex,
the log map can take the path beside it and the walk misses v; these are counted, not checked: issue 46.)

    PYTHONPATH=build/python python3 examples/python/straightest_geodesic.py [mesh.off]
"""
import os
import sys

import numpy as np

import vtp_geodesics

here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")

V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
radius = 4 * np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1).mean()

face, bary = 0, np.array([1 / 3, 1 / 3, 1 / 3])
log, via = solver.log_map(points=([face], [bary]), max_distance=radius, return_via=True)
rho = np.linalg.norm(log, axis=1)
targets = np.flatnonzero(np.isfinite(rho) & (rho > 0) & (via == -1))
directions = log[targets] / rho[targets, None]          # 2D, in the tangent frame of the start (that of log_map)

n = targets.size
paths, end, _, walked, border = solver.trace((np.full(n, face), np.tile(bary, (n, 1))), directions, rho[targets],
                                             return_details=True)
miss = np.array([np.linalg.norm(p[-1] - V[v]) for p, v in zip(paths, targets)])
polyline = np.array([np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in paths])
others = np.ones(len(V), dtype=bool)
meets = np.zeros(n, dtype=bool)                          # a point of the walk at another vertex
for i, (p, v) in enumerate(zip(paths, targets)):
    others[v] = False
    meets[i] = np.any(np.linalg.norm(V[others][None, :, :] - p[:, None, :], axis=2) == 0)
    others[v] = True
for p, v in list(zip(paths, targets))[:3]:
    print("  to vertex %d: %d points, ends at (%.6f, %.6f, %.6f)" % (v, len(p), *p[-1]))
print("%d walks from the centroid of face %d: largest miss of the vertex %.3g, largest length error %.3g; %d walk(s)"
      " meeting another vertex on the way (largest miss %.3g)"
      % (n, face, miss[~meets].max(), np.abs(polyline - rho[targets]).max(), meets.sum(), miss[meets].max(initial=0)))
if n == meets.sum() or miss[~meets].max() > 1e-9 * radius or np.abs(walked - rho[targets]).max() > 1e-9 * radius \
        or np.abs(polyline - rho[targets]).max() > 1e-9 * radius or border.any():
    sys.exit("a walk did not reach its vertex")
