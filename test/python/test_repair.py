# Solver(V, F) on arrays that are not a valid mesh (a pinch vertex, non-manifold edges, duplicate and degenerate
# faces, coincident vertices, flipped faces, a vertex in no face): repaired as the tool repairs the same file,
# every result on the caller's indices, equal to the tool's on that file; repair=False raises the error; the
# drop-ins; through_pinches against distances computed on each sheet.

import math
import subprocess
import warnings

import numpy as np
import pytest

import vtp_geodesics
from conftest import plane_grid, read_tool_labels, read_tool_text
from vtp_geodesics import gdist
from vtp_geodesics import pygeodesic


def rotation(axis, angle):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def pinch_mesh():
    """Two jittered grids touching at one vertex (vertex 24, the centre of the first): a non-manifold vertex;
    plus a vertex in no face (the last one)."""
    A, FA = plane_grid(7, 7, jitter=0.3, seed=1)
    B, FB = plane_grid(7, 7, jitter=0.3, seed=2)
    B = (B - B[24]) @ rotation([1, 2, 3], 1.1).T + A[24]
    keep = np.arange(49) != 24                          # B's centre is A's vertex 24
    index_b = np.full(49, -1)
    index_b[keep] = 49 + np.arange(48)
    index_b[24] = 24
    V = np.vstack([A, B[keep], [[5.0, 5.0, 5.0]]])
    F = np.vstack([FA, index_b[FB]])
    return V, F


def book_mesh():
    """Three pages (grids) around a common edge (the side x = 0 of the first): non-manifold edges."""
    A, FA = plane_grid(5, 6, jitter=0.0)
    V = [A]
    F = [FA]
    on_spine = A[:, 0] == 0
    for k in (1, 2):
        R = rotation([0, 1, 0], 2 * math.pi * k / 3 + 0.1)
        P = A @ R.T
        index = np.arange(len(A))
        new = ~on_spine
        index[new] = sum(len(v) for v in V) + np.arange(new.sum())
        V.append(P[new])
        F.append(index[FA] if k == 1 else index[FA][:, ::-1])
    return np.vstack(V), np.vstack(F)


def messy_mesh():
    """A jittered grid with every other face flipped, duplicate faces (same and opposite orientation),
    degenerate faces, a vertex coincident with vertex 10 used by some of its faces, and a vertex in no face."""
    V, F = plane_grid(8, 8, jitter=0.3, seed=3)
    F = F.copy()
    F[1::2] = F[1::2, ::-1]
    n = len(V)
    V = np.vstack([V, V[10], [[3.0, -1.0, 2.0]]])
    uses = np.nonzero((F == 10).any(axis=1))[0][:2]
    F[uses] = np.where(F[uses] == 10, n, F[uses])
    F = np.vstack([F, F[:3], F[3:5, ::-1], [[0, 0, 1], [5, 9, 5]]])
    return V, F


MESHES = {"pinch": pinch_mesh, "book": book_mesh, "messy": messy_mesh}
SOURCES = {"pinch": [[24], [3], [3, 70]], "book": [[0], [2], [7, 40]], "messy": [[10], [0], [64, 20]]}


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        for p in V:
            f.write("%r %r %r\n" % tuple(float(c) for c in p))
        for t in F:
            f.write("3 %d %d %d\n" % tuple(t))


def solver_of(V, F, **kw):
    with pytest.warns(UserWarning, match="repaired"):
        return vtp_geodesics.Solver(V, F, **kw)


@pytest.mark.parametrize("name", sorted(MESHES))
def test_repair_false_raises_the_error(name):
    V, F = MESHES[name]()
    with pytest.raises(ValueError, match="manifold|repeated vertex"):
        vtp_geodesics.Solver(V, F, repair=False)


