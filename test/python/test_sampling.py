# Farthest-point sampling from Python: against the invariants (distances = a full computation from the
# samples, labels = the nearest sample where it is unique, radii non-increasing and the last one the largest
# distance, areas adding up to the area of the mesh), against the tool (same samples and radii, bit for bit),
# and bad input.

import json
import math
import subprocess

import numpy as np
import pytest

import vtp_geodesics
from conftest import data_file, plane_grid


def mesh_area(V, F):
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()


@pytest.mark.parametrize("method", ["vtp", "pvtp"])
def test_invariants(method):
    V, F = vtp_geodesics.read_mesh(data_file("elephant.off"))
    solver = vtp_geodesics.Solver(V, F)
    r = solver.farthest_point_sampling(15, method=method, threads=2)
    assert isinstance(r, vtp_geodesics.FarthestPointSamples)
    assert r.samples.dtype == np.int64 and r.samples.shape == (15,)
    assert len(set(r.samples.tolist())) == 15
    assert r.radii.shape == (15,) and np.all(np.diff(r.radii) <= 0)
    # the first sample is the vertex farthest from vertex 0
    d0 = solver.distances(0)
    assert r.samples[0] == int(np.argmax(d0))
    # the field is that of a full computation from the samples
    d = solver.distances(r.samples, method=method)
    assert np.max(np.abs(d - r.distances)) <= 1e-12 * d.max()
    assert r.radii[-1] == pytest.approx(d.max(), rel=1e-12)
    assert np.all(r.distances[r.samples] == 0) and np.array_equal(r.labels[r.samples], np.arange(15))
    # the labels are the nearest sample where it is unique by more than rounding
    single = np.stack([solver.distances(int(s)) for s in r.samples])
    order = np.sort(single, axis=0)
    unique = order[1] - order[0] > 1e-9 * d.max()
    assert np.array_equal(r.labels[unique], np.argmin(single, axis=0)[unique])
    # the cells add up to the mesh
    assert r.cell_areas.shape == (15,) and np.all(r.cell_areas > 0)
    assert r.cell_areas.sum() == pytest.approx(mesh_area(V, F), rel=1e-9)
    assert np.all(r.cell_area_uncertainty > 0)


def test_virtual_sources():
    # one virtual source per vertex: the first sample is the farthest from vertex 0 by VSP, the field is never
    # below the exact distance to the samples, PVSP gives the same bits, radii non-increasing
    V, F = vtp_geodesics.read_mesh(data_file("elephant.off"))
    solver = vtp_geodesics.Solver(V, F)
    r = solver.farthest_point_sampling(15, method="vsp")
    assert len(set(r.samples.tolist())) == 15 and np.all(np.diff(r.radii) <= 0)
    assert r.samples[0] == int(np.argmax(solver.distances(0, method="vsp")))
    exact = solver.distances(r.samples)
    assert np.all(r.distances >= exact - 1e-12 * exact.max())
    assert np.all(r.distances[r.samples] == 0) and np.array_equal(r.labels[r.samples], np.arange(15))
    assert r.radii[-1] == r.distances.max()
    p = solver.farthest_point_sampling(15, method="pvsp", threads=2)
    assert np.array_equal(p.samples, r.samples) and np.array_equal(p.distances, r.distances)
    assert np.array_equal(p.labels, r.labels)
    # two per vertex: the same checks, PVSP2 the same bits
    r2 = solver.farthest_point_sampling(15, method="vsp2")
    assert solver.statistics["method"] == "vsp2"
    assert len(set(r2.samples.tolist())) == 15 and np.all(np.diff(r2.radii) <= 0)
    assert r2.samples[0] == int(np.argmax(solver.distances(0, method="vsp2")))
    exact2 = solver.distances(r2.samples)
    assert np.all(r2.distances >= exact2 - 1e-12 * exact2.max())
    assert np.all(r2.distances[r2.samples] == 0) and np.array_equal(r2.labels[r2.samples], np.arange(15))
    p2 = solver.farthest_point_sampling(15, method="pvsp2", threads=2)
    assert np.array_equal(p2.samples, r2.samples) and np.array_equal(p2.distances, r2.distances)
    assert np.array_equal(p2.labels, r2.labels)


