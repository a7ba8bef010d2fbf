// The public interface: genericity (Surface_mesh / Polyhedron_3 / exact-kernel points, property maps,
// named parameters, free function / solver, solver reuse), statistics, the preprocessing on threads, and
// rejected input. The parallel and approximate variants are in test_variants.cpp, compute_each() in
// test_sources.cpp.

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

using namespace vtp_test;
using CGAL::VTP_geodesics::Geodesic_distance_solver;
using CGAL::VTP_geodesics::Invalid_input_error;
using CGAL::VTP_geodesics::Propagation_statistics;
using CGAL::VTP_geodesics::compute_geodesic_distances;

typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
typedef CGAL::Exact_predicates_exact_constructions_kernel Exact_kernel;
typedef CGAL::Surface_mesh<Exact_kernel::Point_3> Exact_surface_mesh;

namespace {

// Distances from vertex number `source` (in the order of vertices(mesh)) written through an associative
// property map (no vertex ids needed), returned in the order of vertices(mesh); NaN where nothing was written.
template <class Mesh, class Map = std::unordered_map<typename boost::graph_traits<Mesh>::vertex_descriptor, double> >
std::vector<double> distances_through_assoc_map(const Mesh& mesh, std::size_t source)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const std::vector<vertex_descriptor> vs(vertices(mesh).begin(), vertices(mesh).end());
  Map map;
  Geodesic_distance_solver<Mesh> solver(mesh);
  solver.compute(boost::make_assoc_property_map(map), vs[source]);
  std::vector<double> d;
  for(vertex_descriptor v : vs)
  {
    auto it = map.find(v);
    d.push_back(it == map.end() ? NOT_A_VERTEX : it->second);
  }
  return d;
}

} // namespace

// ---------------------------------------------------------------------------------------------------
// Genericity
// ---------------------------------------------------------------------------------------------------

TEST(Genericity, surface_mesh_and_polyhedron_give_identical_distances)
{
  const std::vector<std::pair<std::string, Polygon_soup> > soups = {
    {"mushroom", to_soup(load_mesh("mushroom.off"))},
    {"jittered grid", planar_grid(20, 20, 1., 1., 0.3, 99u)}};
  for(const auto& named : soups)
  {
    const Polygon_soup& soup = named.second;
    const Surface_mesh sm = to_mesh<Surface_mesh>(soup);
    const Polyhedron poly = to_mesh<Polyhedron>(soup);
    std::size_t i = 0;
    for(Polyhedron::Vertex_const_handle v : vertices(poly))
      ASSERT_EQ(v->point(), soup.points[i++]) << "vertices must follow the soup order";

    for(std::size_t source : {std::size_t(0), soup.points.size() / 3})
    {
      const std::vector<double> d_sm = distances_through_assoc_map(sm, source);
      const std::vector<double> d_poly = distances_through_assoc_map(poly, source);
      const std::vector<double> d_poly_map =
        distances_through_assoc_map<Polyhedron, std::map<Polyhedron::Vertex_const_handle, double> >(poly, source);
      EXPECT_EQ(std::count_if(d_sm.begin(), d_sm.end(), [](double x) { return std::isnan(x); }), 0)
        << "every vertex must be written";
      EXPECT_TRUE(identical(d_sm, d_poly)) << named.first << ", source " << source;
      EXPECT_TRUE(identical(d_sm, d_poly_map)) << named.first << ", source " << source;

      // and through a Surface_mesh property map
      Surface_mesh sm_copy = sm;
      auto pmap = sm_copy.add_property_map<Vertex_index, double>("v:distance", -1.).first;
      Geodesic_distance_solver<Surface_mesh> solver(sm_copy);
      solver.compute(pmap, Vertex_index(static_cast<Surface_mesh::size_type>(source)));
      std::vector<double> d_pmap;
      for(Vertex_index v : vertices(sm_copy))
        d_pmap.push_back(pmap[v]);
      EXPECT_TRUE(identical(d_sm, d_pmap)) << named.first << ", source " << source;
    }
  }
}

