// Early stop (a distance limit, targets at vertices and at points of faces) and geodesic paths (planar,
// cylinder unfolding, reflex corner, real meshes against CGAL::Surface_mesh_shortest_path), for VTP, PVTP,
// AVTP and PAVTP.

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>
#include <vtp_support/midpoint_subdivision.h>

#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <array>
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
namespace VP = CGAL::VTP_geodesics::parameters;

typedef Surface_mesh::Face_index Face_index;
typedef std::pair<Face_index, std::array<double, 3> > Location;
typedef Geodesic_distance_solver<Surface_mesh> Solver;

namespace {

std::vector<Method> all_methods()
{
  std::vector<Method> r = { { "vtp", false, INF }, { "avtp", false, 2. } };
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
  r.push_back({ "pvtp", true, INF });
  r.push_back({ "pavtp", true, 2. });
#endif
  return r;
}

// Runs `method` on `solver` from `sources` with the extra named parameters `np` (a VP chain); returns the
// distances by vertex index.
template <class Sources, class NP>
std::vector<double> run(Solver& solver, const Surface_mesh& mesh, const Sources& sources, const Method& method,
                        const NP& np)
{
  std::vector<double> d(num_vertices(mesh), NOT_A_VERTEX);
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  if(method.parallel)
  {
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    solver.compute<CGAL::Parallel_tag>(map, sources, np.lambda(method.lambda).number_of_threads(2));
#endif
  }
  else
    solver.compute(map, sources, np.lambda(method.lambda));
  return d;
}

double distance_to_segment(const Point_3& p, const Point_3& a, const Point_3& b)
{
  const Vector_3 ab = b - a, ap = p - a;
  const double l2 = ab.squared_length();
  double t = l2 > 0. ? (ap * ab) / l2 : 0.;
  t = (std::min)(1., (std::max)(0., t));
  return distance(p, a + t * ab);
}

double distance_to_polyline(const Point_3& p, const std::vector<Point_3>& q)
{
  if(q.size() == 1)
    return distance(p, q[0]);
  double d = INF;
  for(std::size_t i = 1; i < q.size(); ++i)
    d = (std::min)(d, distance_to_segment(p, q[i - 1], q[i]));
  return d;
}

// Hausdorff distance between two polylines, from samples along each segment.
double hausdorff(const std::vector<Point_3>& a, const std::vector<Point_3>& b)
{
  double h = 0.;
  for(int pass = 0; pass < 2; ++pass)
  {
    const std::vector<Point_3>& p = pass == 0 ? a : b;
    const std::vector<Point_3>& q = pass == 0 ? b : a;
    for(std::size_t i = 0; i < p.size(); ++i)
    {
      h = (std::max)(h, distance_to_polyline(p[i], q));
      if(i + 1 < p.size())
        for(int s = 1; s < 8; ++s)
          h = (std::max)(h, distance_to_polyline(p[i] + (s / 8.) * (p[i + 1] - p[i]), q));
    }
  }
  return h;
}

// Checks a path given as points and as face locations: same length as points, every location inside its
// face and at its point, every segment inside one face (both ends are points of a common face).
::testing::AssertionResult is_a_path_on_the_surface(const Surface_mesh& mesh, const std::vector<Point_3>& points,
                                                    const std::vector<Location>& locations, double tolerance)
{
  if(points.size() != locations.size() || points.empty())
    return ::testing::AssertionFailure() << points.size() << " points and " << locations.size() << " locations";
  auto faces_of = [&](const Location& l) {
    // the faces that contain the point: its face, and the faces around the edge or vertex it lies on
    std::vector<Face_index> r(1, l.first);
    const Surface_mesh::Halfedge_index h0 = mesh.halfedge(l.first);
    Surface_mesh::Halfedge_index h = h0;
    for(int k = 0; k < 3; ++k, h = mesh.next(h))
    {
      const double bk = l.second[std::size_t(k)], bk1 = l.second[std::size_t((k + 1) % 3)];
      const double bk2 = l.second[std::size_t((k + 2) % 3)];
      if(bk2 == 0. && !mesh.is_border(mesh.opposite(h)))
        r.push_back(mesh.face(mesh.opposite(h)));                   // on the edge of h
      if(bk == 1. && bk1 == 0. && bk2 == 0.)
        for(Face_index f : CGAL::faces_around_target(mesh.prev(h), mesh))
          if(f != Surface_mesh::null_face())
            r.push_back(f);                                         // at the vertex source(h)
    }
    return r;
  };
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    for(double b : locations[i].second)
      if(!(b >= -1e-12 && b <= 1. + 1e-12))
        return ::testing::AssertionFailure() << "point " << i << ": barycentric coordinate " << b;
    if(distance(points[i], point_of(mesh, locations[i])) > tolerance)
      return ::testing::AssertionFailure() << "point " << i << " is not at its location";
    if(i == 0)
      continue;
    const std::vector<Face_index> a = faces_of(locations[i - 1]), b = faces_of(locations[i]);
    bool common = false;
    for(Face_index f : a)
      for(Face_index g : b)
        common = common || f == g;
    if(!common)
      return ::testing::AssertionFailure() << "segment " << i - 1 << "-" << i << " lies in no face";
  }
  return ::testing::AssertionSuccess();
}

