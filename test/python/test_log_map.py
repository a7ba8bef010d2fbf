# The log map of the Python module: Solver.log_map() against the Euclidean polar coordinates of a flat jittered
# grid (from a vertex, from a point of a face, with reference directions, several sources), exp(log(v)) = v on
# the elephant (trace(c, log[v] / rho[v], rho[v]) ends at v for every vertex with via -1, whose geodesic passes
# through no vertex), strict against the default, PVTP against VTP, a repaired mesh, bad input, and the tool's
# --log-map-output against the module.

import subprocess
import warnings

import numpy as np
import pytest

import vtp_geodesics
from conftest import data_file, plane_grid


def angle(a):
    return np.arctan2(a[..., 1], a[..., 0])


def angle_difference(a, b):
    return (a - b + np.pi) % (2 * np.pi) - np.pi


def frame_of_face(V, F, f):
    """The frame of F[f]: x along F[f][0] -> F[f][1], y towards F[f][2] (that of trace() in a face)."""
    q = V[F[f]]
    x = (q[1] - q[0]) / np.linalg.norm(q[1] - q[0])
    y = q[2] - q[0] - ((q[2] - q[0]) @ x) * x
    return x, y / np.linalg.norm(y)


@pytest.fixture(scope="module")
def plane():
    V, F = plane_grid(13, 13, jitter=0.3, seed=5)
    return V, F, vtp_geodesics.Solver(V, F)


def test_plane_from_a_vertex(plane):
    V, F, s = plane
    c = 6 * 13 + 6
    d = V - V[c]
    # with a reference direction (1, 0, 0): the Euclidean coordinates themselves
    x, via = s.log_map(c, reference=[1., 0., 0.], return_via=True)
    assert x.shape == (V.shape[0], 2) and x.dtype == np.float64 and via.dtype == np.int64
    assert np.abs(x - d[:, :2]).max() < 1e-12
    assert (via == -1).all()  # the plane is convex: no geodesic turns at a vertex
    assert (x[c] == 0.).all()
    # (1, 1, 5) projects to (1, 1): theta turns by -pi / 4
    x2 = s.log_map(c, reference=[1., 1., 5.])
    far = np.linalg.norm(d, axis=1) > 1e-9
    assert np.abs(angle_difference(angle(x2[far]), angle(d[far]) - np.pi / 4)).max() < 1e-12
    # the default frame (an edge at c): one rotation of the Euclidean coordinates, rho the distance
    x0 = s.log_map(c)
    assert np.abs(np.linalg.norm(x0, axis=1) - np.linalg.norm(d, axis=1)).max() < 1e-12
    turn = angle_difference(angle(x0[far]), angle(d[far]))
    assert np.abs(angle_difference(turn, turn[0])).max() < 1e-12
    # strict is the same here
    assert np.abs(s.log_map(c, reference=[1., 0., 0.], strict=True) - x).max() < 1e-12


def test_plane_from_a_point_of_a_face(plane):
    V, F, s = plane
    f = 150
    b = np.array([0.2, 0.5, 0.3])
    p = b @ V[F[f]]
    d = V - p
    ux, uy = frame_of_face(V, F, f)
    x = s.log_map(points=(np.array([f]), b.reshape(1, 3)))
    assert np.abs(x[:, 0] - d @ ux).max() < 1e-12 and np.abs(x[:, 1] - d @ uy).max() < 1e-12
    # the same point given as xyz; with a reference direction
    x2 = s.log_map(points=p.reshape(1, 3), reference=[0., 1., 0.])
    assert np.abs(angle_difference(angle(x2), angle(d) - np.pi / 2)).max() < 1e-12


def test_plane_several_sources_and_limit(plane):
    V, F, s = plane
    sources = [14, 150]
    p = np.array([0.7, 0.3, 0.])
    x = s.log_map(sources, points=p.reshape(1, 3), reference=[1., 0., 0.])
    centres = np.array([V[14], V[150], p])
    dist = np.linalg.norm(V[:, None, :] - centres[None, :, :], axis=2)
    order = np.sort(dist, axis=1)
    nearest = dist.argmin(axis=1)
    clear = order[:, 1] - order[:, 0] > 1e-9
    expected = V[:, :2] - centres[nearest, :2]
    assert clear.sum() > V.shape[0] // 2
    assert np.abs(x[clear] - expected[clear]).max() < 1e-12
    # a limit: inf beyond, the full run's coordinates within
    r = 0.2
    xr = s.log_map(sources, points=p.reshape(1, 3), reference=[1., 0., 0.], max_distance=r)
    inside = order[:, 0] < r - 1e-12
    outside = order[:, 0] > r + 1e-12
    assert np.array_equal(xr[inside], x[inside]) and np.isinf(xr[outside]).all()


