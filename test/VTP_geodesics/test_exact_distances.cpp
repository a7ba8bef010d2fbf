// Exact distances from one source vertex (VTP), against values that do not come from the code under test:
// - closed forms: meshes whose geodesic distances follow from elementary geometry (planar domains,
//   developable surfaces, unfoldings of convex polyhedra);
// - CGAL::Surface_mesh_shortest_path (an independent exact algorithm) on real meshes, one case per
//   (mesh, source), sources on the boundary and at saddle vertices included;
// - invariance under midpoint subdivision.
// Hard but valid meshes (components, degenerate faces, ...) are in test_hard_meshes.cpp.

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <vtp_support/midpoint_subdivision.h>
#include <vtp_support/shortest_path_reference.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace vtp_test;

namespace {

// Distances on a convex planar domain: the Euclidean distance to the source.
void check_euclidean(const Polygon_soup& soup, const std::vector<std::size_t>& sources, const std::string& name)
{
  ASSERT_TRUE(is_valid_planar_soup(soup)) << name << ": a triangle is flipped or degenerate";
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(std::size_t s : sources)
  {
    std::vector<double> expected(soup.points.size());
    for(std::size_t i = 0; i < soup.points.size(); ++i)
      expected[i] = distance(soup.points[s], soup.points[i]);
    const std::vector<double> d = vtp_distances(mesh, Vertex_index(static_cast<Surface_mesh::size_type>(s)));
    EXPECT_EQ(d[s], 0.);
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, name + ", source " + std::to_string(s)));
  }
}

} // namespace

TEST(Analytic, planar_regular_grid)
{
  const int n = 24;
  const Polygon_soup soup = planar_grid(n, n, 1., 1.);
  check_euclidean(soup,
                  {grid_vertex(n, 0, 0),          // corner
                   grid_vertex(n, n, n / 3),      // middle of a side
                   grid_vertex(n, n / 2, n / 2),  // center
                   grid_vertex(n, 5, 17)},        // interior, off-center
                  "regular grid");
}

TEST(Analytic, planar_jittered_grid)
{
  const int n = 24;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 20260101u);
  check_euclidean(soup,
                  {grid_vertex(n, 0, 0), grid_vertex(n, n, n), grid_vertex(n, 0, 9), grid_vertex(n, n / 2, n / 2),
                   grid_vertex(n, 19, 4)},
                  "jittered grid");
}

TEST(Analytic, planar_anisotropic_grid)
{
  // [0,20] x [0,1] with 20 x 20 cells: each cell is 20 times longer than high.
  const int n = 20;
  const Polygon_soup soup = planar_grid(n, n, 20., 1.);
  check_euclidean(soup,
                  {grid_vertex(n, 0, 0), grid_vertex(n, n, n / 2), grid_vertex(n, n / 2, n / 2),
                   grid_vertex(n, 3, 14)},
                  "anisotropic grid (x stretched 20x)");
}

TEST(Analytic, planar_anisotropic_jittered_grid)
{
  const int n = 20;
  const Polygon_soup soup = planar_grid(n, n, 20., 1., 0.25, 7u);
  check_euclidean(soup, {grid_vertex(n, 0, n), grid_vertex(n, 11, 6)}, "anisotropic jittered grid");
}

