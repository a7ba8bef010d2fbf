# The module against the C++ tool (bit for bit), analytic cases, and the invariants of the API: labels, limit,
# targets, paths, matrices, statistics, input conversions.

import inspect
import math
import os
import subprocess
import sys

import numpy as np
import pytest
import scipy.sparse

import vtp_geodesics
from conftest import cylinder, data_file, plane_grid, read_tool_labels, read_tool_text


@pytest.mark.parametrize("mesh,sources,method,extra", [
    ("elephant.off", [0], "vtp", []),
    ("elephant.off", [3, 1000, 2000], "pvtp", ["--threads", "2"]),
    ("mech-holes-shark.off", [17], "vtp", ["--max-distance", "0.5"]),
    ("three_peaks.off", [5, 77], "avtp", []),
    ("elephant.off", [0, 500], "vsp", []),
    ("elephant.off", [0, 500], "vsp2", []),
])
def test_equals_tool_bit_for_bit(tool, tmp_path, mesh, sources, method, extra):
    out, labels = tmp_path / "d.txt", tmp_path / "l.txt"
    cmd = [tool, data_file(mesh), "--source", ",".join(map(str, sources)), "--method", method,
           "--output", str(out), "--labels", str(labels)] + extra
    subprocess.run(cmd, check=True, capture_output=True)
    V, F = vtp_geodesics.read_mesh(data_file(mesh))
    solver = vtp_geodesics.Solver(V, F)
    limit = float(extra[extra.index("--max-distance") + 1]) if "--max-distance" in extra else math.inf
    threads = int(extra[extra.index("--threads") + 1]) if "--threads" in extra else 0
    d, lab = solver.distances(sources, method=method, max_distance=limit, threads=threads, return_labels=True)
    expected = read_tool_text(out)
    assert d.dtype == np.float64 and d.shape == expected.shape
    assert np.array_equal(d, expected)          # bit for bit, inf included
    assert np.array_equal(lab, read_tool_labels(labels))


def test_source_point_equals_tool(tool, tmp_path):
    V, F = vtp_geodesics.read_mesh(data_file("elephant.off"))
    xyz = 0.3 * V[10] + 0.3 * V[20] + 0.4 * V[30] + np.array([0.01, 0.0, 0.0])
    out = tmp_path / "d.txt"
    subprocess.run([tool, data_file("elephant.off"), "--source-point", ",".join(repr(float(c)) for c in xyz),
                    "--output", str(out)], check=True, capture_output=True)
    solver = vtp_geodesics.Solver(V, F)
    assert np.array_equal(solver.distances(points=xyz), read_tool_text(out))
    # the same point given as (faces, barycentric)
    faces, bary = solver.locate(xyz)
    assert np.array_equal(solver.distances(points=(faces, bary)), read_tool_text(out))


def test_plane_is_euclidean():
    V, F = plane_grid(21, 17, jitter=0.3)
    solver = vtp_geodesics.Solver(V, F)
    for s in (0, 150, 300):
        d = solver.distances(s)
        exact = np.linalg.norm(V - V[s], axis=1)
        assert np.max(np.abs(d - exact)) <= 1e-12
    # a source at a point inside a face
    faces, bary = np.array([40]), np.array([[0.2, 0.5, 0.3]])
    p = bary[0] @ V[F[40]]
    d = solver.distances(points=(faces, bary))
    assert np.max(np.abs(d - np.linalg.norm(V - p, axis=1))) <= 1e-12


def test_cylinder_unrolled():
    n_around, n_up, r, h = 24, 9, 1.0, 2.0
    V, F = cylinder(n_around, n_up, r, h)
    solver = vtp_geodesics.Solver(V, F)
    chord = 2 * r * math.sin(math.pi / n_around)
    s = 4 * n_around + 3  # a vertex in the middle row
    d = solver.distances(s)
    k = np.arange(len(V))
    around = np.abs(k % n_around - s % n_around)
    around = np.minimum(around, n_around - around)
    exact = np.hypot(around * chord, V[:, 2] - V[s, 2])
    assert np.max(np.abs(d - exact)) <= 1e-12


def test_labels_are_nearest_source(elephant):
    V, F, solver = elephant
    sources = [5, 900, 2100]
    d, labels = solver.distances(sources, return_labels=True)
    single = np.array([solver.distances(s) for s in sources])
    assert np.allclose(d, single.min(axis=0), rtol=0, atol=1e-12)
    assert labels.dtype == np.int64
    assert np.all(labels >= 0)
    assert np.allclose(single[labels, np.arange(len(V))], d, rtol=0, atol=1e-12)
    # vertices first, then points
    faces, bary = np.array([100]), np.array([[1 / 3, 1 / 3, 1 / 3]])
    d2, labels2 = solver.distances([5], points=(faces, bary), return_labels=True)
    assert set(np.unique(labels2)) == {0, 1}
    d_point = solver.distances(points=(faces, bary))
    assert np.allclose(d2, np.minimum(single[0], d_point), rtol=0, atol=1e-12)


