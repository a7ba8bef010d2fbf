# Sources that are curves: Solver.distances(curves=..., source_border=..., signed=...).
#
# On a flat jittered grid of the unit square (z = 0, 81 x 81 vertices, interior vertices moved by less than h / 4,
# counter-clockwise faces), the geodesic distance to a curve of straight pieces is the Euclidean distance to it:
# the expected values are computed from the curves' coordinates alone. Then the module against the tool, bit for
# bit, on the same mesh file and the same curve file (unsigned, signed, the border, mixed sources with labels).

import subprocess
import warnings

import numpy as np
import pytest

import vtp_geodesics

from conftest import plane_grid, read_tool_labels, read_tool_text

POLYGON = [(0.31, 0.29), (0.72, 0.33), (0.69, 0.71), (0.27, 0.66)]  # counter-clockwise
CLOSED = POLYGON + [POLYGON[0]]


def segment_distance(P, a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    t = np.clip(((P - a) @ d) / (d @ d), 0.0, 1.0)
    return np.linalg.norm(P - (a + t[:, None] * d), axis=1), t


def polyline_distance(P, points):
    return np.min([segment_distance(P, points[k], points[k + 1])[0] for k in range(len(points) - 1)], axis=0)


def inside_polygon(P, polygon):
    inside = np.zeros(len(P), dtype=bool)
    for k in range(len(polygon)):
        (x0, y0), (x1, y1) = polygon[k], polygon[(k + 1) % len(polygon)]
        crosses = (y0 > P[:, 1]) != (y1 > P[:, 1])
        with np.errstate(divide="ignore", invalid="ignore"):
            x = x0 + (P[:, 1] - y0) * (x1 - x0) / (y1 - y0)
        inside ^= crosses & (P[:, 0] < x)
    return inside


def xyz(curve):
    return np.array([[x, y, 0.0] for x, y in curve])


@pytest.fixture(scope="module")
def grid():
    V, F = plane_grid(81, 81, jitter=0.25, seed=47)
    return V, F, vtp_geodesics.Solver(V, F)


def test_closed_polygon_euclidean(grid):
    V, F, solver = grid
    d = solver.distances(curves=[xyz(CLOSED)])
    assert np.max(np.abs(d - polyline_distance(V[:, :2], CLOSED))) <= 1e-12


def test_signed_negative_inside(grid):
    V, F, solver = grid
    P = V[:, :2]
    expected = polyline_distance(P, CLOSED)
    inside = inside_polygon(P, POLYGON)
    off = expected > 1e-9
    assert inside.sum() > 100 and (~inside).sum() > 100
    s = solver.distances(curves=[xyz(CLOSED)], signed=True)
    assert np.max(np.abs(np.abs(s) - expected)) <= 1e-12
    assert np.max(np.abs(s - np.where(inside, -expected, expected))[off]) <= 1e-12
    # walked clockwise: the sign flips
    s = solver.distances(curves=[xyz(CLOSED[::-1])], signed=True)
    assert np.max(np.abs(s - np.where(inside, expected, -expected))[off]) <= 1e-12


def test_open_curve_signed(grid):
    V, F, solver = grid
    P = V[:, :2]
    A, B = (0.2, 0.5), (0.8, 0.5)
    dist, t = segment_distance(P, A, B)
    u = solver.distances(curves=[xyz([A, B])])
    assert np.max(np.abs(u - dist)) <= 1e-12
    s = solver.distances(curves=[xyz([A, B])], signed=True)
    interior = (t > 1e-9) & (t < 1 - 1e-9) & (dist > 1e-9)
    assert np.max(np.abs(s - np.where(P[:, 1] > 0.5, -dist, dist))[interior]) <= 1e-12
    # beyond the ends (not level with them: there the end and the inside of the segment are equally near)
    ends = (P[:, 0] < A[0] - 1e-9) | (P[:, 0] > B[0] + 1e-9)
    assert ends.sum() > 100 and np.all(s[ends] > 0)


def test_source_border(grid):
    V, F, solver = grid
    P = V[:, :2]
    sides = np.min([P[:, 0], 1 - P[:, 0], P[:, 1], 1 - P[:, 1]], axis=0)
    assert np.max(np.abs(solver.distances(source_border=True) - sides)) <= 1e-12
    assert np.max(np.abs(solver.distances(source_border=True, signed=True) + sides)) <= 1e-12


def test_curve_as_face_locations(grid):
    # the same polygon given as (faces, barycentric): the same bits as from xyz positions
    V, F, solver = grid
    faces, bary = solver.locate(xyz(CLOSED))
    assert np.array_equal(solver.distances(curves=[(faces, bary)]), solver.distances(curves=[xyz(CLOSED)]))


def test_labels_order(grid):
    V, F, solver = grid
    P = V[:, :2]
    v = 70 * 81 + 10
    point = (0.86, 0.14)
    c1 = [(0.1, 0.5), (0.15, 0.62), (0.12, 0.8)]
    d, labels = solver.distances(v, points=xyz([point]), curves=[xyz(c1), xyz(CLOSED)], source_border=True,
                                 return_labels=True)
    each = np.array([np.linalg.norm(P - V[v, :2], axis=1), np.linalg.norm(P - np.array(point), axis=1),
                     polyline_distance(P, c1), polyline_distance(P, CLOSED),
                     np.min([P[:, 0], 1 - P[:, 0], P[:, 1], 1 - P[:, 1]], axis=0)])
    assert np.max(np.abs(d - each.min(axis=0))) <= 1e-12
    ordered = np.sort(each, axis=0)
    clear = ordered[1] - ordered[0] > 1e-9
    assert np.array_equal(labels[clear], np.argmin(each, axis=0)[clear])
    assert set(labels[clear].tolist()) == set(range(5))


def test_bad_input(grid):
    V, F, solver = grid
    with pytest.raises(ValueError, match="off the surface"):
        solver.distances(curves=[np.array([[0.2, 0.2, 0.0], [0.5, 0.5, 0.3]])])
    with pytest.raises(ValueError, match="at least two distinct points"):
        solver.distances(curves=[np.array([[0.2, 0.2, 0.0]])])
    with pytest.raises(ValueError, match="at least two distinct points"):
        solver.distances(curves=[np.array([[0.2, 0.2, 0.0], [0.2, 0.2, 0.0]])])
    with pytest.raises(ValueError, match="shape"):
        solver.distances(curves=[np.array([0.2, 0.2, 0.0])])
    with pytest.raises(ValueError, match="signed=True needs a source that is a curve"):
        solver.distances(0, signed=True)
    # two closed curves, both counter-clockwise, one inside the other: the ring between them is on the left of
    # the outer one and on the right of the inner one
    outer = [(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9), (0.1, 0.1)]
    inner = [(0.4, 0.4), (0.6, 0.4), (0.6, 0.6), (0.4, 0.6), (0.4, 0.4)]
    with pytest.raises(ValueError, match="not oriented consistently"):
        solver.distances(curves=[xyz(outer), xyz(inner)], signed=True)
    with pytest.raises(ValueError, match="keep_field"):
        solver.distances(curves=[xyz(CLOSED)], keep_field=True, method="avtp")
    with pytest.raises(TypeError, match="list of curves"):
        solver.distances(curves=xyz(CLOSED))
    # a closed surface has no border
    T = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    closed = vtp_geodesics.Solver(T, np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))
    with pytest.raises(ValueError, match="no border"):
        closed.distances(source_border=True)


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        for p in V:
            f.write("%r %r %r\n" % tuple(float(x) for x in p))
        for t in F:
            f.write("3 %d %d %d\n" % tuple(int(x) for x in t))