@pytest.mark.parametrize("name", sorted(MESHES))
def test_warning_says_what_was_repaired(name):
    V, F = MESHES[name]()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        solver = vtp_geodesics.Solver(V, F)
    messages = [str(w.message) for w in caught if issubclass(w.category, UserWarning)]
    assert len(messages) == 1 and solver.repairs and solver.repairs in messages[0]
    expected = {"pinch": "non-manifold vertex", "book": "non-manifold edge", "messy": "reoriented"}[name]
    assert expected in solver.repairs
    if name == "messy":
        assert "removed" in solver.repairs and "merged 1 duplicate point" in solver.repairs
    assert solver.number_of_vertices == len(V) and solver.number_of_faces == len(F)


@pytest.mark.parametrize("name", sorted(MESHES))
@pytest.mark.parametrize("k", [0, 1, 2])
def test_distances_and_labels_equal_the_tool(tool, tmp_path, name, k):
    V, F = MESHES[name]()
    sources = SOURCES[name][k]
    off = tmp_path / "m.off"
    write_off(off, V, F)
    out, labels = tmp_path / "d.txt", tmp_path / "l.txt"
    subprocess.run([tool, str(off), "--source", ",".join(map(str, sources)), "--output", str(out), "--labels",
                    str(labels)], check=True, capture_output=True)
    d, lab = solver_of(V, F).distances(sources, return_labels=True)
    expected = read_tool_text(out)
    assert d.shape == (len(V),)
    assert np.array_equal(d, expected)                     # bit for bit, on the caller's vertices
    assert np.array_equal(lab, read_tool_labels(labels))
    assert d[len(V) - 1] == math.inf or name == "book"      # the vertex in no face
    # read_mesh(repair=False) gives the file's own vertices and faces: the same arrays, the same distances
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        V2, F2 = vtp_geodesics.read_mesh(off, repair=False)
    assert np.array_equal(V2, V) and np.array_equal(F2, F)
    assert np.array_equal(solver_of(V2, F2).distances(sources), expected)


def test_split_source_is_all_its_copies():
    V, F = pinch_mesh()
    solver = solver_of(V, F)
    begin, copies = solver.vertex_copies()
    assert begin[25] - begin[24] == 2                       # the pinch: two copies
    assert begin[len(V)] - begin[len(V) - 1] == 0           # the vertex in no face: none
    d = solver.distances(24)
    assert d[24] == 0 and np.all(np.isfinite(d[:-1]))        # both sheets reached from the pinch
    # from vertex 3 (first sheet), the second sheet is apart: not reached
    d3 = solver.distances(3)
    assert np.all(np.isfinite(d3[:49])) and np.all(np.isinf(d3[49:]))
    # a dropped source: 0 at itself, nothing else
    dd = solver.distances(len(V) - 1)
    assert dd[-1] == 0 and np.all(np.isinf(dd[:-1]))


@pytest.mark.parametrize("name", sorted(MESHES))
def test_targets_and_limit(tool, tmp_path, name):
    V, F = MESHES[name]()
    solver = solver_of(V, F)
    s = SOURCES[name][0][0]
    full = solver.distances(s)
    targets = [1, 24, len(V) - 2, len(V) - 1]
    d = solver.distances(s, targets=targets)
    assert np.array_equal(d[targets], full[targets])
    limit = np.nanmax(full[np.isfinite(full)]) / 2
    dl = solver.distances(s, max_distance=limit)
    assert np.array_equal(dl, np.where(full <= limit, full, math.inf))
    for t in targets:
        assert solver.distance(s, t) == full[t]


