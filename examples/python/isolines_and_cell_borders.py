"""Isolines and cell borders from exact runs that keep their field: the borders between the geodesic Voronoi cells of
three sources and the cells' areas, then isolines at levels chosen after a run, with no new propagation.
Checks: the cells' areas add up to the area of the mesh; every border point is as far from the two sources of its
cells (from a run from each source alone); every isoline point is at its level (``field_distance`` there).

    PYTHONPATH=build/python python3 examples/python/isolines_and_cell_borders.py [mesh.off]
"""
import os
import sys

import numpy as np

import vtp_geodesics

here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")

V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
sources = [0, len(V) // 3, 2 * len(V) // 3]
d = solver.distances(sources, keep_field=True)           # one run from the three sources, keeping its field
tolerance = 1e-9 * d.max()
errors = 0

# the cells' areas, against the area of the mesh
areas, uncertainty = solver.field_cell_areas()
for s, a, u in zip(sources, areas, uncertainty):
    print("  cell of vertex %d: area %.6f (uncertainty %.2g)" % (s, a, u))
mesh_area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()
print("cell areas sum to %.9f, the mesh's area is %.9f" % (areas.sum(), mesh_area))
errors += int(len(areas) != len(sources) or abs(areas.sum() - mesh_area) > 1e-9 * mesh_area)

# isolines of the three sources at a quarter and at half of the largest distance, from the same run
levels = [0.25 * d.max(), 0.5 * d.max()]
isolines = solver.field_isolines(levels)                 # Curve namedtuples: points, faces, barycentric, level, ...
worst = max(np.abs(solver.field_distance((c.faces, c.barycentric)) - c.level).max() for c in isolines)
for c in isolines:
    print("  isoline at %.4f: %d points, %s" % (c.level, len(c.points), "closed" if c.closed else "open"))
print("%d isolines, largest |distance - level| %.3g" % (len(isolines), worst))
errors += int(not isolines or worst > tolerance)

# the borders, with their face locations; then the distance at their points from each source alone
borders = solver.field_cell_borders()
faces = np.concatenate([b.faces for b in borders])
bary = np.concatenate([b.barycentric for b in borders])
cells = np.concatenate([np.tile(b.cells, (len(b.faces), 1)) for b in borders])
to_source = []
for s in sources:
    solver.distances(s, keep_field=True)                 # each run keeps its own field
    to_source.append(solver.field_distance((faces, bary)))
k = np.arange(len(faces))
gap = np.abs(np.array(to_source)[cells[:, 0], k] - np.array(to_source)[cells[:, 1], k])
print("%d borders, %d points, largest difference of the distances to the two sources %.3g"
      % (len(borders), len(faces), gap.max()))
errors += int(not borders or gap.max() > tolerance)

if errors:
    sys.exit("%d check(s) failed" % errors)
