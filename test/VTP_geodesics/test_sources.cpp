// Sources: several at once (the minimum of single-source runs, nearest-source labels), points of the
// surface given as face locations (against CGAL::Surface_mesh_shortest_path with the same locations, and
// analytic planar cases), the source set of the solver, and bad sources. For VTP, PVTP, AVTP and PAVTP, on
// Surface_mesh and Polyhedron_3.
// Many sources one at a time: compute_each() (rows equal single computations bit for bit, errors).

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

using namespace vtp_test;
using CGAL::VTP_geodesics::Geodesic_distance_solver;
using CGAL::VTP_geodesics::Invalid_input_error;
using CGAL::VTP_geodesics::no_source;
namespace VP = CGAL::VTP_geodesics::parameters;

typedef Surface_mesh::Face_index Face_index;
typedef std::pair<Face_index, std::array<double, 3> > Location;
typedef Geodesic_distance_solver<Surface_mesh> Solver;

namespace {

// The four methods: scheduling and reset period.
const Method exact_methods[] = { { "vtp", false, INF }, { "pvtp", true, INF } };
const Method approximate_methods[] = { { "avtp", false, 2. }, { "pavtp", true, 2. } };

// Distances (by vertex index) and nearest-source labels from `sources` (a vertex, a location, or a range).
template <class Sources>
std::pair<std::vector<double>, std::vector<std::size_t> >
run(const Surface_mesh& mesh, const Sources& sources, const Method& method, int threads = 2)
{
  std::vector<double> d(num_vertices(mesh), NOT_A_VERTEX);
  std::vector<std::size_t> labels(num_vertices(mesh), std::size_t(12345));
  auto dmap = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  auto lmap = boost::make_iterator_property_map(labels.begin(), get(boost::vertex_index, mesh));
  Solver solver(mesh);
  const auto np = VP::nearest_source_map(lmap).lambda(method.lambda).number_of_threads(threads);
  if(method.parallel)
  {
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    solver.compute<CGAL::Parallel_tag>(dmap, sources, np);
#else
    ADD_FAILURE() << "no OpenMP";
#endif
  }
  else
    solver.compute(dmap, sources, np);
  return std::make_pair(d, labels);
}

std::vector<const Method*> methods_to_test(bool approximate)
{
  std::vector<const Method*> r;
  for(const Method& m : approximate ? approximate_methods : exact_methods)
  {
#ifndef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    if(m.parallel)
      continue;
#endif
    r.push_back(&m);
  }
  return r;
}

// Reference distances from face locations with CGAL::Surface_mesh_shortest_path (the mesh is connected).
//
// SMSP is wrong for a source point exactly on an edge: on elephant.off, the point (0.45, 0, 0.55) of face
// 2779 gives distances up to 0.25% away from those of the point (0.45 - 1e-10, 1e-10, 0.55) of the same
// face, while ours differ by 2e-12. So a source on an edge (one zero coordinate) is given to SMSP as a
// vertex of a copy of the mesh where the edge is split at that point (the same surface; SMSP is exact from
// vertices, see the oracle tests); the original vertices keep their indices.
std::vector<double> smsp_distances(const Surface_mesh& mesh, const std::vector<Location>& sources)
{
  typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, Surface_mesh> Traits;
  typedef CGAL::Surface_mesh_shortest_path<Traits> Shortest_path;
  Surface_mesh reference = mesh;
  std::vector<Location> in_faces;
  std::vector<Vertex_index> on_edges;
  for(const Location& l : sources)
  {
    int zeros = 0, zero = 0;
    for(int k = 0; k < 3; ++k)
      if(l.second[std::size_t(k)] == 0.)
      {
        ++zeros;
        zero = k;
      }
    if(zeros != 1)
    {
      in_faces.push_back(l);
      continue;
    }
    // the half-edge of the edge opposite to corner `zero`, from corner zero+1 to corner zero+2
    Surface_mesh::Halfedge_index h = reference.halfedge(l.first);
    for(int k = 0; k < (zero + 1) % 3; ++k)
      h = reference.next(h);
    const Point_3 p = point_of(mesh, l);
    const Surface_mesh::Halfedge_index hnew = CGAL::Euler::split_edge(h, reference); // target: the new vertex
    reference.point(reference.target(hnew)) = p;
    if(!reference.is_border(hnew))
      CGAL::Euler::split_face(hnew, reference.next(reference.next(hnew)), reference);
    const Surface_mesh::Halfedge_index o = reference.opposite(h); // now ends at the new vertex
    if(!reference.is_border(o))
      CGAL::Euler::split_face(o, reference.next(reference.next(o)), reference);
    on_edges.push_back(reference.target(hnew));
  }
  Shortest_path shortest_path(reference);
  for(const Location& l : in_faces)
    shortest_path.add_source_point(l.first, Traits::Barycentric_coordinates{ { l.second[0], l.second[1], l.second[2] } });
  for(Vertex_index v : on_edges)
    shortest_path.add_source_point(v);
  shortest_path.build_sequence_tree();
  std::vector<double> d(num_vertices(mesh));
  for(Vertex_index v : vertices(mesh))
    d[v] = shortest_path.shortest_distance_to_source_points(v).first;
  return d;
}


// Checks the labels of a multi-source run: each reached vertex is labelled with a source whose own
// distance at that vertex is the multi-source distance (up to `tolerance` times the largest distance);
// unreached vertices get no_source.
::testing::AssertionResult labels_pick_a_nearest_source(const std::vector<double>& d,
                                                        const std::vector<std::size_t>& labels,
                                                        const std::vector<std::vector<double> >& single,
                                                        double tolerance, bool approximate = false)
{
  const double scale = max_finite(d) > 0. ? max_finite(d) : 1.;
  for(std::size_t v = 0; v < d.size(); ++v)
  {
    if(std::isinf(d[v]))
    {
      if(labels[v] != no_source)
        return ::testing::AssertionFailure() << "unreached vertex " << v << " has label " << labels[v];
      continue;
    }
    if(!(labels[v] < single.size()))
      return ::testing::AssertionFailure() << "vertex " << v << " has label " << labels[v];
    const double own = single[labels[v]][v];
    // exact: the labelled source achieves the distance; approximate: its exact distance is not above it
    const bool ok = approximate ? own <= d[v] + tolerance * scale : std::abs(own - d[v]) <= tolerance * scale;
    if(!ok)
      return ::testing::AssertionFailure() << "vertex " << v << ": distance " << d[v] << ", label " << labels[v]
                                           << " whose own distance is " << own;
  }
  return ::testing::AssertionSuccess();
}

std::vector<double> pointwise_minimum(const std::vector<std::vector<double> >& single)
{
  std::vector<double> m(single.front().size(), INF);
  for(const std::vector<double>& d : single)
    for(std::size_t i = 0; i < m.size(); ++i)
      m[i] = (std::min)(m[i], d[i]);
  return m;
}

Location location(const Surface_mesh& mesh, std::size_t face, double b0, double b1, double b2)
{
  (void)mesh;
  return Location(Face_index(static_cast<Surface_mesh::size_type>(face)), { { b0, b1, b2 } });
}

// The location of the same point of the edge of `h` expressed in the face of opposite(h): the point at
// parameter t from source(h) to target(h).
Location edge_location(const Surface_mesh& mesh, Surface_mesh::Halfedge_index h, double t)
{
  const Face_index f = mesh.face(h);
  std::array<double, 3> b = { { 0., 0., 0. } };
  Surface_mesh::Halfedge_index g = mesh.halfedge(f);
  for(int k = 0; k < 3; ++k, g = mesh.next(g))
  {
    if(mesh.source(g) == mesh.source(h))
      b[static_cast<std::size_t>(k)] = 1. - t;
    if(mesh.source(g) == mesh.target(h))
      b[static_cast<std::size_t>(k)] = t;
  }
  return Location(f, b);
}

} // namespace