TEST(Genericity, exact_kernel_points)
{
  const Polygon_soup soup = to_soup(load_mesh("three_peaks.off"));
  const Surface_mesh sm = to_mesh<Surface_mesh>(soup);
  Exact_surface_mesh esm;
  for(const Point_3& p : soup.points)
    esm.add_vertex(Exact_kernel::Point_3(p.x(), p.y(), p.z()));
  for(const std::vector<std::size_t>& t : soup.polygons)
    ASSERT_NE(esm.add_face(Exact_surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(t[0])),
                           Exact_surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(t[1])),
                           Exact_surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(t[2]))),
              Exact_surface_mesh::null_face());

  const std::vector<double> d = distances_through_assoc_map(sm, 100);
  const std::vector<double> d_exact_points = distances_through_assoc_map(esm, 100);
  // The squared edge lengths are rounded once from exact values instead of computed in double:
  // the results agree to the accuracy of the algorithm, not bit for bit.
  EXPECT_TRUE(distances_near(d_exact_points, d, EXACT_TOLERANCE, "Epeck points vs Epick points"));
}

TEST(Genericity, vertex_point_map_named_parameter)
{
  // Points scaled by 2 through a custom vertex point map: all distances double.
  const Surface_mesh& mesh = elephant();
  std::vector<Point_3> scaled(num_vertices(mesh));
  for(Vertex_index v : vertices(mesh))
    scaled[v] = CGAL::ORIGIN + 2. * (mesh.point(v) - CGAL::ORIGIN);
  auto vpm = boost::make_iterator_property_map(scaled.begin(), get(boost::vertex_index, mesh));

  const Vertex_index s(42);
  std::vector<double> expected = vtp_distances(mesh, s);
  for(double& x : expected)
    x *= 2.;
  std::vector<double> d(num_vertices(mesh), NOT_A_VERTEX);
  compute_geodesic_distances(mesh, boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)), s,
                             CGAL::parameters::vertex_point_map(vpm));
  EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "free function, scaled vertex point map"));

  std::vector<double> d_solver(num_vertices(mesh), NOT_A_VERTEX);
  Geodesic_distance_solver<Surface_mesh, CGAL::Default, decltype(vpm)> solver(mesh, vpm);
  solver.compute(boost::make_iterator_property_map(d_solver.begin(), get(boost::vertex_index, mesh)), s);
  EXPECT_TRUE(identical(d, d_solver));

  // the same with this package's named parameters, and through the solver's named-parameter constructor
  std::vector<double> d_np(num_vertices(mesh), NOT_A_VERTEX);
  compute_geodesic_distances(mesh, boost::make_iterator_property_map(d_np.begin(), get(boost::vertex_index, mesh)), s,
                             CGAL::VTP_geodesics::parameters::vertex_point_map(vpm).minimum_window_length(1e-9));
  EXPECT_TRUE(identical(d, d_np));
  Geodesic_distance_solver<Surface_mesh, CGAL::Default, decltype(vpm)> solver_np(
    mesh, CGAL::parameters::vertex_point_map(vpm));
  std::vector<double> d_solver_np(num_vertices(mesh), NOT_A_VERTEX);
  solver_np.compute(boost::make_iterator_property_map(d_solver_np.begin(), get(boost::vertex_index, mesh)), s);
  EXPECT_TRUE(identical(d, d_solver_np));
}

TEST(Genericity, free_function_and_solver_agree)
{
  const Surface_mesh& mesh = elephant();
  for(Vertex_index s : {Vertex_index(10), Vertex_index(2000)})
  {
    std::vector<double> d_free(num_vertices(mesh), NOT_A_VERTEX);
    Propagation_statistics st;
    compute_geodesic_distances(mesh, boost::make_iterator_property_map(d_free.begin(), get(boost::vertex_index, mesh)), s,
                               CGAL::VTP_geodesics::parameters::statistics(st));
    Propagation_statistics st_solver;
    const std::vector<double> d_solver = vtp_distances(mesh, s, CGAL::parameters::default_values(), &st_solver);
    EXPECT_TRUE(identical(d_free, d_solver));
    EXPECT_EQ(st.reached_vertices, st_solver.reached_vertices);
    EXPECT_EQ(st.max_distance, st_solver.max_distance);
    EXPECT_EQ(st.windows_created, st_solver.windows_created);
  }
}