def test_radius_first_and_plane():
    V, F = plane_grid(30, 30)
    solver = vtp_geodesics.Solver(V, F)
    full = solver.farthest_point_sampling(10, first=5)
    assert full.samples[0] == 5
    r = 0.5 * (full.radii[3] + full.radii[4])
    stopped = solver.farthest_point_sampling(1000, first=5, radius=r)
    assert np.array_equal(stopped.samples, full.samples[:5]) and stopped.radii[-1] <= r
    # on a plane the distances are Euclidean: the covering radius is the largest distance to the nearest sample
    P = V[full.samples]
    euclid = np.min(np.linalg.norm(V[:, None, :] - P[None, :, :], axis=2), axis=1)
    assert np.max(np.abs(euclid - full.distances)) <= 1e-12
    assert full.radii[-1] == pytest.approx(euclid.max(), rel=1e-12)
    assert solver.farthest_point_sampling(0).samples.size == 0


def test_components_and_more_samples_than_vertices():
    # a right triangle and a unit square 4 away from it: two components
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0], [6, 1, 0]], dtype=float)
    F = np.array([[0, 1, 2], [3, 4, 5], [4, 6, 5]], dtype=np.int64)
    solver = vtp_geodesics.Solver(V, F)
    # one sample in the square: the triangle is at inf, labelled -1, and the radius is inf
    one = solver.farthest_point_sampling(1, first=3)
    assert one.samples.tolist() == [3] and one.radii.tolist() == [math.inf]
    assert np.array_equal(np.isinf(one.distances), one.labels == -1)
    assert np.array_equal(one.labels == -1, np.arange(7) < 3)
    assert one.cell_areas.tolist() == pytest.approx([1.0], rel=1e-12)
    # more samples than vertices: every vertex once, then the radius is 0; the radius is inf until the
    # second component has a sample, which is then the second one
    every = solver.farthest_point_sampling(100, first=3)
    huge = solver.farthest_point_sampling(2 ** 70, first=3)
    assert np.array_equal(huge.samples, every.samples) and np.array_equal(huge.radii, every.radii)
    assert sorted(every.samples.tolist()) == list(range(7))
    assert every.radii[0] == math.inf and np.isfinite(every.radii[1]) and every.samples[1] < 3
    assert every.radii[-1] == 0 and np.all(every.radii[:-1] > 0) and np.all(np.diff(every.radii[1:]) <= 0)
    assert np.array_equal(every.labels[every.samples], np.arange(7)) and np.all(every.distances == 0)
    assert every.cell_areas.sum() == pytest.approx(mesh_area(V, F), rel=1e-12)
    # the radius stops it as soon as the covering radius is at most the radius
    assert every.radii[2] < every.radii[1]
    stopped = solver.farthest_point_sampling(100, first=3, radius=every.radii[2])
    assert np.array_equal(stopped.samples, every.samples[:3])


def test_equals_tool(tool, tmp_path):
    samples_file = tmp_path / "s.txt"
    stats_file = tmp_path / "s.json"
    subprocess.run([tool, data_file("elephant.off"), "--farthest-points", "20", "--first", "7",
                    "--samples-output", str(samples_file), "--stats-json", str(stats_file)],
                   check=True, capture_output=True)
    lines = [l.split() for l in open(samples_file) if not l.startswith("#")]
    V, F = vtp_geodesics.read_mesh(data_file("elephant.off"))
    r = vtp_geodesics.Solver(V, F).farthest_point_sampling(20, first=7)
    assert r.samples.tolist() == [int(l[0]) for l in lines]
    assert r.radii.tolist() == [float(l[1]) for l in lines]
    # the cells' areas, from their exact borders in both (vtp)
    stats = json.load(open(stats_file))
    assert stats["min_cell_area"] == r.cell_areas.min() and stats["max_cell_area"] == r.cell_areas.max()


def test_bad_input():
    V, F = plane_grid(5, 5)
    solver = vtp_geodesics.Solver(V, F)
    with pytest.raises(ValueError):
        solver.farthest_point_sampling(-1)
    with pytest.raises(ValueError):
        solver.farthest_point_sampling(3, first=1000)
    with pytest.raises(ValueError):
        solver.farthest_point_sampling(3, first=-2)
    with pytest.raises(ValueError):
        solver.farthest_point_sampling(3, first=2 ** 70)
    with pytest.raises(ValueError):
        solver.farthest_point_sampling(3, radius=-1.0)
    with pytest.raises(ValueError):
        solver.farthest_point_sampling(3, radius=math.nan)
    with pytest.raises(ValueError):
        solver.farthest_point_sampling(3, method="vsp3")
    with pytest.raises(TypeError):
        solver.farthest_point_sampling(2.5)