std::vector<Point_3> path_points(Solver& solver, Vertex_index v)
{
  std::vector<Point_3> p;
  solver.shortest_path_points(v, std::back_inserter(p));
  return p;
}

std::vector<Location> path_locations(Solver& solver, Vertex_index v)
{
  std::vector<Location> l;
  solver.shortest_path_locations(v, std::back_inserter(l));
  return l;
}

typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, Surface_mesh> Smsp_traits;
typedef CGAL::Surface_mesh_shortest_path<Smsp_traits> Smsp;

} // namespace

// ---------------------------------------------------------------------------------------------------
// Distance limit
// ---------------------------------------------------------------------------------------------------

TEST(Distance_limit, equals_the_full_run_inside_and_work_shrinks_with_the_radius)
{
  Surface_mesh mesh = load_mesh("elephant.off");
  vtp_support::midpoint_subdivide(mesh, 1);
  Solver solver(mesh);
  const Vertex_index s(100);
  for(const Method& m : all_methods())
  {
    const std::vector<double> full = run(solver, mesh, s, m, VP::maximum_distance(INF));
    const Propagation_statistics full_stats = solver.statistics();
    EXPECT_FALSE(full_stats.stopped_early);
    const double max_d = max_finite(full);
    std::size_t previous_processed = 0, previous_windows = 0;
    for(double fraction : { 0.1, 0.3, 0.6 })
    {
      const double R = fraction * max_d;
      const std::vector<double> d = run(solver, mesh, s, m, VP::maximum_distance(R));
      const Propagation_statistics st = solver.statistics();
      std::size_t inside = 0, bitwise = 0;
      for(std::size_t i = 0; i < d.size(); ++i)
      {
        if(full[i] <= R)
        {
          ++inside;
          ASSERT_NEAR(d[i], full[i], EXACT_TOLERANCE * max_d) << m.name << ", R = " << R << ", vertex " << i;
          bitwise += d[i] == full[i];
        }
        else
        {
          ASSERT_TRUE(d[i] == INF || d[i] <= R) << m.name << ", vertex " << i << " beyond the limit: " << d[i];
        }
        if(d[i] <= R)
        {
          ASSERT_LE(full[i], R * (1. + 1e-12) + 1e-300) << m.name << ": only vertices within the limit are finite";
        }
      }
      std::cout << "  [" << m.name << ", R = " << fraction << " max] " << inside << " vertices inside, " << bitwise
                << " bitwise equal to the full run; processed " << st.vertices_processed << " of "
                << full_stats.vertices_processed << ", windows " << st.windows_propagated << " of "
                << full_stats.windows_propagated << std::endl;
      EXPECT_TRUE(st.stopped_early);
      EXPECT_GT(inside, 0u);
      EXPECT_LT(st.vertices_processed, full_stats.vertices_processed);
      EXPECT_LT(st.windows_propagated, full_stats.windows_propagated);
      EXPECT_GT(st.vertices_processed, previous_processed) << "the work grows with the radius";
      EXPECT_GT(st.windows_propagated, previous_windows);
      previous_processed = st.vertices_processed;
      previous_windows = st.windows_propagated;
    }
    // a tiny limit: the source only (and vertices at distance 0)
    const std::vector<double> d = run(solver, mesh, s, m, VP::maximum_distance(0.));
    EXPECT_EQ(d[s], 0.);
    EXPECT_EQ(solver.statistics().reached_vertices, 1u);
  }
}