// L = [0,2]x[0,1] U [0,1]x[0,2], reflex corner c = (1,1). The shortest path from s to p is the segment
// [s,p] if it stays in L, else the path s -> c -> p (the only reflex vertex of a simply connected domain).
TEST(Analytic, l_shape_reflex_corner)
{
  const int n = 8;
  const Polygon_soup soup = l_shape(n);
  ASSERT_TRUE(is_valid_planar_soup(soup));
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Point_3 c(1, 1, 0);

  // A point with x > 1 lies in [0,2]x[0,1] only, a point with y > 1 in [0,1]x[0,2] only; any two other
  // combinations lie together in one of the two (convex) rectangles. For a in the first and b in the
  // second, [a,b] stays in L iff b is not strictly to the right of the line (a, c) (exact predicate).
  auto visible = [&c](const Point_3& s, const Point_3& p) {
    const bool s_right = s.x() > 1, s_top = s.y() > 1, p_right = p.x() > 1, p_top = p.y() > 1;
    if(!((s_right && p_top) || (s_top && p_right)))
      return true;
    const Point_3& a = s_right ? s : p;
    const Point_3& b = s_right ? p : s;
    return CGAL::orientation(Point_2(a.x(), a.y()), Point_2(c.x(), c.y()), Point_2(b.x(), b.y())) !=
           CGAL::RIGHT_TURN;
  };

  const std::vector<Point_3> sources = {Point_3(2, 0, 0),                         // convex corner
                                        Point_3(14. / n, 4. / n, 0),              // interior, right arm
                                        Point_3(4. / n, 14. / n, 0),              // interior, top arm
                                        Point_3(2, 6. / n, 0),                    // boundary, right arm
                                        Point_3(1, 1, 0),                         // the reflex corner
                                        Point_3(0, 0, 0)};                        // sees everything
  std::size_t hidden_total = 0;
  for(const Point_3& sp : sources)
  {
    const Vertex_index s = find_vertex(mesh, sp);
    ASSERT_NE(s, Surface_mesh::null_vertex());
    std::vector<double> expected(num_vertices(mesh));
    for(Vertex_index v : vertices(mesh))
    {
      const Point_3& p = mesh.point(v);
      if(visible(sp, p))
        expected[v] = distance(sp, p);
      else
      {
        expected[v] = distance(sp, c) + distance(c, p);
        ++hidden_total;
      }
    }
    const std::vector<double> d = vtp_distances(mesh, s);
    EXPECT_EQ(d[s], 0.);
    std::ostringstream name;
    name << "L-shape, source (" << sp.x() << "," << sp.y() << ")";
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, name.str()));
  }
  EXPECT_GT(hidden_total, 50u) << "the test must have vertices hidden behind the reflex corner";
}

// The lateral surface of a prism is developable: cut along a vertical edge, it unrolls isometrically into
// the strip [0,L] x [0,H] (u = arc length along the polygon, v = height); on the closed surface the
// distance is the minimum over the images of the target shifted by -L, 0, +L in the periodic strip
// (the infinite strip is convex, so the straight segments are realizable).
TEST(Analytic, open_prism_developable)
{
  const int sides = 12, bands = 8;
  const Polygon_soup soup = open_prism(sides, bands, 1., 2.);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);

  std::vector<double> u(sides + 1, 0.); // arc length of corner k along the polygon (exact unrolling)
  for(int k = 0; k < sides; ++k)
    u[k + 1] = u[k] + distance(soup.points[k], soup.points[(k + 1) % sides]);
  const double perimeter = u[sides];

  const int source_corners[][2] = {{0, 0}, {5, 4}, {3, bands}, {7, 1}};
  for(const auto& sc : source_corners)
  {
    const std::size_t s = std::size_t(sc[1]) * sides + sc[0];
    std::vector<double> expected(soup.points.size());
    for(int r = 0; r <= bands; ++r)
      for(int k = 0; k < sides; ++k)
      {
        const std::size_t i = std::size_t(r) * sides + k;
        const double dv = soup.points[i].z() - soup.points[s].z();
        double best = INF;
        for(int wrap = -1; wrap <= 1; ++wrap)
          best = (std::min)(best, std::hypot(u[k] - u[sc[0]] + wrap * perimeter, dv));
        expected[i] = best;
      }
    const std::vector<double> d = vtp_distances(mesh, Vertex_index(static_cast<Surface_mesh::size_type>(s)));
    EXPECT_EQ(d[s], 0.);
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE,
                               "open prism, source corner " + std::to_string(sc[0]) + " ring " +
                                 std::to_string(sc[1])));
  }
}

