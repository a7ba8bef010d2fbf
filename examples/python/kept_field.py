"""The kept field: one exact run from two sources that keeps its windows, then the distance and the nearest source
at any point of the surface, and isolines at levels chosen after the run, with no new propagation.

    PYTHONPATH=build/python python3 examples/python/kept_field.py [mesh.off]
"""
import os
import sys

import numpy as np

import vtp_geodesics

here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")

V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
sources = [0, 1000]
d = solver.distances(sources, keep_field=True)   # one run; the solver keeps its field until its next computation
print("kept field: %d windows, %.1f KiB" % (solver.statistics["field_pieces"], solver.field_bytes / 1024))

# a few positions (their nearest surface points): the exact distance there, not an interpolation of the vertices
xyz = np.array([V[F[10]].mean(axis=0), V[F[2000]].mean(axis=0), 0.5 * (V[0] + V[1000])])
dist, label = solver.field_distance(xyz, return_labels=True)
for p, r, k in zip(xyz, dist, label):
    print("point (%.3f, %.3f, %.3f): distance %.6f, nearest source %d (vertex %d)" % (*p, r, k, sources[k]))

# isolines at levels chosen now, from the largest distance of the run: still no new propagation
levels = np.linspace(0, d.max(), 6)[1:-1]
curves = solver.field_isolines(levels)
for level in levels:
    at = [c for c in curves if c["level"] == level]
    length = sum(np.linalg.norm(np.diff(c["points"], axis=0, append=c["points"][:1] if c["closed"] else None),
                                axis=1).sum() for c in at)
    print("isolines at %.4f: %d curves, %.4f long" % (level, len(at), length))
areas, _ = solver.field_cell_areas()
print("cell areas (nearest source): %.6f, %.6f" % tuple(areas))
