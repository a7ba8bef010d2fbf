// Runs from known distances (named parameter initial_distances), farthest-point sampling and geodesic
// Voronoi cell areas. Expected values: the minimum of single-source runs (a run from known distances adds its
// sources to the field), the naive farthest-point sampling (a full multi-source run from all the samples so
// far at every step), the area of the mesh, and a planar bisector.

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace vtp_test;
using CGAL::VTP_geodesics::Geodesic_distance_solver;
using CGAL::VTP_geodesics::Invalid_input_error;
using CGAL::VTP_geodesics::Propagation_statistics;
using CGAL::VTP_geodesics::no_source;
namespace VP = CGAL::VTP_geodesics::parameters;

typedef Geodesic_distance_solver<Surface_mesh> Solver;
typedef Surface_mesh::Face_index Face_index;
typedef std::pair<Face_index, std::array<double, 3> > Location;

namespace {

struct Field
{
  std::vector<double> d;
  std::vector<std::size_t> label;
  Propagation_statistics statistics;
};

enum Method_kind { VTP, PVTP, AVTP, VSP, VSP2 };

template <class Sources, class NP>
Field compute(const Surface_mesh& mesh, const Sources& sources, Method_kind method, const NP& np)
{
  Field f;
  f.d.assign(num_vertices(mesh), NOT_A_VERTEX);
  f.label.assign(num_vertices(mesh), std::size_t(12345));
  auto dmap = boost::make_iterator_property_map(f.d.begin(), get(boost::vertex_index, mesh));
  auto lmap = boost::make_iterator_property_map(f.label.begin(), get(boost::vertex_index, mesh));
  Solver solver(mesh);
  const auto all = np.nearest_source_map(lmap).number_of_threads(2)
                     .lambda(method == AVTP ? 2. : INF).virtual_sources(method == VSP || method == VSP2)
                     .virtual_sources_per_vertex(method == VSP2 ? 2 : 1);
  if(method == PVTP)
  {
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    solver.compute<CGAL::Parallel_tag>(dmap, sources, all);
#else
    ADD_FAILURE() << "no OpenMP";
#endif
  }
  else
    solver.compute(dmap, sources, all);
  f.statistics = solver.statistics();
  return f;
}

// The field of `sources` added to `known` (its labels numbered from `first_label`).
template <class Sources>
Field add_to(const Surface_mesh& mesh, const Field& known, const Sources& sources, std::size_t first_label,
             Method_kind method)
{
  auto kd = boost::make_iterator_property_map(known.d.begin(), get(boost::vertex_index, mesh));
  auto kl = boost::make_iterator_property_map(known.label.begin(), get(boost::vertex_index, mesh));
  return compute(mesh, sources, method,
                 VP::initial_distances(kd).initial_nearest_sources(kl).first_source_label(first_label));
}

template <class Sources>
Field plain(const Surface_mesh& mesh, const Sources& sources, Method_kind method)
{
  return compute(mesh, sources, method, VP::minimum_window_length(1e-9));
}

std::vector<Method_kind> exact_kinds()
{
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
  return { VTP, PVTP };
#else
  return { VTP };
#endif
}

// The vertex of the largest value (ties: the lowest index), as the sampling chooses.
std::size_t farthest_vertex(const std::vector<double>& d)
{
  std::size_t best = 0;
  for(std::size_t v = 1; v < d.size(); ++v)
    if(d[v] > d[best])
      best = v;
  return best;
}

// Two components: the elephant and a sphere beside it.
Surface_mesh two_components()
{
  Polygon_soup soup = to_soup(load_mesh("elephant_395.off"));
  soup.append(to_soup(load_mesh("sphere.off")), Vector_3(3., 0., 0.));
  return to_mesh<Surface_mesh>(soup);
}

// The meshes of the comparisons: closed, with boundaries, two components, needles (zero-length edges).
std::vector<std::pair<std::string, Surface_mesh> > test_meshes()
{
  std::vector<std::pair<std::string, Surface_mesh> > r;
  r.emplace_back("elephant_395", load_mesh("elephant_395.off"));
  r.emplace_back("elephant-with-holes_565", load_mesh("elephant-with-holes_565.off"));
  r.emplace_back("two components", two_components());
  r.emplace_back("degenerate_zero_length_edges", load_mesh("degenerate_zero_length_edges.off"));
  return r;
}

} // namespace