TEST(Distance_limit, invalid_limits_are_rejected)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  Solver solver(mesh);
  std::vector<double> d(num_vertices(mesh));
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  for(double bad : { -1., -INF, std::numeric_limits<double>::quiet_NaN() })
    EXPECT_THROW(solver.compute(map, Vertex_index(0), VP::maximum_distance(bad)), Invalid_input_error) << bad;
  EXPECT_NO_THROW(solver.compute(map, Vertex_index(0), VP::maximum_distance(INF)));
}

// ---------------------------------------------------------------------------------------------------
// Targets
// ---------------------------------------------------------------------------------------------------

TEST(Targets, vertex_targets_stop_early_and_equal_the_full_run)
{
  Surface_mesh mesh = load_mesh("knot1.off");
  vtp_support::midpoint_subdivide(mesh, 1);
  Solver solver(mesh);
  const Vertex_index s(0);
  for(const Method& m : all_methods())
  {
    const std::vector<double> full = run(solver, mesh, s, m, VP::stop_at_targets(true));
    const std::size_t full_processed = solver.statistics().vertices_processed;
    // the 5 vertices nearest the source after itself
    std::vector<std::pair<double, std::size_t> > order;
    for(std::size_t i = 0; i < full.size(); ++i)
      order.push_back(std::make_pair(full[i], i));
    std::sort(order.begin(), order.end());
    std::vector<Vertex_index> targets;
    for(std::size_t i = 1; i <= 5; ++i)
      targets.push_back(Vertex_index(static_cast<Surface_mesh::size_type>(order[i].second)));
    const std::vector<double> d = run(solver, mesh, s, m, VP::targets(targets));
    const Propagation_statistics st = solver.statistics();
    EXPECT_TRUE(st.stopped_early) << m.name;
    EXPECT_LT(st.vertices_processed, full_processed / 10) << m.name << ": near targets, little work";
    ASSERT_EQ(solver.number_of_targets(), targets.size());
    for(std::size_t i = 0; i < targets.size(); ++i)
    {
      EXPECT_NEAR(solver.target_distance(i), full[targets[i]], EXACT_TOLERANCE * max_finite(full)) << m.name;
      EXPECT_EQ(solver.target_distance(i), d[targets[i]]);
    }
    // every finite output is final (equal to the full run); the others are +infinity
    for(std::size_t i = 0; i < d.size(); ++i)
    {
      if(std::isfinite(d[i]))
      {
        ASSERT_NEAR(d[i], full[i], EXACT_TOLERANCE * max_finite(full)) << m.name << ", vertex " << i;
      }
      else
      {
        ASSERT_EQ(d[i], INF);
      }
    }
    // a far target: the whole mesh, the same distance
    const Vertex_index far(static_cast<Surface_mesh::size_type>(order.back().second));
    run(solver, mesh, s, m, VP::targets(far));
    EXPECT_NEAR(solver.target_distance(0), full[far], EXACT_TOLERANCE * max_finite(full)) << m.name;
  }
}

