# From a file to the answer: read_mesh() of a valid OFF file (parsed and checked, no halfedge structure built) gives
# the mesh that CGAL's readers give for the same mesh in another format, and the same errors as before; the stages
# in the statistics of the Solver and of the tool add up.

import json
import subprocess

import numpy as np
import pytest

import vtp_geodesics
from conftest import data_file


def write_obj(path, V, F):
    with open(path, "w") as f:
        for p in V:
            f.write("v %r %r %r\n" % tuple(float(c) for c in p))
        for t in F:
            f.write("f %d %d %d\n" % tuple(int(i) + 1 for i in t))


@pytest.mark.parametrize("mesh", ["elephant.off", "elephant-with-holes.off", "mech-holes-shark.off", "knot1.off",
                                  "three_peaks.off"])
def test_fast_off_path_equals_cgal_reader(tmp_path, mesh):
    V, F = vtp_geodesics.read_mesh(data_file(mesh))          # the fast path: parsed and checked
    obj = tmp_path / "mesh.obj"
    write_obj(obj, V, F)
    V2, F2 = vtp_geodesics.read_mesh(str(obj))                 # CGAL's OBJ reader, then the mesh built
    assert V.dtype == V2.dtype == np.float64 and F.dtype == F2.dtype == np.int64
    assert np.array_equal(V, V2) and np.array_equal(F, F2)
    # the same distances as from the arrays of the slow path
    assert np.array_equal(vtp_geodesics.Solver(V, F).distances(0), vtp_geodesics.Solver(V2, F2).distances(0))


@pytest.mark.parametrize("text,message", [
    ("OFF\n3 1 0\n0 0 0\n1 0 0\n", "ends after 2 of 3 vertices"),
    ("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "ends after 1 of 2 faces"),
    ("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "vertex 1 has a non-finite coordinate"),
    ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "face 0 refers to vertex 3, out of range"),
    ("OFF\n0 0 0\n", "no vertices"),
    ("", "empty"),
])
def test_fast_off_path_bad_input(tmp_path, text, message):
    p = tmp_path / "bad.off"
    p.write_text(text)
    with pytest.raises(ValueError, match=message):
        vtp_geodesics.read_mesh(str(p))


def test_fast_off_path_leaves_repairs_to_the_tools_reader(tmp_path):
    # two triangles sharing only vertex 0: not a valid mesh, repaired by duplicating the vertex (with a warning)
    p = tmp_path / "pinched.off"
    p.write_text("OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n")
    with pytest.warns(UserWarning, match="repaired"):
        V, F = vtp_geodesics.read_mesh(str(p))
    assert V.shape == (6, 3) and F.shape == (2, 3)


def check_stages(st, from_read_mesh):
    stages = ["read_seconds", "repair_seconds", "preprocessing_seconds", "propagation_seconds", "write_seconds",
              "other_seconds", "total_seconds", "outside_propagation_ratio"]
    assert set(stages) <= set(st)
    assert st["write_seconds"] == 0                                   # the caller's outputs
    if from_read_mesh:
        # read_mesh()'s reading, and its check of the faces (the Solver's build does not check them again)
        assert st["read_seconds"] > 0 and st["repair_seconds"] > st["mesh_build_seconds"] > 0
    else:
        assert st["read_seconds"] == 0 and st["repair_seconds"] == st["mesh_build_seconds"] > 0
    assert st["propagation_seconds"] == st["seconds"] > 0
    assert st["total_seconds"] == pytest.approx(st["read_seconds"] + st["repair_seconds"]
                                                + st["preprocessing_seconds"] + st["seconds"])
    assert st["outside_propagation_ratio"] == pytest.approx(
        (st["total_seconds"] - st["seconds"]) / st["seconds"])


def test_solver_stages_add_up(elephant):
    V, F, solver = elephant          # read by read_mesh(), then the first Solver on V and F
    solver.distances(0)
    check_stages(solver.statistics, True)


@pytest.mark.parametrize("mesh", ["elephant.off", "elephant-with-holes.off", "mech-holes-shark.off"])
def test_solver_takes_read_mesh_check_once(mesh):
    # the first Solver on read_mesh()'s arrays builds the mesh from read_mesh()'s check of the faces; the
    # second checks them itself: the same mesh (the same bits of distances), and only the first counts the reading
    V, F = vtp_geodesics.read_mesh(data_file(mesh), threads=2)
    first, second = vtp_geodesics.Solver(V, F, threads=2), vtp_geodesics.Solver(V, F, threads=1)
    d1, d2 = first.distances(0), second.distances(0)
    assert d1.tobytes() == d2.tobytes()
    check_stages(first.statistics, True)
    check_stages(second.statistics, False)


def test_solver_on_other_faces_checks_them(tmp_path):
    # arrays changed after read_mesh() (other faces, or another number of vertices): no reading counted, and the
    # check of the new faces is done (an invalid mesh is still found)
    V, F = vtp_geodesics.read_mesh(data_file("elephant.off"))
    G = F.copy()
    G[0] = G[0, ::-1]                                # one face turned over: two faces with the same oriented edge
    with pytest.raises(ValueError, match="not form a manifold"):
        vtp_geodesics.Solver(V, G, repair=False)
    s = vtp_geodesics.Solver(V, F[:, [1, 2, 0]])     # the same triangles, each from its second corner
    s.distances(0)
    check_stages(s.statistics, False)
    V, F = vtp_geodesics.read_mesh(data_file("elephant.off"))
    W = np.vstack([V, [[0., 0., 0.]]])               # one more vertex, in no face
    s = vtp_geodesics.Solver(W, F)
    s.distances(0)
    check_stages(s.statistics, False)
    # a file read by CGAL's reader (OBJ) counts its reading too
    obj = tmp_path / "mesh.obj"
    write_obj(obj, V, F)
    V2, F2 = vtp_geodesics.read_mesh(str(obj))
    s = vtp_geodesics.Solver(V2, F2)
    s.distances(0)
    assert s.statistics["read_seconds"] > 0


def test_tool_stages_add_up(tool, tmp_path):
    out, stats = tmp_path / "d.txt", tmp_path / "s.json"
    subprocess.run([tool, data_file("elephant.off"), "--output", str(out), "--stats-json", str(stats)], check=True,
                   capture_output=True)
    s = json.loads(stats.read_text())
    named = ["read_seconds", "repair_seconds", "preprocessing_seconds", "propagation_seconds", "write_seconds"]
    assert all(s[k] >= 0 for k in named + ["other_seconds"])
    assert s["propagation_seconds"] == s["seconds"] > 0
    assert s["total_seconds"] >= sum(s[k] for k in named)
    assert s["total_seconds"] == pytest.approx(sum(s[k] for k in named) + s["other_seconds"], rel=1e-9)
    assert s["outside_propagation_ratio"] == pytest.approx(
        (s["total_seconds"] - s["propagation_seconds"]) / s["propagation_seconds"], rel=1e-9)
