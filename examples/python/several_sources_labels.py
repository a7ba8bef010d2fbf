"""Several sources: the distance to the nearest one and which one it is (geodesic Voronoi regions), drawn
with tripcolor in a flat projection.

    PYTHONPATH=build/python python3 examples/python/several_sources_labels.py [mesh.off] [labels.png]
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
out = sys.argv[2] if len(sys.argv) > 2 else "several_sources_labels.png"

V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
sources = [0, 700, 1400, 2100]
# a source may also be a point of the surface: here the surface point nearest to the centroid
d, labels = solver.distances(sources, points=V.mean(axis=0)[None, :], return_labels=True)
for k in range(len(sources) + 1):
    print("source %d: %d vertices" % (k, (labels == k).sum()))

# seen from +z: the faces drawn from the farthest to the nearest
Fz = F[np.argsort(V[F, 2].mean(axis=1))]
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
axes[0].tripcolor(V[:, 0], V[:, 1], Fz, facecolors=d[Fz].mean(axis=1), cmap="viridis")
axes[0].set_title("distance to the nearest source")
axes[1].tripcolor(V[:, 0], V[:, 1], Fz, facecolors=labels[Fz[:, 0]].astype(float), cmap="tab10")
axes[1].set_title("nearest source (label)")
for ax in axes:
    ax.plot(V[sources, 0], V[sources, 1], "k*")
    ax.set_aspect("equal")
    ax.set_axis_off()
fig.savefig(out, dpi=120, bbox_inches="tight")
print("wrote", out)