// ---------------------------------------------------------------------------------------------------
// Several vertex sources
// ---------------------------------------------------------------------------------------------------

TEST(Multiple_sources, minimum_of_single_sources_with_labels)
{
  for(const char* name : { "elephant.off", "mech-holes-shark.off" })
  {
    const Surface_mesh mesh = load_mesh(name);
    const std::size_t n = num_vertices(mesh);
    const std::vector<Vertex_index> sources = { Vertex_index(3), Vertex_index(static_cast<Surface_mesh::size_type>(n / 3)),
                                                Vertex_index(static_cast<Surface_mesh::size_type>(n / 2)),
                                                Vertex_index(static_cast<Surface_mesh::size_type>(n - 2)) };
    std::vector<std::vector<double> > single;
    for(Vertex_index s : sources)
      single.push_back(vtp_distances(mesh, s));
    const std::vector<double> expected = pointwise_minimum(single);
    for(const Method* m : methods_to_test(false))
    {
      const auto r = run(mesh, sources, *m);
      EXPECT_TRUE(distances_near(r.first, expected, EXACT_TOLERANCE, std::string(name) + ", " + m->name + ", 4 sources"));
      EXPECT_TRUE(labels_pick_a_nearest_source(r.first, r.second, single, EXACT_TOLERANCE)) << name << ", " << m->name;
      for(std::size_t i = 0; i < sources.size(); ++i)
        EXPECT_EQ(r.second[sources[i]], i) << "a source is its own nearest source";
    }
    for(const Method* m : methods_to_test(true))
    {
      const auto r = run(mesh, sources, *m);
      double below = 0.;
      for(std::size_t i = 0; i < n; ++i)
      {
        ASSERT_TRUE(std::isfinite(r.first[i])) << name << ", " << m->name << ", vertex " << i;
        below = (std::max)(below, expected[i] - r.first[i]);
      }
      EXPECT_LE(below, EXACT_TOLERANCE * max_finite(expected)) << name << ", " << m->name << ": never below exact";
      EXPECT_TRUE(labels_pick_a_nearest_source(r.first, r.second, single, EXACT_TOLERANCE, true)) << name << ", " << m->name;
    }
  }
}

