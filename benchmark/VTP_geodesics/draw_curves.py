# Draws the curves of `vtp_geodesics --curves-output` (OBJ: g level_<value>, g border_<i>_<j>) over the mesh (OFF),
# seen along -x, only their visible parts (a depth buffer of the mesh): isolines blue, cell borders red.
#   /usr/bin/python3 draw_curves.py MESH.off CURVES.obj OUT.png
# The README figure: vtp_geodesics --farthest-points 6 --isolines 12 --curves-output cam.obj camel.off, then
#   draw_curves.py camel.off cam.obj doc/VTP_geodesics/fig/curves_camel.png
import sys, numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection, LineCollection
mesh, obj, out = sys.argv[1:4]
with open(mesh) as f:
    toks = [l for l in f.read().split("\n") if l.strip() and not l.startswith("#")]
nv, nf = map(int, toks[1].split()[:2])
V = np.array([list(map(float, toks[2+i].split()[:3])) for i in range(nv)])
F = np.array([list(map(int, toks[2+nv+i].split()[1:4])) for i in range(nf)])
# view: x to the right, y up, looking along -z
AX = (2, 1, 0)  # horizontal, vertical, towards the viewer
def proj(P): return P[:, [AX[0], AX[1]]]
n = np.cross(V[F[:,1]]-V[F[:,0]], V[F[:,2]]-V[F[:,0]]); n /= np.linalg.norm(n, axis=1)[:, None] + 1e-30
depth = V[F].mean(axis=1)[:, AX[2]]
order = np.argsort(depth)
shade = 0.35 + 0.6 * np.abs(n[:, AX[2]])
fig, ax = plt.subplots(figsize=(7, 5.6), dpi=110)
ax.add_collection(PolyCollection([proj(V[F[i]]) for i in order], facecolors=[(s, s, s) for s in shade[order]], edgecolors="none"))
groups = {}
pts = []; cur = None
for line in open(obj):
    if line.startswith("g "): cur = line.split()[1]; groups.setdefault(cur, [])
    elif line.startswith("v "): pts.append(list(map(float, line.split()[1:4])))
    elif line.startswith("l "):
        idx = [int(t) - 1 for t in line.split()[1:]]
        groups[cur].append(np.array(pts)[idx])
P = np.array(pts)
# depth buffer of the mesh, to draw only the visible parts of the curves
W, H = 900, 700
lo = proj(V).min(axis=0); hi = proj(V).max(axis=0); sc = min((W - 1) / (hi[0] - lo[0]), (H - 1) / (hi[1] - lo[1]))
Z = np.full((H, W), -np.inf)
Q = (proj(V) - lo) * sc; D = V[:, AX[2]]
for f in F:
    a, b, c = Q[f]; x0, y0 = np.floor(np.minimum(np.minimum(a, b), c)).astype(int); x1, y1 = np.ceil(np.maximum(np.maximum(a, b), c)).astype(int)
    xs, ys = np.meshgrid(np.arange(x0, x1 + 1), np.arange(y0, y1 + 1))
    det = (b[0]-a[0])*(c[1]-a[1]) - (c[0]-a[0])*(b[1]-a[1])
    if abs(det) < 1e-12: continue
    l1 = ((xs-a[0])*(c[1]-a[1]) - (c[0]-a[0])*(ys-a[1])) / det; l2 = ((b[0]-a[0])*(ys-a[1]) - (xs-a[0])*(b[1]-a[1])) / det
    m = (l1 >= -0.01) & (l2 >= -0.01) & (l1 + l2 <= 1.01)
    z = D[f[0]] + l1 * (D[f[1]] - D[f[0]]) + l2 * (D[f[2]] - D[f[0]])
    xs, ys, z = xs[m], ys[m], z[m]
    ok = (xs >= 0) & (xs < W) & (ys >= 0) & (ys < H)
    np.maximum.at(Z, (ys[ok], xs[ok]), z[ok])
eps = 0.004 * (D.max() - D.min())
def visible_parts(c):
    q = ((proj(c) - lo) * sc).round().astype(int)
    q[:, 0] = q[:, 0].clip(0, W - 1); q[:, 1] = q[:, 1].clip(0, H - 1)
    vis = c[:, AX[2]] >= Z[q[:, 1], q[:, 0]] - eps
    parts, start = [], None
    for i, v in enumerate(vis):
        if v and start is None: start = i
        if (not v or i == len(vis) - 1) and start is not None:
            end = i + 1 if v else i
            if end - start >= 2: parts.append(proj(c[start:end]))
            start = None
    return parts
iso = [p for g, cs in groups.items() if g.startswith("level") for c in cs for p in visible_parts(c)]
bor = [p for g, cs in groups.items() if g.startswith("border") for c in cs for p in visible_parts(c)]
ax.add_collection(LineCollection(iso, colors="#1f77b4", linewidths=0.7))
ax.add_collection(LineCollection(bor, colors="#d62728", linewidths=1.4))
ax.set_xlim(lo[0], hi[0]); ax.set_ylim(lo[1], hi[1])
ax.set_aspect("equal"); ax.axis("off")
plt.tight_layout(); plt.savefig(out)