def test_exp_of_log_on_the_elephant(elephant):
    # every vertex with via -1, all of them: exactly those whose traced path passes through no vertex, and
    # trace(c, log[v] / rho[v], rho[v]) ends at v to 1e-9 of the largest distance (issue 46: a geodesic that
    # grazes a vertex w, tied with the path through w, used to get via -1 and the straight line's theta, and the
    # walk left the line at w: 17 of 443 from vertex 0; now via is w there)
    V, F, s = elephant
    for source in [0, 3, 1000, (100, np.array([0.2, 0.3, 0.5]))]:
        if isinstance(source, tuple):
            f, b = source
            kw = dict(sources=[], points=(np.array([f]), b.reshape(1, 3)))
        else:
            kw = dict(sources=source)
        x, via = s.log_map(return_via=True, **kw)
        rho = np.linalg.norm(x, axis=1)
        assert np.abs(rho - s.distances(**kw)).max() < 1e-12
        largest = rho.max()
        reached = np.flatnonzero(rho > 0.)
        if source == 0:  # (one run per path: from one source; the C++ test does it from all five)
            through = np.array([(s.path(int(v), return_locations=True, **kw)[2][1:-1] > 1. - 1e-12).any()
                                for v in reached])
            assert np.array_equal(via[reached] == -1, ~through)
        ends = reached[via[reached] == -1]
        assert ends.size > 100
        if source == 0:
            assert ends.size == 426  # (443 before the fix, 17 of them not reached)
        n = ends.size
        directions = x[ends] / rho[ends, None]
        if isinstance(source, tuple):
            paths, _, _ = s.trace((np.full(n, f), np.tile(b, (n, 1))), directions, rho[ends])
        else:
            paths, _, _ = s.trace(np.full(n, source), directions, rho[ends])
        errors = np.array([np.linalg.norm(q[-1] - V[v]) for q, v in zip(paths, ends)])
        assert errors.max() <= 1e-9 * largest, "worst %g at vertex %d" % (errors.max() / largest,
                                                                          ends[errors.argmax()])


def test_strict_and_default(elephant):
    V, F, s = elephant
    x, via = s.log_map(3, return_via=True)
    xs, vias = s.log_map(3, strict=True, return_via=True)
    assert np.array_equal(via, vias)
    rho = np.linalg.norm(x, axis=1)
    assert np.abs(np.linalg.norm(xs, axis=1) - rho).max() < 1e-12
    direct = via == -1
    assert np.abs(x[direct] - xs[direct]).max() < 1e-12 * rho.max()
    behind = np.flatnonzero(via >= 0)
    assert behind.size > 100  # the elephant has saddles: most of it lies behind one
    # strict: behind s, the theta of s
    assert np.abs(angle_difference(angle(xs[behind]), angle(xs[via[behind]]))).max() < 1e-9
    # the default goes on from s's coordinates: not the same angle
    assert (np.abs(angle_difference(angle(x[behind]), angle(xs[behind]))) > 1e-3).sum() > behind.size // 4
    # the via vertex is nearer to the source
    assert (rho[via[behind]] < rho[behind]).all()


def test_several_sources_relative_to_the_nearest(elephant):
    V, F, s = elephant
    sources = [3, 1500]
    x, via = s.log_map(sources, return_via=True)
    d, labels = s.distances(sources, return_labels=True)
    assert np.abs(np.linalg.norm(x, axis=1) - d).max() < 1e-12
    singles = [s.log_map(c, return_via=True) for c in sources]
    single_d = [s.distances(c) for c in sources]
    compared = 0
    for k in range(2):
        other = single_d[1 - k]
        mine = (labels == k) & (other - single_d[k] > 1e-9 * d.max()) & (via == -1) & (singles[k][1] == -1)
        assert np.abs(x[mine] - singles[k][0][mine]).max() < 1e-12 * d.max()
        compared += mine.sum()
    assert compared > V.shape[0] // 10