TEST(Multiple_sources, sources_in_different_components)
{
  // a grid, a tetrahedron far away, a second grid with no source, and an isolated vertex
  Polygon_soup soup = planar_grid(6, 6, 1., 1., 0.2, 3u);
  soup.append(regular_tetrahedron(), Vector_3(10, 0, 0));
  soup.append(planar_grid(3, 3, 1., 1.), Vector_3(0, 10, 0));
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Vertex_index isolated = mesh.add_vertex(Point_3(50, 50, 50));
  const Vertex_index in_grid(8), in_tetrahedron(50);
  const std::vector<Vertex_index> sources = { in_grid, in_tetrahedron };
  const std::vector<std::vector<double> > single = { vtp_distances(mesh, in_grid), vtp_distances(mesh, in_tetrahedron) };
  for(const Method* m : methods_to_test(false))
  {
    const auto r = run(mesh, sources, *m);
    EXPECT_TRUE(distances_near(r.first, pointwise_minimum(single), EXACT_TOLERANCE, std::string(m->name) + ", two components"));
    EXPECT_TRUE(labels_pick_a_nearest_source(r.first, r.second, single, EXACT_TOLERANCE)) << m->name;
    for(std::size_t i = 0; i < 49; ++i)
      EXPECT_EQ(r.second[i], 0u) << "grid vertex " << i;
    for(std::size_t i = 49; i < 53; ++i)
      EXPECT_EQ(r.second[i], 1u) << "tetrahedron vertex " << i;
    for(std::size_t i = 53; i < 70; ++i)
    {
      EXPECT_EQ(r.first[i], INF);
      EXPECT_EQ(r.second[i], no_source);
    }
    EXPECT_EQ(r.first[isolated], INF);
    EXPECT_EQ(r.second[isolated], no_source);
  }
  // an isolated vertex as a source reaches itself only
  const auto r = run(mesh, std::vector<Vertex_index>{ isolated, in_tetrahedron }, exact_methods[0]);
  EXPECT_EQ(r.first[isolated], 0.);
  EXPECT_EQ(r.second[isolated], 0u);
  EXPECT_EQ(r.first[0], INF);
}

