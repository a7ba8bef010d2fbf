// Comparison with an independent exact algorithm (CGAL::Surface_mesh_shortest_path) on real meshes,
// invariance under midpoint subdivision, and hard-but-valid input (several components, isolated vertices,
// Surface_mesh with removed elements, sources on the boundary and on saddle vertices).

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <vtp_support/midpoint_subdivision.h>
#include <vtp_support/shortest_path_reference.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <string>
#include <vector>

using namespace vtp_test;
using vtp_support::midpoint_subdivide;
using vtp_support::shortest_path_reference_distances;

namespace {

// Meshes are read once per process.
const Surface_mesh& cached_mesh(const std::string& name)
{
  static std::map<std::string, Surface_mesh> cache;
  auto it = cache.find(name);
  if(it == cache.end())
    it = cache.emplace(name, load_mesh(name)).first;
  return it->second;
}

std::size_t count_finite(const std::vector<double>& d)
{
  std::size_t n = 0;
  for(double x : d)
    if(std::isfinite(x))
      ++n;
  return n;
}

// ---------------------------------------------------------------------------------------------------
// Oracle: CGAL::Surface_mesh_shortest_path, one test case per (mesh, source).
// ---------------------------------------------------------------------------------------------------

enum class Source_choice { first, middle, last, boundary, saddle };

const char* source_choice_name(Source_choice c)
{
  switch(c)
  {
    case Source_choice::first: return "first_vertex";
    case Source_choice::middle: return "middle_vertex";
    case Source_choice::last: return "last_vertex";
    case Source_choice::boundary: return "boundary_vertex";
    case Source_choice::saddle: return "saddle_vertex";
  }
  return "unknown";
}

struct Oracle_case
{
  std::string mesh;
  Source_choice source;
};

std::ostream& operator<<(std::ostream& os, const Oracle_case& c)
{
  return os << c.mesh << " / " << source_choice_name(c.source);
}

std::string oracle_case_name(const ::testing::TestParamInfo<Oracle_case>& info)
{
  std::string name = info.param.mesh.substr(0, info.param.mesh.rfind('.'));
  for(char& ch : name)
    if(!std::isalnum(static_cast<unsigned char>(ch)))
      ch = '_';
  return name + "__" + source_choice_name(info.param.source);
}

class Oracle : public ::testing::TestWithParam<Oracle_case>
{};

TEST_P(Oracle, matches_surface_mesh_shortest_path)
{
  const Surface_mesh& mesh = cached_mesh(GetParam().mesh);
  const std::size_t n = num_vertices(mesh);
  Vertex_index source;
  switch(GetParam().source)
  {
    case Source_choice::first: source = Vertex_index(0); break;
    case Source_choice::middle: source = Vertex_index(static_cast<Surface_mesh::size_type>(n / 2)); break;
    case Source_choice::last: source = Vertex_index(static_cast<Surface_mesh::size_type>(n - 1)); break;
    case Source_choice::boundary:
      source = first_boundary_vertex(mesh);
      ASSERT_NE(source, Surface_mesh::null_vertex()) << "the mesh has no boundary";
      ASSERT_TRUE(mesh.is_border(source));
      break;
    case Source_choice::saddle:
      source = strongest_saddle_vertex(mesh);
      ASSERT_NE(source, Surface_mesh::null_vertex()) << "the mesh has no saddle vertex";
      ASSERT_GT(angle_sum(mesh, source), 2. * PI);
      ASSERT_FALSE(mesh.is_border(source));
      break;
  }

  const std::vector<double> reference = shortest_path_reference_distances(mesh, source);
  ASSERT_EQ(count_finite(reference), n) << "the test meshes are connected";
  const std::vector<double> d = vtp_distances(mesh, source);
  EXPECT_EQ(d[source], 0.);
  std::ostringstream what;
  what << GetParam() << " (vertex " << std::size_t(source) << ")";
  EXPECT_TRUE(distances_near(d, reference, EXACT_TOLERANCE, what.str()));
}

INSTANTIATE_TEST_SUITE_P(
  Real_meshes, Oracle,
  ::testing::Values(Oracle_case{"elephant-with-holes.off", Source_choice::boundary},
                    Oracle_case{"elephant-with-holes.off", Source_choice::saddle},
                    Oracle_case{"elephant-with-holes.off", Source_choice::middle},
                    Oracle_case{"elephant.off", Source_choice::first},
                    Oracle_case{"elephant.off", Source_choice::middle},
                    Oracle_case{"elephant.off", Source_choice::saddle},
                    Oracle_case{"mushroom.off", Source_choice::first},
                    Oracle_case{"mushroom.off", Source_choice::boundary},
                    Oracle_case{"mushroom.off", Source_choice::saddle},
                    Oracle_case{"three_peaks.off", Source_choice::middle},
                    Oracle_case{"three_peaks.off", Source_choice::boundary},
                    Oracle_case{"three_peaks.off", Source_choice::saddle},
                    Oracle_case{"knot1.off", Source_choice::first},
                    Oracle_case{"knot1.off", Source_choice::middle},
                    Oracle_case{"knot1.off", Source_choice::saddle},
                    Oracle_case{"mech-holes-shark.off", Source_choice::first},
                    Oracle_case{"mech-holes-shark.off", Source_choice::boundary},
                    Oracle_case{"mech-holes-shark.off", Source_choice::saddle},
                    Oracle_case{"sphere.off", Source_choice::first},
                    Oracle_case{"sphere.off", Source_choice::middle},
                    Oracle_case{"sphere.off", Source_choice::last}),
  oracle_case_name);

// ---------------------------------------------------------------------------------------------------
// Invariance: 1-to-4 midpoint subdivision keeps the surface (each triangle is cut into four coplanar
// ones), hence the geodesic distances between the original vertices.
// ---------------------------------------------------------------------------------------------------

void check_subdivision_invariance(const Surface_mesh& mesh, int levels, const std::vector<Vertex_index>& sources,
                                  const std::string& name)
{
  Surface_mesh fine = mesh;
  midpoint_subdivide(fine, levels);
  const std::size_t n = num_vertices(mesh);
  ASSERT_EQ(num_faces(fine), num_faces(mesh) << (2 * levels));
  for(Vertex_index v : vertices(mesh))
    ASSERT_EQ(fine.point(v), mesh.point(v)) << "the original vertices must come first, in order";

  for(Vertex_index s : sources)
  {
    const std::vector<double> coarse_d = vtp_distances(mesh, s);
    const std::vector<double> fine_d = vtp_distances(fine, s);
    const std::vector<double> fine_on_coarse(fine_d.begin(), fine_d.begin() + static_cast<std::ptrdiff_t>(n));
    EXPECT_TRUE(distances_near(fine_on_coarse, coarse_d, EXACT_TOLERANCE,
                               name + ", " + std::to_string(levels) + " subdivision level(s), source " +
                                 std::to_string(std::size_t(s))));
  }
}

} // namespace

