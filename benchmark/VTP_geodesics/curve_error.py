#!/usr/bin/env python3
"""The error of a per-vertex distance from a closed curve (issue 47, item 5; doc/VTP_geodesics/source_curves_anchor.txt).

  curve_error.py DIST.txt --cube MESH.off                     the cube ring z = 0.5 of curve_cases.py cube
  curve_error.py DIST.txt --polygon MESH.off CURVE            a flat mesh (z = 0) whose domain is convex: the
                                                              Euclidean distance to the polygon of CURVE's vertices
  curve_error.py DIST.txt --polyline MESH.off CURVE           the same, CURVE an open polyline (unsigned only)
  curve_error.py DIST.txt --reference REF.txt                 another per-vertex file (e.g. our exact distances)
  options: --signed / --unsigned (default: from DIST's header line), --flip (negate DIST; default: on for a signed
           file written by geometry-central's driver, 'gc_geo curve_heat signed'), --label TEXT

DIST.txt, REF.txt: '#' header lines, then one distance per vertex in the OFF order: curve_heat_comparison's output
(ours: negative on the left of the curve) or the anchor driver's `curve_heat` output (geometry-central's sign is
positive on the left: it is negated here, so that both are compared with our convention).

The exact answers (our sign: negative on the left; left = outward face normal x direction of travel):
  cube: on the sides |z - 0.5|, on the top and bottom 0.5 + the distance to that face's border (the unfolding of
        the side across the nearest border edge); the ring is walked counter-clockwise seen from +z, so the part
        above it is on its left: signed = 0.5 - z on the sides, -(0.5 + b) on the top, +(0.5 + b) on the bottom.
  polygon: the Euclidean distance to the closed polyline of the curve's vertices (on a flat mesh with a convex
        border the geodesic distance is the Euclidean one); signed negative inside a counter-clockwise polygon.
Prints one line: label, vertices, max |error| / max |exact|, mean |error| / max |exact|, max |error|, the vertex of
the largest error and its distance from the curve (in the answer), max |exact|, and off=K: the vertices whose error
exceeds 1e-9 of max |exact| (for a closed polygon: how many inside and outside it, and how many above the answer).
"""
import argparse
import re
import sys

import numpy as np


def read_values(path):
    header, vals = [], []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                header.append(s)
                continue
            vals.append(float(s.split()[0]))
    return " ".join(header), np.array(vals)


def read_off(path):
    with open(path) as f:
        toks = []
        for line in f:
            line = line.split("#", 1)[0]
            toks += line.split()
    if not toks[0].startswith("OFF"):
        sys.exit("%s: not an OFF file" % path)
    nv = int(toks[1])
    return np.array(toks[4:4 + 3 * nv], dtype=float).reshape(nv, 3)


def read_curve(path):
    with open(path) as f:
        return [int(t) for t in f.read().split()]


def cube_answer(P):
    x, y, z = P[:, 0], P[:, 1], P[:, 2]
    tol = 1e-12
    top, bottom = np.abs(z - 1) < tol, np.abs(z) < tol
    border = np.minimum(np.minimum(x, 1 - x), np.minimum(y, 1 - y))
    d = np.where(top | bottom, 0.5 + border, np.abs(z - 0.5))
    s = np.where(top, -d, np.where(bottom, d, 0.5 - z))
    return d, s


def polygon_answer(P, loop, closed=True):
    Q = P[loop][:, :2]
    A, B = Q, np.roll(Q, -1, axis=0)
    if not closed:
        A, B = Q[:-1], Q[1:]
    X = P[:, :2]
    best = np.full(len(X), np.inf)
    for a, b in zip(A, B):  # distance to each segment
        ab = b - a
        t = np.clip(((X - a) @ ab) / (ab @ ab), 0.0, 1.0)
        best = np.minimum(best, np.hypot(*(X - a - t[:, None] * ab).T))
    if not closed:
        return best, None
    # inside: even-odd crossing of a ray to +x
    inside = np.zeros(len(X), dtype=bool)
    for a, b in zip(A, B):
        cross = (a[1] > X[:, 1]) != (b[1] > X[:, 1])
        with np.errstate(divide="ignore", invalid="ignore"):
            xi = a[0] + (X[:, 1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        inside ^= cross & (X[:, 0] < xi)
    area = 0.5 * np.sum(A[:, 0] * B[:, 1] - B[:, 0] * A[:, 1])
    if area <= 0:
        sys.exit("polygon: the curve is not counter-clockwise (area %g)" % area)
    return best, np.where(inside, -best, best)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dist")
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--cube", metavar="MESH")
    g.add_argument("--polygon", nargs=2, metavar=("MESH", "CURVE"))
    g.add_argument("--polyline", nargs=2, metavar=("MESH", "CURVE"))
    g.add_argument("--reference", metavar="REF")
    sg = ap.add_mutually_exclusive_group()
    sg.add_argument("--signed", dest="signed", action="store_true", default=None)
    sg.add_argument("--unsigned", dest="signed", action="store_false")
    ap.add_argument("--flip", action="store_true", default=None, help="negate DIST (default: for gc_geo signed)")
    ap.add_argument("--no-flip", dest="flip", action="store_false")
    ap.add_argument("--label", default=None)
    a = ap.parse_args()

    header, d = read_values(a.dist)
    signed = a.signed
    if signed is None:
        signed = re.search(r"\bsigned\b", header) is not None
    flip = a.flip
    if flip is None:
        flip = signed and "gc_geo curve_heat signed" in header
    if flip:
        d = -d
    if a.cube:
        du, ds = cube_answer(read_off(a.cube))
        exact = ds if signed else du
    elif a.polygon:
        du, ds = polygon_answer(read_off(a.polygon[0]), read_curve(a.polygon[1]))
        exact = ds if signed else du
        side = ds
    elif a.polyline:
        if signed:
            sys.exit("--polyline: an open polyline has no sign here")
        du, _ = polygon_answer(read_off(a.polyline[0]), read_curve(a.polyline[1]), closed=False)
        exact = du
    else:
        rh, exact = read_values(a.reference)
        if signed and "gc_geo curve_heat signed" in rh:
            exact = -exact
        du = np.abs(exact)
    if len(exact) != len(d):
        sys.exit("%s has %d values, the answer %d" % (a.dist, len(d), len(exact)))
    bad = ~np.isfinite(d)
    if bad.any():
        print("%s: %d non-finite values" % (a.dist, bad.sum()), file=sys.stderr)
    err = np.abs(d - exact)
    scale = np.max(np.abs(exact))
    off = err > 1e-9 * scale
    off_text = "  off=%d" % off.sum()
    if a.polygon and off.any():
        above = np.abs(d) > np.abs(exact)
        off_text += " (inside %d, outside %d; above the answer %d)" % ((off & (side < 0)).sum(), (off & (side > 0)).sum(),
                                                                       (off & above).sum())
    i = int(np.nanargmax(np.where(bad, np.inf, err)))
    label = a.label or a.dist
    print("%s  %s  n=%d  max_rel=%.3e  mean_rel=%.3e  max_abs=%.3e  at_vertex=%d (answer %.4g, from curve %.4g)"
          "  max_dist=%.6g%s%s" % (label, "signed" if signed else "unsigned", len(d), err.max() / scale,
                                   np.mean(err) / scale, err.max(), i, exact[i], du[i], scale, off_text,
                                   "  flipped" if flip else ""))


if __name__ == "__main__":
    main()