@pytest.mark.parametrize("name", sorted(MESHES))
def test_paths_on_caller_indices(tool, tmp_path, name):
    V, F = MESHES[name]()
    solver = solver_of(V, F)
    s = SOURCES[name][0][0]
    d = solver.distances(s)
    reached = [t for t in range(len(V)) if np.isfinite(d[t]) and t != s][::7]
    off, paths = tmp_path / "m.off", tmp_path / "p.txt"
    write_off(off, V, F)
    subprocess.run([tool, str(off), "--source", str(s), "--path-to", ",".join(map(str, reached)), "--path-output",
                    str(paths)], check=True, capture_output=True)
    tool_paths = [np.array([float(x) for x in line.split()[1:]]).reshape(-1, 3) for line in open(paths)]
    for t, tp in zip(reached, tool_paths):
        P, faces, bary = solver.path(t, sources=s, return_locations=True)
        assert np.allclose(P[0], V[s], atol=1e-12) and np.allclose(P[-1], V[t], atol=1e-12)
        length = np.linalg.norm(np.diff(P, axis=0), axis=1).sum()
        assert length == pytest.approx(d[t], rel=1e-9, abs=1e-12)
        # the locations are faces of F with barycentric coordinates of F's corners
        assert np.all(faces >= 0) and np.all(faces < len(F))
        assert np.allclose(np.einsum("ki,kij->kj", bary, V[F[faces]]), P, atol=1e-9)
        assert np.array_equal(P, tp[::-1])                   # the tool's path, from the target
    if name != "book":                                       # the vertex in no face
        with pytest.raises(ValueError, match="no face"):
            solver.path(len(V) - 1, sources=s)


@pytest.mark.parametrize("name", sorted(MESHES))
def test_points_and_locate(tool, tmp_path, name):
    V, F = MESHES[name]()
    solver = solver_of(V, F)
    xyz = 0.2 * V[F[5, 0]] + 0.3 * V[F[5, 1]] + 0.5 * V[F[5, 2]]
    faces, bary = solver.locate(xyz)
    assert np.allclose(bary[0] @ V[F[faces[0]]], xyz, atol=1e-12)
    off, out = tmp_path / "m.off", tmp_path / "d.txt"
    write_off(off, V, F)
    subprocess.run([tool, str(off), "--source-point", ",".join(repr(float(c)) for c in xyz), "--output", str(out)],
                   check=True, capture_output=True)
    assert np.array_equal(solver.distances(points=xyz), read_tool_text(out))
    # the same point as face 5 of F and its barycentric coordinates: the same distances to rounding
    d5 = solver.distances(points=([5], [[0.2, 0.3, 0.5]]))
    assert np.allclose(d5, read_tool_text(out), rtol=1e-12, atol=1e-12)
    if name == "messy":
        with pytest.raises(ValueError, match="removed it as degenerate"):
            solver.distances(points=([len(F) - 1], [[0.2, 0.3, 0.5]]))


@pytest.mark.parametrize("name", sorted(MESHES))
def test_matrices_are_rows_of_distances(name):
    V, F = MESHES[name]()
    solver = solver_of(V, F)
    rows = [SOURCES[name][0][0], 1, len(V) - 1, 24]
    M = solver.matrix(rows)
    for i, s in enumerate(rows):
        assert np.array_equal(M[i], solver.distances(s))
    cols = [0, 24, len(V) - 1, 5]
    assert np.array_equal(solver.matrix(rows, targets=cols), M[:, cols])
    limit = np.nanmax(M[np.isfinite(M)]) / 3
    S = solver.matrix(rows, max_distance=limit)
    dense = S.toarray()
    within = M <= limit
    assert S.nnz == within.sum() and np.array_equal(dense[within], M[within])
    M32 = solver.matrix(rows, dtype=np.float32)
    assert np.array_equal(M32, M.astype(np.float32))


@pytest.mark.parametrize("name", sorted(MESHES))
def test_sampling_equals_the_tool(tool, tmp_path, name):
    V, F = MESHES[name]()
    off, samples, out, labels = tmp_path / "m.off", tmp_path / "s.txt", tmp_path / "d.txt", tmp_path / "l.txt"
    write_off(off, V, F)
    subprocess.run([tool, str(off), "--farthest-points", "6", "--first", "1", "--samples-output", str(samples),
                    "--output", str(out), "--labels", str(labels)], check=True, capture_output=True)
    lines = [l.split() for l in open(samples) if not l.startswith("#")]
    r = solver_of(V, F).farthest_point_sampling(6, first=1)
    assert r.samples.tolist() == [int(l[0]) for l in lines]
    assert r.radii.tolist() == [float(l[1]) for l in lines]
    assert np.array_equal(r.distances, read_tool_text(out))
    assert np.array_equal(r.labels, read_tool_labels(labels))


