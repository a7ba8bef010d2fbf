"""A geodesic path between two vertices: its points, its length (= the distance), and a picture.

    PYTHONPATH=build/python python3 examples/python/geodesic_path.py [mesh.off] [path.png]
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import vtp_geodesics

here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")
out = sys.argv[2] if len(sys.argv) > 2 else "geodesic_path.png"

V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
source, target = 0, 2000
path = solver.path(target, sources=source)     # (k, 3): from the source to the target
length = np.linalg.norm(np.diff(path, axis=0), axis=1).sum()
print("path of %d points, length %.12g, distance %.12g" % (len(path), length, solver.distance(source, target)))

fig = plt.figure(figsize=(6, 5))
ax = fig.add_subplot(projection="3d")
ax.plot_trisurf(V[:, 0], V[:, 1], V[:, 2], triangles=F, color="lightgrey", alpha=0.35, linewidth=0)
ax.plot(path[:, 0], path[:, 1], path[:, 2], "r-", linewidth=2)
ax.set_axis_off()
fig.savefig(out, dpi=120, bbox_inches="tight")
print("wrote", out)
