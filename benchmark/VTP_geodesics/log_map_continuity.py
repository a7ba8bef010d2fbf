#!/usr/bin/env python3
"""How continuous and how exact log maps are: the jump of theta across the edges away from the source and the
cut locus, and the error of rho and theta against an exact log map, for several log maps of one mesh and source.

    /usr/bin/python3 benchmark/VTP_geodesics/log_map_continuity.py MESH.off --exact EXACT.txt \\
        --method default=ours.txt --method strict=ours_strict.txt --method heat=vhm.txt

Input files: one line per vertex in the order of MESH.off, lines starting with '#' skipped, rho in column 0
and theta (radians) in column 1, 'inf' where unreached: `vtp_geodesics MESH --source S --log-map-output FILE`
(columns rho theta via) and geometry-central's log maps written as `rho theta x y` fit as they are. EXACT is
the reference: its rho is the exact distance, its theta is exact where its via column is -1 (the geodesic
passes through no vertex); by default columns 4 (via) and 5 (theta) of geometry-central's exact log map
written as `rho theta x y via theta_scaled` (theta_scaled: the angle scaled by 2 pi / the angle sum at the
source, the convention of vtp_geodesics and of the vector heat method).

Measures, for each --method:
- jumps: |theta(a) - theta(b)| wrapped to [0, pi] over the edges (a, b) kept: both ends reached, both farther
  than --near mean edge lengths from the source (exact rho), neither within one ring of a cut-locus vertex.
  A vertex is on the cut locus when, in the faces around it, the gradient of the exact rho (linear on each
  face) is shorter than 1 - --short (two fronts meet inside the face) or two of these gradients differ in
  direction by more than --spread degrees (fronts meet along an edge). The rule reads the exact rho only, so
  the same edges are kept for every method. Median, 99th and 99.9th percentile, largest. The rule cannot see
  the stretches of the cut locus where the two fronts arrive (nearly) parallel (behind a focus): there the
  exact theta jumps while rho stays smooth, and those edges remain (they carry the largest jumps of exact log
  maps). So also:
- spurious jumps: the number of kept edges across which the method's theta jumps by more than --spurious
  radians while the exact geodesics of both ends leave the source in directions less than --same radians
  apart (EXACT's theta column, defined at every vertex: the direction of the first segment of the exact
  path): jumps that the exact geometry does not have. (Zero for the strict polyhedral theta by construction.)
- rho error: |rho - exact rho| / exact rho over the vertices farther than --near mean edge lengths (median,
  99th percentile, largest).
- theta error: over the vertices whose exact geodesic passes through no vertex (via -1), but the source, after
  turning the method's theta by the constant offset that aligns the zero directions (the programs take
  different reference edges): the circular mean of theta - exact theta over these same vertices. The offset is
  printed. Median, 99th percentile, largest.
"""

import argparse
import math
import sys

import numpy as np


def read_off(path):
    tokens = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0]
            tokens.extend(line.split())
    i = 1 if tokens[0] in ("OFF", "off") else 0
    nv, nf = int(tokens[i]), int(tokens[i + 1])
    i += 3
    V = np.array(tokens[i:i + 3 * nv], dtype=float).reshape(nv, 3)
    i += 3 * nv
    F = []
    for _ in range(nf):
        k = int(tokens[i])
        if k != 3:
            sys.exit("%s: only triangles are read, got a face of %d corners" % (path, k))
        F.append([int(t) for t in tokens[i + 1:i + 4]])
        i += 1 + k
    return V, np.array(F, dtype=np.int64)


def read_columns(path, n):
    rows = [line.split() for line in open(path) if line.strip() and not line.lstrip().startswith("#")]
    if len(rows) != n:
        sys.exit("%s: %d lines for %d vertices" % (path, len(rows), n))
    width = min(len(r) for r in rows)
    return np.array([[float(x) for x in r[:width]] for r in rows])


def wrap(a):
    """angles to (-pi, pi]"""
    return np.angle(np.exp(1j * a))


def percentiles(x, qs):
    if x.size == 0:
        return [math.nan] * len(qs)
    return list(np.percentile(x, qs))