def write_curves(path, curves):
    with open(path, "w") as f:
        f.write("\n\n".join("\n".join("%r %r %r" % tuple(float(x) for x in p) for p in c) for c in curves) + "\n")


def run_tool(tool, args):
    r = subprocess.run([tool] + args, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stderr == "" or r.stderr.startswith("vtp_geodesics: note: "), r.stderr


@pytest.mark.parametrize("case", ["unsigned", "signed", "border", "border_signed", "mixed", "repaired_signed",
                                  "repaired_mixed"])
def test_python_equals_tool(grid, tool, tmp_path, case):
    V, F, _ = grid
    if case.startswith("repaired"):
        # every other face flipped: the tool and the module repair the file and the arrays alike
        F = F.copy()
        F[::2] = F[::2, ::-1]
        case = case[len("repaired_"):]
    mesh = str(tmp_path / "grid.off")
    write_off(mesh, V, F)
    VF, FF = vtp_geodesics.read_mesh(mesh, repair=False)
    assert np.array_equal(VF, V) and np.array_equal(FF, F)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the repair's note, for the flipped faces
        solver = vtp_geodesics.Solver(VF, FF)
    assert bool(solver.repairs) == (F is not grid[1])
    curves = [xyz(CLOSED), xyz([(0.1, 0.5), (0.15, 0.62), (0.12, 0.8)])]
    write_curves(str(tmp_path / "curves.txt"), curves)
    out, lab = str(tmp_path / "d.txt"), str(tmp_path / "l.txt")
    if case == "unsigned":
        run_tool(tool, [mesh, "--source-curve", str(tmp_path / "curves.txt"), "--output", out])
        expected = solver.distances(curves=curves)
    elif case == "signed":
        write_curves(str(tmp_path / "polygon.txt"), [xyz(CLOSED)])
        run_tool(tool, [mesh, "--source-curve", str(tmp_path / "polygon.txt"), "--signed", "--output", out])
        expected = solver.distances(curves=[xyz(CLOSED)], signed=True)
    elif case == "border":
        run_tool(tool, [mesh, "--source-border", "--output", out])
        expected = solver.distances(source_border=True)
    elif case == "border_signed":
        run_tool(tool, [mesh, "--source-border", "--signed", "--output", out])
        expected = solver.distances(source_border=True, signed=True)
    else:
        run_tool(tool, [mesh, "--source-border", "--source-curve", str(tmp_path / "curves.txt"), "--source", "6000",
                        "--source-point", "0.86,0.14,0", "--output", out, "--labels", lab])
        expected, labels = solver.distances(6000, points=np.array([[0.86, 0.14, 0.0]]), curves=curves,
                                            source_border=True, return_labels=True)
        assert np.array_equal(read_tool_labels(lab), labels)
    got = read_tool_text(out)
    assert got.shape == expected.shape
    assert np.array_equal(got, expected), "largest difference %g" % np.max(np.abs(got - expected))


def test_kept_field_offset_curves(grid):
    """keep_field=True with a curve: the field at random points of the surface is the Euclidean distance to the
    polygon, and its isolines (the offset curves) lie at their level from it, to 1e-12; no cell borders."""
    V, F, solver = grid
    d = solver.distances(curves=[xyz(CLOSED)], keep_field=True)
    assert np.max(np.abs(d - polyline_distance(V[:, :2], CLOSED))) <= 1e-12
    rng = np.random.default_rng(3)
    faces = rng.integers(0, len(F), 500)
    b = rng.dirichlet([1.0, 1.0, 1.0], 500)
    P = np.einsum("ij,ijk->ik", b, V[F[faces]])
    field = solver.field_distance((faces, b))
    assert np.max(np.abs(field - polyline_distance(P[:, :2], CLOSED))) <= 1e-12
    levels = [0.02, 0.05, 0.125]
    curves = solver.field_isolines(levels)
    assert len(curves) >= 3
    for c in curves:
        assert c.level in levels
        assert np.max(np.abs(polyline_distance(c.points[:, :2], CLOSED) - c.level)) <= 1e-12
    # inside and outside: both sides of the polygon at 0.02 and 0.05
    for level in levels[:2]:
        sides = {bool(inside_polygon(c.points[:1, :2], POLYGON)[0]) for c in curves if c.level == level}
        assert sides == {True, False}
    with pytest.raises(ValueError, match="cell borders"):
        solver.field_cell_borders()