TEST(Multiple_sources, repeated_sources)
{
  const Surface_mesh mesh = load_mesh("knot1.off");
  const std::vector<double> one = vtp_distances(mesh, Vertex_index(7));
  const auto r = run(mesh, std::vector<Vertex_index>{ Vertex_index(7), Vertex_index(7), Vertex_index(7) }, exact_methods[0]);
  for(std::size_t i = 0; i < one.size(); ++i)
  {
    ASSERT_EQ(r.first[i], one[i]) << "the same source three times is one source";
    ASSERT_EQ(r.second[i], 0u) << "ties between equal sources go to the first";
  }
}

// Two sources on a plane: the labels split the vertices along the perpendicular bisector.
TEST(Multiple_sources, planar_bisector)
{
  const int n = 30;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 21u);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Location a = location(mesh, 2 * (n * 7 + 5), 0.2, 0.3, 0.5);        // a point inside a face
  const Location b(Face_index(static_cast<Surface_mesh::size_type>(2 * (n * 22 + 21) + 1)), { { 0.6, 0.4, 0. } });
  const Point_3 pa = point_of(mesh, a), pb = point_of(mesh, b);
  for(const Method* m : methods_to_test(false))
  {
    const auto r = run(mesh, std::vector<Location>{ a, b }, *m);
    std::size_t checked = 0;
    for(Vertex_index v : vertices(mesh))
    {
      const double da = distance(mesh.point(v), pa), db = distance(mesh.point(v), pb);
      EXPECT_NEAR(r.first[v], (std::min)(da, db), EXACT_TOLERANCE * std::sqrt(2.)) << m->name << ", vertex " << v;
      if(std::abs(da - db) < 1e-9)
        continue; // on the bisector: either label
      EXPECT_EQ(r.second[v], da < db ? 0u : 1u) << m->name << ", vertex " << v;
      ++checked;
    }
    EXPECT_GT(checked, soup.points.size() - 5);
  }
}

// ---------------------------------------------------------------------------------------------------
// Sources at points of the surface
// ---------------------------------------------------------------------------------------------------

TEST(Face_location_sources, euclidean_on_a_plane)
{
  const int n = 20;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 8u);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(const Location& l : { location(mesh, 137, 0.2, 0.3, 0.5), location(mesh, 0, 1. / 3., 1. / 3., 1. / 3.),
                            location(mesh, 411, 0.999, 0.0005, 0.0005), location(mesh, 50, 0.5, 0.5, 0.) })
  {
    const Point_3 p = point_of(mesh, l);
    std::vector<double> expected(num_vertices(mesh));
    for(Vertex_index v : vertices(mesh))
      expected[v] = distance(mesh.point(v), p);
    for(const Method* m : methods_to_test(false))
      EXPECT_TRUE(distances_near(run(mesh, l, *m).first, expected, EXACT_TOLERANCE,
                                 std::string(m->name) + ", face " + std::to_string(std::size_t(l.first))));
    for(const Method* m : methods_to_test(true))
    {
      const std::vector<double> d = run(mesh, l, *m).first;
      for(Vertex_index v : vertices(mesh))
        EXPECT_GE(d[v], expected[v] - EXACT_TOLERANCE) << m->name << ": never below exact";
    }
  }
}

