#!/usr/bin/env python3
"""The meshes and curves of the side-by-side with the signed heat method (issue 47, item 5;
doc/VTP_geodesics/source_curves_anchor.txt). Each writes an OFF mesh and a curve file: 0-based vertex indices, one
per line, each joined to the next by a mesh edge and the last to the first (a closed loop; the format of
curve_heat_comparison and of the anchor driver's curve_heat mode).

  curve_cases.py cube N OUT.off OUT.curve
      the unit cube, N x N squares a side split along alternating diagonals, faces outward; the ring z = 0.5
      (N even) around its four sides walked (0,0,.5) (1,0,.5) (1,1,.5) (0,1,.5): counter-clockwise seen from +z,
      the top on its left.
  curve_cases.py grid N JITTER SEED LO HI OUT.off OUT.curve
      N x N vertices on [0,1]^2 (z = 0, faces counter-clockwise, normal +z), spacing h = 1/(N-1); the interior
      vertices moved by uniform(-JITTER h, JITTER h) in x and y (JITTER <= 0.25 keeps every triangle positive);
      quads split along alternating diagonals. The loop runs along the grid lines (mesh edges) of rows and
      columns LO and HI: (LO,LO) (HI,LO) (HI,HI) (LO,HI), counter-clockwise, its inside on its left.
  curve_cases.py sphere NLON NLAT R OUT.off OUT.curve [START]
      a UV sphere of radius R: two poles and NLAT - 1 rings of NLON vertices (NLAT even: the ring at latitude 0
      exists), quads split along alternating diagonals, caps of triangles; the loop is the equator walked
      eastward (counter-clockwise seen from +z, the north on its left), starting at its vertex START (default 0).
  curve_cases.py points MESH.off CURVE OUT.txt
      the closed curve CURVE of MESH as the points `X Y Z` of `vtp_geodesics --source-curve` (its first point
      repeated last: closed).
"""
import math
import random
import sys


def write_off(path, points, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in points:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in faces:
            f.write("3 %d %d %d\n" % tuple(t))


def write_curve(path, ids):
    with open(path, "w") as f:
        for i in ids:
            f.write("%d\n" % i)


def quad(faces, a, b, c, d, alt):
    """the quad a b c d (counter-clockwise seen from outside) as two triangles, along a-c or b-d"""
    if alt:
        faces += [(a, b, c), (a, c, d)]
    else:
        faces += [(a, b, d), (b, c, d)]


def cube(n):
    index, points, faces = {}, [], []

    def vid(i, j, k):
        key = (i, j, k)
        if key not in index:
            index[key] = len(points)
            points.append((i / n, j / n, k / n))
        return index[key]

    # each side: origin o, in-plane steps u and v with u x v = the outward normal
    sides = [((0, 0, 0), (0, 1, 0), (1, 0, 0)),  # z = 0, normal -z
             ((0, 0, n), (1, 0, 0), (0, 1, 0)),  # z = 1, normal +z
             ((0, 0, 0), (1, 0, 0), (0, 0, 1)),  # y = 0, normal -y
             ((0, n, 0), (0, 0, 1), (1, 0, 0)),  # y = 1, normal +y
             ((0, 0, 0), (0, 0, 1), (0, 1, 0)),  # x = 0, normal -x
             ((n, 0, 0), (0, 1, 0), (0, 0, 1))]  # x = 1, normal +x
    for o, u, v in sides:
        def at(a, b):
            return vid(*(o[c] + a * u[c] + b * v[c] for c in range(3)))
        for a in range(n):
            for b in range(n):
                quad(faces, at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1), (a + b) % 2 == 0)
    k = n // 2
    ring = [vid(i, 0, k) for i in range(n)] + [vid(n, j, k) for j in range(n)] + \
           [vid(n - i, n, k) for i in range(n)] + [vid(0, n - j, k) for j in range(n)]
    return points, faces, ring


