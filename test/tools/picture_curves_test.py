#!/usr/bin/env python3
# Copyright (c) 2026  VTP_geodesics contributors.
# All rights reserved.
#
# This file is part of the tests of the VTP_geodesics package.
#
# SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
#
# Author(s) : VTP_geodesics contributors

"""The curves that `vtp_geodesics --picture` draws are those of the library (geodesic_curves.h), not a linear
interpolation of the vertex distances: on a coarse plane mesh, where the isolines of a source are circles and the
border of two cells is their bisector, the pixels that the picture darkens lie within a pixel of the projection of
the exact curve. (A linear interpolation of the vertex distances on faces of 100 pixels is off the circles by
many pixels near the source.)

    picture_curves_test.py isolines|borders --tool VTP_GEODESICS --work DIR

The PNG is read with matplotlib; the camera is found from the picture itself: the plane [0,1]^2 seen along -z
fills a square of the picture (its non-white pixels left of the colour bar).
"""

import argparse
import math
import os
import subprocess
import sys

import numpy as np
import matplotlib.image

GRID = 8  # squares per side: faces of about 100 pixels


def write_plane(path):
    """[0,1]^2 in GRID x GRID squares, each cut by a diagonal (alternating), z = 0."""
    n = GRID
    lines = ["OFF", "%d %d 0" % ((n + 1) ** 2, 2 * n * n)]
    for j in range(n + 1):
        for i in range(n + 1):
            lines.append("%.17g %.17g 0" % (i / n, j / n))
    for j in range(n):
        for i in range(n):
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            if (i + j) % 2 == 0:
                lines += ["3 %d %d %d" % (a, b, c), "3 %d %d %d" % (a, c, d)]
            else:
                lines += ["3 %d %d %d" % (a, b, d), "3 %d %d %d" % (b, c, d)]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def run(tool, *args):
    p = subprocess.run([tool] + [str(a) for a in args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        sys.exit("FAIL: %s exited with %d: %s" % (" ".join([tool] + list(map(str, args))), p.returncode, p.stderr))


def read_png(path):
    img = matplotlib.image.imread(path)
    return np.rint(np.asarray(img[:, :, :3], dtype=np.float64) * 255.)


def camera(img):
    """The plane's square in the picture: (x0, y0, pixels per unit); a point (X, Y) of the plane is at pixel
    coordinates (x0 + X s, y0 + (1 - Y) s) (pixel centres at i + 0.5)."""
    h, w, _ = img.shape
    drawn = np.any(img < 255, axis=2)
    drawn[:, w - 200:] = False  # the colour bar's panel
    ys, xs = np.nonzero(drawn)
    x0, x1, y0, y1 = xs.min(), xs.max() + 1, ys.min(), ys.max() + 1
    if abs((x1 - x0) - (y1 - y0)) > 1:
        sys.exit("FAIL: the plane is not drawn as a square (%d x %d pixels)" % (x1 - x0, y1 - y0))
    return float(x0), float(y0), float(x1 - x0)


def plane_points(pixels, cam):
    x0, y0, s = cam
    ys, xs = pixels
    return (xs + 0.5 - x0) / s, 1. - (ys + 0.5 - y0) / s


def far_from(X, Y, points, cam, radius_px):
    keep = np.ones(X.shape, dtype=bool)
    for p in points:
        keep &= np.hypot(X - p[0], Y - p[1]) * cam[2] > radius_px
    return keep


def inside_length(f, samples=20000):
    """Length of the part of a parametrized curve t in [0, 1) -> (x, y) inside [0,1]^2 (sampled)."""
    t = np.arange(samples) / samples
    x, y, speed = f(t)
    inside = (x > 0) & (x < 1) & (y > 0) & (y < 1)
    return float(np.sum(speed[inside]) / samples)


def levels_of_obj(path):
    levels, points, group = [], [], None
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "g" and w[1].startswith("level_"):
                levels.append(float(w[1][len("level_"):]))
            elif w and w[0] == "v":
                points.append([float(x) for x in w[1:4]])
    return levels, np.array(points)


def check_isolines(tool, work, mesh):
    source = (0.43, 0.37)
    common = [mesh, "--source-point", "%g,%g,0" % source, "--view", "0,0,-1"]
    lines_png, plain_png, obj = (os.path.join(work, n) for n in ("isolines.png", "plain.png", "isolines.obj"))
    run(tool, *common, "--picture", lines_png, "--isolines", 8, "--curves-output", obj)
    run(tool, *common, "--picture", plain_png, "--isolines", 0)
    levels, points = levels_of_obj(obj)
    if len(levels) < 4:
        sys.exit("FAIL: %d levels in %s" % (len(levels), obj))
    radii = np.hypot(points[:, 0] - source[0], points[:, 1] - source[1])
    off = np.min(np.abs(radii[:, None] - np.array(levels)[None, :]), axis=1)
    if off.max() > 1e-9:
        sys.exit("FAIL: a point of --curves-output is %g off its circle" % off.max())

    lines, plain = read_png(lines_png), read_png(plain_png)
    cam = camera(plain)
    # The isolines darken the colours (to 0.22 on the line): pixels darkened by more than 40%.
    darkened = np.sum(lines, axis=2) < 0.6 * np.sum(plain, axis=2)
    darkened[:, lines.shape[1] - 200:] = False
    X, Y = plane_points(np.nonzero(darkened), cam)
    keep = far_from(X, Y, [source], cam, 12.)
    X, Y = X[keep], Y[keep]
    r = np.hypot(X - source[0], Y - source[1])
    to_level = np.abs(r[:, None] - np.array(levels)[None, :]) * cam[2]
    nearest = np.argmin(to_level, axis=1)
    off_px = to_level[np.arange(len(r)), nearest]
    if len(off_px) == 0 or off_px.max() > 1.0:
        sys.exit("FAIL: a darkened pixel is %.2f pixels off the circles of the levels (%d pixels)"
                 % (off_px.max() if len(off_px) else float("nan"), len(off_px)))
    for k, level in enumerate(levels):
        length = inside_length(lambda t: (source[0] + level * np.cos(2 * math.pi * t),
                                          source[1] + level * np.sin(2 * math.pi * t),
                                          np.full(t.shape, 2 * math.pi * level))) * cam[2]
        drawn = int(np.sum(nearest == k))
        if length > 30 and drawn < 0.7 * length:
            sys.exit("FAIL: level %g: %d darkened pixels for an arc of %.0f pixels" % (level, drawn, length))
    print("isolines: %d levels, %d darkened pixels, all within %.2f pixels of their circle"
          % (len(levels), len(off_px), off_px.max()))


def check_borders(tool, work, mesh):
    a, b = (0.3, 0.4), (0.72, 0.61)
    png = os.path.join(work, "borders.png")
    run(tool, mesh, "--source-point", "%g,%g,0" % a, "--source-point", "%g,%g,0" % b, "--view", "0,0,-1",
        "--picture", png, "--picture-colour", "labels")
    img = read_png(png)
    cam = camera(img)
    # The cells are light colours; the border darkens them to 0.22: dark pixels.
    dark = np.max(img, axis=2) < 100
    dark[:, img.shape[1] - 200:] = False
    X, Y = plane_points(np.nonzero(dark), cam)
    keep = far_from(X, Y, [a, b], cam, 12.)
    X, Y = X[keep], Y[keep]
    # the bisector: points equidistant from a and b
    nx, ny = b[0] - a[0], b[1] - a[1]
    norm = math.hypot(nx, ny)
    mx, my = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    off_px = np.abs((X - mx) * nx + (Y - my) * ny) / norm * cam[2]
    if len(off_px) == 0 or off_px.max() > 1.0:
        sys.exit("FAIL: a dark pixel is %.2f pixels off the bisector (%d pixels)"
                 % (off_px.max() if len(off_px) else float("nan"), len(off_px)))
    tx, ty = -ny / norm, nx / norm
    length = inside_length(lambda t: (mx + (t - 0.5) * 4 * tx, my + (t - 0.5) * 4 * ty, np.full(t.shape, 4.))) * cam[2]
    if len(off_px) < 0.7 * length:
        sys.exit("FAIL: %d dark pixels for a border of %.0f pixels" % (len(off_px), length))
    # The colours of the cells meet on the border: one colour on each side, beyond 2 pixels from it (and from the
    # markers), not the corner's label of the faces it crosses.
    ys, xs = np.nonzero(np.ones(img.shape[:2], dtype=bool))
    X, Y = plane_points((ys, xs), cam)
    inside = (X > 0) & (X < 1) & (Y > 0) & (Y < 1) & far_from(X, Y, [a, b], cam, 12.)
    side = ((X - mx) * nx + (Y - my) * ny) / norm * cam[2]
    colours = []
    for region in (inside & (side < -2.), inside & (side > 2.)):
        c = np.unique(img[ys[region], xs[region]].reshape(-1, 3), axis=0)
        if len(c) != 1:
            sys.exit("FAIL: %d colours on one side of the border (one cell)" % len(c))
        colours.append(tuple(c[0]))
    if colours[0] == colours[1]:
        sys.exit("FAIL: both cells have the colour %s" % (colours[0],))
    print("borders: %d dark pixels, all within %.2f pixels of the bisector; one colour on each side"
          % (len(off_px), off_px.max()))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case", choices=["isolines", "borders"])
    parser.add_argument("--tool", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    mesh = os.path.join(args.work, "plane.off")
    write_plane(mesh)
    (check_isolines if args.case == "isolines" else check_borders)(args.tool, args.work, mesh)


if __name__ == "__main__":
    main()