TEST(Genericity, reused_solver_equals_fresh_solvers)
{
  const Surface_mesh& mesh = elephant();
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  EXPECT_EQ(solver.number_of_vertices(), num_vertices(mesh));
  EXPECT_EQ(solver.number_of_faces(), num_faces(mesh));
  for(Vertex_index s : {Vertex_index(0), Vertex_index(1234), Vertex_index(2774), Vertex_index(0)})
  {
    std::vector<double> d(num_vertices(mesh), NOT_A_VERTEX);
    solver.compute(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)), s);
    EXPECT_TRUE(identical(d, vtp_distances(mesh, s))) << "source " << std::size_t(s);

    // the dense accessors report the same distances
    for(Vertex_index v : vertices(mesh))
    {
      ASSERT_EQ(solver.distance(v), d[v]);
      ASSERT_EQ(solver.distances()[solver.vertex_id(v)], d[v]);
    }
    // the source set of the solver gives the same
    solver.clear_sources();
    solver.add_source(s);
    std::vector<double> from_set(num_vertices(mesh), NOT_A_VERTEX);
    solver.compute(boost::make_iterator_property_map(from_set.begin(), get(boost::vertex_index, mesh)));
    EXPECT_TRUE(identical(d, from_set));
  }
}

// ---------------------------------------------------------------------------------------------------
// Statistics: only relations that any correct window-propagation engine satisfies.
// ---------------------------------------------------------------------------------------------------

TEST(Statistics, consistent_with_the_output)
{
  const Surface_mesh& mesh = elephant();
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  std::vector<double> d(num_vertices(mesh), NOT_A_VERTEX);
  solver.compute(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)), Vertex_index(77));
  const Propagation_statistics st = solver.statistics();

  EXPECT_EQ(st.vertices, num_vertices(mesh));
  EXPECT_EQ(st.faces, num_faces(mesh));
  EXPECT_EQ(st.method, "vtp");
  EXPECT_EQ(st.sources, 1u);
  EXPECT_EQ(st.threads, 1);
  EXPECT_GT(st.windows_created, 0u);
  EXPECT_GT(st.windows_propagated, 0u);
  EXPECT_GT(st.peak_live_windows, 0u);
  EXPECT_GE(st.peak_window_bytes, st.peak_live_windows * 5 * sizeof(double)) << "a window holds at least 5 doubles";
  EXPECT_GT(st.vertices_processed, 0u);
  EXPECT_GE(st.seconds, 0.);
  EXPECT_GE(st.output_seconds, 0.);
  EXPECT_EQ(st.resets, 0u) << "the exact algorithm never resets windows";

  std::size_t finite = 0;
  double largest = 0.;
  for(double x : d)
    if(std::isfinite(x))
    {
      ++finite;
      largest = (std::max)(largest, x);
    }
  EXPECT_EQ(finite, num_vertices(mesh)) << "elephant.off is connected";
  EXPECT_EQ(st.reached_vertices, finite);
  EXPECT_EQ(st.max_distance, largest);

  // statistics() reports the last computation
  EXPECT_EQ(solver.statistics().reached_vertices, st.reached_vertices);
  EXPECT_EQ(solver.statistics().max_distance, st.max_distance);
  EXPECT_EQ(solver.statistics().windows_created, st.windows_created);
}

TEST(Statistics, mesh_quantities)
{
  // a regular grid of right isosceles triangles: 2n(n+1) axis-parallel edges of length 1/n and n^2 diagonals
  const int n = 10;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1.));
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  const double expected_mean = (2. * n * (n + 1) / n + n * n * std::sqrt(2.) / n) / (2. * n * (n + 1) + n * n);
  EXPECT_NEAR(solver.mean_edge_length(), expected_mean, 1e-14);
  EXPECT_GE(solver.anisotropy(), 1.);
  EXPECT_EQ(solver.number_of_pseudo_source_vertices(), std::size_t(4 * n)) << "the boundary vertices; no saddle";
  EXPECT_GE(solver.preprocessing_seconds(), 0.);
}

// ---------------------------------------------------------------------------------------------------
// Rejected input
// ---------------------------------------------------------------------------------------------------