TEST(Targets, face_targets_match_smsp_and_the_plane)
{
  // analytic: a plane
  {
    const int n = 16;
    const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1., 0.3, 4u));
    Solver solver(mesh);
    const Location source(Face_index(40), { { 0.2, 0.5, 0.3 } });
    const std::vector<Location> targets = { Location(Face_index(300), { { 0.1, 0.1, 0.8 } }),
                                            Location(Face_index(511), { { 0.5, 0.5, 0. } }),
                                            Location(Face_index(40), { { 0.6, 0.2, 0.2 } }) };  // the source's face
    for(const Method& m : all_methods())
    {
      if(m.lambda < INF)
        continue;
      run(solver, mesh, source, m, VP::targets(targets));
      for(std::size_t i = 0; i < targets.size(); ++i)
        EXPECT_NEAR(solver.target_distance(i), distance(point_of(mesh, source), point_of(mesh, targets[i])), 1e-13)
          << m.name << ", target " << i;
    }
  }
  // real meshes: CGAL SMSP queried at the same face locations (inside faces: SMSP is wrong at edge points)
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "three_peaks.off" })
  {
    const Surface_mesh mesh = load_mesh(name);
    const std::size_t nf = num_faces(mesh);
    Smsp smsp(mesh);
    smsp.add_source_point(Vertex_index(7));
    smsp.build_sequence_tree();
    std::vector<Location> targets;
    for(std::size_t k = 1; k <= 6; ++k)
      targets.push_back(Location(Face_index(static_cast<Surface_mesh::size_type>(k * nf / 7)), { { 0.3, 0.45, 0.25 } }));
    Solver solver(mesh);
    std::vector<double> full(num_vertices(mesh));
    solver.compute(boost::make_iterator_property_map(full.begin(), get(boost::vertex_index, mesh)), Vertex_index(7));
    for(const Method& m : all_methods())
    {
      run(solver, mesh, Vertex_index(7), m, VP::targets(targets));
      for(std::size_t i = 0; i < targets.size(); ++i)
      {
        const double expected =
          smsp.shortest_distance_to_source_points(targets[i].first,
                                                  Smsp_traits::Barycentric_coordinates{ { 0.3, 0.45, 0.25 } }).first;
        if(m.lambda < INF)
          EXPECT_GE(solver.target_distance(i), expected - EXACT_TOLERANCE * max_finite(full)) << name << ", " << m.name;
        else
          EXPECT_NEAR(solver.target_distance(i), expected, EXACT_TOLERANCE * max_finite(full))
            << name << ", " << m.name << ", target " << i;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// Paths
// ---------------------------------------------------------------------------------------------------

TEST(Paths, a_single_straight_segment_on_a_plane)
{
  const int n = 20;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 17u);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Vertex_index s(static_cast<Surface_mesh::size_type>(grid_vertex(n, 3, 4)));
  for(const Method& m : all_methods())
  {
    if(m.lambda < INF)
      continue;
    Solver solver(mesh);
    const std::vector<double> d = run(solver, mesh, s, m, VP::record_paths(true));
    for(Vertex_index v : { Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, 17, 15))),
                           Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, 0, 20))),
                           Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, 20, 0))) })
    {
      const std::vector<Point_3> p = path_points(solver, v);
      ASSERT_GE(p.size(), 2u);
      EXPECT_EQ(p.front(), mesh.point(v));
      EXPECT_EQ(p.back(), mesh.point(s));
      EXPECT_NEAR(polyline_length(p), d[v], 1e-12 * std::sqrt(2.)) << m.name;
      EXPECT_NEAR(polyline_length(p), distance(mesh.point(s), mesh.point(v)), 1e-12 * std::sqrt(2.));
      for(const Point_3& q : p)
        EXPECT_LT(distance_to_segment(q, mesh.point(s), mesh.point(v)), 1e-12) << m.name << ": off the straight line";
      EXPECT_TRUE(is_a_path_on_the_surface(mesh, p, path_locations(solver, v), 1e-12));
    }
  }
}

