// Polar patches (Polar_patches.h, Geodesic_distance_solver::polar_patches()): each patch equals the log map of
// one run from its centre with the same maximum distance (bit for bit, against the engine's own run; and
// against compute() with log_map()), in any order of the centres and on any number of threads; analytic
// values on the plane; rejected input.

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>
#include <CGAL/VTP_geodesics/Polar_patches.h>
#include <CGAL/VTP_geodesics/internal/propagation/Local_propagation.h>
#include <CGAL/VTP_geodesics/internal/log_map/Log_map_output.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_import.h>
#include <CGAL/VTP_geodesics/internal/solver/Settings_from_parameters.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

using namespace vtp_test;

namespace {

namespace PI_ = CGAL::VTP_geodesics::internal;
namespace PP = CGAL::VTP_geodesics::parameters;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Surface_mesh> Patch_solver;
typedef std::pair<Surface_mesh::Face_index, std::array<double, 3> > Patch_location;
const double patch_two_pi = 2. * 3.14159265358979323846;

// the angle a - b reduced to [-pi, pi]
double patch_angle_gap(double a, double b) { return std::abs(std::remainder(a - b, patch_two_pi)); }

// The largest distance from vertex 0 (to size the radii).
double patch_largest_distance(const Surface_mesh& mesh)
{
  const std::vector<double> d = vtp_distances(mesh, Vertex_index(0));
  return max_finite(d);
}

// Every local run of a Local_propagation (one workspace, reused in a shuffled order of the centres, so that each
// run starts from what the previous ones left) gives the same bits as a fresh run of the engine: the vertices
// within the cutoff, their distance, theta and via.
TEST(PolarPatches, LocalRunsEqualEngineRunsBitwise)
{
  const Surface_mesh mesh = load_mesh("elephant-with-holes.off");  // border vertices too
  PI_::Mesh_index<Surface_mesh> index(mesh);
  PI_::import_mesh(index, get(CGAL::vertex_point, mesh), CGAL::VTP_geodesics::Geodesic_traits_3<Kernel>(), 1);
  const PI_::Mesh_arrays& m = index.arrays;
  const double largest = patch_largest_distance(mesh);
  std::vector<PI_::Seed> seeds;
  for(PI_::Index v = 0; v < m.nv; ++v)
  {
    PI_::Seed s;
    s.kind = PI_::Seed::AT_VERTEX;
    s.element = v;
    seeds.push_back(s);
  }
  for(PI_::Index f = 0; f < m.nf; f += 53)  // points inside faces and on edges (given in the face of the seed)
  {
    seeds.push_back(PI_::seed_from_barycentric(m, f, 0.2, 0.3, 0.5, 0));
    seeds.back().user_face = f;
    seeds.push_back(PI_::seed_from_barycentric(m, f, 0.6, 0.4, 0., 0));
    seeds.back().user_face = f;
  }
  std::mt19937 shuffle(5);
  std::shuffle(seeds.begin(), seeds.end(), shuffle);
  PI_::Propagation_engine engine;
  PI_::Local_propagation local;
  std::size_t compared = 0, beyond = 0;
  for(const bool strict : {false, true})
    for(const double radius : {0.05 * largest, 0.2 * largest, INF})
    {
      const auto np = PP::maximum_distance(radius).log_map_strict(strict);
      int threads = 0;
      PI_::Propagation_settings settings = PI_::settings_from_parameters(np, index, threads);
      settings.log_map = true;
      settings.log_map_strict = strict;
      for(std::size_t k = 0; k < seeds.size(); k += (radius < 0.1 * largest ? 1 : radius < INF ? 3 : 41))
      {
        const std::vector<PI_::Seed> one(1, seeds[k]);
        PI_::prepare_log_map(index, get(CGAL::vertex_point, mesh), np, one, engine.direction());
        PI_::prepare_log_map(index, get(CGAL::vertex_point, mesh), np, one, local.direction());
        CGAL::VTP_geodesics::Propagation_statistics st;
        engine.run<CGAL::Sequential_tag>(m, one, std::vector<PI_::Target>(), settings, 1, st);
        local.run(m, seeds[k], settings);
        const std::vector<double>& d = engine.distances();
        std::vector<char> in_patch(static_cast<std::size_t>(m.nv), 0);
        for(PI_::Index v : local.reached())
        {
          ASSERT_FALSE(in_patch[static_cast<std::size_t>(v)]) << "a vertex listed twice";
          in_patch[static_cast<std::size_t>(v)] = 1;
          if(!(local.distances()[v] <= local.cutoff()))
          {
            ++beyond;
            EXPECT_EQ(d[v], INF);
            in_patch[static_cast<std::size_t>(v)] = 0;
            continue;
          }
          const double rho = settings.unit != 1. ? local.distances()[v] * settings.unit : local.distances()[v];
          ASSERT_EQ(rho, d[v]) << "vertex " << v;  // bitwise
          ASSERT_EQ(local.direction().theta[v], engine.direction().theta[v]) << "vertex " << v;
          ASSERT_EQ(local.direction().via[v], engine.direction().via[v]) << "vertex " << v;
          ++compared;
        }
        for(PI_::Index v = 0; v < m.nv; ++v)
          ASSERT_EQ(in_patch[static_cast<std::size_t>(v)] != 0, d[v] < INF) << "vertex " << v;
      }
    }
  EXPECT_GT(compared, 50000u);
  EXPECT_GT(beyond, 0u);  // the runs stopped early: some reached vertices lay beyond the radius
}

// The patches of the solver against compute() with log_map() and the same maximum distance from each centre:
// the same vertices (ascending), rho bitwise, theta the angle of the tangent coordinates, in [0, 2 pi).
TEST(PolarPatches, EqualTheLogMapOfOneRun)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  Patch_solver solver(mesh);
  const double radius = 0.1 * patch_largest_distance(mesh);
  std::vector<Vertex_index> centres;
  for(Vertex_index v : vertices(mesh))
    centres.push_back(v);
  std::vector<Patch_location> points;
  for(Surface_mesh::Face_index f : faces(mesh))
    if(std::size_t(f) % 97 == 3)
      points.push_back(Patch_location(f, {0.25, 0.25, 0.5}));
  for(const bool strict : {false, true})
  {
    const auto np = PP::log_map_strict(strict);
    const CGAL::VTP_geodesics::Polar_patches p = solver.polar_patches(centres, radius, np);
    const CGAL::VTP_geodesics::Polar_patches q = solver.polar_patches(points, radius, np);
    ASSERT_EQ(p.number_of_patches(), centres.size());
    ASSERT_EQ(q.number_of_patches(), points.size());
    EXPECT_EQ(solver.statistics().sources, points.size());
    EXPECT_TRUE(solver.statistics().stopped_early);
    EXPECT_EQ(solver.statistics().reached_vertices, q.number_of_entries());
    const std::size_t n = index_range(mesh);
    std::vector<double> d(n);
    std::vector<std::array<double, 2> > x(n);
    auto dm = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
    auto xm = boost::make_iterator_property_map(x.begin(), get(boost::vertex_index, mesh));
    auto check = [&](const CGAL::VTP_geodesics::Polar_patches& r, std::size_t i) {
      std::size_t finite = 0;
      for(double e : d)
        finite += e < INF ? 1 : 0;
      ASSERT_EQ(r.offsets[i + 1] - r.offsets[i], finite) << "patch " << i;
      for(std::size_t k = r.offsets[i]; k < r.offsets[i + 1]; ++k)
      {
        if(k > r.offsets[i])
        {
          ASSERT_LT(r.vertices[k - 1], r.vertices[k]);
        }
        const Vertex_index v = solver.vertex_list()[r.vertices[k]];
        ASSERT_EQ(r.rho[k], d[v]) << "patch " << i;  // bitwise
        ASSERT_LE(r.rho[k], radius);
        ASSERT_GE(r.theta[k], 0.);
        ASSERT_LT(r.theta[k], patch_two_pi);
        if(r.rho[k] > 0.)
        {
          EXPECT_NEAR(patch_angle_gap(r.theta[k], std::atan2(x[v][1], x[v][0])), 0., 1e-13);
        }
        else
        {
          EXPECT_EQ(r.theta[k], 0.);
        }
      }
    };
    for(std::size_t i = 0; i < centres.size(); i += 23)
    {
      solver.compute(dm, centres[i], np.maximum_distance(radius).log_map(xm));
      check(p, i);
    }
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      solver.compute(dm, points[i], np.maximum_distance(radius).log_map(xm));
      check(q, i);
    }
  }
}