def cut_locus_vertices(V, F, rho, short, spread_degrees):
    """The vertices around which the exact rho's face gradients say two fronts meet (see the docstring)."""
    p0, p1, p2 = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    e1, e2 = p1 - p0, p2 - p0
    d1, d2 = rho[F[:, 1]] - rho[F[:, 0]], rho[F[:, 2]] - rho[F[:, 0]]
    a11, a12, a22 = (e1 * e1).sum(1), (e1 * e2).sum(1), (e2 * e2).sum(1)
    det = a11 * a22 - a12 * a12
    ok = np.isfinite(d1) & np.isfinite(d2) & (det > 0)
    with np.errstate(invalid="ignore", divide="ignore"):
        a = (a22 * d1 - a12 * d2) / det
        b = (a11 * d2 - a12 * d1) / det
    g = a[:, None] * e1 + b[:, None] * e2
    length = np.linalg.norm(g, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        unit = g / length[:, None]
    flagged = np.zeros(len(V), dtype=bool)
    flagged[F[ok & (length < 1 - short)].ravel()] = True
    # per vertex: the largest angle between two face gradients around it (against the mean direction, doubled
    # as a bound would be loose; pairwise over the ring instead)
    cos_limit = math.cos(math.radians(spread_degrees))
    ring = [[] for _ in range(len(V))]
    for f in np.flatnonzero(ok):
        for v in F[f]:
            ring[v].append(f)
    for v, faces in enumerate(ring):
        if flagged[v] or len(faces) < 2:
            continue
        u = unit[faces]
        if (u @ u.T).min() < cos_limit:
            flagged[v] = True
    return flagged


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("mesh")
    p.add_argument("--exact", required=True, help="the exact log map (see above)")
    p.add_argument("--exact-via-column", type=int, default=4)
    p.add_argument("--exact-theta-column", type=int, default=5)
    p.add_argument("--method", action="append", required=True, metavar="LABEL=FILE")
    p.add_argument("--near", type=float, default=10., help="mean edge lengths around the source left out (10)")
    p.add_argument("--short", type=float, default=0.1, help="gradient shorter than 1 - SHORT: cut locus (0.1)")
    p.add_argument("--spread", type=float, default=45., help="degrees between face gradients: cut locus (45)")
    p.add_argument("--spurious", type=float, default=0.1, help="radians: a spurious jump is larger (0.1)")
    p.add_argument("--same", type=float, default=0.01, help="radians: exact departures this close are the same (0.01)")
    a = p.parse_args()

    V, F = read_off(a.mesh)
    n = len(V)
    E = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    E = np.unique(E, axis=0)
    mean_edge = np.linalg.norm(V[E[:, 0]] - V[E[:, 1]], axis=1).mean()
    exact = read_columns(a.exact, n)
    rho_x = exact[:, 0]
    theta_x = exact[:, a.exact_theta_column]
    direct = (exact[:, a.exact_via_column] == -1) & (rho_x > 0) & np.isfinite(rho_x)
    far = np.isfinite(rho_x) & (rho_x > a.near * mean_edge)
    cut = cut_locus_vertices(V, F, rho_x, a.short, a.spread)
    band = cut.copy()  # the cut-locus vertices and their neighbours
    band[E[cut[E[:, 0]], 1]] = True
    band[E[cut[E[:, 1]], 0]] = True
    kept_edges = far[E[:, 0]] & far[E[:, 1]] & ~band[E[:, 0]] & ~band[E[:, 1]]
    print("%s: %d vertices, %d edges, mean edge %.4g; far (rho > %g mean edges): %d vertices; cut locus: %d "
          "vertices (%d with their ring); edges kept: %d of %d; direct geodesics (exact via -1): %d"
          % (a.mesh, n, len(E), mean_edge, a.near, far.sum(), cut.sum(), band.sum(), kept_edges.sum(), len(E),
             direct.sum()))
    exact_jump = np.abs(wrap(theta_x[E[:, 0]] - theta_x[E[:, 1]]))
    print("| method | edges | jump median | 99% | 99.9% | max | spurious jumps | rho rel. error median | 99% | max "
          "| theta offset | theta error median | 99% | max |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for item in a.method:
        label, _, path = item.partition("=")
        m = read_columns(path, n)
        rho, theta = m[:, 0], m[:, 1]
        reached = np.isfinite(rho) & np.isfinite(theta)
        keep = kept_edges & reached[E[:, 0]] & reached[E[:, 1]]
        jump = np.abs(wrap(theta[E[keep, 0]] - theta[E[keep, 1]]))
        j = percentiles(jump, [50, 99, 99.9, 100])
        spurious = int(((jump > a.spurious) & (exact_jump[keep] < a.same)).sum())
        r = far & reached
        rel = np.abs(rho[r] - rho_x[r]) / rho_x[r]
        e = percentiles(rel, [50, 99, 100])
        d = direct & reached
        offset = float(np.angle(np.exp(1j * (theta[d] - theta_x[d])).mean()))
        t = percentiles(np.abs(wrap(theta[d] - theta_x[d] - offset)), [50, 99, 100])
        print("| %s | %d | %.3g | %.3g | %.3g | %.3g | %d | %.3g | %.3g | %.3g | %.4f | %.3g | %.3g | %.3g |"
              % (label, keep.sum(), j[0], j[1], j[2], j[3], spurious, e[0], e[1], e[2], offset, t[0], t[1], t[2]))


if __name__ == "__main__":
    main()