TEST(Paths, the_unfolded_straight_line_on_a_cylinder)
{
  // lateral surface of a prism of 24 sides: unfolded, a strip where geodesics are straight
  const int sides = 24, bands = 10;
  const double radius = 1., height = 3.;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(open_prism(sides, bands, radius, height));
  const double side = 2. * radius * std::sin(PI / sides);
  auto unfold = [&](const Point_3& p) {
    // the side whose chord is nearest, and the position along it
    int best = 0;
    double best_d = INF;
    for(int k = 0; k < sides; ++k)
    {
      const Point_3 a(radius * std::cos(2. * PI * k / sides), radius * std::sin(2. * PI * k / sides), p.z());
      const Point_3 b(radius * std::cos(2. * PI * (k + 1) / sides), radius * std::sin(2. * PI * (k + 1) / sides), p.z());
      const double dk = distance_to_segment(p, a, b);
      if(dk < best_d - 1e-12)
      {
        best_d = dk;
        best = k;
      }
    }
    const Point_3 a(radius * std::cos(2. * PI * best / sides), radius * std::sin(2. * PI * best / sides), p.z());
    return std::make_pair(best * side + distance(p, a), p.z());
  };
  const Vertex_index s(0);                                                                // corner 0, ring 0
  const Vertex_index t(static_cast<Surface_mesh::size_type>(bands * sides + 5));          // corner 5, top ring
  Solver solver(mesh);
  std::vector<double> d(num_vertices(mesh));
  solver.compute(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)), s, VP::record_paths(true));
  const double expected = std::sqrt(25. * side * side + height * height);
  EXPECT_NEAR(d[t], expected, 1e-13);
  const std::vector<Point_3> p = path_points(solver, t);
  EXPECT_GT(p.size(), 6u) << "the path crosses the edges of the strip";
  EXPECT_NEAR(polyline_length(p), expected, 1e-12);
  const std::pair<double, double> u0 = unfold(mesh.point(s)), u1 = unfold(mesh.point(t));
  for(const Point_3& q : p)
  {
    const std::pair<double, double> u = unfold(q);
    // distance of (u.first, u.second) to the unfolded segment
    const double ax = u1.first - u0.first, ay = u1.second - u0.second;
    const double off = std::abs(ax * (u.second - u0.second) - ay * (u.first - u0.first)) / std::sqrt(ax * ax + ay * ay);
    EXPECT_LT(off, 1e-12) << "path point off the unfolded straight line";
  }
  EXPECT_TRUE(is_a_path_on_the_surface(mesh, p, path_locations(solver, t), 1e-12));
}

TEST(Paths, around_the_reflex_corner_of_an_l_shape)
{
  const int n = 10;
  const Polygon_soup soup = l_shape(n);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Vertex_index s = find_vertex(mesh, Point_3(1.8, 0.9, 0.));
  const Vertex_index t = find_vertex(mesh, Point_3(0.9, 1.8, 0.));
  const Vertex_index corner = find_vertex(mesh, Point_3(1., 1., 0.));
  ASSERT_NE(s, Surface_mesh::null_vertex());
  for(const Method& m : all_methods())
  {
    if(m.lambda < INF)
      continue;
    Solver solver(mesh);
    const std::vector<double> d = run(solver, mesh, s, m, VP::record_paths(true));
    const std::vector<Point_3> p = path_points(solver, t);
    const double expected = 2. * distance(mesh.point(s), mesh.point(corner));
    EXPECT_NEAR(d[t], expected, 1e-14);
    EXPECT_NEAR(polyline_length(p), expected, 1e-14) << m.name;
    EXPECT_NE(std::find(p.begin(), p.end(), mesh.point(corner)), p.end()) << m.name << ": the path turns at the corner";
    for(const Point_3& q : p)
      EXPECT_LT((std::min)(distance_to_segment(q, mesh.point(s), mesh.point(corner)),
                           distance_to_segment(q, mesh.point(corner), mesh.point(t))), 1e-14);
  }
}