def test_limit(elephant):
    V, F, solver = elephant
    full = solver.distances(7)
    R = 0.25 * full.max()
    d, labels = solver.distances(7, max_distance=R, return_labels=True)
    inside = full <= R
    assert np.array_equal(d[inside], full[inside])
    assert np.all(np.isinf(d[~inside]))
    assert np.all(labels[~inside] == -1)
    assert solver.statistics["stopped_early"]


def test_targets(elephant):
    V, F, solver = elephant
    full = solver.distances(11)
    targets = [12, 40, 300]
    d = solver.distances(11, targets=targets)
    assert np.array_equal(d[targets], full[targets])
    finite = np.isfinite(d)
    assert np.array_equal(d[finite], full[finite])
    assert solver.statistics["stopped_early"]


def test_path_length_is_distance(elephant):
    V, F, solver = elephant
    full = solver.distances(0)
    for t in (500, 1500, 2700):
        P, faces, bary = solver.path(t, sources=0, return_locations=True)
        assert P.shape[1] == 3 and P.shape[0] >= 2 and faces.shape == (P.shape[0],) and bary.shape == P.shape
        assert np.array_equal(P[0], V[0]) and np.array_equal(P[-1], V[t])  # from the source to the target
        length = np.linalg.norm(np.diff(P, axis=0), axis=1).sum()
        assert abs(length - full[t]) <= 1e-9 * max(1.0, full[t])
        # the locations denote the same points
        Q = np.einsum("ij,ijk->ik", bary, V[F[faces]])
        assert np.allclose(Q, P, rtol=0, atol=1e-12)
        assert abs(solver.distance(0, t) - full[t]) <= 1e-12 * max(1.0, full[t])


def test_path_to_point_and_distance_between_points(elephant):
    V, F, solver = elephant
    a = (np.int64(50), [0.2, 0.3, 0.5])
    b = V[1234] * 1.0
    da = solver.distances(points=(np.array([50]), np.array([[0.2, 0.3, 0.5]])))
    assert abs(solver.distance(a, 1234) - da[1234]) <= 1e-12
    P = solver.path(b, points=(np.array([50]), np.array([[0.2, 0.3, 0.5]])))
    assert abs(np.linalg.norm(np.diff(P, axis=0), axis=1).sum() - da[1234]) <= 1e-9


def test_matrix_rows_equal_single_runs(elephant):
    V, F, solver = elephant
    rows = [0, 17, 17, 2000]
    M = solver.matrix(rows)
    assert M.dtype == np.float64 and M.shape == (4, len(V))
    for i, s in enumerate(rows):
        assert np.array_equal(M[i], solver.distances(s))
    cols = [3, 1, 4, 1, 5]
    Mt = solver.matrix(rows, targets=cols, threads=1)
    assert np.array_equal(Mt, M[:, cols])
    M32 = solver.matrix(rows, dtype=np.float32)
    assert M32.dtype == np.float32 and np.array_equal(M32, M.astype(np.float32))


def test_matrix_sparse_equals_dense_inside_limit(elephant):
    V, F, solver = elephant
    rows = np.arange(0, len(V), 97)
    dense = solver.matrix(rows)
    R = 0.2
    S = solver.matrix(rows, max_distance=R)
    assert isinstance(S, scipy.sparse.csr_matrix) and S.shape == dense.shape and S.dtype == np.float64
    inside = dense <= R
    assert S.nnz == inside.sum()
    assert np.all(S.data <= R)
    rr, cc = S.nonzero() if False else (np.repeat(np.arange(S.shape[0]), np.diff(S.indptr)), S.indices)
    assert np.array_equal(S.data, dense[rr, cc])
    assert np.array_equal(np.sort(np.flatnonzero(inside)), np.sort(rr * dense.shape[1] + cc))
    S32 = solver.matrix(rows, max_distance=R, dtype=np.float32)
    assert S32.dtype == np.float32 and np.array_equal(S32.data, S.data.astype(np.float32))