def test_dropins_repair_and_keep_indices():
    V, F = pinch_mesh()
    expected = solver_of(V, F).distances([3, 70])
    with pytest.warns(UserWarning, match="repaired"):
        d = gdist.compute_gdist(V, F.astype(np.int32), np.array([3, 70], dtype=np.int32))
    assert np.array_equal(d, expected)
    with pytest.warns(UserWarning, match="repaired"):
        d = gdist.compute_gdist(V, F.astype(np.int32) + 1, np.array([3, 70], dtype=np.int32),
                                np.array([0, 24, 96], dtype=np.int32), is_one_indexed=True)
    assert np.array_equal(d, expected[[0, 24, 96]])
    solver = solver_of(V, F)
    with pytest.warns(UserWarning, match="repaired"):
        M = gdist.local_gdist_matrix(V, F.astype(np.int32), max_distance=0.3)
    row = solver.distances(24)
    near = np.nonzero((row <= 0.3) & (np.arange(len(V)) != 24))[0]
    assert M.shape == (len(V), len(V)) and M[24].nnz == len(near)
    assert np.allclose(M[24].toarray()[0, near], row[near], rtol=1e-12)   # the symmetric minimum, to rounding
    with pytest.warns(UserWarning, match="repaired"):
        alg = pygeodesic.PyGeodesicAlgorithmExact(V, F)
    d, best = alg.geodesicDistances(np.array([3, 70]))
    assert np.array_equal(d, expected) and best.dtype == np.int32 and best[-1] == -1
    length, path = alg.geodesicDistance(3, 30)
    assert length == solver.distance(3, 30)
    assert np.allclose(path[0], V[30]) and np.allclose(path[-1], V[3])
    assert np.linalg.norm(np.diff(path, axis=0), axis=1).sum() == pytest.approx(length, rel=1e-9)


def sheet_distances(V, F, keep_vertices, source):
    """Distances on the sub-mesh of the faces whose vertices are all in keep_vertices, from `source`."""
    faces = F[np.all(np.isin(F, keep_vertices), axis=1)]
    return vtp_geodesics.Solver(V, faces).distances(source)


def test_through_pinches_joins_the_sheets():
    V, F = pinch_mesh()
    apart = solver_of(V, F)
    joined = solver_of(V, F, through_pinches=True)
    sheet_a = np.arange(49)
    sheet_b = np.r_[24, 49:97]
    for s in (3, 70):
        d_apart = apart.distances(s)
        d = joined.distances(s)
        assert np.all(d <= d_apart)
        home, other = (sheet_a, sheet_b) if s < 49 else (sheet_b, sheet_a)
        assert np.array_equal(d[home], d_apart[home])
        # across: to the pinch on the home sheet, then from the pinch on the other sheet
        across = d[24] + sheet_distances(V, F, other, 24)
        assert np.allclose(d[other], across[other], rtol=1e-12, atol=1e-12)
        assert d[len(V) - 1] == math.inf
        assert joined.distance(s, other[5]) == d[other[5]]
    d, lab = joined.distances([3, 70], return_labels=True)
    assert np.array_equal(d, np.minimum(joined.distances(3), joined.distances(70)))
    assert set(lab[:-1].tolist()) <= {0, 1} and lab[-1] == -1
    with pytest.raises(ValueError, match="through_pinches"):
        joined.path(60, sources=3)
    with pytest.raises(ValueError, match="through_pinches"):
        joined.matrix([3])
    with pytest.raises(ValueError, match="through_pinches"):
        joined.distance(3, (5, [0.2, 0.3, 0.5]))
    # a valid mesh: through_pinches changes nothing
    Vg, Fg = plane_grid(6, 6)
    assert np.array_equal(vtp_geodesics.Solver(Vg, Fg, through_pinches=True).distances(3),
                          vtp_geodesics.Solver(Vg, Fg).distances(3))