#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
TEST(PolarPatches, ParallelEqualsSequential)
{
  const Surface_mesh mesh = load_mesh("elephant-with-holes.off");
  Patch_solver solver(mesh);
  const double radius = 0.08 * patch_largest_distance(mesh);
  std::vector<Vertex_index> centres;
  for(Vertex_index v : vertices(mesh))
    centres.push_back(v);
  for(const bool strict : {false, true})
  {
    const CGAL::VTP_geodesics::Polar_patches a = solver.polar_patches(centres, radius, PP::log_map_strict(strict));
    for(const int threads : {1, 2, 3})
    {
      const CGAL::VTP_geodesics::Polar_patches b = solver.polar_patches<CGAL::Parallel_tag>(
        centres, radius, PP::log_map_strict(strict).number_of_threads(threads));
      EXPECT_EQ(a.offsets, b.offsets);
      EXPECT_EQ(a.vertices, b.vertices);
      EXPECT_TRUE(identical(a.rho, b.rho));
      EXPECT_TRUE(identical(a.theta, b.theta));
      EXPECT_EQ(solver.statistics().threads, threads);
    }
  }
}
#endif

// On a flat jittered grid (a convex domain): a patch is every vertex within the radius of the centre by the
// Euclidean distance, rho that distance and theta its angle from the reference direction, to 1e-12.
TEST(PolarPatches, FlatGridAnalytic)
{
  const int n = 14;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1., 0.3, 19));
  Patch_solver solver(mesh);
  const double radius = 0.27;
  std::vector<Vertex_index> centres;
  std::vector<Point_3> at;
  for(int i = 1; i < n; i += 3)
    for(int j = 2; j < n; j += 4)
    {
      centres.push_back(Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, i, j))));
      at.push_back(mesh.point(centres.back()));
    }
  std::vector<Patch_location> points;
  for(Surface_mesh::Face_index f : faces(mesh))
    if(std::size_t(f) % 41 == 7)
    {
      points.push_back(Patch_location(f, {0.1, 0.3, 0.6}));
      const auto h = halfedge(f, mesh);
      const Point_3 &a = mesh.point(source(h, mesh)), &b = mesh.point(target(h, mesh)),
                    &c = mesh.point(target(next(h, mesh), mesh));
      at.push_back(Point_3(0.1 * a.x() + 0.3 * b.x() + 0.6 * c.x(), 0.1 * a.y() + 0.3 * b.y() + 0.6 * c.y(), 0.));
    }
  const auto np = PP::reference_direction(std::array<double, 3>{1., 0., 0.});
  const CGAL::VTP_geodesics::Polar_patches pv = solver.polar_patches(centres, radius, np);
  const CGAL::VTP_geodesics::Polar_patches pf = solver.polar_patches(points, radius, np);
  std::size_t checked = 0;
  auto expect_disk = [&](const CGAL::VTP_geodesics::Polar_patches& r, std::size_t i, const Point_3& c) {
    std::vector<double> rho(num_vertices(mesh), -1.), theta(num_vertices(mesh), 0.);
    for(std::size_t k = r.offsets[i]; k < r.offsets[i + 1]; ++k)
    {
      rho[solver.vertex_list()[r.vertices[k]]] = r.rho[k];
      theta[solver.vertex_list()[r.vertices[k]]] = r.theta[k];
    }
    for(Vertex_index v : vertices(mesh))
    {
      const Point_3 p = mesh.point(v);
      const double e = std::hypot(p.x() - c.x(), p.y() - c.y());
      if(std::abs(e - radius) < 1e-12)
        continue;  // on the circle: either way
      ASSERT_EQ(rho[v] >= 0., e < radius) << "vertex " << std::size_t(v) << " at " << e;
      if(e > radius)
        continue;
      EXPECT_NEAR(rho[v], e, 1e-12);
      if(e > 1e-9)
      {
        EXPECT_NEAR(patch_angle_gap(theta[v], std::atan2(p.y() - c.y(), p.x() - c.x())), 0., 1e-12);
      }
      ++checked;
    }
  };
  for(std::size_t i = 0; i < centres.size(); ++i)
    expect_disk(pv, i, at[i]);
  for(std::size_t i = 0; i < points.size(); ++i)
    expect_disk(pf, i, at[centres.size() + i]);
  EXPECT_GT(checked, 500u);
  // a border vertex: its angles scaled by pi / pi, its reference the border edge along +x
  const Vertex_index b(static_cast<Surface_mesh::size_type>(grid_vertex(n, 6, 0)));
  const CGAL::VTP_geodesics::Polar_patches pb = solver.polar_patches(std::vector<Vertex_index>(1, b), radius);
  expect_disk(pb, 0, mesh.point(b));
}