TEST(Bad_input, quad_mesh_is_rejected)
{
  const Surface_mesh quads = to_mesh<Surface_mesh>(quad_grid(3));
  EXPECT_THROW(Geodesic_distance_solver<Surface_mesh>{quads}, Invalid_input_error);
  std::vector<double> d(num_vertices(quads));
  EXPECT_THROW(compute_geodesic_distances(quads, boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, quads)),
                                          Vertex_index(0)),
               Invalid_input_error);

  const Polyhedron quad_polyhedron = to_mesh<Polyhedron>(quad_grid(3));
  EXPECT_THROW(Geodesic_distance_solver<Polyhedron>{quad_polyhedron}, Invalid_input_error);

  // a single quad among triangles
  Polygon_soup mixed = planar_grid(3, 3, 1., 1.);
  mixed.polygons.erase(mixed.polygons.begin(), mixed.polygons.begin() + 2); // the two triangles of cell (0,0)
  mixed.polygons.push_back({grid_vertex(3, 0, 0), grid_vertex(3, 1, 0), grid_vertex(3, 1, 1), grid_vertex(3, 0, 1)});
  const Surface_mesh mixed_mesh = to_mesh<Surface_mesh>(mixed);
  EXPECT_THROW(Geodesic_distance_solver<Surface_mesh>{mixed_mesh}, Invalid_input_error);
}

// The preprocessing on several threads (named parameter number_of_threads of the constructor) builds the
// same arrays, bit for bit, as on one: the same flags, lengths, areas, statistics, and then the same distances.
// Meshes with a border, zero-length edges and degenerate faces, several components; a Polyhedron_3, whose
// dynamic property maps are hash maps, read by the threads at once. (Without OpenMP, the parameter is ignored.)
template <class Mesh>
void expect_same_preprocessing(const Mesh& mesh, int threads)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const Geodesic_distance_solver<Mesh> one(mesh);
  const Geodesic_distance_solver<Mesh> many(mesh, CGAL::VTP_geodesics::parameters::number_of_threads(threads));
  const auto& a = one.mesh_arrays();
  const auto& b = many.mesh_arrays();
  EXPECT_EQ(a.nv, b.nv);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.opposite, b.opposite);
  EXPECT_EQ(a.corner_begin, b.corner_begin);
  EXPECT_EQ(a.corners, b.corners);
  EXPECT_EQ(a.is_pseudo_source, b.is_pseudo_source);
  EXPECT_EQ(a.is_degenerate_face, b.is_degenerate_face);
  ASSERT_EQ(a.geometry.faces.size(), b.geometry.faces.size());
  for(std::size_t f = 0; f < a.geometry.faces.size(); ++f)
  {
    const auto& ga = a.geometry.faces[f];
    const auto& gb = b.geometry.faces[f];
    ASSERT_TRUE(ga.length[0] == gb.length[0] && ga.length[1] == gb.length[1] && ga.length[2] == gb.length[2]
                && ga.area == gb.area)
      << "face " << f;
  }
  EXPECT_EQ(a.number_of_edges, b.number_of_edges);
  EXPECT_EQ(a.mean_edge_length, b.mean_edge_length);
  EXPECT_EQ(a.min_edge_length, b.min_edge_length);
  EXPECT_EQ(a.max_edge_length, b.max_edge_length);
  EXPECT_EQ(a.anisotropy, b.anisotropy);
  EXPECT_EQ(one.mean_edge_length(), many.mean_edge_length());
  EXPECT_EQ(one.number_of_pseudo_source_vertices(), many.number_of_pseudo_source_vertices());

  // and the same distances, in the order of vertices(mesh)
  const vertex_descriptor source = *vertices(mesh).begin();
  std::vector<std::vector<double> > d;
  for(int run = 0; run < 2; ++run)
  {
    std::map<vertex_descriptor, double> map;
    Geodesic_distance_solver<Mesh> solver(mesh, CGAL::VTP_geodesics::parameters::number_of_threads(run == 0 ? 1 : threads));
    solver.compute(boost::make_assoc_property_map(map), source);
    d.emplace_back();
    for(vertex_descriptor v : vertices(mesh))
      d.back().push_back(map.at(v));
  }
  EXPECT_TRUE(identical(d[0], d[1]));
}

TEST(Preprocessing, any_number_of_threads_gives_the_same_arrays)
{
  for(const char* name : { "elephant-with-holes.off", "degenerate_zero_length_edges.off", "knot1.off",
                           "nearly_collinear_flat.off" })
  {
    SCOPED_TRACE(name);
    const Surface_mesh mesh = load_mesh(name);
    for(int threads : { 2, 3, 0 })
    {
      SCOPED_TRACE(threads);
      expect_same_preprocessing(mesh, threads);
    }
  }
  Polygon_soup two = planar_grid(6, 5, 1., 1.);  // two components
  const Polygon_soup other = regular_tetrahedron();
  const std::size_t offset = two.points.size();
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  for(std::vector<std::size_t> polygon : other.polygons)
  {
    for(std::size_t& v : polygon)
      v += offset;
    two.polygons.push_back(polygon);
  }
  expect_same_preprocessing(to_mesh<Surface_mesh>(two), 2);
  expect_same_preprocessing(to_mesh<Polyhedron>(two), 2);
  Polyhedron elephant_polyhedron;
  CGAL::copy_face_graph(elephant(), elephant_polyhedron);
  expect_same_preprocessing(elephant_polyhedron, 2);
}

