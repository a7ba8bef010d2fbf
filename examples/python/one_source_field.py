"""Distances from one vertex, drawn to a PNG with matplotlib.

    PYTHONPATH=build/python python3 examples/python/one_source_field.py [mesh.off] [field.png]
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import vtp_geodesics

here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")
out = sys.argv[2] if len(sys.argv) > 2 else "one_source_field.png"

V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
d = solver.distances(0)                      # float64 (n,), exact geodesic distances from vertex 0
print("largest distance %.6g, reached %d of %d vertices" % (d.max(), (d < float("inf")).sum(), len(V)))

fig = plt.figure(figsize=(6, 5))
ax = fig.add_subplot(projection="3d")
surf = ax.plot_trisurf(V[:, 0], V[:, 1], V[:, 2], triangles=F, cmap="viridis", linewidth=0)
surf.set_array(d[F].mean(axis=1))            # one colour per face: the mean of its corners
ax.scatter(*V[0], color="red", s=30)
ax.set_axis_off()
fig.colorbar(surf, ax=ax, shrink=0.6, label="geodesic distance")
fig.savefig(out, dpi=120, bbox_inches="tight")
print("wrote", out)