TEST(Paths, real_meshes_match_smsp)
{
  for(const char* name : { "elephant.off", "mech-holes-shark.off", "mushroom.off" })
  {
    const Surface_mesh mesh = load_mesh(name);
    const std::size_t n = num_vertices(mesh);
    const Vertex_index s(static_cast<Surface_mesh::size_type>(n / 5));
    Smsp smsp(mesh);
    smsp.add_source_point(s);
    smsp.build_sequence_tree();
    for(const Method& m : all_methods())
    {
      Solver solver(mesh);
      const std::vector<double> d = run(solver, mesh, s, m, VP::record_paths(true));
      const double max_d = max_finite(d);
      std::size_t compared = 0, ties = 0;
      for(std::size_t k = 0; k < 40; ++k)
      {
        const Vertex_index v(static_cast<Surface_mesh::size_type>((k * 7919) % n));
        if(!std::isfinite(d[v]))
          continue;
        const std::vector<Point_3> p = path_points(solver, v);
        ASSERT_NEAR(polyline_length(p), d[v], 1e-12 * max_d) << name << ", " << m.name << ", vertex " << v;
        ASSERT_TRUE(is_a_path_on_the_surface(mesh, p, path_locations(solver, v), 1e-12 * max_d))
          << name << ", " << m.name << ", vertex " << v;
        EXPECT_EQ(p.front(), mesh.point(v));
        EXPECT_EQ(p.back(), mesh.point(s));
        if(m.lambda < INF)
          continue;
        std::vector<Point_3> reference;
        smsp.shortest_path_points_to_source_points(v, std::back_inserter(reference));
        const double h = hausdorff(p, reference);
        if(h > 1e-9 * max_d)
        {
          // two different shortest paths of the same length are both right
          ASSERT_NEAR(polyline_length(reference), polyline_length(p), 1e-12 * max_d)
            << name << ", " << m.name << ", vertex " << v << ": Hausdorff distance " << h << " to CGAL's path";
          ++ties;
        }
        ++compared;
      }
      std::cout << "  [" << name << ", " << m.name << "] " << compared << " paths compared with CGAL, " << ties
                << " ties skipped" << std::endl;
      if(m.lambda == INF)
      {
        EXPECT_GT(compared, 30u);
      }
    }
  }
}

TEST(Paths, through_a_vertex_and_zero_length_edges)
{
  // found by vtp_stress: the path of vertex 40 goes exactly through vertex 208 (the end of a window), which
  // coincides with vertex 124 and is a vertex of a sliver; the walk face by face cannot follow the line there
  const Surface_mesh mesh = load_mesh("degenerate_zero_length_edges.off");
  const std::size_t n = num_vertices(mesh);
  for(const Method& m : all_methods())
    for(std::size_t source : { std::size_t(164), std::size_t(0), n / 2 })
    {
      const Vertex_index s(static_cast<Surface_mesh::size_type>(source));
      if(mesh.is_isolated(s))
        continue;
      Solver solver(mesh);
      const std::vector<double> d = run(solver, mesh, s, m, VP::record_paths(true));
      const double max_d = max_finite(d);
      for(Vertex_index v : vertices(mesh))
      {
        if(mesh.is_isolated(v) || !std::isfinite(d[v]))
          continue;
        const std::vector<Point_3> p = path_points(solver, v);
        ASSERT_NEAR(polyline_length(p), d[v], 1e-12 * max_d) << m.name << ", source " << s << ", vertex " << v;
        ASSERT_TRUE(is_a_path_on_the_surface(mesh, p, path_locations(solver, v), 1e-12 * max_d))
          << m.name << ", source " << s << ", vertex " << v;
        ASSERT_EQ(p.front(), mesh.point(v));
        ASSERT_EQ(p.back(), mesh.point(s));
      }
    }
}

