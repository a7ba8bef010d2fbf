#!/usr/bin/env python3
"""Tests of the sources that are curves of vtp_geodesics (--source-curve, --source-border, --signed), against the
Euclidean answer on a flat jittered grid (run by ctest, one test per case; see curve_tests.cmake).

    source_curve_test.py CASE --tool VTP_GEODESICS --work DIR

The mesh: the unit square of the plane z = 0, an N x N grid of spacing h = 1 / (N - 1) whose interior vertices are
moved in x and y by at most h / 4 (a seeded random draw) and whose border vertices stay put, each square cut into
two triangles, counter-clockwise seen from above (normal +z). On a plane, the geodesic distance to a curve made of
straight pieces is the Euclidean distance to it: to a closed polygon, to an open polyline, to the square's sides;
the expected values below are computed from the curve's coordinates alone, never from an output of the tool.

Cases:
  polygon         a closed counter-clockwise polygon: every vertex at its Euclidean distance to the polygon (1e-12)
  polygon_pvtp    the same with --method pvtp --threads 2
  limit           the same signed, with --max-distance 0.1: the signed distance within it, inf beyond
  signed          the same with --signed: negative inside, positive outside, |value| = the unsigned distance
  signed_cw       the same polygon walked clockwise: positive inside, negative outside
  open_signed     an open segment: unsigned = distance to the segment; --signed: negative on its left (+y) where the
                  nearest point is inside the segment, positive on its right and beyond its ends
  border          --source-border: distance to the square's sides; with --signed, minus that (the border runs with
                  the surface on its left)
  labels          --source V, --source-point, two --source-curve files (one with two curves, a blank line between
                  them) and --source-border: the distance is the least of the five, the label (--labels) the
                  index of the nearest in that order (vertices, points, curves, border) where it is clear
  offset_curves   --levels A,B --curves-output: the isolines of the distance to the polygon are its offset curves
                  (every point at distance A or B from the polygon, 1e-9), from the kept field of the curves
"""

import argparse
import os
import subprocess
import sys

import numpy as np

N = 81                     # the bar: an 81 x 81 grid
TOLERANCE = 1e-12
POLYGON = [(0.31, 0.29), (0.72, 0.33), (0.69, 0.71), (0.27, 0.66)]  # counter-clockwise


def write_grid(path, n=N, seed=47):
    """The jittered grid (see the module's docstring) as OFF; returns its vertices (n * n, 3)."""
    h = 1.0 / (n - 1)
    i, j = np.meshgrid(np.arange(n), np.arange(n))  # i: column (x), j: row (y); vertex j * n + i
    x, y = i * h, j * h
    inner = (i > 0) & (i < n - 1) & (j > 0) & (j < n - 1)
    rng = np.random.default_rng(seed)
    x = x + np.where(inner, rng.uniform(-0.25, 0.25, x.shape) * h, 0.0)
    y = y + np.where(inner, rng.uniform(-0.25, 0.25, y.shape) * h, 0.0)
    V = np.stack([x.ravel(), y.ravel(), np.zeros(n * n)], axis=1)
    faces = []
    for r in range(n - 1):
        for c in range(n - 1):
            a, b, d, e = r * n + c, r * n + c + 1, (r + 1) * n + c + 1, (r + 1) * n + c
            faces += [(a, b, d), (a, d, e)] if (r + c) % 2 else [(a, b, e), (b, d, e)]
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(faces)))
        for p in V:
            f.write("%r %r %r\n" % (float(p[0]), float(p[1]), float(p[2])))
        for t in faces:
            f.write("3 %d %d %d\n" % t)
    return V