TEST(Subdivision_invariance, elephant)
{
  const Surface_mesh& mesh = cached_mesh("elephant.off");
  check_subdivision_invariance(mesh, 1, {Vertex_index(0), strongest_saddle_vertex(mesh)}, "elephant");
}

TEST(Subdivision_invariance, mushroom_with_boundary)
{
  const Surface_mesh& mesh = cached_mesh("mushroom.off");
  check_subdivision_invariance(mesh, 1, {Vertex_index(7), first_boundary_vertex(mesh)}, "mushroom");
}

TEST(Subdivision_invariance, jittered_grid)
{
  const int n = 24;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1., 0.3, 4242u));
  check_subdivision_invariance(mesh, 2,
                               {Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, 0, 0))),
                                Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, 13, 9)))},
                               "jittered grid");
}

// ---------------------------------------------------------------------------------------------------
// Hard but valid input
// ---------------------------------------------------------------------------------------------------

// Two connected components: the other component is unreachable (+infinity); the component of the source
// matches the oracle run on that component alone.
TEST(Hard_input, two_components)
{
  const Polygon_soup a = to_soup(cached_mesh("three_peaks.off"));
  const Polygon_soup b = to_soup(cached_mesh("sphere.off"));
  Polygon_soup both = a;
  both.append(b, Vector_3(100, 0, 0));
  const Surface_mesh mesh = to_mesh<Surface_mesh>(both);
  const Surface_mesh mesh_a = to_mesh<Surface_mesh>(a);
  const Surface_mesh mesh_b = to_mesh<Surface_mesh>(b);
  const std::size_t na = a.points.size(), nb = b.points.size();

  {
    const Vertex_index s(17);
    std::vector<double> expected = shortest_path_reference_distances(mesh_a, s);
    expected.resize(na + nb, INF);
    CGAL::VTP_geodesics::Propagation_statistics st;
    const std::vector<double> d = vtp_distances(mesh, s, CGAL::parameters::default_values(), &st);
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "two components, source in the first"));
    EXPECT_EQ(st.reached_vertices, na);
  }
  {
    const Vertex_index s_b(5);
    const std::vector<double> reference = shortest_path_reference_distances(mesh_b, s_b);
    std::vector<double> expected(na, INF);
    expected.insert(expected.end(), reference.begin(), reference.end());
    CGAL::VTP_geodesics::Propagation_statistics st;
    const std::vector<double> d = vtp_distances(mesh, Vertex_index(static_cast<Surface_mesh::size_type>(na + 5)),
                                                CGAL::parameters::default_values(), &st);
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "two components, source in the second"));
    EXPECT_EQ(st.reached_vertices, nb);
  }
}

