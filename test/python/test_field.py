# The kept field of the Python module (distances(..., keep_field=True), field_distance(), field_nearest_source(),
# field_bytes, the field_* curves; the C++ keep_field and Geodesic_distance_solver::field_distance()): on a flat
# jittered grid against Euclidean distances; two symmetric cells of the unit square (borders on the diagonal,
# areas 1/2, also through farthest-point sampling); the elephant against targeted exact runs and PVTP; a
# repaired (pinched) mesh on the caller's indices; what replaces the field; bad input; the example.

import doctest
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import vtp_geodesics
from conftest import HERE, plane_grid
from test_repair import pinch_mesh, solver_of


def random_face_points(F, k, seed):
    rng = np.random.default_rng(seed)
    return rng.integers(0, len(F), k), rng.dirichlet([1.0, 1.0, 1.0], k)


def xyz_of(V, F, faces, bary):
    return np.einsum("ij,ijk->ik", bary, V[F[faces]])


def test_plane_field_is_euclidean():
    V, F = plane_grid(15, 13, jitter=0.3, seed=4)
    s = vtp_geodesics.Solver(V, F)
    sources = [3 * 13 + 4, 11 * 13 + 9]
    source_point = (np.array([100]), np.array([[0.2, 0.3, 0.5]]))  # a third source, inside face 100
    centres = np.vstack([V[sources], xyz_of(V, F, *source_point)])
    d, labels = s.distances(sources, points=source_point, keep_field=True, return_labels=True)
    assert s.has_kept_field
    faces, bary = random_face_points(F, 500, 7)
    P = xyz_of(V, F, faces, bary)
    field, field_labels = s.field_distance((faces, bary), return_labels=True)
    assert field.dtype == np.float64 and field.shape == (500,)
    assert field_labels.dtype == np.int64 and field_labels.shape == (500,)
    # the plane (a convex square): the distance is the Euclidean distance to the nearest source
    euclid = np.linalg.norm(P[:, None, :] - centres[None, :, :], axis=2)
    assert np.abs(field - euclid.min(axis=1)).max() < 1e-12
    # the label is the nearer source wherever the two nearest differ: the vertices of sources, then the point
    order = np.sort(euclid, axis=1)
    unique = order[:, 1] - order[:, 0] > 1e-12
    assert unique.sum() > 490
    assert np.array_equal(field_labels[unique], euclid.argmin(axis=1)[unique])
    assert set(field_labels.tolist()) == {0, 1, 2}
    assert np.array_equal(s.field_nearest_source((faces, bary)), field_labels)
    # xyz positions are located on the surface: the same values
    assert np.abs(s.field_distance(P) - field).max() < 1e-12
    # at the vertices: the distances and labels of the run
    vd, vl = s.field_distance(np.arange(len(V)), return_labels=True)
    assert np.array_equal(vd, d)
    unique_v = np.sort(np.linalg.norm(V[:, None, :] - centres[None, :, :], axis=2), axis=1)
    unique_v = unique_v[:, 1] - unique_v[:, 0] > 1e-12
    assert np.array_equal(vl[unique_v], labels[unique_v])
    # one vertex, one (face, barycentric) pair
    assert s.field_distance(sources[0]).shape == (1,) and s.field_distance(sources[0])[0] == 0.0
    assert s.field_distance((5, [0.2, 0.3, 0.5]))[0] == pytest.approx(
        np.linalg.norm(xyz_of(V, F, [5], np.array([[0.2, 0.3, 0.5]])) - centres, axis=1).min(), abs=1e-12)
    # the memory of the field, as in the statistics
    st = s.statistics
    assert st["field_bytes"] == s.field_bytes > 0 and st["field_pieces"] > 0


def test_plane_field_isolines_at_levels_chosen_after_the_run():
    V, F = plane_grid(21, 21, jitter=0.3, seed=3)
    s = vtp_geodesics.Solver(V, F)
    c = 10 * 21 + 10
    s.distances(c, keep_field=True)
    curves = s.field_isolines([0.15, 0.35], chord_tolerance=1e-6, return_locations=True)
    assert [k["level"] for k in curves] == [0.15, 0.35] and all(k["closed"] for k in curves)
    for k in curves:
        assert np.abs(np.linalg.norm(k["points"] - V[c], axis=1) - k["level"]).max() < 1e-9
        assert np.abs(s.field_distance((k["faces"], k["barycentric"])) - k["level"]).max() < 1e-9
    # still kept: the same curves as one run of isolines() from the same source
    again = s.isolines([0.15, 0.35], sources=c, chord_tolerance=1e-6)
    for a, b in zip(curves, again):
        assert np.array_equal(a["points"], b["points"])


