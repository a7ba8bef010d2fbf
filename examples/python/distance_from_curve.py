"""The distance from a curve drawn on the surface, unsigned and signed (negative on the left of the curve: inside a
counter-clockwise loop seen from the side of the faces' normals), and from the border of the mesh.

1. A flat jittered grid of the unit square, made here, and a closed counter-clockwise polygon: the geodesic
   distance is the Euclidean distance to the polygon, negative inside with ``signed=True``; ``source_border=True``
   gives the distance to the square's sides.
2. The elephant (or the mesh of the command line) and a curve through three of its vertices: the distance to the
   curve is 0 at its points and never more than the distance to any of them.
The script checks both and exits non-zero otherwise.

    PYTHONPATH=build/python python3 examples/python/distance_from_curve.py [mesh.off]
"""
import os
import sys

import numpy as np

import vtp_geodesics


def jittered_square(n, seed=47):
    """An n x n grid of the unit square (z = 0), interior vertices moved by less than a quarter of the spacing,
    counter-clockwise triangles."""
    h = 1.0 / (n - 1)
    j, i = np.divmod(np.arange(n * n), n)
    inner = (i > 0) & (i < n - 1) & (j > 0) & (j < n - 1)
    rng = np.random.default_rng(seed)
    V = np.stack([i * h, j * h, np.zeros(n * n)], axis=1)
    V[inner, :2] += rng.uniform(-0.25, 0.25, (inner.sum(), 2)) * h
    F = []
    for r in range(n - 1):
        for c in range(n - 1):
            a, b, d, e = r * n + c, r * n + c + 1, (r + 1) * n + c + 1, (r + 1) * n + c
            F += [(a, b, d), (a, d, e)]
    return V, np.array(F)


def distance_to_polyline(P, points):
    best = np.full(len(P), np.inf)
    for a, b in zip(points[:-1], points[1:]):
        t = np.clip(((P - a) @ (b - a)) / ((b - a) @ (b - a)), 0.0, 1.0)
        best = np.minimum(best, np.linalg.norm(P - (a + t[:, None] * (b - a)), axis=1))
    return best


def fail(message):
    print("FAILED:", message)
    sys.exit(1)


# 1. The plane
V, F = jittered_square(41)
solver = vtp_geodesics.Solver(V, F)
polygon = np.array([[0.31, 0.29, 0.0], [0.72, 0.33, 0.0], [0.69, 0.71, 0.0], [0.27, 0.66, 0.0], [0.31, 0.29, 0.0]])
d = solver.distances(curves=[polygon])                     # one source: the closed polygon (last point = first)
s = solver.distances(curves=[polygon], signed=True)        # negative inside
b = solver.distances(source_border=True)                   # the border of the square
euclid = distance_to_polyline(V[:, :2], polygon[:, :2])
inside = s < 0
x, y = V[:, 0], V[:, 1]
worst = max(np.max(np.abs(d - euclid)), np.max(np.abs(np.abs(s) - euclid)),
            np.max(np.abs(b - np.minimum.reduce([x, 1 - x, y, 1 - y]))))
print("plane: %d vertices, %d inside the polygon; largest difference from the Euclidean distances: %.3g"
      % (len(V), inside.sum(), worst))
if not worst <= 1e-12:
    fail("the distances on the plane are not the Euclidean ones")
centre = np.argmin(np.linalg.norm(V[:, :2] - [0.5, 0.5], axis=1))
corner = 0
if not (s[centre] < 0 < s[corner]):
    fail("the signed distance is not negative inside the counter-clockwise polygon and positive outside")

# 2. A curve through three vertices of a real mesh
here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")
V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
through = [0, len(V) // 3, 2 * len(V) // 3]
d = solver.distances(curves=[V[through]])                 # the vertices' positions, located on the surface
from_points = np.array([solver.distances(v) for v in through])
excess = np.max(d - from_points.min(axis=0))
print("%s: curve through vertices %s: largest distance %.6g, at its points %s, largest excess over the distance "
      "to one of its points %.3g" % (os.path.basename(mesh), through, d.max(), d[through], excess))
if not (np.all(d[through] == 0) and excess <= 1e-12 * d.max()):
    fail("the distance to the curve is not 0 at its points, or exceeds the distance to one of them")
print("done")