TEST(Face_location_sources, match_surface_mesh_shortest_path)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "three_peaks.off" })
  {
    const Surface_mesh mesh = load_mesh(name);
    const std::size_t nf = num_faces(mesh);
    // a boundary edge of the mesh (if any), and a point on it
    std::vector<Location> on_boundary;
    for(Surface_mesh::Halfedge_index h : halfedges(mesh))
      if(mesh.is_border(mesh.opposite(h)))
      {
        on_boundary.push_back(edge_location(mesh, h, 0.37));
        break;
      }
    std::vector<std::vector<Location> > cases = {
      { location(mesh, nf / 7, 0.2, 0.3, 0.5) },                     // inside a face
      { location(mesh, nf / 2, 0.45, 0., 0.55) },                     // on an edge
      { location(mesh, nf / 3, 0., 1., 0.) },                         // at a vertex
      { location(mesh, 11, 0.6, 0.3, 0.1), location(mesh, nf - 5, 0.1, 0.1, 0.8),
        location(mesh, nf / 2 + 3, 0., 0.25, 0.75) } };               // several
    if(!on_boundary.empty())
      cases.push_back(on_boundary);
    for(const std::vector<Location>& sources : cases)
    {
      const std::vector<double> reference = smsp_distances(mesh, sources);
      const std::string what = std::string(name) + ", " + std::to_string(sources.size()) + " location(s), face "
                               + std::to_string(std::size_t(sources[0].first));
      for(const Method* m : methods_to_test(false))
      {
        const auto r = run(mesh, sources, *m);
        EXPECT_TRUE(distances_near(r.first, reference, EXACT_TOLERANCE, what + ", " + m->name));
        if(sources.size() > 1)
        {
          std::vector<std::vector<double> > single;
          for(const Location& l : sources)
            single.push_back(run(mesh, l, exact_methods[0]).first);
          EXPECT_TRUE(labels_pick_a_nearest_source(r.first, r.second, single, EXACT_TOLERANCE)) << what;
        }
      }
    }
  }
}

TEST(Face_location_sources, the_same_point_from_either_face)
{
  const Surface_mesh mesh = load_mesh("mushroom.off");
  std::size_t tested = 0;
  for(Surface_mesh::Halfedge_index h : halfedges(mesh))
  {
    if(mesh.is_border(h) || mesh.is_border(mesh.opposite(h)) || std::size_t(h) % 397 != 0)
      continue;
    const Location in_face = edge_location(mesh, h, 0.3);
    const Location in_other_face = edge_location(mesh, mesh.opposite(h), 0.7);
    const auto a = run(mesh, in_face, exact_methods[0]);
    const auto b = run(mesh, in_other_face, exact_methods[0]);
    EXPECT_TRUE(distances_near(a.first, b.first, EXACT_TOLERANCE, "edge point from either face"));
    ++tested;
  }
  EXPECT_GT(tested, 10u);

  // a corner of a face is the vertex itself: identical results, from each face around the vertex
  const Vertex_index v(123);
  const std::vector<double> from_vertex = vtp_distances(mesh, v);
  for(Surface_mesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
  {
    if(mesh.is_border(h))
      continue;
    const Location corner = edge_location(mesh, h, 1.); // t = 1: the target of h, i.e. v
    const std::vector<double> d = run(mesh, corner, exact_methods[0]).first;
    for(std::size_t i = 0; i < d.size(); ++i)
      ASSERT_EQ(d[i], from_vertex[i]) << "vertex " << i;
  }
}

// A point a rounding error away from an edge or a vertex (as PMP::locate gives them) is that edge point or
// that vertex: windows from a source image that close to the line of an edge cannot be propagated accurately.
TEST(Face_location_sources, points_within_rounding_of_an_edge_or_a_vertex)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  for(std::size_t f : { 100u, 1500u, 2000u, 2779u })
  {
    const std::vector<double> on_edge = run(mesh, location(mesh, f, 0.45, 0., 0.55), exact_methods[0]).first;
    const std::vector<double> at_vertex = run(mesh, location(mesh, f, 0., 0., 1.), exact_methods[0]).first;
    for(double e : { 1e-13, 1e-15, 1e-16, 1e-17, 1e-300 })
    {
      EXPECT_TRUE(distances_near(run(mesh, location(mesh, f, 0.45 - e, e, 0.55), exact_methods[0]).first, on_edge,
                                 EXACT_TOLERANCE, "face " + std::to_string(f) + ", " + std::to_string(e) + " from an edge"));
      EXPECT_TRUE(distances_near(run(mesh, location(mesh, f, e, e, 1. - 2. * e), exact_methods[0]).first, at_vertex,
                                 EXACT_TOLERANCE, "face " + std::to_string(f) + ", " + std::to_string(e) + " from a vertex"));
    }
  }
}