def test_two_symmetric_cells_of_the_unit_square():
    V, F = plane_grid(11, 11, jitter=0.3, seed=5)   # the corners are not jittered
    a, b = 0, len(V) - 1
    assert np.array_equal(V[a], [0, 0, 0]) and np.array_equal(V[b], [1, 1, 0])
    s = vtp_geodesics.Solver(V, F)
    borders = s.cell_borders([a, b], return_locations=True)
    assert len(borders) == 1 and borders[0]["cells"] == (0, 1)
    p = borders[0]["points"]
    assert len(p) > 10
    assert np.abs(p[:, 0] + p[:, 1] - 1).max() < 1e-12
    # the cells: half of the square each
    areas, uncertainty = s.cell_areas([a, b])
    assert areas.shape == (2,) and np.abs(areas - 0.5).max() < 1e-12
    assert np.all(uncertainty >= 0)
    # the same from the kept field of distances()
    s.distances([a, b], keep_field=True)
    areas_kept, _ = s.field_cell_areas()
    assert np.abs(areas_kept - 0.5).max() < 1e-12
    kept_borders = s.field_cell_borders()
    assert len(kept_borders) == 1 and np.array_equal(kept_borders[0]["points"], p)
    # farthest-point sampling from a: the second sample is b (the only vertex at sqrt(2)); exact cells
    r = s.farthest_point_sampling(2, first=a)
    assert r.samples.tolist() == [a, b]
    assert np.abs(r.cell_areas - 0.5).max() < 1e-12
    assert np.all(r.cell_area_uncertainty < 1e-3)   # the chord tolerance times the border
    # the approximate methods (and exact_cell_areas=False) keep the estimate from the vertex values: it adds up
    # to the square, its uncertainty is the area of the faces that the border crosses
    for estimate in (s.farthest_point_sampling(2, first=a, method="avtp"),
                     s.farthest_point_sampling(2, first=a, exact_cell_areas=False)):
        assert estimate.samples.tolist() == [a, b]
        assert estimate.cell_areas.sum() == pytest.approx(1.0, rel=1e-12)
        assert np.all(estimate.cell_area_uncertainty > 0.05)


def test_sampling_cell_areas_are_those_of_the_exact_borders(elephant):
    V, F, s = elephant
    r = s.farthest_point_sampling(6)
    areas, uncertainty = s.cell_areas(r.samples)
    assert np.array_equal(r.cell_areas, areas)
    assert np.array_equal(r.cell_area_uncertainty, uncertainty)


def test_elephant_borders_are_equidistant(elephant):
    V, F, s = elephant
    sources = [0, 99, 1000]
    top = s.distances(sources).max()
    borders = s.cell_borders(sources, return_locations=True)
    assert {c["cells"] for c in borders} == {(0, 1), (0, 2), (1, 2)}
    errors = []
    for c in borders:
        i, j = c["cells"]
        for f, b in zip(c["faces"], c["barycentric"]):
            errors.append(abs(s.distance(sources[i], (int(f), b)) - s.distance(sources[j], (int(f), b))))
    errors = np.array(errors)
    share = np.mean(errors <= 1e-9 * top)
    print("elephant, sources 0, 99, 1000: %d of %d border points equidistant to 1e-9 of the largest distance "
          "(%.2f%%), the largest difference %.3g of it" % ((errors <= 1e-9 * top).sum(), len(errors), 100 * share,
                                                           errors.max() / top))
    # every one (with the borders from the corners' labels, 679 of 691: the junction of the three cells was not
    # solved inside its face)
    assert len(errors) > 600 and share == 1.0


def test_elephant_field_equals_targeted_runs(elephant):
    V, F, s = elephant
    sources = [0, 99, 1000]
    d = s.distances(sources, keep_field=True)
    top = d.max()
    faces, bary = random_face_points(F, 200, 11)
    field, labels = s.field_distance((faces, bary), return_labels=True)
    s.distances(sources, method="pvtp", threads=2, keep_field=True)
    parallel, parallel_labels = s.field_distance((faces, bary), return_labels=True)
    # distance() runs replace the field: every field query above
    single = np.array([[s.distance(x, (int(f), b)) for x in sources] for f, b in zip(faces, bary)])
    assert not s.has_kept_field
    assert np.abs(field - single.min(axis=1)).max() <= 1e-12 * top
    assert np.abs(parallel - field).max() <= 1e-12 * top
    order = np.sort(single, axis=1)
    unique = order[:, 1] - order[:, 0] > 1e-12 * top
    assert unique.sum() > 190
    assert np.array_equal(labels[unique], single.argmin(axis=1)[unique])
    assert np.array_equal(parallel_labels[unique], labels[unique])


def test_limit_gives_inf_and_no_label():
    V, F = plane_grid(11, 11)
    s = vtp_geodesics.Solver(V, F)
    s.distances(0, max_distance=0.5, keep_field=True)
    d, labels = s.field_distance(np.array([[0.2, 0.2, 0.0], [0.9, 0.9, 0.0]]), return_labels=True)
    assert d[0] == pytest.approx(math.sqrt(0.08), abs=1e-12) and labels[0] == 0
    assert d[1] == math.inf and labels[1] == -1