// A radius of +infinity: each patch is the whole log map of its centre's component.
TEST(PolarPatches, InfiniteRadiusIsTheWholeLogMap)
{
  const Surface_mesh mesh = load_mesh("elephant_395.off");
  Patch_solver solver(mesh);
  const std::vector<Vertex_index> centres = {Vertex_index(0), Vertex_index(17), Vertex_index(0)};
  const CGAL::VTP_geodesics::Polar_patches p = solver.polar_patches(centres, INF);
  const std::vector<double> d = vtp_distances(mesh, Vertex_index(0));
  std::size_t finite = 0;
  for(double e : d)
    finite += e < INF ? 1 : 0;
  EXPECT_EQ(p.offsets[1], finite);
  for(std::size_t k = 0; k < p.offsets[1]; ++k)
    EXPECT_EQ(p.rho[k], d[solver.vertex_list()[p.vertices[k]]]);
  // the same centre twice: the same patch
  EXPECT_TRUE(std::equal(p.vertices.begin(), p.vertices.begin() + static_cast<std::ptrdiff_t>(p.offsets[1]),
                         p.vertices.begin() + static_cast<std::ptrdiff_t>(p.offsets[2])));
  EXPECT_TRUE(std::equal(p.theta.begin(), p.theta.begin() + static_cast<std::ptrdiff_t>(p.offsets[1]),
                         p.theta.begin() + static_cast<std::ptrdiff_t>(p.offsets[2])));
}