TEST(Paths, through_coincident_vertices_that_lower_each_other_by_rounding)
{
  // found by the fuzzer (fuzz_vtp.cpp; slivers 8 times longer than wide, minimised by hand): vertices 1 and 5
  // coincide (a zero-length edge between two faces of zero area). Vertex 5 got its distance from a window
  // whose line reaches it at the point of vertex 1 (through a face of zero area between them), one ulp below
  // the distance of vertex 1; then vertex 1 got that distance from vertex 5, along the zero-length edge: each
  // one's record led through the other, and the trace-back went round until it lost the line (the query
  // threw "the geodesic path could not be traced back"). An offer within rounding of the recorded one no
  // longer replaces it (Path_record::tie).
  Polygon_soup soup;
  soup.points = {Point_3(0.15625, 1.5, 0.), Point_3(0.21875, 1.5, 1.), Point_3(0.34375, 1.5, -0.25),
                 Point_3(0.53125, 0.5, 0.75), Point_3(0.0625, 2.5, 0.), Point_3(0.21875, 1.5, 1.),
                 Point_3(0.3125, 2.25, -0.25), Point_3(0.4375, 1.75, 0.), Point_3(0.125, 2.5, 0.),
                 Point_3(0.21875, 3.5, 0.25), Point_3(0.4375, 3.5, 0.25), Point_3(0.46875, 2.5, 0.5),
                 Point_3(0.21875, 4.5, -0.5), Point_3(0.3125, 3.75, 0.), Point_3(0.5, 3.75, 1.),
                 Point_3(0.6875, 3.75, 0.5), Point_3(0.3125, 5.25, -0.25), Point_3(0.3125, 5.25, 1.),
                 Point_3(0.5625, 4.5, 0.5), Point_3(0.5625, 4.75, 0.25)};
  soup.polygons = {{0, 1, 5},    {0, 5, 4},    {1, 2, 6},    {1, 6, 5},    {2, 3, 6},   {3, 7, 6},
                   {4, 5, 8},    {5, 9, 8},    {5, 6, 9},    {6, 7, 10},   {7, 11, 10}, {8, 9, 12},
                   {9, 13, 12},  {10, 11, 14}, {11, 15, 14}, {12, 13, 16}, {13, 17, 16}, {13, 14, 18},
                   {13, 18, 17}, {14, 15, 19}, {14, 19, 18}};
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(const Method& m : all_methods())
    for(std::size_t source : { std::size_t(7), std::size_t(0), std::size_t(16) })
    {
      const Vertex_index s(static_cast<Surface_mesh::size_type>(source));
      Solver solver(mesh);
      const std::vector<double> d = run(solver, mesh, s, m, VP::record_paths(true));
      const double max_d = max_finite(d);
      for(Vertex_index v : vertices(mesh))
      {
        std::vector<Point_3> p;
        ASSERT_NO_THROW(p = path_points(solver, v)) << m.name << ", source " << s << ", vertex " << v;
        ASSERT_NEAR(polyline_length(p), d[v], 1e-12 * max_d) << m.name << ", source " << s << ", vertex " << v;
        ASSERT_TRUE(is_a_path_on_the_surface(mesh, p, path_locations(solver, v), 1e-12 * max_d))
          << m.name << ", source " << s << ", vertex " << v;
        ASSERT_EQ(p.front(), mesh.point(v));
        ASSERT_EQ(p.back(), mesh.point(s));
      }
    }
}