// A run from known distances equals the minimum of the two fields, labels included (where the two differ by
// more than rounding), for every source form and exact method.
TEST(Initial_distances, equal_the_minimum_of_the_fields_with_labels)
{
  for(const auto& named : test_meshes())
  {
    const Surface_mesh& mesh = named.second;
    const std::size_t n = num_vertices(mesh);
    const std::vector<Vertex_index> a = { Vertex_index(0), Vertex_index(static_cast<unsigned>(n / 3)) };
    const Face_index f(static_cast<unsigned>(num_faces(mesh) / 2));
    const std::vector<Location> b = { Location(f, {{0.2, 0.3, 0.5}}),
                                      Location(Face_index(static_cast<unsigned>(num_faces(mesh) - 1)), {{0.5, 0.5, 0.}}) };
    for(Method_kind method : exact_kinds())
    {
      SCOPED_TRACE(named.first + (method == PVTP ? " pvtp" : " vtp"));
      const Field fa = plain(mesh, a, method), fb = plain(mesh, b, method);
      const Field sum = add_to(mesh, fa, b, 2, method);
      const double scale = (std::max)(max_finite(fa.d), max_finite(fb.d));
      for(std::size_t v = 0; v < n; ++v)
      {
        const double expected = (std::min)(fa.d[v], fb.d[v]);
        if(std::isinf(expected))
        {
          EXPECT_TRUE(std::isinf(sum.d[v])) << "vertex " << v;
          EXPECT_EQ(sum.label[v], no_source) << "vertex " << v;
          continue;
        }
        ASSERT_NEAR(sum.d[v], expected, 1e-12 * scale) << "vertex " << v;
        if(std::abs(fa.d[v] - fb.d[v]) > 1e-9 * scale)
        {
          EXPECT_EQ(sum.label[v], fa.d[v] < fb.d[v] ? fa.label[v] : fb.label[v] + 2) << "vertex " << v;
        }
      }
    }
  }
}

// The approximate methods keep their guarantee: never below the exact minimum, never above the known field.
TEST(Initial_distances, approximate_methods_stay_upper_bounds)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  const std::vector<Vertex_index> a = { Vertex_index(0), Vertex_index(900) };
  const std::vector<Vertex_index> b = { Vertex_index(2000) };
  const Field ea = plain(mesh, a, VTP), eb = plain(mesh, b, VTP);
  for(Method_kind method : { AVTP, VSP, VSP2 })
  {
    SCOPED_TRACE(method == AVTP ? "avtp" : method == VSP ? "vsp" : "vsp2");
    const Field known = plain(mesh, a, method);
    const Field sum = add_to(mesh, known, b, 2, method);
    const double scale = max_finite(ea.d);
    double error = 0.;
    for(std::size_t v = 0; v < num_vertices(mesh); ++v)
    {
      const double exact = (std::min)(ea.d[v], eb.d[v]);
      EXPECT_GE(sum.d[v], exact - 1e-12 * scale) << "vertex " << v;
      EXPECT_LE(sum.d[v], known.d[v]) << "vertex " << v;
      error += (sum.d[v] - exact) / scale;
    }
    EXPECT_LT(error / static_cast<double>(num_vertices(mesh)), 0.02);
  }
}

// A source that wins a small region does the work of that region: the known field of 100 sources, and a
// new source one edge away from one of them.
TEST(Initial_distances, a_source_that_wins_little_does_little_work)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  const std::size_t n = num_vertices(mesh);
  std::vector<Vertex_index> a;
  for(std::size_t v = 0; v < n; v += n / 100)
    a.push_back(Vertex_index(static_cast<unsigned>(v)));
  const Field known = plain(mesh, a, VTP);
  const Vertex_index near = target(halfedge(a[10], mesh), mesh);
  const Field single = plain(mesh, near, VTP);
  const Field sum = add_to(mesh, known, near, a.size(), VTP);
  const double scale = max_finite(known.d);
  for(std::size_t v = 0; v < n; ++v)
    ASSERT_NEAR(sum.d[v], (std::min)(known.d[v], single.d[v]), 1e-12 * scale) << "vertex " << v;
  EXPECT_LT(sum.statistics.vertices_processed * 20, single.statistics.vertices_processed);
  EXPECT_LT(sum.statistics.windows_created * 20, single.statistics.windows_created);
  // a source already in the field (distance 0) does nothing
  const Field again = add_to(mesh, known, a[3], a.size(), VTP);
  EXPECT_EQ(again.statistics.windows_created, 0u);
  EXPECT_TRUE(identical(again.d, known.d));
}