@pytest.mark.skipif("pvtp" not in vtp_geodesics.methods, reason="built without OpenMP")
def test_pvtp_equals_vtp(elephant):
    V, F, s = elephant
    for strict in (False, True):
        x, via = s.log_map(0, strict=strict, return_via=True)
        xp, viap = s.log_map(0, strict=strict, return_via=True, method="pvtp", threads=3)
        assert np.array_equal(via, viap)
        rho = np.linalg.norm(x, axis=1)
        differ = (np.abs(angle_difference(angle(x), angle(xp))) > 1e-9) & (rho > 0)
        assert differ.sum() == 0 if strict else differ.sum() <= V.shape[0] // 1000 + 1


def test_repaired_mesh():
    # two tetrahedra sharing vertex 0 (a non-manifold vertex, split by the repair), and vertex 7 in no face
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1], [5, 5, 5]], float)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = vtp_geodesics.Solver(V, F)
    x, via = s.log_map(1, return_via=True)
    d = s.distances(1)
    assert np.abs(np.linalg.norm(x[np.isfinite(d)], axis=1) - d[np.isfinite(d)]).max() < 1e-12
    assert np.isinf(x[[4, 5, 6, 7]]).all() and (via[[4, 5, 6, 7]] == -1).all()
    assert (x[1] == 0).all() and ((via >= -1) & (via < 8)).all()
    # from the split vertex: both tetrahedra, each relative to its own copy
    x0 = s.log_map(0)
    assert np.isfinite(x0[:7]).all() and np.abs(np.linalg.norm(x0[1:7], axis=1) - 1.).max() < 1e-12


def test_isolated_source_vertex():
    # a tetrahedron and vertex 4 in no face (a valid mesh, no repair): the isolated source is at 0, reaches nothing
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [5, 5, 5]], float)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    s = vtp_geodesics.Solver(V, F)
    x = s.log_map(4)
    assert (x[4] == 0.).all() and np.isinf(x[:4]).all()
    x = s.log_map([4, 1])
    assert (x[4] == 0.).all() and (x[1] == 0.).all()
    assert np.abs(np.linalg.norm(x[[0, 2, 3]], axis=1) - s.distances(1)[[0, 2, 3]]).max() < 1e-12


@pytest.mark.parametrize("kwargs, error, message", [
    (dict(method="avtp"), ValueError, "vtp"),
    (dict(method="vsp"), ValueError, "vtp"),
    (dict(method="dijkstra"), ValueError, "unknown method"),
    (dict(reference=[0., 0., 0.]), ValueError, "reference"),
    (dict(reference=[np.nan, 0., 1.]), ValueError, "reference"),
    (dict(reference=[1., 0.]), ValueError, "reference"),
    (dict(sources=10 ** 7), ValueError, "out of range"),
    (dict(sources=[]), ValueError, "no source"),
    (dict(max_distance=-1.), ValueError, "max_distance"),
    (dict(strict="yes"), TypeError, "strict"),
    (dict(sources=1.5), TypeError, "sources"),
])
def test_bad_input(elephant, kwargs, error, message):
    _V, _F, s = elephant
    with pytest.raises(error, match=message):
        s.log_map(**kwargs)


def test_reference_orthogonal_to_the_plane(plane):
    _V, _F, s = plane
    with pytest.raises(ValueError, match="reference direction"):
        s.log_map(84, reference=[0., 0., 1.])


def test_tool_log_map_output(tool, tmp_path, elephant):
    V, F, s = elephant
    out = tmp_path / "log_map.txt"
    for strict in (False, True):
        subprocess.run([tool, data_file("elephant.off"), "--source", "7", "--log-map-output", str(out)]
                       + (["--log-map-strict"] if strict else []), check=True, capture_output=True)
        rows = [line.split() for line in out.read_text().splitlines()]
        assert len(rows) == V.shape[0]
        rho = np.array([float(r[0]) for r in rows])
        theta = np.array([float(r[1]) for r in rows])
        via_tool = np.array([int(r[2]) for r in rows])
        x, via = s.log_map(7, strict=strict, return_via=True)
        assert np.array_equal(rho, s.distances(7))
        assert np.array_equal(via_tool, via)
        assert ((theta >= 0) & (theta < 2 * np.pi)).all()
        reached = rho > 0
        assert np.abs(angle_difference(theta[reached], angle(x[reached]))).max() < 1e-12