TEST(Paths, to_face_targets_and_with_several_sources)
{
  const Surface_mesh mesh = load_mesh("elephant-with-holes.off");
  const std::size_t nf = num_faces(mesh);
  const std::vector<Vertex_index> sources = { Vertex_index(10), Vertex_index(1500) };
  const Location target(Face_index(static_cast<Surface_mesh::size_type>(nf / 3)), { { 0.25, 0.25, 0.5 } });
  Smsp smsp(mesh);
  for(Vertex_index s : sources)
    smsp.add_source_point(s);
  smsp.build_sequence_tree();
  for(bool recorded : { true, false })
  {
    Solver solver(mesh);
    std::vector<double> d(num_vertices(mesh));
    std::vector<std::size_t> labels(num_vertices(mesh));
    solver.compute(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)), sources,
                   VP::targets(target).stop_at_targets(false).record_paths(recorded).nearest_source_map(
                     boost::make_iterator_property_map(labels.begin(), get(boost::vertex_index, mesh))));
    const double max_d = max_finite(d);
    // the face target
    std::vector<Point_3> p;
    std::vector<Location> l;
    solver.shortest_path_points(target, std::back_inserter(p));
    solver.shortest_path_locations(target, std::back_inserter(l));
    EXPECT_NEAR(polyline_length(p), solver.target_distance(0), 1e-12 * max_d);
    EXPECT_TRUE(is_a_path_on_the_surface(mesh, p, l, 1e-12 * max_d));
    EXPECT_LT(distance(p.front(), point_of(mesh, target)), 1e-14);
    std::vector<Point_3> reference;
    smsp.shortest_path_points_to_source_points(target.first,
                                               Smsp_traits::Barycentric_coordinates{ { 0.25, 0.25, 0.5 } },
                                               std::back_inserter(reference));
    EXPECT_LT(hausdorff(p, reference), 1e-9 * max_d);
    // a point that was not a target: traced by a second propagation
    const Location other(Face_index(static_cast<Surface_mesh::size_type>(2 * nf / 3)), { { 0.1, 0.6, 0.3 } });
    std::vector<Point_3> q;
    solver.shortest_path_points(other, std::back_inserter(q));
    const double expected = smsp.shortest_distance_to_source_points(
      other.first, Smsp_traits::Barycentric_coordinates{ { 0.1, 0.6, 0.3 } }).first;
    EXPECT_NEAR(polyline_length(q), expected, 1e-12 * max_d);
    for(Vertex_index v : vertices(mesh))
      ASSERT_EQ(solver.distance(v), d[v]) << "the results of the computation do not change";
    // several sources: each path ends at the nearest one
    for(std::size_t k = 0; k < 30; ++k)
    {
      const Vertex_index v(static_cast<Surface_mesh::size_type>(k * 97 % num_vertices(mesh)));
      if(!std::isfinite(d[v]))
        continue;
      const std::vector<Point_3> pv = path_points(solver, v);
      EXPECT_NEAR(polyline_length(pv), d[v], 1e-12 * max_d);
      EXPECT_EQ(pv.back(), mesh.point(sources[labels[v]])) << "vertex " << v;
    }
    // a path to a source is the source alone
    EXPECT_EQ(path_points(solver, sources[1]).size(), 1u);
  }
}

TEST(Paths, bad_requests)
{
  Polygon_soup soup = planar_grid(5, 5, 1., 1.);
  soup.append(regular_tetrahedron(), Vector_3(10, 0, 0));
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  Solver solver(mesh);
  std::vector<Point_3> p;
  EXPECT_THROW(solver.shortest_path_points(Vertex_index(3), std::back_inserter(p)), Invalid_input_error)
    << "no computation yet";
  std::vector<double> d(num_vertices(mesh));
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  for(bool recorded : { true, false })
  {
    solver.compute(map, Vertex_index(0), VP::record_paths(recorded).maximum_distance(1.));
    EXPECT_THROW(solver.shortest_path_points(Vertex_index(37), std::back_inserter(p)), Invalid_input_error)
      << "another component";
    EXPECT_THROW(solver.shortest_path_points(Location(Face_index(52), { { 0.2, 0.3, 0.5 } }), std::back_inserter(p)),
                 Invalid_input_error)
      << "a point of another component";
    const Vertex_index far(35); // (1, 1): at distance sqrt 2 > 1
    EXPECT_THROW(solver.shortest_path_points(far, std::back_inserter(p)), Invalid_input_error)
      << "beyond the limit";
    EXPECT_THROW(solver.shortest_path_points(Vertex_index(1000), std::back_inserter(p)), Invalid_input_error);
    EXPECT_THROW(solver.shortest_path_points(Location(Face_index(0), { { 0.5, 0.6, 0.5 } }), std::back_inserter(p)),
                 Invalid_input_error);
    p.clear();
    solver.shortest_path_points(Vertex_index(7), std::back_inserter(p));
    EXPECT_NEAR(polyline_length(p), d[7], 1e-14);
  }
}