TEST(Bad_input, initial_distances)
{
  const Surface_mesh mesh = load_mesh("elephant_395.off");
  std::vector<double> known(num_vertices(mesh), 1.);
  std::vector<double> out(num_vertices(mesh));
  auto kd = boost::make_iterator_property_map(known.begin(), get(boost::vertex_index, mesh));
  auto od = boost::make_iterator_property_map(out.begin(), get(boost::vertex_index, mesh));
  Solver solver(mesh);
  known[7] = std::numeric_limits<double>::quiet_NaN();
  try
  {
    solver.compute(od, Vertex_index(0), VP::initial_distances(kd));
    ADD_FAILURE() << "NaN accepted";
  }
  catch(const Invalid_input_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("vertex 7"), std::string::npos) << e.what();
  }
  known[7] = -1.;
  EXPECT_THROW(solver.compute(od, Vertex_index(0), VP::initial_distances(kd)), Invalid_input_error);
  known[7] = 1.;
  EXPECT_THROW(solver.compute(od, Vertex_index(0), VP::initial_distances(kd).maximum_distance(1.)),
               Invalid_input_error);
  EXPECT_THROW(solver.compute(od, Vertex_index(0), VP::initial_distances(kd).record_paths(true)), Invalid_input_error);
  EXPECT_THROW(solver.compute(od, Vertex_index(0), VP::first_source_label(3)), Invalid_input_error);
  solver.compute(od, Vertex_index(0), VP::initial_distances(kd));
  for(std::size_t v = 0; v < out.size(); ++v)
    EXPECT_LE(out[v], 1.);
  std::vector<Point_3> path;
  EXPECT_THROW(solver.shortest_path_points(Vertex_index(5), std::back_inserter(path)), Invalid_input_error);
  EXPECT_THROW(solver.compute_each(std::vector<Vertex_index>(1, Vertex_index(0)),
                                   [](std::size_t, Vertex_index, const std::vector<double>&) {},
                                   VP::initial_distances(kd)),
               Invalid_input_error);
}

