# Straightest geodesics (the exp map) of the Python module: Solver.trace() against the straight segment of the
# plane, the unrolled line of a prism, exp(log(v)) = v on the elephant (from a point of a face along the first
# segment of v's exact path), batches = single walks, threads, bad input, and the tool's --trace.

import subprocess

import numpy as np
import pytest

import vtp_geodesics
from conftest import cylinder, data_file, plane_grid


def point_of(V, F, face, bary):
    return np.asarray(bary) @ V[F[face]]


def face_and_bary(V, F, p):
    """A face of the plane z = 0 containing p strictly inside, and p's barycentric coordinates in it."""
    for f, t in enumerate(F):
        a, b, c = V[t, :2]
        m = np.array([b - a, c - a]).T
        l1, l2 = np.linalg.solve(m, p[:2] - a)
        bary = np.array([1 - l1 - l2, l1, l2])
        if (bary > 1e-9).all():
            return f, bary
    raise AssertionError("no face contains %s" % p)


def test_plane_gives_the_segment():
    V, F = plane_grid(21, 21, jitter=0.3, seed=4)
    s = vtp_geodesics.Solver(V, F)
    rng = np.random.default_rng(2)
    for _ in range(40):
        p = np.append(rng.uniform(0.35, 0.65, 2), 0.)
        a = rng.uniform(-np.pi, np.pi)
        d = np.array([np.cos(a), np.sin(a), 0.])
        length = rng.uniform(0., 0.3)
        f, b = face_and_bary(V, F, p)
        path, (ef, eb), ed = s.trace((f, b), d, length)
        assert path.shape[1] == 3 and path.dtype == np.float64
        assert np.abs(path[0] - p).max() < 1e-14
        assert np.abs(path[-1] - (p + length * d)).max() < 1e-12
        assert np.abs(point_of(V, F, ef, eb) - path[-1]).max() < 1e-12
        assert np.abs(ed - d).max() < 1e-12
        # the same direction in 2D, in the frame of F[f] (x along F[f][0] -> F[f][1], y towards F[f][2])
        q = V[F[f]]
        x = (q[1] - q[0]) / np.linalg.norm(q[1] - q[0])
        y = np.cross(np.cross(x, q[2] - q[0]), x)
        y /= np.linalg.norm(y)
        path2, _, _ = s.trace((f, b), [d @ x, d @ y], length)
        assert np.abs(path2[-1] - path[-1]).max() < 1e-12
        # from xyz: the nearest surface point (p itself)
        path3, _, _ = s.trace(p, d, length)
        assert np.abs(path3[-1] - path[-1]).max() < 1e-12


def test_border_and_details():
    V, F = plane_grid(11, 11)
    s = vtp_geodesics.Solver(V, F)
    f, b = face_and_bary(V, F, np.array([0.52, 0.47, 0.]))
    path, end, ed, walked, border = s.trace((f, b), [1., 0., 0.], 5., return_details=True)
    assert border and walked == pytest.approx(0.48, abs=1e-12)
    assert path[-1][0] == pytest.approx(1., abs=1e-15)
    assert (np.asarray(end[1]) == 0.).any()  # on an edge of its face
    # length 0: the start
    path, end, ed = s.trace(60, [1., 0.], 0.)
    assert path.shape == (1, 3) and np.array_equal(path[0], V[60])