def test_methods_and_statistics(elephant):
    V, F, solver = elephant
    exact = solver.distances(0)
    assert np.allclose(solver.distances(0, method="pvtp", threads=2), exact, rtol=1e-12, atol=1e-12)
    approx = solver.distances(0, method="avtp", lam=2.0)
    assert np.all(approx >= exact - 1e-12)
    st = solver.statistics
    assert st["method"] == "avtp" and st["vertices"] == len(V) and st["windows_propagated"] > 0
    assert {"round_selection_seconds", "round_propagation_seconds", "round_merge_seconds", "seconds",
            "preprocessing_seconds", "mesh_build_seconds"} <= set(st)
    assert tuple(st) == vtp_geodesics.statistics_keys  # every key, in the order of the description
    assert set(vtp_geodesics.methods) >= {"vtp", "pvtp", "avtp", "pavtp", "vsp", "pvsp"}
    # one virtual source per vertex: every distance is a path length (never below exact), the same on 2 threads
    vsp = solver.distances(0, method="vsp")
    assert np.all(vsp >= exact - 1e-12 * exact.max())
    assert np.mean((vsp[1:] - exact[1:]) / exact[1:]) < 0.02
    assert solver.statistics["method"] == "vsp"
    assert np.array_equal(solver.distances(0, method="pvsp", threads=2), vsp)
    # two per vertex: still an upper bound, more accurate, the same on 2 threads
    vsp2 = solver.distances(0, method="vsp2")
    assert np.all(vsp2 >= exact - 1e-12 * exact.max())
    assert solver.statistics["method"] == "vsp2"
    assert np.mean((vsp2[1:] - exact[1:]) / exact[1:]) < np.mean((vsp[1:] - exact[1:]) / exact[1:])
    assert np.array_equal(solver.distances(0, method="pvsp2", threads=2), vsp2)


def test_array_likes_are_converted(elephant):
    V, F, solver = elephant
    reference = solver.distances(9)
    for V2, F2 in [(V.astype(np.float32).astype(np.float64), F.astype(np.int32)),
                   (np.asfortranarray(V), np.asfortranarray(F.astype(np.uint32))),
                   (np.hstack([V, V])[:, ::2], F.tolist())]:
        d = vtp_geodesics.Solver(V2, F2).distances(np.int32(9))
        assert np.array_equal(d, vtp_geodesics.Solver(np.ascontiguousarray(V2, dtype=np.float64), F).distances(9))
    assert np.array_equal(vtp_geodesics.Solver(V.tolist(), F).distances(9), reference)


def test_read_mesh_repairs_with_a_warning(tmp_path):
    # a quad split into two triangles by the reader's triangulation
    p = tmp_path / "quads.off"
    p.write_text("OFF\n6 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n4 0 1 4 3\n4 1 2 5 4\n")
    with pytest.warns(UserWarning, match="triangulated"):
        V, F = vtp_geodesics.read_mesh(str(p))
    assert V.dtype == np.float64 and F.dtype == np.int64 and F.shape == (4, 3)
    d = vtp_geodesics.Solver(V, F).distances(0)
    assert np.allclose(d, np.linalg.norm(V - V[0], axis=1), rtol=0, atol=1e-12)
    with pytest.raises(FileNotFoundError):
        vtp_geodesics.read_mesh(str(tmp_path / "none.off"))
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(ValueError):
        vtp_geodesics.read_mesh(str(bad))


def test_docstrings():
    for obj in [vtp_geodesics, vtp_geodesics.Solver, vtp_geodesics.read_mesh, vtp_geodesics.Solver.distances,
                vtp_geodesics.Solver.path, vtp_geodesics.Solver.distance, vtp_geodesics.Solver.matrix,
                vtp_geodesics.Solver.locate, vtp_geodesics.Solver.statistics]:
        assert obj.__doc__ and len(obj.__doc__) > 40


def test_lambda_defaults_to_the_recommended_one():
    assert vtp_geodesics.recommended_lambda == vtp_geodesics._core.recommended_lambda > 0
    for f in [vtp_geodesics.Solver.distances, vtp_geodesics.Solver.distance, vtp_geodesics.Solver.matrix,
              vtp_geodesics.Solver.farthest_point_sampling]:
        assert inspect.signature(f).parameters["lam"].default == vtp_geodesics.recommended_lambda


def test_matrix_progress_on_stderr(elephant, capsys):
    V, F, solver = elephant
    M = solver.matrix([0, 1, 2], progress=True)
    assert "3 / 3 rows" in capsys.readouterr().err
    assert np.array_equal(M[2], solver.distances(2))


def test_statistics_while_a_matrix_runs():
    # statistics from another thread while a matrix runs: it waits for the matrix without holding the GIL, which
    # the matrix takes every 0.2 s to check for Ctrl-C (holding it, both waited for ever). In a child process, so
    # that a deadlock fails the test instead of hanging it.
    script = "\n".join([
        "import threading, time",
        "import vtp_geodesics",
        "from conftest import plane_grid",
        "V, F = plane_grid(30, 30)",
        "solver = vtp_geodesics.Solver(V, F, threads=2)",
        "done = threading.Event()",
        "def read():",
        "    while not done.is_set():",
        "        solver.statistics",
        "        time.sleep(0.01)",
        "reader = threading.Thread(target=read)",
        "reader.start()",
        "solver.matrix(list(range(len(V))) * 2, dtype='float32')",
        "done.set()",
        "reader.join()",
        "print(solver.statistics['method'])",
    ])
    here = os.path.dirname(os.path.abspath(__file__))
    r = subprocess.run([sys.executable, "-c", script], cwd=here, capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "vtp"