// Farthest-point sampling equals the naive method: at every step, a full run from all the samples so far,
// and the farthest vertex (lowest index among ties). Two vertices whose distances differ by rounding may
// be taken in either order: then the sampling must have taken one of the farthest, and the naive method
// follows it.
TEST(Farthest_point_sampling, equals_the_naive_method)
{
  for(const auto& named : test_meshes())
  {
    const Surface_mesh& mesh = named.second;
    const std::size_t n = num_vertices(mesh);
    for(Method_kind method : exact_kinds())
    {
      SCOPED_TRACE(named.first + (method == PVTP ? " pvtp" : " vtp"));
      Solver solver(mesh);
      const std::size_t k = 12;
      CGAL::VTP_geodesics::Farthest_point_samples<Vertex_index> r;
      if(method == PVTP)
      {
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
        r = solver.farthest_point_sampling<CGAL::Parallel_tag>(k, VP::number_of_threads(2));
#endif
      }
      else
        r = solver.farthest_point_sampling(k);
      ASSERT_EQ(r.samples.size(), k);
      ASSERT_EQ(r.radii.size(), k);
      // the first sample: the vertex farthest from vertex 0
      EXPECT_EQ(std::size_t(r.samples[0]), farthest_vertex(plain(mesh, Vertex_index(0), method).d));
      std::vector<Vertex_index> so_far;
      Field naive;
      for(std::size_t i = 0; i < k; ++i)
      {
        if(i > 0)
        {
          // the naive choice
          const std::size_t best = farthest_vertex(naive.d);
          const double scale = max_finite(naive.d);
          const double taken = naive.d[std::size_t(r.samples[i])];
          if(std::size_t(r.samples[i]) != best)
          {
            EXPECT_TRUE(taken == naive.d[best] || std::abs(taken - naive.d[best]) <= 1e-12 * scale)
              << "sample " << i << ": " << std::size_t(r.samples[i]) << " at " << taken << ", naive " << best
              << " at " << naive.d[best];
          }
        }
        so_far.push_back(r.samples[i]);
        naive = plain(mesh, so_far, method);
        const double radius = *std::max_element(naive.d.begin(), naive.d.end());
        const double scale = std::isinf(radius) ? max_finite(naive.d) : radius;
        if(std::isinf(radius))
        {
          EXPECT_TRUE(std::isinf(r.radii[i])) << "radius " << i;
        }
        else
        {
          EXPECT_NEAR(r.radii[i], radius, 1e-12 * scale) << "radius " << i;
        }
      }
      const double scale = max_finite(naive.d);
      for(std::size_t v = 0; v < n; ++v)
      {
        if(std::isinf(naive.d[v]))
        {
          EXPECT_TRUE(std::isinf(r.distances[v]));
          EXPECT_EQ(r.labels[v], no_source);
          continue;
        }
        ASSERT_NEAR(r.distances[v], naive.d[v], 1e-12 * scale) << "vertex " << v;
      }
      // labels: the nearest sample, where it is unique by more than rounding
      std::vector<Field> single;
      for(Vertex_index s : r.samples)
        single.push_back(plain(mesh, s, method));
      for(std::size_t v = 0; v < n; ++v)
      {
        std::size_t best = no_source;
        double d1 = INF, d2 = INF;
        for(std::size_t i = 0; i < k; ++i)
          if(single[i].d[v] < d1)
          {
            d2 = d1;
            d1 = single[i].d[v];
            best = i;
          }
          else
            d2 = (std::min)(d2, single[i].d[v]);
        if(d2 - d1 > 1e-9 * scale)
        {
          EXPECT_EQ(r.labels[v], best) << "vertex " << v;
        }
      }
    }
  }
}

TEST(Farthest_point_sampling, radius_first_sample_and_every_vertex)
{
  const Surface_mesh mesh = load_mesh("elephant_395.off");
  Solver solver(mesh);
  const auto all = solver.farthest_point_sampling(5, VP::first_sample(Vertex_index(17)));
  EXPECT_EQ(std::size_t(all.samples[0]), 17u);
  for(std::size_t i = 1; i < all.radii.size(); ++i)
    EXPECT_LE(all.radii[i], all.radii[i - 1]);
  // a radius stops the sampling at the first covering radius not above it
  const double r = 0.5 * (all.radii[2] + all.radii[3]);
  const auto stopped = solver.farthest_point_sampling(100, VP::first_sample(Vertex_index(17)).sampling_radius(r));
  ASSERT_EQ(stopped.samples.size(), 4u);
  EXPECT_TRUE(std::equal(stopped.samples.begin(), stopped.samples.end(), all.samples.begin()));
  EXPECT_LE(stopped.radii.back(), r);
  // more samples than vertices: every vertex once, then the radius is 0
  const Surface_mesh tetrahedron = to_mesh<Surface_mesh>(regular_tetrahedron());
  Solver small(tetrahedron);
  const auto every = small.farthest_point_sampling(10);
  ASSERT_EQ(every.samples.size(), 4u);
  EXPECT_EQ(every.radii.back(), 0.);
  std::vector<Vertex_index> sorted = every.samples;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(std::unique(sorted.begin(), sorted.end()) == sorted.end());
  EXPECT_TRUE(small.farthest_point_sampling(0).samples.empty());
  // bad input
  EXPECT_THROW(solver.farthest_point_sampling(3, VP::first_sample(Vertex_index(100000))), Invalid_input_error);
  EXPECT_THROW(solver.farthest_point_sampling(3, VP::sampling_radius(-1.)), Invalid_input_error);
  EXPECT_THROW(solver.farthest_point_sampling(3, VP::maximum_distance(1.)), Invalid_input_error);
}