// Unit cube, source at the corner s = (0,0,0).
// - On the three faces through s (x=0, y=0 or z=0), the distance is |p - s|: the segment lies in the face
//   and the Euclidean distance is a lower bound.
// - On the face x=1 (and symmetrically y=1, z=1), with p = (1, y, z):
//     d = min( sqrt((1+y)^2 + z^2), sqrt((1+z)^2 + y^2) ),
//   the two unfoldings through the faces y=0 and z=0. Proof: call g this function (extended by symmetry to
//   the three far faces). g is continuous across the far edges and is a minimum of distances to fixed points
//   of each face's plane, so it is 1-Lipschitz for the intrinsic distance of the far faces; on the hexagon
//   where far and near faces meet, g(q) = |q| = d(s,q). A shortest path leaves the near faces for the last
//   time at some q on that hexagon, so d(s,p) = |q| + (length in the far faces) >= g(q) + (g(p) - g(q)).
//   The two unfoldings are realizable paths, so d = g. At the far corner (1,1,1): sqrt(5).
TEST(Analytic, cube_corner_source)
{
  const int n = 6;
  std::vector<std::array<int, 3> > lattice;
  const Polygon_soup soup = subdivided_cube(n, &lattice);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);

  std::size_t s = soup.points.size(), far_corner = soup.points.size();
  for(std::size_t i = 0; i < lattice.size(); ++i)
  {
    if(lattice[i] == std::array<int, 3>{{0, 0, 0}}) s = i;
    if(lattice[i] == std::array<int, 3>{{n, n, n}}) far_corner = i;
  }
  ASSERT_LT(s, soup.points.size());
  ASSERT_LT(far_corner, soup.points.size());

  std::vector<double> expected(soup.points.size());
  std::size_t on_far_faces = 0;
  for(std::size_t i = 0; i < soup.points.size(); ++i)
  {
    const std::array<int, 3>& l = lattice[i];
    const Point_3& p = soup.points[i];
    if(l[0] == 0 || l[1] == 0 || l[2] == 0)
      expected[i] = distance(p, soup.points[s]);
    else
    {
      // p is on a far face: the axis with coordinate n, the two others y, z in the formula
      const int axis = (l[0] == n) ? 0 : (l[1] == n ? 1 : 2);
      const double a = CGAL::to_double(p[(axis + 1) % 3]), b = CGAL::to_double(p[(axis + 2) % 3]);
      expected[i] = (std::min)(std::hypot(1. + a, b), std::hypot(1. + b, a));
      ++on_far_faces;
    }
  }
  ASSERT_EQ(on_far_faces, std::size_t(3 * n * n - 3 * n + 1));
  EXPECT_DOUBLE_EQ(expected[far_corner], std::sqrt(5.));

  const std::vector<double> d = vtp_distances(mesh, Vertex_index(static_cast<Surface_mesh::size_type>(s)));
  EXPECT_EQ(d[s], 0.);
  EXPECT_NEAR(d[far_corner], std::sqrt(5.), EXACT_TOLERANCE * std::sqrt(5.));
  EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "cube, corner source"));
}

namespace {

// Regular tetrahedron T0 T1 T2 T3, source T0. A point p on a face through T0 is at distance |p - T0|
// (the segment lies in the face). A point p of the opposite face T1 T2 T3 is at distance
// min_e |p - T0'_e|, T0'_e being T0 unfolded across the edge e = (Ti, Tj) into the plane of the opposite
// face: T0'_e = Ti + Tj - Tk (the rhombus of two equilateral triangles). Lower bound: the path enters the
// opposite face for the last time at some q on an edge e, and |T0 - q| + |q - p| = |T0'_e - q| + |q - p|.
// Realizable: the three unfolded faces and the opposite face form an equilateral triangle of side 2a
// with the T0'_e at its corners, and [T0'_e, p] crosses e inside the edge.
double tetrahedron_expected(const std::array<Point_3, 4>& t, const Point_3& p)
{
  auto plane_distance = [&p](const Point_3& a, const Point_3& b, const Point_3& c) {
    const Vector_3 normal = CGAL::cross_product(b - a, c - a);
    return std::abs(CGAL::to_double((p - a) * normal)) / std::sqrt(CGAL::to_double(normal.squared_length()));
  };
  const double opposite = plane_distance(t[1], t[2], t[3]);
  const double through_source = (std::min)({plane_distance(t[0], t[1], t[2]), plane_distance(t[0], t[2], t[3]),
                                            plane_distance(t[0], t[3], t[1])});
  if(through_source < opposite)
    return distance(p, t[0]);
  double best = INF;
  for(int k = 1; k <= 3; ++k)
  {
    const Point_3& ti = t[k % 3 + 1];
    const Point_3& tj = t[(k + 1) % 3 + 1];
    const Point_3 image = ti + (tj - t[k]);
    best = (std::min)(best, distance(p, image));
  }
  return best;
}

} // namespace