TEST(Face_location_sources, polyhedron_equals_surface_mesh)
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor P_vertex;
  typedef boost::graph_traits<Polyhedron>::face_descriptor P_face;
  const Polygon_soup soup = to_soup(load_mesh("three_peaks.off"));
  const Surface_mesh sm = to_mesh<Surface_mesh>(soup);
  const Polyhedron poly = to_mesh<Polyhedron>(soup);
  // the same faces, in the same order, with the same first half-edge? compare the points of the locations
  const std::vector<P_face> pfaces(faces(poly).begin(), faces(poly).end());
  const std::vector<P_vertex> pvertices(vertices(poly).begin(), vertices(poly).end());
  const std::size_t f = pfaces.size() / 3;
  const std::array<double, 3> b = { { 0.25, 0.5, 0.25 } };
  std::pair<P_face, std::array<double, 3> > pl(pfaces[f], b);
  // the Surface_mesh face with the same three points, the coordinates rotated to its first half-edge
  const Point_3 p0 = pfaces[f]->halfedge()->prev()->vertex()->point();
  std::size_t sm_face = 0;
  std::array<double, 3> sb = b;
  bool found = false;
  for(Face_index g : faces(sm))
  {
    Surface_mesh::Halfedge_index h = sm.halfedge(g);
    std::array<Point_3, 3> q = { { sm.point(sm.source(h)), sm.point(sm.target(h)), sm.point(sm.target(sm.next(h))) } };
    for(int k = 0; k < 3 && !found; ++k)
      if(q[std::size_t(k)] == p0 && q[std::size_t((k + 1) % 3)] == pfaces[f]->halfedge()->vertex()->point()
         && q[std::size_t((k + 2) % 3)] == pfaces[f]->halfedge()->next()->vertex()->point())
      {
        for(int j = 0; j < 3; ++j)
          sb[std::size_t((k + j) % 3)] = b[std::size_t(j)];
        sm_face = std::size_t(g);
        found = true;
      }
    if(found)
      break;
  }
  ASSERT_TRUE(found);
  const std::vector<double> d_sm = run(sm, Location(Face_index(static_cast<Surface_mesh::size_type>(sm_face)), sb),
                                       exact_methods[0]).first;
  std::unordered_map<P_vertex, double> pd;
  CGAL::VTP_geodesics::compute_geodesic_distances(poly, boost::make_assoc_property_map(pd), pl);
  for(std::size_t i = 0; i < pvertices.size(); ++i)
    EXPECT_NEAR(pd[pvertices[i]], d_sm[i], EXACT_TOLERANCE * max_finite(d_sm)) << "vertex " << i;
  // and a range of Polyhedron vertices
  std::unordered_map<P_vertex, double> pv;
  CGAL::VTP_geodesics::compute_geodesic_distances(poly, boost::make_assoc_property_map(pv),
                                                  std::vector<P_vertex>{ pvertices[3], pvertices[40] });
  const std::vector<double> d_sm_v = run(sm, std::vector<Vertex_index>{ Vertex_index(3), Vertex_index(40) }, exact_methods[0]).first;
  for(std::size_t i = 0; i < pvertices.size(); ++i)
    EXPECT_EQ(pv[pvertices[i]], d_sm_v[i]) << "vertex " << i;
}