TEST(Bad_input, quad_mesh_is_rejected_with_several_threads)
{
  const Surface_mesh quads = to_mesh<Surface_mesh>(quad_grid(3));
  EXPECT_THROW((Geodesic_distance_solver<Surface_mesh>{quads, CGAL::VTP_geodesics::parameters::number_of_threads(2)}),
               Invalid_input_error);
  // a non-finite edge length found by one of the threads
  Polygon_soup grid = planar_grid(20, 20, 1., 1.);
  grid.points[grid.points.size() / 2] = Point_3(std::numeric_limits<double>::infinity(), 0., 0.);
  const Surface_mesh infinite = to_mesh<Surface_mesh>(grid);
  EXPECT_THROW((Geodesic_distance_solver<Surface_mesh>{infinite, CGAL::VTP_geodesics::parameters::number_of_threads(2)}),
               Invalid_input_error);
}

// A vertex point map that throws for one vertex: the exception leaves the (threaded) preprocessing as it is.
struct Throwing_point_map
{
  typedef Vertex_index key_type;
  typedef Point_3 value_type;
  typedef Point_3 reference;
  typedef boost::readable_property_map_tag category;
  const Surface_mesh* mesh;
  Vertex_index bad;
  friend Point_3 get(const Throwing_point_map& m, Vertex_index v)
  {
    if(v == m.bad)
      throw std::runtime_error("no point for this vertex");
    return m.mesh->point(v);
  }
};

TEST(Bad_input, exception_of_the_point_map_leaves_the_preprocessing)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  const Throwing_point_map map{ &mesh, Vertex_index(static_cast<Surface_mesh::size_type>(num_vertices(mesh) / 2)) };
  typedef Geodesic_distance_solver<Surface_mesh, CGAL::Default, Throwing_point_map> Solver;
  for(int threads : { 1, 2 })
    EXPECT_THROW((Solver{ mesh, CGAL::VTP_geodesics::parameters::vertex_point_map(map).number_of_threads(threads) }),
                 std::runtime_error);
}

TEST(Bad_input, source_not_in_the_mesh_is_rejected)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(regular_tetrahedron());
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  std::vector<double> d(num_vertices(mesh));
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  const Vertex_index outside(static_cast<Surface_mesh::size_type>(num_vertices(mesh) + 10));
  EXPECT_THROW(solver.compute(map, outside), Invalid_input_error);
  EXPECT_THROW(solver.add_source(outside), Invalid_input_error);
  EXPECT_THROW(solver.compute(map, Surface_mesh::null_vertex()), Invalid_input_error);
  EXPECT_THROW(compute_geodesic_distances(mesh, map, outside), Invalid_input_error);
  EXPECT_THROW(compute_geodesic_distances(mesh, map, std::vector<Vertex_index>{Vertex_index(0), outside}),
               Invalid_input_error);
  // no source at all
  EXPECT_THROW(solver.compute(map), Invalid_input_error);
  EXPECT_THROW(compute_geodesic_distances(mesh, map, std::vector<Vertex_index>()), Invalid_input_error);

  // the solver is still usable after a rejected call
  EXPECT_NO_THROW(solver.compute(map, Vertex_index(1)));
  EXPECT_EQ(d[1], 0.);
}

TEST(Bad_input, removed_source_vertex_is_rejected)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  const Vertex_index corner(static_cast<Surface_mesh::size_type>(grid_vertex(4, 4, 4)));
  std::vector<Surface_mesh::Face_index> around;
  for(Surface_mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(corner), mesh))
    if(f != Surface_mesh::null_face())
      around.push_back(f);
  for(Surface_mesh::Face_index f : around)
    CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  ASSERT_TRUE(mesh.is_removed(corner));

  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  std::vector<double> d(index_range(mesh));
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  EXPECT_THROW(solver.compute(map, corner), Invalid_input_error);
  EXPECT_NO_THROW(solver.compute(map, Vertex_index(0)));
}

