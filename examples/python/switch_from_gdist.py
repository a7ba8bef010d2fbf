"""The one-line switch from gdist: the rest of a gdist program stays as it is.

    PYTHONPATH=build/python python3 examples/python/switch_from_gdist.py [mesh.off]
"""
import os
import sys

import numpy

# import gdist                          # before
from vtp_geodesics import gdist         # after: same functions, arguments and return types

import vtp_geodesics

here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")
V, F = vtp_geodesics.read_mesh(mesh)
vertices, triangles = V.astype(numpy.float64), F.astype(numpy.int32)   # what gdist requires

d = gdist.compute_gdist(vertices, triangles, source_indices=numpy.array([0], dtype=numpy.int32),
                        target_indices=numpy.array([10, 20, 30], dtype=numpy.int32))
print("compute_gdist:", d)
M = gdist.local_gdist_matrix(vertices, triangles, max_distance=0.05)
print("local_gdist_matrix:", repr(M))
print("symmetric:", (M != M.T).nnz == 0, " largest entry:", M.data.max())
P = gdist.distance_matrix_of_selected_points(vertices, triangles, numpy.array([0, 100, 200], dtype=numpy.int32))
print("distance_matrix_of_selected_points:", P.nnz, "entries")