def test_repaired_mesh_on_the_callers_indices():
    V, F = pinch_mesh()                       # two sheets touching at vertex 24; the last vertex in no face
    s = solver_of(V, F)
    sources = [24, 70]                        # the pinch is two sources (a copy on each sheet), label 0
    assert np.diff(s.vertex_copies()[0])[24] == 2
    d, labels = s.distances(sources, keep_field=True, return_labels=True)
    vd, vl = s.field_distance(np.arange(len(V)), return_labels=True)
    assert np.array_equal(vd, d) and np.array_equal(vl, labels)
    assert vd[-1] == math.inf and vl[-1] == -1
    faces, bary = random_face_points(F, 40, 3)
    field, field_labels = s.field_distance((faces, bary), return_labels=True)
    single = np.array([[s.distance(x, (int(f), b)) for x in sources] for f, b in zip(faces, bary)])
    assert np.abs(field - single.min(axis=1)).max() <= 1e-12 * d[np.isfinite(d)].max()
    order = np.sort(single, axis=1)
    unique = order[:, 1] - order[:, 0] > 1e-12
    assert unique.sum() > 35 and set(field_labels[unique].tolist()) == {0, 1}
    assert np.array_equal(field_labels[unique], single.argmin(axis=1)[unique])
    with pytest.raises(ValueError, match="through_pinches"):
        solver_of(V, F, through_pinches=True).distances(sources, keep_field=True)


def test_what_replaces_the_field():
    V, F = plane_grid(8, 8)
    s = vtp_geodesics.Solver(V, F)
    point = (np.array([3]), np.array([[0.2, 0.3, 0.5]]))

    def kept():
        s.distances([0, 63], keep_field=True)
        assert s.has_kept_field and s.field_bytes > 0

    kept()
    s.matrix([1, 2])
    s.polar_patches([5], radius=0.3)
    s.trace(5, [1.0, 0.0], 0.3)
    s.locate([[0.5, 0.5, 0.0]])
    s.field_isolines([0.3])
    s.field_cell_areas()
    assert s.has_kept_field and s.field_distance(point).shape == (1,)
    for replace in (lambda: s.distances(0), lambda: s.distance(0, 9), lambda: s.path(9, sources=0),
                    lambda: s.isolines([0.3], sources=0), lambda: s.cell_borders([0, 63]), lambda: s.cell_areas([0, 63]),
                    lambda: s.log_map(0), lambda: s.farthest_point_sampling(3)):
        kept()
        replace()
        assert not s.has_kept_field and s.field_bytes == 0
        with pytest.raises(ValueError, match="keep_field=True"):
            s.field_distance(point)


def test_bad_input():
    V, F = plane_grid(6, 6)
    s = vtp_geodesics.Solver(V, F)
    point = (np.array([3]), np.array([[0.2, 0.3, 0.5]]))
    # no run yet, a run without keep_field
    for query in (lambda: s.field_distance(point), lambda: s.field_nearest_source(point),
                  lambda: s.field_isolines([0.1]), lambda: s.field_cell_borders(), lambda: s.field_cell_areas()):
        with pytest.raises(ValueError, match=r"compute with distances\(\.\.\., keep_field=True\)"):
            query()
    assert not s.has_kept_field and s.field_bytes == 0
    s.distances(0)
    with pytest.raises(ValueError, match="keep_field=True"):
        s.field_distance(point)
    # the approximate methods, targets
    for method in ("avtp", "pavtp", "vsp", "pvsp2"):
        with pytest.raises(ValueError, match="exact method"):
            s.distances(0, method=method, keep_field=True)
    with pytest.raises(ValueError, match="targets"):
        s.distances(0, targets=[5], keep_field=True)
    # points off the mesh
    s.distances(0, keep_field=True)
    with pytest.raises(ValueError, match="face index 50 out of range"):
        s.field_distance((np.array([50]), np.array([[0.2, 0.3, 0.5]])))
    with pytest.raises(ValueError, match="barycentric"):
        s.field_distance((np.array([3]), np.array([[0.2, 0.3, 0.6]])))
    with pytest.raises(ValueError, match="barycentric"):
        s.field_distance((np.array([3]), np.array([[-0.2, 0.7, 0.5]])))
    with pytest.raises(ValueError, match="vertex index 36 out of range"):
        s.field_distance([1, 36])
    with pytest.raises(ValueError, match="vertex index -1 out of range"):
        s.field_nearest_source(-1)
    with pytest.raises(ValueError, match="non-finite"):
        s.field_distance([[0.5, math.nan, 0.0]])
    with pytest.raises(ValueError, match="as floats"):
        s.field_distance(np.array([[0, 0, 0]]))
    with pytest.raises(ValueError, match="shapes"):
        s.field_distance((np.array([3, 4]), np.array([[0.2, 0.3, 0.5]])))
    with pytest.raises(TypeError):
        s.field_distance(True)
    # nothing given, nothing returned; the field is still there after the errors
    assert s.field_distance([]).shape == (0,)
    assert s.has_kept_field


def test_docstring_examples():
    from vtp_geodesics import _field
    result = doctest.testmod(_field)
    assert result.attempted > 0 and result.failed == 0


def test_example_runs():
    example = os.path.join(HERE, "..", "..", "examples", "python", "kept_field.py")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    out = subprocess.run([sys.executable, example], check=True, capture_output=True, text=True, env=env).stdout
    assert "nearest source" in out and "isolines" in out