TEST(Bad_input, invalid_options_are_rejected)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  std::vector<double> d(num_vertices(mesh));
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  const double nan = std::numeric_limits<double>::quiet_NaN();

  namespace VP = CGAL::VTP_geodesics::parameters;
  for(double lambda : {0., -0., -1., -INF, nan})
  {
    EXPECT_THROW(solver.compute(map, Vertex_index(0), VP::lambda(lambda)), Invalid_input_error) << "lambda = " << lambda;
    EXPECT_THROW(compute_geodesic_distances(mesh, map, Vertex_index(0), VP::lambda(lambda)), Invalid_input_error)
      << "lambda = " << lambda;
  }
  for(double lambda_g : {-1., -1e-300, nan, INF})
    EXPECT_THROW(solver.compute(map, Vertex_index(0), VP::lambda(2.).lambda_g(lambda_g)), Invalid_input_error)
      << "lambda_g = " << lambda_g;
  for(double length : {-1e-9, 1., nan})
    EXPECT_THROW(solver.compute(map, Vertex_index(0), VP::minimum_window_length(length)), Invalid_input_error)
      << "minimum_window_length = " << length;
  EXPECT_THROW(solver.compute(map, Vertex_index(0), VP::number_of_threads(-1)), Invalid_input_error);

  // valid parameters
  EXPECT_NO_THROW(solver.compute(map, Vertex_index(0)));
  EXPECT_NO_THROW(solver.compute(map, Vertex_index(0), VP::lambda(2.5).lambda_g(0.)));
}

TEST(Bad_input, non_finite_or_huge_coordinates_are_rejected)
{
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), 1e300, -1e300, INF})
  {
    Polygon_soup soup = planar_grid(3, 3, 1., 1.);
    soup.points[grid_vertex(3, 1, 2)] = Point_3(0.3, bad, 0.);
    const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    EXPECT_THROW(Geodesic_distance_solver<Surface_mesh>{mesh}, Invalid_input_error) << "coordinate " << bad;
    std::vector<double> d(num_vertices(mesh));
    EXPECT_THROW(compute_geodesic_distances(mesh, boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)),
                                            Vertex_index(0)),
                 Invalid_input_error)
      << "coordinate " << bad;
  }
}

TEST(Bad_input, error_type_and_message)
{
  const Surface_mesh quads = to_mesh<Surface_mesh>(quad_grid(2));
  try
  {
    Geodesic_distance_solver<Surface_mesh> solver(quads);
    FAIL() << "a quad mesh must be rejected";
  }
  catch(const std::invalid_argument& e) // Invalid_input_error is an std::invalid_argument
  {
    EXPECT_NE(dynamic_cast<const Invalid_input_error*>(&e), nullptr);
    EXPECT_FALSE(std::string(e.what()).empty());
  }
}

// The message of the exception thrown by f (empty if none).
template <class F>
std::string message_of(F f)
{
  try
  {
    f();
  }
  catch(const Invalid_input_error& e)
  {
    return e.what();
  }
  return std::string();
}

// The messages name what is wrong: the vertex (in the order of vertices(tm)), the face, the source or target
// (its position in the user's list).
#define EXPECT_MESSAGE(call, part)                                                   \
  do                                                                                 \
  {                                                                                  \
    const std::string message = message_of(call);                                    \
    EXPECT_NE(message.find(part), std::string::npos) << "message: " << message;      \
  } while(0)