TEST(Analytic, regular_tetrahedron)
{
  const Polygon_soup soup = regular_tetrahedron();
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const double a = 2. * std::sqrt(2.);
  for(std::size_t s = 0; s < 4; ++s)
  {
    const std::vector<double> d = vtp_distances(mesh, Vertex_index(static_cast<Surface_mesh::size_type>(s)));
    std::vector<double> expected(4, a);
    expected[s] = 0.;
    EXPECT_EQ(d[s], 0.);
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "tetrahedron, source " + std::to_string(s)));
  }
}

TEST(Analytic, subdivided_regular_tetrahedron)
{
  const Polygon_soup soup = regular_tetrahedron();
  const std::array<Point_3, 4> t = {{soup.points[0], soup.points[1], soup.points[2], soup.points[3]}};
  const double a = 2. * std::sqrt(2.);
  for(int levels = 1; levels <= 4; ++levels)
  {
    Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    vtp_support::midpoint_subdivide(mesh, levels);
    ASSERT_EQ(num_faces(mesh), std::size_t(4) << (2 * levels));
    ASSERT_EQ(mesh.point(Vertex_index(0)), t[0]);

    std::vector<double> expected(num_vertices(mesh));
    for(Vertex_index v : vertices(mesh))
      expected[v] = tetrahedron_expected(t, mesh.point(v));
    const std::vector<double> d = vtp_distances(mesh, Vertex_index(0));
    EXPECT_EQ(d[0], 0.);
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "tetrahedron, " + std::to_string(levels) + " level(s)"));

    // Explicit values: the other original vertices at distance a; the midpoints of the edges through the
    // source at a/2; the midpoints of the opposite edges at the height of a face, a sqrt(3)/2.
    for(int k = 1; k <= 3; ++k)
    {
      EXPECT_NEAR(d[find_vertex(mesh, t[k])], a, EXACT_TOLERANCE * a);
      EXPECT_NEAR(d[find_vertex(mesh, CGAL::midpoint(t[0], t[k]))], a / 2., EXACT_TOLERANCE * a);
      EXPECT_NEAR(d[find_vertex(mesh, CGAL::midpoint(t[k], t[k % 3 + 1]))], a * std::sqrt(3.) / 2.,
                  EXACT_TOLERANCE * a);
    }
    if(levels >= 2)
    {
      // (T1 + T2 + 2 T3) / 4 (the midpoint of the midpoints of T1 T3 and T2 T3) lies inside the opposite face.
      // In a frame of that face, T1 = (0,0), T2 = (a,0), T3 = (a/2,h) with h = a sqrt(3)/2, the point is
      // (a/2, h/2); the unfolded sources are T2 + T3 - T1 = (3a/2, h), T3 + T1 - T2 = (-a/2, h) at distance
      // sqrt(a^2 + h^2/4) = sqrt(19) a / 4, and T1 + T2 - T3 = (a/2, -h) at distance 3h/2 = sqrt(27) a / 4.
      const Point_3 inner = CGAL::midpoint(CGAL::midpoint(t[1], t[3]), CGAL::midpoint(t[2], t[3]));
      const Vertex_index vi = find_vertex(mesh, inner);
      ASSERT_NE(vi, Surface_mesh::null_vertex());
      EXPECT_NEAR(tetrahedron_expected(t, inner), std::sqrt(19.) * a / 4., 1e-14 * a);
      EXPECT_NEAR(d[vi], std::sqrt(19.) * a / 4., EXACT_TOLERANCE * a);
    }
  }
}

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
