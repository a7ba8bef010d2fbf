# The cost of Solver(V, F, repair=True) and of through_pinches=True, from Python (doc/VTP_geodesics/python.txt):
# MESH, and a copy of it turned about its vertex of largest x and pinched to it there (one non-manifold vertex),
# and MESH with every other face flipped.
#
#   PYTHONPATH=build/python /usr/bin/python3 benchmark/VTP_geodesics/python_repair_benchmark.py MESH
#
# Prints the best of 3 wall times of Solver() and distances() (through_pinches: one run).
import sys, time, math, warnings
import numpy as np
import vtp_geodesics as vg
warnings.simplefilter("ignore")
V, F = vg.read_mesh(sys.argv[1])
n = len(V)
def rot(axis, a):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(a) * K + (1 - math.cos(a)) * K @ K
p = int(np.argmax(V[:, 0]))                      # the pinch: an extreme vertex
B = (V - V[p]) @ rot([1, 2, 3], 2.0).T + V[p]
idx = np.arange(n) + n; idx[p] = p
V2 = np.vstack([V, np.delete(B, p, axis=0)])
idx[p+1:] -= 1
F2 = np.vstack([F, idx[F]])
def t(f, k=3):
    best = math.inf
    for _ in range(k):
        t0 = time.perf_counter(); r = f(); best = min(best, time.perf_counter() - t0)
    return best, r
tv, _ = t(lambda: vg.Solver(V, F))
tr, s_apart = t(lambda: vg.Solver(V2, F2))
_, s_join = t(lambda: vg.Solver(V2, F2, through_pinches=True), 1)
print("mesh %s: %d vertices; pinched double: %d vertices, %s" % (sys.argv[1], n, len(V2), s_apart.repairs))
print("Solver(valid mesh) %.3f s; Solver(pinched double, repaired) %.3f s" % (tv, tr))
src = int(np.argmin(V[:, 0]))
ta, da = t(lambda: s_apart.distances(src))
tj, dj = t(lambda: s_join.distances(src))
print("distances from %d: apart %.3f s (reached %d), through_pinches %.3f s (reached %d, %d join runs); ratio %.2f"
      % (src, ta, np.isfinite(da).sum(), tj, np.isfinite(dj).sum(), s_join._core.join_runs, tj / ta))
# flipped faces only: the repair's cost on a mesh that needs only reorientation
F3 = F.copy(); F3[::2] = F3[::2, ::-1]
tf, s3 = t(lambda: vg.Solver(V, F3))
d3, d0 = s3.distances(src), vg.Solver(V, F).distances(src)
print("Solver(every other face flipped) %.3f s: %s; largest difference to the valid mesh: %.2e of the largest distance" % (tf, s3.repairs, np.max(np.abs(d3 - d0)) / d0.max()))