// ---------------------------------------------------------------------------------------------------
// The source set of the solver, and bad sources
// ---------------------------------------------------------------------------------------------------

TEST(Source_set, mixed_vertices_and_locations_equal_the_range_forms)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  const Location l = location(mesh, 100, 0.3, 0.3, 0.4);
  Solver solver(mesh);
  EXPECT_EQ(solver.number_of_sources(), 0u);
  solver.add_source(Vertex_index(10));
  solver.add_source(l);
  solver.add_sources(std::vector<Vertex_index>{ Vertex_index(2000) });
  EXPECT_EQ(solver.number_of_sources(), 3u);
  std::vector<double> d(num_vertices(mesh));
  std::vector<std::size_t> labels(num_vertices(mesh));
  solver.compute(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)),
                 VP::nearest_source_map(boost::make_iterator_property_map(labels.begin(), get(boost::vertex_index, mesh))));
  const std::vector<std::vector<double> > single = { vtp_distances(mesh, Vertex_index(10)), run(mesh, l, exact_methods[0]).first,
                                                     vtp_distances(mesh, Vertex_index(2000)) };
  EXPECT_TRUE(distances_near(d, pointwise_minimum(single), EXACT_TOLERANCE, "source set"));
  EXPECT_TRUE(labels_pick_a_nearest_source(d, labels, single, EXACT_TOLERANCE));
  EXPECT_EQ(solver.statistics().sources, 3u);
  solver.clear_sources();
  EXPECT_EQ(solver.number_of_sources(), 0u);
  EXPECT_THROW(solver.compute(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh))),
               Invalid_input_error);
}

TEST(Bad_input, invalid_face_locations_are_rejected)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  CGAL::Euler::remove_face(mesh.halfedge(Face_index(5)), mesh);
  Solver solver(mesh);
  std::vector<double> d(index_range(mesh));
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(const std::array<double, 3>& b : { std::array<double, 3>{ { -0.1, 0.6, 0.5 } }, std::array<double, 3>{ { 0.5, 0.6, 0.5 } },
                                         std::array<double, 3>{ { nan, 0.5, 0.5 } }, std::array<double, 3>{ { INF, 0., 0. } },
                                         std::array<double, 3>{ { 0., 0., 0. } } })
  {
    EXPECT_THROW(solver.compute(map, Location(Face_index(0), b)), Invalid_input_error) << b[0] << " " << b[1] << " " << b[2];
    EXPECT_THROW(solver.add_source(Location(Face_index(0), b)), Invalid_input_error);
  }
  const std::array<double, 3> fine = { { 0.2, 0.3, 0.5 } };
  EXPECT_THROW(solver.compute(map, Location(Face_index(5), fine)), Invalid_input_error) << "removed face";
  EXPECT_THROW(solver.compute(map, Location(Surface_mesh::null_face(), fine)), Invalid_input_error);
  EXPECT_THROW(solver.compute(map, Location(Face_index(1000), fine)), Invalid_input_error);
  EXPECT_NO_THROW(solver.compute(map, Location(Face_index(0), fine)));
  // rounding-level deviations are accepted
  EXPECT_NO_THROW(solver.compute(map, Location(Face_index(0), { { -1e-17, 0.5, 0.5 + 1e-16 } })));
  EXPECT_EQ(solver.number_of_sources(), 0u) << "a rejected source is not added";
}

// ---------------------------------------------------------------------------------------------------
// Many sources: compute_each()
// ---------------------------------------------------------------------------------------------------

namespace {

// Rows of compute_each() by row index, with the number of times each row was handed over.
struct Collected_rows
{
  std::vector<std::vector<double> > rows;
  std::vector<int> calls;
};

template <class Tag, class Sources, class NP>
Collected_rows collect_rows(Geodesic_distance_solver<Surface_mesh>& solver, const Sources& sources, const NP& np)
{
  Collected_rows c;
  c.rows.resize(sources.size());
  c.calls.assign(sources.size(), 0);
  solver.compute_each<Tag>(sources, [&](std::size_t i, const typename Sources::value_type&, const std::vector<double>& d) {
    c.rows[i] = d;
    ++c.calls[i];
  }, np);
  return c;
}

} // namespace