def test_prism_unrolls():
    n = 16
    V, F = cylinder(n, 9, radius=1., height=4.)
    s = vtp_geodesics.Solver(V, F)
    chord = np.linalg.norm(V[1] - V[0])
    # from the middle of a side face, upwards at 0.1 rad, once around the prism and more
    p = 0.5 * (V[0] + V[1]) + np.array([0., 0., 0.25])
    t = (V[1] - V[0]) / chord
    a = 0.1
    d = np.cos(a) * t + np.sin(a) * np.array([0., 0., 1.])
    length = 1.5 * n * chord / np.cos(a)
    path, _, ed = s.trace(p, d, length)
    assert path[-1][2] == pytest.approx(0.25 + length * np.sin(a), abs=1e-11)
    assert ed[2] == pytest.approx(np.sin(a), abs=1e-12)
    # half a chord further than 1.5 turns round: the middle of the side opposite to the start
    assert np.abs(path[-1][:2] - 0.5 * (V[n // 2] + V[n // 2 + 1])[:2]).max() < 1e-11


def test_exp_of_log_on_the_elephant(elephant):
    V, F, s = elephant
    f = 100
    b = np.array([0.2, 0.3, 0.5])
    rho = s.distances(sources=[], points=(np.array([f]), b.reshape(1, 3)))
    largest = rho[np.isfinite(rho)].max()
    checked = 0
    starts_f, directions, lengths, ends = [], [], [], []
    for v in range(0, V.shape[0], 3):
        P, faces, bary = s.path(v, sources=[], points=(np.array([f]), b.reshape(1, 3)), return_locations=True)
        if len(P) < 2 or (bary[1:-1] == 1.).any():  # through a vertex: skipped
            continue
        starts_f.append(f)
        directions.append(P[1] - P[0])
        lengths.append(rho[v])
        ends.append(v)
    n = len(ends)
    assert n > 100
    paths, _, _ = s.trace((np.full(n, f), np.tile(b, (n, 1))), np.array(directions), np.array(lengths))
    errors = np.array([np.linalg.norm(p[-1] - V[v]) for p, v in zip(paths, ends)])
    checked = (errors <= 1e-9 * largest).sum()
    assert checked == n, "worst %g" % (errors.max() / largest)
    # on two threads: the same
    paths2, _, _ = s.trace((np.full(n, f), np.tile(b, (n, 1))), np.array(directions), np.array(lengths), threads=2)
    assert all(np.array_equal(p, q) for p, q in zip(paths, paths2))


def test_batch_equals_single_walks(elephant):
    V, F, s = elephant
    starts = np.array([0, 5, 77, 300])
    rng = np.random.default_rng(1)
    dirs = rng.normal(size=(4, 2))
    paths, (faces, bary), ed = s.trace(starts, dirs, 0.3)
    assert faces.shape == (4,) and bary.shape == (4, 3) and ed.shape == (4, 3)
    for i in range(4):
        p, (f, b), e = s.trace(int(starts[i]), dirs[i], 0.3)
        assert np.array_equal(p, paths[i]) and f == faces[i] and np.array_equal(b, bary[i])
        assert np.array_equal(e, ed[i]) and abs(np.linalg.norm(e) - 1.) < 1e-12


@pytest.mark.parametrize("start, direction, length, message", [
    (0, [0., 0.], 1., "direction"),
    (0, [np.nan, 1.], 1., "direction"),
    (0, [1., 0.], -1., "length"),
    (0, [1., 0.], np.nan, "length"),
    (0, [1., 0.], np.inf, "length"),
    (10 ** 7, [1., 0.], 1., "out of range"),
    (0, [1., 0., 0., 0.], 1., "direction"),
])
def test_bad_input(elephant, start, direction, length, message):
    _V, _F, s = elephant
    with pytest.raises(ValueError, match=message):
        s.trace(start, direction, length)


def test_tool_trace(tool, tmp_path, elephant):
    V, F, s = elephant
    out = tmp_path / "trace.txt"
    subprocess.run([tool, data_file("elephant.off"), "--trace", "12,0.3,-1,0.2,0.4", "--trace", "40,1,0,0,0.1",
                    "--path-output", str(out)], check=True, capture_output=True)
    lines = out.read_text().splitlines()
    assert len(lines) == 2
    for line, (v, d, length) in zip(lines, [(12, [0.3, -1, 0.2], 0.4), (40, [1., 0., 0.], 0.1)]):
        values = [float(x) for x in line.split()]
        points = np.array(values[1:]).reshape(-1, 3)
        assert int(values[0]) == points.shape[0]
        path, _, _ = s.trace(v, d, length)
        assert points.shape == path.shape and np.abs(points - path).max() < 1e-12
    bad = subprocess.run([tool, data_file("elephant.off"), "--trace", "12,0,0,0,1", "--path-output", str(out)],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "direction" in bad.stderr