// With one and with two virtual sources per vertex (VSP, VSP2): each run adds a sample to the field of those
// before (a run from known distances that takes only the vertices the sample lowers). Expected: the first
// sample is the vertex farthest from vertex 0 in a run of the same method; the field is never below the
// exact distance to the nearest sample, nor to the sample of its label (it is the length of a path from it);
// 0 and its own label at each sample; the covering radii do not increase and the last is the largest
// distance; PVSP / PVSP2 give the same bits on 2 and 3 threads; unreachable vertices stay +infinity; the
// field stays close to the exact one.
TEST(Farthest_point_sampling, with_virtual_sources)
{
  for(int per_vertex : { 1, 2 })
  for(const auto& named : test_meshes())
  {
    SCOPED_TRACE(named.first + (per_vertex == 1 ? " vsp" : " vsp2"));
    const Surface_mesh& mesh = named.second;
    const std::size_t n = num_vertices(mesh);
    const std::size_t k = 12;
    Solver solver(mesh);
    const auto r =
      solver.farthest_point_sampling(k, VP::virtual_sources(true).virtual_sources_per_vertex(per_vertex));
    ASSERT_EQ(r.samples.size(), k);
    ASSERT_EQ(r.radii.size(), k);
    EXPECT_EQ(r.statistics.method, per_vertex == 1 ? "vsp" : "vsp2");
    const Field first_run = plain(mesh, Vertex_index(0), per_vertex == 1 ? VSP : VSP2);
    EXPECT_EQ(std::size_t(r.samples[0]), farthest_vertex(first_run.d));
    for(std::size_t i = 1; i < k; ++i)
      EXPECT_LE(r.radii[i], r.radii[i - 1]) << "radius " << i;
    EXPECT_EQ(r.radii.back(), *std::max_element(r.distances.begin(), r.distances.end()));
    std::vector<Vertex_index> sorted = r.samples;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_TRUE(std::unique(sorted.begin(), sorted.end()) == sorted.end());

    const Field exact = plain(mesh, r.samples, VTP);
    std::vector<Field> single;
    for(Vertex_index s : r.samples)
      single.push_back(plain(mesh, s, VTP));
    const double scale = max_finite(exact.d);
    double error = 0.;
    std::size_t counted = 0;
    for(std::size_t v = 0; v < n; ++v)
    {
      if(std::isinf(exact.d[v]))
      {
        EXPECT_TRUE(std::isinf(r.distances[v])) << "vertex " << v;
        EXPECT_EQ(r.labels[v], no_source) << "vertex " << v;
        continue;
      }
      ASSERT_LT(r.labels[v], k) << "vertex " << v;
      EXPECT_GE(r.distances[v], exact.d[v] - 1e-12 * scale) << "vertex " << v;
      EXPECT_GE(r.distances[v], single[r.labels[v]].d[v] - 1e-12 * scale) << "vertex " << v;
      if(exact.d[v] > 0.)
      {
        error += (r.distances[v] - exact.d[v]) / exact.d[v];
        ++counted;
      }
    }
    for(std::size_t i = 0; i < k; ++i)
    {
      EXPECT_EQ(r.distances[std::size_t(r.samples[i])], 0.) << "sample " << i;
      EXPECT_EQ(r.labels[std::size_t(r.samples[i])], i) << "sample " << i;
    }
    // (mean relative error, measured: vsp 0.21-1.19% on these meshes, the most with zero-length edges; vsp2
    // 0.02-1.08%)
    EXPECT_LT(error / double(counted), 0.02);
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    for(int threads : { 2, 3 })
    {
      SCOPED_TRACE(threads);
      const auto p = solver.farthest_point_sampling<CGAL::Parallel_tag>(
        k, VP::virtual_sources(true).virtual_sources_per_vertex(per_vertex).number_of_threads(threads));
      EXPECT_TRUE(p.samples == r.samples);
      EXPECT_TRUE(p.radii == r.radii);
      EXPECT_TRUE(identical(p.distances, r.distances));
      EXPECT_TRUE(p.labels == r.labels);
      EXPECT_EQ(p.statistics.method, per_vertex == 1 ? "pvsp" : "pvsp2");
    }
#endif
    // the solver runs an exact sampling again as before
    const auto again = solver.farthest_point_sampling(k);
    Solver fresh(mesh);
    const auto reference = fresh.farthest_point_sampling(k);
    EXPECT_TRUE(again.samples == reference.samples);
    EXPECT_TRUE(identical(again.distances, reference.distances));
  }
}