TEST(Bad_input, messages_name_the_vertex_face_source_or_target)
{
  namespace VP = CGAL::VTP_geodesics::parameters;
  Polygon_soup soup = planar_grid(3, 3, 1., 1.);
  soup.points[grid_vertex(3, 1, 2)] = Point_3(0.3, std::numeric_limits<double>::quiet_NaN(), 0.);
  const Surface_mesh nan_mesh = to_mesh<Surface_mesh>(soup);
  const std::string nan_vertex = "vertex " + std::to_string(grid_vertex(3, 1, 2)) + " has a non-finite coordinate";
  for(int threads : { 1, 2 })
    EXPECT_MESSAGE(([&] { Geodesic_distance_solver<Surface_mesh> s(nan_mesh, VP::number_of_threads(threads)); }),
                   nan_vertex);

  const Surface_mesh quads = to_mesh<Surface_mesh>(quad_grid(2));
  EXPECT_MESSAGE(([&] { Geodesic_distance_solver<Surface_mesh> s(quads); }), "face 0 is not a triangle");

  const Surface_mesh mesh = to_mesh<Surface_mesh>(regular_tetrahedron());
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  std::vector<double> d(num_vertices(mesh));
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  const Vertex_index outside(static_cast<Surface_mesh::size_type>(num_vertices(mesh) + 10));
  const std::vector<Vertex_index> sources = { Vertex_index(0), Vertex_index(1), outside };
  EXPECT_MESSAGE(([&] { solver.compute(map, sources); }), "source 2 is not a vertex");
  const std::vector<Vertex_index> targets = { Vertex_index(1), outside };
  EXPECT_MESSAGE(([&] { solver.compute(map, Vertex_index(0), VP::targets(targets)); }), "target 1 is not a vertex");
  const auto bad_location = std::make_pair(*faces(mesh).begin(), std::array<double, 3>{ { 0.5, 0.9, 0. } });
  EXPECT_MESSAGE(([&] { solver.compute(map, bad_location); }), "source 0 (in face 0)");
  EXPECT_MESSAGE(([&] { solver.compute(map, Vertex_index(0), VP::number_of_threads(-3)); }), "got -3");
}

// ------------------------------------------------------------------------------------------------------
// Numbering: the solver numbers the vertices along a space-filling curve inside, users see the order
// of vertices(tm) everywhere.
// ------------------------------------------------------------------------------------------------------

TEST(Numbering, users_see_the_order_of_the_mesh_whatever_the_order_inside)
{
  namespace VP = CGAL::VTP_geodesics::parameters;
  const Surface_mesh& mesh = elephant();
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  const std::vector<Vertex_index> in_order(vertices(mesh).begin(), vertices(mesh).end());
  ASSERT_EQ(solver.vertex_list(), in_order);
  for(std::size_t i = 0; i < in_order.size(); ++i)
    ASSERT_EQ(solver.vertex_id(in_order[i]), i);
  // the engine's own numbering is another one (else this test would not test anything)
  const auto& arrays = solver.mesh_arrays();
  std::size_t renumbered = 0;
  std::size_t f = 0;
  for(auto face : faces(mesh))
  {
    auto h = halfedge(face, mesh);
    for(int k = 0; k < 3; ++k, h = next(h, mesh))
      renumbered += std::size_t(arrays.source[3 * f + std::size_t(k)]) != solver.vertex_id(source(h, mesh));
    ++f;
  }
  EXPECT_GT(renumbered, num_faces(mesh));

  const Vertex_index s(1234);
  for(bool vsp : { false, true })
  {
    std::vector<double> d(num_vertices(mesh), NOT_A_VERTEX);
    solver.compute(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)), s,
                   VP::virtual_sources(vsp));
    ASSERT_EQ(d[s], 0.);
    for(Vertex_index v : vertices(mesh))
    {
      ASSERT_EQ(solver.distance(v), d[v]);
      ASSERT_EQ(solver.distances()[solver.vertex_id(v)], d[v]);
    }
    std::size_t rows = 0;
    solver.compute_each(std::vector<Vertex_index>(1, s), [&](std::size_t, Vertex_index, const std::vector<double>& row) {
      ++rows;
      for(Vertex_index v : vertices(mesh))
        ASSERT_EQ(row[solver.vertex_id(v)], d[v]) << "vertex " << std::size_t(v);
    }, VP::virtual_sources(vsp));
    EXPECT_EQ(rows, 1u);
  }
}