// The sink: each centre once, the rows as polar_patches() gives them; an exception of the sink comes out.
TEST(PolarPatches, SinkGetsEachPatchOnce)
{
  const Surface_mesh mesh = load_mesh("elephant_395.off");
  Patch_solver solver(mesh);
  std::vector<Vertex_index> centres;
  for(Vertex_index v : vertices(mesh))
    centres.push_back(v);
  const double radius = 0.2 * patch_largest_distance(mesh);
  const CGAL::VTP_geodesics::Polar_patches p = solver.polar_patches(centres, radius);
  std::vector<int> calls(centres.size(), 0);
  solver.compute_each_polar_patch(centres, radius, [&](std::size_t i, Vertex_index c, const std::vector<std::uint32_t>& v,
                                                       const std::vector<double>& rho, const std::vector<double>& theta) {
    ++calls[i];
    EXPECT_EQ(c, centres[i]);
    ASSERT_EQ(v.size(), p.offsets[i + 1] - p.offsets[i]);
    ASSERT_EQ(rho.size(), v.size());
    ASSERT_EQ(theta.size(), v.size());
    for(std::size_t k = 0; k < v.size(); ++k)
    {
      EXPECT_EQ(v[k], p.vertices[p.offsets[i] + k]);
      EXPECT_EQ(rho[k], p.rho[p.offsets[i] + k]);
      EXPECT_EQ(theta[k], p.theta[p.offsets[i] + k]);
    }
  });
  for(int c : calls)
    EXPECT_EQ(c, 1);
  int seen = 0;
  EXPECT_THROW(solver.compute_each_polar_patch(centres, radius,
                                               [&](std::size_t, Vertex_index, const std::vector<std::uint32_t>&,
                                                   const std::vector<double>&, const std::vector<double>&) {
                                                 if(++seen == 3)
                                                   throw std::runtime_error("sink");
                                               }),
               std::runtime_error);
  EXPECT_EQ(seen, 3);
}

TEST(PolarPatches, RejectedInput)
{
  const Surface_mesh mesh = load_mesh("elephant_395.off");
  Patch_solver solver(mesh);
  const std::vector<Vertex_index> centres = {Vertex_index(0), Vertex_index(5)};
  typedef CGAL::VTP_geodesics::Invalid_input_error Error;
  int calls = 0;
  auto sink = [&](std::size_t, Vertex_index, const std::vector<std::uint32_t>&, const std::vector<double>&,
                  const std::vector<double>&) { ++calls; };
  EXPECT_THROW(solver.polar_patches(centres, -1.), Error);
  EXPECT_THROW(solver.polar_patches(centres, std::nan("")), Error);
  EXPECT_THROW(solver.compute_each_polar_patch(centres, -0.5, sink), Error);
  // a centre out of range, after good ones: nothing is computed
  const std::vector<Vertex_index> bad = {Vertex_index(0), Vertex_index(1), Vertex_index(100000)};
  try
  {
    solver.compute_each_polar_patch(bad, 0.1, sink);
    ADD_FAILURE() << "no error";
  }
  catch(const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("centre 2"), std::string::npos) << e.what();
  }
  EXPECT_EQ(calls, 0);
  // a face location that is not on the mesh, or with bad coordinates
  const std::vector<Patch_location> outside = {Patch_location(Surface_mesh::Face_index(0), {0.5, 0.6, 0.1})};
  EXPECT_THROW(solver.polar_patches(outside, 0.1), Error);
  // the approximate methods carry no direction
  EXPECT_THROW(solver.polar_patches(centres, 0.1, PP::lambda(8.)), Error);
  EXPECT_THROW(solver.polar_patches(centres, 0.1, PP::virtual_sources(true)), Error);
  // an empty list of centres: no patch
  const CGAL::VTP_geodesics::Polar_patches none = solver.polar_patches(std::vector<Vertex_index>(), 0.1);
  EXPECT_EQ(none.number_of_patches(), 0u);
  EXPECT_EQ(none.offsets.size(), 1u);
}

} // namespace