def segment_distance(P, a, b):
    """Euclidean distances of the points P (k, 2) to the segment [a, b], and the parameter t in [0, 1] of the
    nearest point."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    t = np.clip(((P - a) @ d) / (d @ d), 0.0, 1.0)
    return np.linalg.norm(P - (a + t[:, None] * d), axis=1), t


def polyline_distance(P, points):
    return np.min([segment_distance(P, points[k], points[k + 1])[0] for k in range(len(points) - 1)], axis=0)


def inside_polygon(P, polygon):
    """Whether each point of P (k, 2) is inside the polygon (crossings of a ray towards +x)."""
    inside = np.zeros(len(P), dtype=bool)
    for k in range(len(polygon)):
        (x0, y0), (x1, y1) = polygon[k], polygon[(k + 1) % len(polygon)]
        crosses = (y0 > P[:, 1]) != (y1 > P[:, 1])
        with np.errstate(divide="ignore", invalid="ignore"):
            x = x0 + (P[:, 1] - y0) * (x1 - x0) / (y1 - y0)
        inside ^= crosses & (P[:, 0] < x)
    return inside


def write_curves(path, curves):
    """Curves (lists of (x, y)) to a --source-curve file, z = 0, a blank line between curves."""
    with open(path, "w") as f:
        f.write("\n\n".join("\n".join("%r %r 0" % (float(x), float(y)) for x, y in c) for c in curves) + "\n")


def run_tool(tool, args):
    r = subprocess.run([tool] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    if r.returncode != 0 or r.stderr:
        sys.exit("FAIL: %s %s\nexit code %d, stderr: %s" % (tool, " ".join(args), r.returncode, r.stderr))
    return r


def read_values(path):
    with open(path) as f:
        return np.array([float(line) for line in f])


class Checker:
    def __init__(self):
        self.failures = 0

    def close(self, what, got, expected, tolerance=TOLERANCE, mask=None):
        got, expected = np.asarray(got, float), np.asarray(expected, float)
        if mask is None:
            mask = np.ones(len(got), dtype=bool)
        error = np.abs(got[mask] - expected[mask])
        worst = float(error.max()) if error.size else 0.0
        ok = got.shape == expected.shape and bool(np.all(error <= tolerance))
        print("%s: %s (%d values, largest difference %.3g, tolerance %.3g)"
              % ("ok" if ok else "FAIL", what, int(mask.sum()), worst, tolerance))
        if not ok:
            self.failures += 1
            k = int(np.argmax(np.where(mask, np.abs(got - expected), -1.0)))
            print("   worst at vertex %d: got %r, expected %r" % (k, float(got[k]), float(expected[k])))

    def true(self, what, condition, detail=""):
        print("%s: %s %s" % ("ok" if condition else "FAIL", what, detail))
        if not condition:
            self.failures += 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case")
    parser.add_argument("--tool", required=True)
    parser.add_argument("--work", required=True)
    a = parser.parse_args()
    os.makedirs(a.work, exist_ok=True)
    work = lambda name: os.path.join(a.work, name)
    mesh = work("grid.off")
    V = write_grid(mesh)
    P = V[:, :2]
    check = Checker()
    closed = POLYGON + [POLYGON[0]]
    polygon_distance = polyline_distance(P, closed)
    inside = inside_polygon(P, POLYGON)
    on_curve = polygon_distance <= 1e-9  # no sign there

    if a.case in ("polygon", "polygon_pvtp", "signed", "signed_cw"):
        curve = closed if a.case != "signed_cw" else closed[::-1]
        write_curves(work("polygon.txt"), [curve])
        extra = {"polygon": [], "polygon_pvtp": ["--method", "pvtp", "--threads", "2"]}.get(a.case, ["--signed"])
        run_tool(a.tool, [mesh, "--source-curve", work("polygon.txt"), "--output", work("d.txt")] + extra)
        d = read_values(work("d.txt"))
        if a.case.startswith("polygon"):
            check.close("distance to the closed polygon = Euclidean (%s)" % (" ".join(extra) or "vtp"), d,
                        polygon_distance)
        else:
            sign = np.where(inside, -1.0, 1.0) * (1.0 if a.case == "signed" else -1.0)
            check.close("signed distance: |value| = Euclidean distance to the polygon", np.abs(d), polygon_distance)
            check.close("signed distance = %s inside" % ("negative" if a.case == "signed" else "positive"),
                        d, sign * polygon_distance, mask=~on_curve)
            check.true("vertices inside and outside both present", inside.sum() > 100 and (~inside).sum() > 100)
    elif a.case == "limit":
        write_curves(work("polygon.txt"), [closed])
        run_tool(a.tool, [mesh, "--source-curve", work("polygon.txt"), "--signed", "--max-distance", "0.1",
                          "--output", work("d.txt")])
        d = read_values(work("d.txt"))
        sign = np.where(inside, -1.0, 1.0)
        clear = np.abs(polygon_distance - 0.1) > 1e-9
        within = polygon_distance < 0.1
        check.close("--max-distance 0.1: the signed distance within it", d, sign * polygon_distance,
                    mask=within & clear & ~on_curve)
        check.true("--max-distance 0.1: inf beyond it", bool(np.all(np.isinf(d[~within & clear]))),
                   "(%d vertices)" % int((~within & clear).sum()))
    elif a.case == "open_signed":
        A, B = (0.2, 0.5), (0.8, 0.5)
        write_curves(work("segment.txt"), [[A, B]])
        run_tool(a.tool, [mesh, "--source-curve", work("segment.txt"), "--output", work("u.txt")])
        run_tool(a.tool, [mesh, "--source-curve", work("segment.txt"), "--signed", "--output", work("s.txt")])
        u, s = read_values(work("u.txt")), read_values(work("s.txt"))
        dist, t = segment_distance(P, A, B)
        check.close("distance to the open segment = Euclidean", u, dist)
        check.close("|signed| = unsigned", np.abs(s), dist)
        interior = (t > 1e-9) & (t < 1 - 1e-9) & (dist > 1e-9)
        left = P[:, 1] > 0.5
        check.close("signed: negative on the left (+y) where the nearest point is inside the segment",
                    s, np.where(left, -dist, dist), mask=interior)
        # beyond the ends (not level with them: there the end and the inside of the segment are equally near)
        ends = (P[:, 0] < A[0] - 1e-9) | (P[:, 0] > B[0] + 1e-9)
        check.true("signed: positive where the nearest point is an end", bool(np.all(s[ends] > 0)),
                   "(%d vertices)" % int(ends.sum()))
    elif a.case == "border":
        run_tool(a.tool, [mesh, "--source-border", "--output", work("u.txt")])
        run_tool(a.tool, [mesh, "--source-border", "--signed", "--output", work("s.txt")])
        u, s = read_values(work("u.txt")), read_values(work("s.txt"))
        sides = np.min([P[:, 0], 1 - P[:, 0], P[:, 1], 1 - P[:, 1]], axis=0)
        check.close("--source-border = distance to the square's sides", u, sides)
        check.close("--source-border --signed = minus that (the surface is on the border's left)", s, -sides)
    elif a.case == "labels":
        v = 70 * N + 10                                  # an interior vertex, near (0.125, 0.875)
        point = (0.86, 0.14)
        two = [[(0.1, 0.5), (0.15, 0.62), (0.12, 0.8)], [(0.45, 0.93), (0.6, 0.9)]]  # open curves
        third = [(0.88, 0.45), (0.9, 0.6), (0.86, 0.8), (0.88, 0.45)]                  # closed
        write_curves(work("two.txt"), two)
        write_curves(work("third.txt"), [third])
        write_curves(work("polygon.txt"), [closed])
        run_tool(a.tool, [mesh, "--source-curve", work("two.txt"), "--source", str(v), "--source-border",
                          "--source-point", "%r,%r,0" % point, "--source-curve", work("polygon.txt"),
                          "--source-curve", work("third.txt"),
                          "--output", work("d.txt"), "--labels", work("l.txt")])
        d = read_values(work("d.txt"))
        labels = read_values(work("l.txt")).astype(int)
        # the order of the labels: --source, --source-point, the curves of the files in their order, the border
        each = np.array([np.linalg.norm(P - V[v, :2], axis=1), np.linalg.norm(P - np.array(point), axis=1),
                         polyline_distance(P, two[0]), polyline_distance(P, two[1]), polygon_distance,
                         polyline_distance(P, third), np.min([P[:, 0], 1 - P[:, 0], P[:, 1], 1 - P[:, 1]], axis=0)])
        check.close("distance = the least of the seven sources", d, each.min(axis=0))
        ordered = np.sort(each, axis=0)
        clear = ordered[1] - ordered[0] > 1e-9
        expected = np.argmin(each, axis=0)
        check.true("labels: the nearest source, numbered --source, --source-point, curves, border",
                   bool(np.all(labels[clear] == expected[clear])),
                   "(%d clear vertices, %d differ; every label present: %s)"
                   % (int(clear.sum()), int((labels[clear] != expected[clear]).sum()),
                      sorted(set(labels[clear].tolist())) == list(range(7))))
    elif a.case == "offset_curves":
        write_curves(work("polygon.txt"), [closed])
        levels = (0.05, 0.125)
        run_tool(a.tool, [mesh, "--source-curve", work("polygon.txt"), "--levels", "%r,%r" % levels,
                          "--curves-output", work("offsets.obj")])
        points, groups = [], {}
        group = None
        with open(work("offsets.obj")) as f:
            for line in f:
                w = line.split()
                if w and w[0] == "v":
                    points.append([float(x) for x in w[1:4]])
                elif w and w[0] == "g":
                    group = w[1]
                elif w and w[0] == "l":
                    groups.setdefault(group, set()).update(int(k) - 1 for k in w[1:])
        points = np.array(points)
        for level in levels:
            name = [g for g in groups if g.startswith("level_") and abs(float(g[6:]) - level) < 1e-15]
            check.true("an isoline group at level %r" % level, len(name) == 1)
            if len(name) == 1:
                k = sorted(groups[name[0]])
                check.close("offset curve at %r: every point at that distance from the polygon" % level,
                            polyline_distance(points[k, :2], closed), np.full(len(k), level), tolerance=1e-9)
    else:
        sys.exit("unknown case " + a.case)
    if check.failures:
        sys.exit("%d check(s) failed" % check.failures)
    print("done")


if __name__ == "__main__":
    main()