// The same mesh with its vertices listed in a shuffled order gives the same distances, bit for bit (the
// numbering inside depends on the points only), and the same farthest-point samples.
TEST(Numbering, distances_do_not_depend_on_the_order_of_the_vertices)
{
  namespace VP = CGAL::VTP_geodesics::parameters;
  const Polygon_soup soup = to_soup(elephant());
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);  // built as the shuffled copy is
  std::vector<std::size_t> new_of(soup.points.size());
  for(std::size_t i = 0; i < new_of.size(); ++i)
    new_of[i] = i;
  std::mt19937 generator(7);
  std::shuffle(new_of.begin(), new_of.end(), generator);
  Polygon_soup shuffled;
  shuffled.points.resize(soup.points.size());
  for(std::size_t i = 0; i < new_of.size(); ++i)
    shuffled.points[new_of[i]] = soup.points[i];
  for(const std::vector<std::size_t>& polygon : soup.polygons)
    shuffled.add_triangle(new_of[polygon[0]], new_of[polygon[1]], new_of[polygon[2]]);
  const Surface_mesh other = to_mesh<Surface_mesh>(shuffled);

  const std::size_t s = 2774;
  for(bool vsp : { false, true })
  {
    const std::vector<double> d = vtp_distances(mesh, Vertex_index(Surface_mesh::size_type(s)), VP::virtual_sources(vsp));
    const std::vector<double> e
      = vtp_distances(other, Vertex_index(Surface_mesh::size_type(new_of[s])), VP::virtual_sources(vsp));
    for(std::size_t i = 0; i < d.size(); ++i)
      ASSERT_EQ(d[i], e[new_of[i]]) << "vertex " << i << (vsp ? " (vsp)" : " (vtp)");
  }

  Geodesic_distance_solver<Surface_mesh> a(mesh), b(other);
  const auto first = a.farthest_point_sampling(6, VP::first_sample(Vertex_index(Surface_mesh::size_type(s))));
  const auto second = b.farthest_point_sampling(6, VP::first_sample(Vertex_index(Surface_mesh::size_type(new_of[s]))));
  ASSERT_EQ(first.samples.size(), second.samples.size());
  for(std::size_t k = 0; k < first.samples.size(); ++k)
    EXPECT_EQ(new_of[std::size_t(first.samples[k])], std::size_t(second.samples[k]));
  for(std::size_t i = 0; i < new_of.size(); ++i)
  {
    ASSERT_EQ(first.distances[i], second.distances[new_of[i]]);
    ASSERT_EQ(first.labels[i], second.labels[new_of[i]]);
  }
}

// Error messages name vertices by their place in vertices(tm).
TEST(Numbering, messages_name_vertices_in_the_order_of_the_mesh)
{
  namespace VP = CGAL::VTP_geodesics::parameters;
  Polygon_soup soup = planar_grid(6, 6, 1., 1.);
  Polygon_soup two = soup;
  two.append(soup, Vector_3(3., 0., 0.));  // a second component
  const Surface_mesh mesh = to_mesh<Surface_mesh>(two);
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  std::vector<double> d(num_vertices(mesh));
  auto map = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  for(std::size_t bad : { std::size_t(0), std::size_t(17), std::size_t(40), std::size_t(num_vertices(mesh) - 1) })
  {
    std::vector<double> known(num_vertices(mesh), 1.);
    known[bad] = -2.;
    auto known_map = boost::make_iterator_property_map(known.begin(), get(boost::vertex_index, mesh));
    EXPECT_MESSAGE(([&] { solver.compute(map, Vertex_index(0), VP::initial_distances(known_map)); }),
                   "initial distance of vertex " + std::to_string(bad) + " is");
  }
  // faces too are numbered otherwise inside (by their least vertex), and named by their place in faces(tm)
  const std::size_t last_face = num_faces(mesh) - 1;
  const auto& source_of = solver.mesh_arrays().source;
  for(std::size_t f = 1; f < num_faces(mesh); ++f)
    ASSERT_LE((std::min)({ source_of[3 * f - 3], source_of[3 * f - 2], source_of[3 * f - 1] }),
              (std::min)({ source_of[3 * f], source_of[3 * f + 1], source_of[3 * f + 2] }));
  const auto bad_location = std::make_pair(Surface_mesh::Face_index(Surface_mesh::size_type(last_face)),
                                           std::array<double, 3>{ { 0.5, 0.9, 0. } });
  EXPECT_MESSAGE(([&] { solver.compute(map, bad_location); }),
                 "source 0 (in face " + std::to_string(last_face) + ")");

  solver.compute(map, Vertex_index(0));
  const std::size_t unreachable = num_vertices(mesh) - 3;
  ASSERT_EQ(d[unreachable], INF);
  std::vector<Point_3> path;
  EXPECT_MESSAGE(([&] { solver.shortest_path_points(Vertex_index(Surface_mesh::size_type(unreachable)),
                                                     std::back_inserter(path)); }),
                 "no path: vertex " + std::to_string(unreachable) + " is not reached");
}
