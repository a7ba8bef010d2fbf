"""Geodesic polar coordinates (the log map) of a local patch around a vertex, flattened into its tangent plane,
and the straightest geodesics that walk back from the centre to the patch's vertices.

    PYTHONPATH=build/python python3 examples/python/polar_patch.py [mesh.off] [vertex] [patch.png]
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
centre = int(sys.argv[2]) if len(sys.argv) > 2 else 1165
out = sys.argv[3] if len(sys.argv) > 3 else "polar_patch.png"

V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
radius = 0.15 * np.max(solver.distances(centre))
# rho (cos theta, sin theta) per vertex, inf beyond the radius; via: the vertex a geodesic turns at (-1: none)
log, via = solver.log_map(centre, max_distance=radius, return_via=True)
inside = np.flatnonzero(np.isfinite(log[:, 0]))
rho = np.linalg.norm(log[inside], axis=1)
theta = np.arctan2(log[inside, 1], log[inside, 0])
print("%d vertices within %.4g of vertex %d, %d behind a saddle or border vertex"
      % (inside.size, radius, centre, np.count_nonzero(via[inside] >= 0)))

# the exponential map undoes the log map: walk from the centre in the direction theta for rho
direct = inside[(via[inside] == -1) & (rho > 0)]
d = log[direct] / np.linalg.norm(log[direct], axis=1)[:, None]
paths, _, _ = solver.trace(np.full(direct.size, centre), d, np.linalg.norm(log[direct], axis=1))
errors = np.array([np.linalg.norm(p[-1] - V[v]) for p, v in zip(paths, direct)])
print("walked back to %d vertices (all those with via -1), largest miss %.3g"
      % (direct.size, errors.max()))

plt.figure(figsize=(5, 5))
plt.scatter(log[inside, 0], log[inside, 1], c=theta, cmap="hsv", s=8)
plt.gca().set_aspect("equal")
plt.title("log map of vertex %d (radius %.3g)" % (centre, radius))
plt.savefig(out, dpi=100)
print("wrote", out)