def grid(n, jitter, seed, lo, hi):
    rng = random.Random(seed)
    h = 1.0 / (n - 1)
    points = []
    for j in range(n):
        for i in range(n):
            x, y = i * h, j * h
            if 0 < i < n - 1 and 0 < j < n - 1:
                x += rng.uniform(-jitter, jitter) * h
                y += rng.uniform(-jitter, jitter) * h
            points.append((x, y, 0.0))
    faces = []
    for j in range(n - 1):
        for i in range(n - 1):
            quad(faces, j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i, (i + j) % 2 == 0)
    ring = [lo * n + i for i in range(lo, hi)] + [j * n + hi for j in range(lo, hi)] + \
           [hi * n + i for i in range(hi, lo, -1)] + [j * n + lo for j in range(hi, lo, -1)]
    return points, faces, ring


def sphere(nlon, nlat, r, start):
    points = [(0.0, 0.0, r)]  # north pole
    for a in range(1, nlat):
        lat = math.pi / 2 - math.pi * a / nlat
        z = 0.0 if 2 * a == nlat else r * math.sin(lat)
        for b in range(nlon):
            lon = 2 * math.pi * b / nlon
            points.append((r * math.cos(lat) * math.cos(lon), r * math.cos(lat) * math.sin(lon), z))
    points.append((0.0, 0.0, -r))  # south pole
    south = len(points) - 1

    def ring(a, b):  # vertex b of ring a (1 .. nlat-1)
        return 1 + (a - 1) * nlon + b % nlon

    faces = []
    for b in range(nlon):
        faces.append((0, ring(1, b), ring(1, b + 1)))
        faces.append((south, ring(nlat - 1, b + 1), ring(nlat - 1, b)))
    for a in range(1, nlat - 1):
        for b in range(nlon):
            # seen from outside, counter-clockwise: south-west, south-east, north-east, north-west
            quad(faces, ring(a + 1, b), ring(a + 1, b + 1), ring(a, b + 1), ring(a, b), (a + b) % 2 == 0)
    eq = nlat // 2
    loop = [ring(eq, start + b) for b in range(nlon)]
    return points, faces, loop


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    kind = argv[1]
    if kind == "cube" and len(argv) == 5:
        n = int(argv[2])
        if n % 2:
            sys.exit("cube: N must be even (the ring z = 0.5 must be a ring of vertices)")
        pts, fcs, loop = cube(n)
        out_off, out_curve = argv[3], argv[4]
    elif kind == "grid" and len(argv) == 9:
        n, jit, seed, lo, hi = int(argv[2]), float(argv[3]), int(argv[4]), int(argv[5]), int(argv[6])
        if not (0 <= jit <= 0.25 and 0 <= lo < hi < n):
            sys.exit("grid: need JITTER in [0, 0.25] and 0 <= LO < HI < N")
        pts, fcs, loop = grid(n, jit, seed, lo, hi)
        out_off, out_curve = argv[7], argv[8]
    elif kind == "points" and len(argv) == 5:
        with open(argv[2]) as f:
            toks = [t for line in f for t in line.split("#", 1)[0].split()]
        nv = int(toks[1])
        pts = [tuple(toks[4 + 3 * i:7 + 3 * i]) for i in range(nv)]
        with open(argv[3]) as f:
            loop = [int(t) for t in f.read().split()]
        with open(argv[4], "w") as f:
            for i in loop + loop[:1]:
                f.write("%s %s %s\n" % pts[i])
        print("%s: %d points" % (argv[4], len(loop) + 1))
        return
    elif kind == "sphere" and len(argv) in (7, 8):
        nlon, nlat, r = int(argv[2]), int(argv[3]), float(argv[4])
        if nlat % 2 or nlat < 4 or nlon < 3:
            sys.exit("sphere: NLAT must be even and >= 4, NLON >= 3")
        pts, fcs, loop = sphere(nlon, nlat, r, int(argv[7]) if len(argv) == 8 else 0)
        out_off, out_curve = argv[5], argv[6]
    else:
        sys.exit(__doc__)
    write_off(out_off, pts, fcs)
    write_curve(out_curve, loop)
    print("%s: %d vertices, %d faces; %s: %d curve vertices" % (out_off, len(pts), len(fcs), out_curve, len(loop)))


if __name__ == "__main__":
    main(sys.argv)