// The free function writes what the solver member returns; the work of k samples is far below k full runs.
TEST(Farthest_point_sampling, free_function_and_work)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  const std::size_t n = num_vertices(mesh);
  Solver solver(mesh);
  const auto r = solver.farthest_point_sampling(100);
  std::vector<Vertex_index> samples;
  std::vector<double> radii, d(n);
  std::vector<std::size_t> labels(n);
  Propagation_statistics st;
  CGAL::VTP_geodesics::farthest_point_sampling(
    mesh, 100, std::back_inserter(samples),
    VP::covering_radii(std::back_inserter(radii))
      .vertex_distance_map(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)))
      .nearest_source_map(boost::make_iterator_property_map(labels.begin(), get(boost::vertex_index, mesh)))
      .statistics(st));
  EXPECT_TRUE(samples == r.samples);
  EXPECT_TRUE(radii == r.radii);
  EXPECT_TRUE(identical(d, r.distances));
  EXPECT_TRUE(labels == r.labels);
  EXPECT_EQ(st.sources, 100u);
  EXPECT_EQ(st.windows_created, r.statistics.windows_created);
  // 100 samples: the vertices taken add up to a few full runs (a full run takes every vertex once or more)
  const Field one = plain(mesh, Vertex_index(0), VTP);
  EXPECT_LT(r.statistics.vertices_processed, 12 * one.statistics.vertices_processed);
  EXPECT_LT(r.statistics.windows_created, 12 * one.statistics.windows_created);
  // with virtual sources too
  const auto v = solver.farthest_point_sampling(100, VP::virtual_sources(true));
  EXPECT_EQ(v.statistics.method, "vsp");
  const Field vsp = plain(mesh, Vertex_index(0), VSP);
  EXPECT_LT(v.statistics.vertices_processed, 12 * vsp.statistics.vertices_processed);
  const auto v2 = solver.farthest_point_sampling(100, VP::virtual_sources(true).virtual_sources_per_vertex(2));
  EXPECT_EQ(v2.statistics.method, "vsp2");
  const Field vsp2 = plain(mesh, Vertex_index(0), VSP2);
  EXPECT_LT(v2.statistics.vertices_processed, 12 * vsp2.statistics.vertices_processed);
}

// Voronoi cells: the areas add up to the area of the mesh, and on a plane with two sources the cells are
// the two half-planes of the bisector, within the stated uncertainty.
TEST(Voronoi_cells, areas)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  Solver solver(mesh);
  const auto r = solver.farthest_point_sampling(20);
  const auto cells = CGAL::VTP_geodesics::geodesic_voronoi_cell_areas(mesh, r.samples.size(), r.labels, r.distances);
  ASSERT_EQ(cells.areas.size(), 20u);
  double sum = 0.;
  for(std::size_t i = 0; i < cells.areas.size(); ++i)
  {
    EXPECT_GT(cells.areas[i], 0.);
    sum += cells.areas[i];
  }
  const double area = CGAL::Polygon_mesh_processing::area(mesh);
  EXPECT_NEAR(sum, area, 1e-9 * area);

  const Surface_mesh plane = to_mesh<Surface_mesh>(planar_grid(21, 20, 1., 1.));
  const Vertex_index s0 = find_vertex(plane, Point_3(0., 0.5, 0.)), s1 = find_vertex(plane, Point_3(1., 0.5, 0.));
  const Field two = plain(plane, std::vector<Vertex_index>{ s0, s1 }, VTP);
  const auto halves = CGAL::VTP_geodesics::geodesic_voronoi_cell_areas(plane, 2, two.label, two.d);
  for(int i = 0; i < 2; ++i)
  {
    // the faces of the column that the bisector x = 1/2 crosses are split: within a quarter of their area
    EXPECT_NEAR(halves.uncertainty[i], 1. / 21., 1e-12) << "cell " << i;
    EXPECT_NEAR(halves.areas[i], 0.5, 0.25 * halves.uncertainty[i]) << "cell " << i;
  }
  EXPECT_NEAR(halves.areas[0] + halves.areas[1], 1., 1e-12);
  EXPECT_THROW(CGAL::VTP_geodesics::geodesic_voronoi_cell_areas(plane, 1, two.label, two.d),
               Invalid_input_error);
}