// An isolated vertex (in no face) is unreachable; as a source it reaches only itself.
TEST(Hard_input, isolated_vertex)
{
  Polygon_soup soup = to_soup(cached_mesh("sphere.off"));
  const std::size_t n = soup.points.size();
  soup.points.push_back(Point_3(0.1, 0.2, 0.3)); // inside the sphere, in no face
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  ASSERT_EQ(num_vertices(mesh), n + 1);
  ASSERT_TRUE(mesh.is_isolated(Vertex_index(static_cast<Surface_mesh::size_type>(n))));

  {
    const Surface_mesh sphere = to_mesh<Surface_mesh>(to_soup(cached_mesh("sphere.off")));
    std::vector<double> expected = shortest_path_reference_distances(sphere, Vertex_index(3));
    expected.push_back(INF);
    const std::vector<double> d = vtp_distances(mesh, Vertex_index(3));
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "sphere plus an isolated vertex"));
  }
  {
    std::vector<double> expected(n + 1, INF);
    expected[n] = 0.;
    CGAL::VTP_geodesics::Propagation_statistics st;
    const std::vector<double> d = vtp_distances(mesh, Vertex_index(static_cast<Surface_mesh::size_type>(n)),
                                                CGAL::parameters::default_values(), &st);
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "isolated source"));
    EXPECT_EQ(st.reached_vertices, 1u);
    EXPECT_EQ(st.max_distance, 0.);
  }
}

// A Surface_mesh with removed (not garbage-collected) elements: the removed ones must be skipped, and the
// distances of the others match the oracle on a compacted copy.
TEST(Hard_input, surface_mesh_with_removed_elements)
{
  Surface_mesh mesh = cached_mesh("elephant.off");
  // remove all the faces around one vertex (which removes the vertex: it becomes isolated) ...
  const Vertex_index removed_vertex(1000);
  std::vector<Surface_mesh::Face_index> around;
  for(Surface_mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(removed_vertex), mesh))
    around.push_back(f);
  for(Surface_mesh::Face_index f : around)
    CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  // ... and one face elsewhere
  const Surface_mesh::Face_index removed_face(4000);
  ASSERT_FALSE(mesh.is_removed(removed_face));
  CGAL::Euler::remove_face(mesh.halfedge(removed_face), mesh);
  ASSERT_TRUE(mesh.has_garbage());
  ASSERT_TRUE(mesh.is_removed(removed_vertex));
  ASSERT_TRUE(mesh.is_removed(removed_face));

  std::vector<std::size_t> new_index;
  const Surface_mesh compact = to_mesh<Surface_mesh>(to_soup(mesh, &new_index));
  // (BGL's num_vertices() of a Surface_mesh counts the removed vertices too)
  ASSERT_EQ(compact.number_of_vertices(), mesh.number_of_vertices());
  ASSERT_EQ(compact.number_of_faces(), mesh.number_of_faces());

  // a source far from the holes, and one on the border of the first hole
  Vertex_index on_hole = Surface_mesh::null_vertex();
  for(Vertex_index v : vertices(mesh))
    if(mesh.is_border(v) && on_hole == Surface_mesh::null_vertex())
      on_hole = v;
  ASSERT_NE(on_hole, Surface_mesh::null_vertex());
  for(Vertex_index s : {Vertex_index(0), on_hole})
  {
    ASSERT_FALSE(mesh.is_removed(s));
    const std::vector<double> reference =
      shortest_path_reference_distances(compact, Vertex_index(static_cast<Surface_mesh::size_type>(new_index[s])));
    std::vector<double> expected(index_range(mesh), NOT_A_VERTEX);
    for(Vertex_index v : vertices(mesh))
      expected[v] = reference[new_index[v]];
    CGAL::VTP_geodesics::Propagation_statistics st;
    const std::vector<double> d = vtp_distances(mesh, s, CGAL::parameters::default_values(), &st);
    EXPECT_EQ(st.vertices, std::size_t(mesh.number_of_vertices()));
    EXPECT_EQ(st.faces, std::size_t(mesh.number_of_faces()));
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE,
                               "elephant with removed elements, source " + std::to_string(std::size_t(s))));
  }
}
