"""A sparse local distance matrix: every vertex to every vertex within a radius, rows on all cores, as a
scipy.sparse.csr_matrix (float32 to halve its memory).

    PYTHONPATH=build/python python3 examples/python/sparse_local_matrix.py [mesh.off] [radius]
"""
import os
import sys
import time

import numpy as np

import vtp_geodesics

here = os.path.dirname(os.path.abspath(__file__))
mesh = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "elephant.off")
V, F = vtp_geodesics.read_mesh(mesh)
solver = vtp_geodesics.Solver(V, F)
radius = float(sys.argv[2]) if len(sys.argv) > 2 else 5 * solver.mean_edge_length

t0 = time.perf_counter()
M = solver.matrix(max_distance=radius, dtype=np.float32)   # all vertices as sources, Ctrl-C stops it
seconds = time.perf_counter() - t0
print("%d x %d, %d entries within %.4g (%.1f per row), %.2f s, %.1f MB"
      % (M.shape[0], M.shape[1], M.nnz, radius, M.nnz / M.shape[0], seconds,
         (M.data.nbytes + M.indices.nbytes + M.indptr.nbytes) / 1e6))
# e.g. a geodesic Gaussian smoothing of a signal over the surface
w = M.copy()
w.data = np.exp(-(w.data / (radius / 2)) ** 2)
signal = np.random.default_rng(0).normal(size=len(V))
smooth = (w @ signal) / np.asarray(w.sum(axis=1)).ravel()
print("signal std %.3f -> smoothed %.3f" % (signal.std(), smooth.std()))