@pytest.mark.parametrize("name", sorted(MESHES))
def test_through_pinches_equals_the_tool(tool, tmp_path, name):
    V, F = MESHES[name]()
    sources = SOURCES[name][2]
    off, out, labels = tmp_path / "m.off", tmp_path / "d.txt", tmp_path / "l.txt"
    write_off(off, V, F)
    subprocess.run([tool, str(off), "--through-pinches", "--source", ",".join(map(str, sources)), "--output", str(out),
                    "--labels", str(labels)], check=True, capture_output=True)
    d, lab = solver_of(V, F, through_pinches=True).distances(sources, return_labels=True)
    assert np.array_equal(d, read_tool_text(out)) and np.array_equal(lab, read_tool_labels(labels))
    assert np.all(d <= solver_of(V, F).distances(sources))
    # with a limit: the joined field, limited
    limit = np.max(d[np.isfinite(d)]) / 2
    subprocess.run([tool, str(off), "--through-pinches", "--source", ",".join(map(str, sources)), "--max-distance",
                    repr(limit), "--output", str(out)], check=True, capture_output=True)
    assert np.array_equal(read_tool_text(out), np.where(d <= limit, d, math.inf))
    r = subprocess.run([tool, str(off), "--through-pinches", "--path-to", "5", "--path-output", str(out)],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "--through-pinches takes no --path-to" in r.stderr


def test_through_pinches_against_a_dijkstra_over_the_pinches():
    """Three grids: A and B touch at two vertices, B and C at one. The joined distance of a vertex is the least,
    over the pinches, of the distance of the pinch plus the distance on the sheet, where the distances of the
    pinches come from Dijkstra's algorithm on the graph of pinches and the distances within each sheet."""
    grids = [plane_grid(6, 6, jitter=0.25, seed=s) for s in (4, 5, 6)]
    frames = [rotation([0, 0, 1], 0.0), rotation([1, 2, 3], 1.3), rotation([3, -1, 2], 2.1)]
    # pinches: (sheet, vertex of its grid) glued together: the second sheet's faces use the first's vertex (the
    # second's own is then in no face)
    glue = [((0, 14), (1, 7)), ((0, 21), (1, 28)), ((1, 22), (2, 15))]
    offsets = [0, 36, 72]
    V = np.vstack([g[0] @ R.T + 10 * k for k, (g, R) in enumerate(zip(grids, frames))])
    index = np.arange(108)
    for (a, va), (b, vb) in glue:
        index[offsets[b] + vb] = offsets[a] + va
    F = np.vstack([index[g[1] + o] for g, o in zip(grids, offsets)])
    joined = solver_of(V, F, through_pinches=True)
    s = 3                                                    # in sheet A
    d = joined.distances(s)
    # the oracle: per sheet, distances from the source and from each pinch of the sheet
    sheets = [np.unique(index[np.arange(36) + o]) for o in offsets]
    pinches = sorted(set(int(index[offsets[a] + va]) for (a, va), _ in glue))
    def on_sheet(k, src):
        return sheet_distances(V, F, sheets[k], src)
    best = {p: math.inf for p in pinches}
    for p in pinches:
        if p in sheets[0]:
            best[p] = on_sheet(0, s)[p]
    done = set()
    while len(done) < len(pinches):                          # Dijkstra over the pinches
        p = min((q for q in pinches if q not in done), key=lambda q: best[q])
        done.add(p)
        for k in range(3):
            if p in sheets[k]:
                dk = on_sheet(k, p)
                for q in pinches:
                    if q in sheets[k]:
                        best[q] = min(best[q], best[p] + dk[q])
    expected = np.full(len(V), math.inf)
    expected[sheets[0]] = on_sheet(0, s)[sheets[0]]
    for p in pinches:
        for k in range(3):
            if p in sheets[k]:
                expected[sheets[k]] = np.minimum(expected[sheets[k]], best[p] + on_sheet(k, p)[sheets[k]])
    reached = np.isfinite(expected)
    assert np.array_equal(reached, np.isfinite(d)) and reached[sheets[2]].all()
    assert np.allclose(d[reached], expected[reached], rtol=1e-12, atol=1e-12)
    assert 2 <= joined._core.join_runs <= 3                  # one run per pinch reached whose copies differ