TEST(Compute_each, rows_equal_single_computations_bitwise)
{
  const Surface_mesh& mesh = elephant();
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  std::vector<Vertex_index> sources;
  for(std::size_t i = 0; i < 12; ++i)
    sources.push_back(Vertex_index(static_cast<Surface_mesh::size_type>(i * 229)));
  namespace VP = CGAL::VTP_geodesics::parameters;
  for(double lambda : { INF, 4. })
    for(double limit : { INF, 0.3 })
    {
      const auto np = VP::lambda(lambda).maximum_distance(limit);
      std::vector<std::vector<double> > expected;
      for(Vertex_index s : sources)
      {
        solver.compute(vtp_test::Discard_map(), s, np);
        expected.push_back(solver.distances());
      }
      const Collected_rows sequential = collect_rows<CGAL::Sequential_tag>(solver, sources, np);
      EXPECT_EQ(solver.statistics().sources, sources.size());
      for(std::size_t i = 0; i < sources.size(); ++i)
      {
        EXPECT_EQ(sequential.calls[i], 1);
        EXPECT_TRUE(identical(sequential.rows[i], expected[i])) << "row " << i << ", lambda " << lambda << ", limit " << limit;
      }
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
      for(int threads : { 1, 2, 3 })
      {
        const Collected_rows parallel = collect_rows<CGAL::Parallel_tag>(solver, sources, np.number_of_threads(threads));
        EXPECT_EQ(solver.statistics().threads, threads);
        for(std::size_t i = 0; i < sources.size(); ++i)
        {
          EXPECT_EQ(parallel.calls[i], 1);
          EXPECT_TRUE(identical(parallel.rows[i], expected[i])) << "row " << i << ", " << threads << " threads";
        }
      }
#endif
    }
  // face locations as sources
  typedef std::pair<Surface_mesh::Face_index, std::array<double, 3> > Location;
  const std::vector<Location> locations = { Location(Surface_mesh::Face_index(5), { { 0.2, 0.3, 0.5 } }),
                                            Location(Surface_mesh::Face_index(900), { { 0., 0.5, 0.5 } }) };
  const Collected_rows rows = collect_rows<CGAL::Sequential_tag>(solver, locations, CGAL::parameters::default_values());
  for(std::size_t i = 0; i < locations.size(); ++i)
  {
    solver.compute(vtp_test::Discard_map(), locations[i]);
    EXPECT_TRUE(identical(rows.rows[i], solver.distances()));
  }
}

TEST(Compute_each, errors)
{
  const Surface_mesh& mesh = elephant();
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  std::vector<Vertex_index> sources(20, Vertex_index(3));
  // a bad source: refused before any row
  std::vector<Vertex_index> bad = sources;
  bad[7] = Vertex_index(static_cast<Surface_mesh::size_type>(num_vertices(mesh) + 1));
  int calls = 0;
  EXPECT_THROW(solver.compute_each(bad, [&](std::size_t, Vertex_index, const std::vector<double>&) { ++calls; }),
               Invalid_input_error);
  EXPECT_EQ(calls, 0);
  // a sink that throws: no row after that, and the exception comes out
  for(int threads : { 1, 2 })
  {
    calls = 0;
    auto sink = [&](std::size_t, Vertex_index, const std::vector<double>&) {
      if(++calls == 3)
        throw std::runtime_error("disk full");
    };
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    EXPECT_THROW(solver.compute_each<CGAL::Parallel_tag>(sources, sink,
                                                         CGAL::VTP_geodesics::parameters::number_of_threads(threads)),
                 std::runtime_error);
#else
    EXPECT_THROW(solver.compute_each(sources, sink), std::runtime_error);
#endif
    EXPECT_EQ(calls, 3);
  }
}
