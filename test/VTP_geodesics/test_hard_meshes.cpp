// Hard but valid input: sources on the boundary and on saddle vertices, several components and isolated
// vertices, zero-area faces and zero-length edges, needle and cap triangles, very large and very small
// coordinates, a non-manifold (pinched) vertex, and Surface_mesh with removed elements.
//
// Every result is checked against properties that any correct result has (no NaN, no negative value,
// 0 at the source, finite exactly on the component of the source, at least the Euclidean distance to the
// source, 1-Lipschitz along the edges), and against expected values from CGAL's exact algorithm
// (Surface_mesh_shortest_path, on the same mesh or, for degenerate meshes on which it cannot run, on a
// non-degenerate mesh of the same surface), from elementary geometry, or from invariants (scaling).

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <vtp_support/midpoint_subdivision.h>
#include <vtp_support/shortest_path_reference.h>

#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace vtp_test;
using CGAL::VTP_geodesics::Geodesic_distance_solver;
using CGAL::VTP_geodesics::Propagation_statistics;
using vtp_support::midpoint_subdivide;
using vtp_support::shortest_path_reference_distances;

namespace {

Vertex_index vertex(std::size_t i) { return Vertex_index(static_cast<Surface_mesh::size_type>(i)); }

// Connected components over the edges; an isolated vertex is a component of its own.
std::vector<std::size_t> components(const Surface_mesh& mesh)
{
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> label(index_range(mesh), none);
  std::size_t next = 0;
  for(Vertex_index start : vertices(mesh))
  {
    if(label[start] != none)
      continue;
    std::vector<Vertex_index> stack(1, start);
    label[start] = next;
    while(!stack.empty())
    {
      const Vertex_index v = stack.back();
      stack.pop_back();
      if(mesh.is_isolated(v))
        continue;
      for(Surface_mesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
        if(label[mesh.source(h)] == none)
        {
          label[mesh.source(h)] = next;
          stack.push_back(mesh.source(h));
        }
    }
    ++next;
  }
  return label;
}

// Properties of every correct result `d` (indexed by vertex index) from the source `s`:
// - no NaN and no negative value; 0 at the source;
// - finite exactly on the connected component of the source (+infinity elsewhere);
// - at least the Euclidean distance to the source (a path on the surface is a path in space);
// - |d(u) - d(v)| <= |uv| along every edge (a shortest path can be extended by the edge).
// The last two are checked up to 1e-12 * (largest finite distance).
::testing::AssertionResult satisfies_invariants(const Surface_mesh& mesh, const std::vector<double>& d, Vertex_index s,
                                                const std::string& what)
{
  const std::vector<std::size_t> label = components(mesh);
  const double tolerance = EXACT_TOLERANCE * (std::max)(max_finite(d), 1e-300);
  std::ostringstream errors;
  std::size_t n_errors = 0;
  auto error = [&](const std::string& message) {
    if(n_errors++ < 5)
      errors << "\n  " << message;
  };
  errors.precision(17);
  if(!(d[s] == 0.))
    error("the source has distance " + std::to_string(d[s]));
  for(Vertex_index v : vertices(mesh))
  {
    const double x = d[v];
    const std::string at = "vertex " + std::to_string(std::size_t(v)) + ": ";
    if(std::isnan(x) || x < 0.)
    {
      error(at + "NaN or negative distance " + std::to_string(x));
      continue;
    }
    if(std::isfinite(x) != (label[v] == label[s]))
    {
      error(at + "distance " + std::to_string(x) + " but " + (label[v] == label[s] ? "" : "not ")
            + "in the component of the source");
      continue;
    }
    if(std::isfinite(x) && x < distance(mesh.point(s), mesh.point(v)) - tolerance)
      error(at + "distance " + std::to_string(x) + " below the Euclidean distance "
            + std::to_string(distance(mesh.point(s), mesh.point(v))));
  }
  for(Surface_mesh::Edge_index e : edges(mesh))
  {
    const Vertex_index u = mesh.vertex(e, 0), v = mesh.vertex(e, 1);
    if(std::isfinite(d[u]) && std::isfinite(d[v])
       && std::abs(d[u] - d[v]) > distance(mesh.point(u), mesh.point(v)) + tolerance)
      error("edge (" + std::to_string(std::size_t(u)) + ", " + std::to_string(std::size_t(v)) + "): |"
            + std::to_string(d[u]) + " - " + std::to_string(d[v]) + "| > edge length "
            + std::to_string(distance(mesh.point(u), mesh.point(v))));
  }
  if(n_errors == 0)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": " << n_errors << " violated properties" << errors.str();
}

// Runs the solver and checks the invariants and the expected distances.
void check(const Surface_mesh& mesh, Vertex_index s, const std::vector<double>& expected, const std::string& what)
{
  const std::vector<double> d = vtp_distances(mesh, s);
  EXPECT_TRUE(satisfies_invariants(mesh, d, s, what));
  EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, what));
}

std::vector<double> euclidean_distances(const Polygon_soup& soup, std::size_t s)
{
  std::vector<double> d(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    d[i] = distance(soup.points[s], soup.points[i]);
  return d;
}

// True iff no triangle of the planar soup (z = 0) is clockwise, and the triangles cover exactly
// `area` (so that the soup is a flat mesh of the domain without fold, possibly with degenerate triangles).
bool is_unfolded_planar_soup(const Polygon_soup& soup, double area)
{
  double sum = 0.;
  for(const std::vector<std::size_t>& t : soup.polygons)
  {
    const Point_3 &a = soup.points[t[0]], &b = soup.points[t[1]], &c = soup.points[t[2]];
    if(CGAL::orientation(Point_2(a.x(), a.y()), Point_2(b.x(), b.y()), Point_2(c.x(), c.y())) == CGAL::RIGHT_TURN)
      return false;
    sum += 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
  }
  return std::abs(sum - area) <= 1e-12 * area;
}

typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, Surface_mesh> Smsp_traits;
typedef CGAL::Surface_mesh_shortest_path<Smsp_traits> Smsp;

} // namespace

// ---------------------------------------------------------------------------------------------------
// Sources on the boundary
// ---------------------------------------------------------------------------------------------------

// Height fields with holes: every boundary vertex (outer boundary and hole boundaries) as a source,
// against CGAL's exact algorithm.
TEST(Boundary_source, height_field_with_holes_matches_cgal)
{
  const int n = 12;
  Polygon_soup soup = planar_grid(n, n, 1., 1., 0.25, 77u);
  for(Point_3& p : soup.points)
    p = Point_3(p.x(), p.y(), 0.3 * std::sin(4. * p.x()) * std::cos(3. * p.y()));
  // two holes: remove the two triangles of cells (3,3), (3,4), (8,7)
  std::vector<std::vector<std::size_t> > kept;
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    const std::size_t cell = f / 2, i = cell % n, j = cell / n;
    if(!((i == 3 && (j == 3 || j == 4)) || (i == 8 && j == 7)))
      kept.push_back(soup.polygons[f]);
  }
  soup.polygons = kept;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  std::size_t tested = 0;
  for(Vertex_index s : vertices(mesh))
  {
    if(!mesh.is_border(s) || (std::size_t(s) % 3 != 0 && std::size_t(s) / (n + 1) != 4))
      continue; // every third outer boundary vertex, and the hole vertices of row 4
    check(mesh, s, shortest_path_reference_distances(mesh, s), "height field with holes, source " +
          std::to_string(std::size_t(s)));
    ++tested;
  }
  EXPECT_GE(tested, 18u);
}

// ---------------------------------------------------------------------------------------------------
// Sources on saddle vertices
// ---------------------------------------------------------------------------------------------------

// Five right-angled triangles around O: the triangles (O, P_k, P_k+1) with the ring e1, e2, e3, -e2, -e3
// (consecutive ring points are orthogonal), so that the cone angle at O is 5 * 90 = 450 degrees: O is a
// saddle vertex, the ring is the boundary. The surface is the cone of angle 450 degrees cut at radius
// ~1: in polar coordinates (r, theta) around O (theta in [0, 450) measured from P_1), two points at
// angular separation delta (the smaller of both ways around) are at distance
//   sqrt(r1^2 + r2^2 - 2 r1 r2 cos(delta)) if delta < 180 degrees (the unfolded sector is convex),
//   r1 + r2 otherwise (through O).
// Subdivided twice, so that there are vertices inside the faces.
TEST(Saddle_source, cone_of_450_degrees_analytic)
{
  const Vector_3 ring[5] = {Vector_3(1, 0, 0), Vector_3(0, 1, 0), Vector_3(0, 0, 1), Vector_3(0, -1, 0),
                            Vector_3(0, 0, -1)};
  Polygon_soup soup;
  soup.points.push_back(Point_3(0, 0, 0));
  for(const Vector_3& r : ring)
    soup.points.push_back(CGAL::ORIGIN + r);
  for(std::size_t k = 0; k < 5; ++k)
    soup.add_triangle(0, 1 + k, 1 + (k + 1) % 5);
  Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  midpoint_subdivide(mesh, 2);
  ASSERT_NEAR(angle_sum(mesh, vertex(0)), 2.5 * PI, 1e-12);

  // polar coordinates of each vertex in the unfolded cone
  const double right = PI / 2;
  std::vector<double> radius, theta;
  for(Vertex_index v : vertices(mesh))
  {
    const Vector_3 p = mesh.point(v) - CGAL::ORIGIN;
    radius.push_back(std::sqrt(p.squared_length()));
    double t = 0.;
    if(radius.back() > 0.)
      for(std::size_t k = 0; k < 5; ++k)
      {
        // p in the sector spanned by ring[k], ring[k+1]: p = a ring[k] + b ring[k+1], a, b >= 0, nothing else
        const double a = p * ring[k], b = p * ring[(k + 1) % 5];
        if(a >= 0. && b >= 0. && std::abs(a * a + b * b - p.squared_length()) <= 1e-15)
        {
          t = right * double(k) + std::atan2(b, a);
          break;
        }
      }
    theta.push_back(t);
  }
  auto cone_distance = [&](std::size_t i, std::size_t j) {
    double delta = std::abs(theta[i] - theta[j]);
    delta = (std::min)(delta, 5. * right - delta);
    if(delta < PI)
      return std::sqrt((std::max)(0., radius[i] * radius[i] + radius[j] * radius[j]
                                        - 2. * radius[i] * radius[j] * std::cos(delta)));
    return radius[i] + radius[j];
  };
  for(std::size_t s : {std::size_t(0), std::size_t(1), std::size_t(3), std::size_t(num_vertices(mesh)) - 1})
  {
    std::vector<double> expected(num_vertices(mesh));
    for(std::size_t i = 0; i < expected.size(); ++i)
      expected[i] = cone_distance(s, i);
    check(mesh, vertex(s), expected, "cone of 450 degrees, source " + std::to_string(s));
    check(mesh, vertex(s), shortest_path_reference_distances(mesh, vertex(s)),
          "cone of 450 degrees vs CGAL, source " + std::to_string(s));
  }
}

// Monkey saddle z = x^3 - 3 x y^2 (the center has a strong negative curvature): sources at the center and
// at the vertex of largest angle sum, against CGAL's exact algorithm.
TEST(Saddle_source, monkey_saddle_matches_cgal)
{
  const int n = 16;
  Polygon_soup soup = planar_grid(n, n, 2., 2., 0.2, 31u);
  for(Point_3& p : soup.points)
  {
    const double x = p.x() - 1., y = p.y() - 1.;
    p = Point_3(x, y, x * x * x - 3. * x * y * y);
  }
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Vertex_index center = vertex(grid_vertex(n, n / 2, n / 2));
  ASSERT_GT(angle_sum(mesh, center), 2. * PI);
  const Vertex_index strongest = strongest_saddle_vertex(mesh);
  ASSERT_NE(strongest, Surface_mesh::null_vertex());
  for(Vertex_index s : {center, strongest})
    check(mesh, s, shortest_path_reference_distances(mesh, s), "monkey saddle, source " + std::to_string(std::size_t(s)));
}

// ---------------------------------------------------------------------------------------------------
// Several components, isolated vertices
// ---------------------------------------------------------------------------------------------------

TEST(Components, several_components_and_isolated_vertices)
{
  // isolated vertices first, in the middle and last; three components: a tetrahedron (closed), a
  // jittered planar grid (open, convex), an open prism (two boundary loops)
  Polygon_soup soup;
  soup.points.push_back(Point_3(-5, -5, -5));
  soup.append(regular_tetrahedron(), Vector_3(0, 0, 10));
  soup.points.push_back(Point_3(0.5, 0.5, 0.)); // inside the grid's square, in no face
  soup.points.push_back(Point_3(7, 7, 7));
  const std::size_t grid_first = soup.points.size();
  const Polygon_soup grid = planar_grid(6, 6, 1., 1., 0.3, 5u);
  soup.append(grid);
  soup.append(open_prism(7, 3, 1., 2.), Vector_3(20, 0, 0));
  soup.points.push_back(Point_3(1e3, 0, 0));
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const std::vector<std::size_t> isolated = {0, 5, 6, num_vertices(mesh) - 1};
  for(std::size_t i : isolated)
    ASSERT_TRUE(mesh.is_isolated(vertex(i)));

  // a source in each component: the oracle finds the component by a search over the edges
  for(std::size_t s : {std::size_t(2), grid_first + 10, grid_first + grid.points.size() + 4})
  {
    Propagation_statistics st;
    const std::vector<double> d = vtp_distances(mesh, vertex(s), CGAL::parameters::default_values(), &st);
    const std::vector<double> expected = shortest_path_reference_distances(mesh, vertex(s));
    EXPECT_TRUE(satisfies_invariants(mesh, d, vertex(s), "several components, source " + std::to_string(s)));
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "several components, source " + std::to_string(s)));
    std::size_t finite = 0;
    for(double x : expected)
      finite += std::isfinite(x) ? 1 : 0;
    EXPECT_EQ(st.reached_vertices, finite);
    EXPECT_EQ(st.max_distance, max_finite(d));
    for(std::size_t i : isolated)
      EXPECT_EQ(d[i], INF) << "isolated vertex " << i;
  }
  // the grid: Euclidean distances (convex planar domain)
  {
    const std::size_t s = grid_first + 17;
    std::vector<double> expected(num_vertices(mesh), INF);
    for(std::size_t i = 0; i < grid.points.size(); ++i)
      expected[grid_first + i] = distance(soup.points[s], soup.points[grid_first + i]);
    check(mesh, vertex(s), expected, "several components, planar grid");
  }
  // an isolated source reaches only itself, even at the position of a point of a face's plane
  for(std::size_t s : isolated)
  {
    Propagation_statistics st;
    const std::vector<double> d = vtp_distances(mesh, vertex(s), CGAL::parameters::default_values(), &st);
    std::vector<double> expected(num_vertices(mesh), INF);
    expected[s] = 0.;
    EXPECT_TRUE(distances_near(d, expected, 0., "isolated source " + std::to_string(s)));
    EXPECT_EQ(st.reached_vertices, 1u);
  }
}

// A single triangle: the distances are the edge lengths.
TEST(Components, single_triangle)
{
  Polygon_soup soup;
  soup.points = {Point_3(0, 0, 0), Point_3(3, 0, 0), Point_3(0, 4, 1)};
  soup.add_triangle(0, 1, 2);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(std::size_t s = 0; s < 3; ++s)
    check(mesh, vertex(s), euclidean_distances(soup, s), "single triangle, source " + std::to_string(s));
}

// ---------------------------------------------------------------------------------------------------
// Zero-area faces and zero-length edges (CGAL's Surface_mesh_shortest_path fails on such meshes, with
// an assertion or a crash: the expected values come from geometry, or from the oracle run on a
// non-degenerate mesh of the same surface).
// ---------------------------------------------------------------------------------------------------

// The "sliding" mesh: a lower triangle (4,-2), (6,0), (2,0) and an upper triangle (1,0), (5,0), (3,2)
// of the plane z = 0, glued along y = 0 through four zero-area triangles whose vertices all lie on the
// line y = 0. Intrinsically it is the planar region L U U U [1,6]x{0}: the shortest paths are
// straight where the segment crosses y = 0 within [2,5] (where both triangles meet), and else bend at
// the corner (2,0) or (5,0).
TEST(Degenerate, zero_area_triangles_analytic)
{
  Polygon_soup soup;
  soup.points = {Point_3(4, -2, 0), Point_3(6, 0, 0), Point_3(4, 0, 0), Point_3(2, 0, 0),
                 Point_3(1, 0, 0),  Point_3(3, 0, 0), Point_3(5, 0, 0), Point_3(3, 2, 0)};
  soup.polygons = {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}, {2, 1, 6}, {2, 6, 4}, {4, 6, 5}, {5, 6, 7}, {4, 5, 7}};
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  std::size_t degenerate = 0;
  for(const std::vector<std::size_t>& t : soup.polygons)
    degenerate += CGAL::collinear(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]) ? 1 : 0;
  ASSERT_EQ(degenerate, 4u);

  const double r2 = std::sqrt(2.), r5 = std::sqrt(5.), r17 = std::sqrt(17.);
  // Vertices 5 and 6 lie on the line y = 0 in no non-degenerate lower triangle: their paths into the
  // lower triangle cross zero-area triangles.
  const std::map<std::size_t, std::vector<double> > expected = {
    {0, {0, 2 * r2, 2, 2 * r2, 1 + 2 * r2, r5, r5, r17}},
    {1, {2 * r2, 0, 2, 4, 5, 3, 1, 1 + 2 * r2}},
    {2, {2, 2, 0, 2, 3, 1, 1, r5}},
    {3, {2 * r2, 4, 2, 0, 1, 1, 3, r5}},
    {4, {1 + 2 * r2, 5, 3, 1, 0, 2, 4, 2 * r2}},
    {5, {r5, 3, 1, 1, 2, 0, 2, 2}},
    {6, {r5, 1, 1, 3, 4, 2, 0, 2 * r2}},
    {7, {r17, 1 + 2 * r2, r5, r5, 2 * r2, 2, 2 * r2, 0}}};
  for(const auto& e : expected)
    check(mesh, vertex(e.first), e.second, "sliding zero-area triangles, source " + std::to_string(e.first));
}

// The smallest case of the test below: a flat 4 x 4 grid of the square [0,4]^2 in which vertex (1,1) is
// moved onto vertex (1,0) (a zero-length edge; the triangles around vertex (1,1) become degenerate or
// stretch, none is folded): the distances are Euclidean, also from the two coincident vertices.
TEST(Degenerate, coincident_vertices_in_a_flat_grid)
{
  const int n = 4;
  Polygon_soup soup = planar_grid(n, n, double(n), double(n));
  soup.points[grid_vertex(n, 1, 1)] = soup.points[grid_vertex(n, 1, 0)];
  ASSERT_TRUE(is_unfolded_planar_soup(soup, double(n * n))) << "the test mesh is folded";
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(std::size_t s = 0; s < soup.points.size(); ++s)
    check(mesh, vertex(s), euclidean_distances(soup, s), "4 x 4 grid, (1,1) onto (1,0), source " + std::to_string(s));
}

// A flat 8 x 8 grid of the unit square in which some vertices are moved onto a neighbor (zero-length
// edges, coincident vertices) or onto the middle of an edge of their star (three collinear vertices):
// the triangles around them become degenerate, none is folded, so the surface is still the square and
// the distances are Euclidean.
TEST(Degenerate, zero_length_edges_and_collinear_vertices_planar)
{
  const int n = 8;
  Polygon_soup soup = planar_grid(n, n, double(n), double(n));
  auto at = [&](int i, int j) -> Point_3& { return soup.points[grid_vertex(n, i, j)]; };
  // vertices (i, j) with i + j even have all their cells' diagonals: their star is the square of side 2
  at(5, 5) = at(5, 4);               // coincident with (5,4)
  at(3, 3) = Point_3(2.5, 2, 0);     // on the edge (2,2)-(3,2) of its star: three collinear points
  at(2, 0) = at(1, 0);               // coincident, on the boundary
  at(6, 8) = Point_3(6.5, 8, 0);     // on the boundary, collinear with its neighbors (already) and closer
  at(1, 7) = at(0, 8);               // coincident with the corner
  ASSERT_TRUE(is_unfolded_planar_soup(soup, double(n * n))) << "the test mesh is folded";
  std::size_t degenerate = 0;
  for(const std::vector<std::size_t>& t : soup.polygons)
    degenerate += CGAL::collinear(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]) ? 1 : 0;
  ASSERT_GE(degenerate, 8u);

  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(std::size_t s : {grid_vertex(n, 5, 5), grid_vertex(n, 5, 4), grid_vertex(n, 3, 3), grid_vertex(n, 2, 0),
                       grid_vertex(n, 1, 7), grid_vertex(n, 0, 8), grid_vertex(n, 0, 0), grid_vertex(n, 7, 2)})
    check(mesh, vertex(s), euclidean_distances(soup, s), "degenerate flat grid, source " + std::to_string(s));
}

// Triangles that are collinear up to rounding (decimal coordinates such as 0.05, 0.075, 0.15 on one line),
// found by the fuzzer. On the flat convex hexagon the distances are Euclidean; on the height field,
// CGAL's exact algorithm gives them (the same on the mesh subdivided twice).
TEST(Degenerate, nearly_collinear_triangle_flat)
{
  const Surface_mesh mesh = load_mesh("nearly_collinear_flat.off");
  const Polygon_soup soup = to_soup(mesh);
  for(std::size_t s = 0; s < soup.points.size(); ++s)
    check(mesh, vertex(s), euclidean_distances(soup, s), "nearly collinear triangle, flat, source " + std::to_string(s));
}

TEST(Degenerate, nearly_collinear_triangle_height_field)
{
  const Surface_mesh mesh = load_mesh("nearly_collinear_height_field.off");
  for(std::size_t s : {0, 5, 6, 11, 17, 24})
    check(mesh, vertex(s), shortest_path_reference_distances(mesh, vertex(s)),
          "nearly collinear triangle, height field, source " + std::to_string(s));
}

namespace {

// Some edges of `soup`, far apart: (a, b) of every `step`-th triangle, skipping triangles that touch an
// already chosen edge.
std::vector<std::pair<std::size_t, std::size_t> > spread_edges(const Polygon_soup& soup, std::size_t step)
{
  std::vector<std::pair<std::size_t, std::size_t> > chosen;
  std::vector<unsigned char> used(soup.points.size(), 0);
  for(std::size_t f = 0; f < soup.polygons.size(); f += step)
  {
    const std::vector<std::size_t>& t = soup.polygons[f];
    if(used[t[0]] || used[t[1]] || used[t[2]])
      continue;
    chosen.emplace_back(t[0], t[1]);
    for(std::size_t v : t)
      used[v] = 1;
  }
  return chosen;
}

} // namespace

// Closed meshes in which several edges (a, b) are split at a new vertex m placed exactly on a: the two
// triangles (a, m, .) have a zero-length edge and zero area, the surface is unchanged, so the distances
// of the original vertices are those of the original mesh (from CGAL's exact algorithm) and m is at
// the distance of a; as a source, m gives the distances from a.
TEST(Degenerate, zero_length_edges_on_closed_meshes)
{
  for(const char* name : {"sphere.off", "elephant.off"})
  {
    const Surface_mesh original = load_mesh(name);
    Polygon_soup soup = to_soup(original);
    const std::size_t n = soup.points.size();
    std::vector<std::pair<std::size_t, std::size_t> > splits; // (a, m)
    for(const auto& e : spread_edges(soup, soup.polygons.size() / 12))
      splits.emplace_back(e.first, split_edge(soup, e.first, e.second, soup.points[e.first]));
    const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    ASSERT_GE(splits.size(), 8u);

    for(std::size_t source_of_original : {std::size_t(0), splits[3].first})
    {
      const std::vector<double> reference = shortest_path_reference_distances(original, vertex(source_of_original));
      std::vector<double> expected(reference);
      expected.resize(reference.size() + splits.size());
      for(const auto& am : splits)
        expected[am.second] = reference[am.first];
      ASSERT_EQ(expected.size(), num_vertices(mesh));
      check(mesh, vertex(source_of_original), expected,
            std::string(name) + " with zero-length edges, source " + std::to_string(source_of_original));
      if(source_of_original == splits[3].first)
        check(mesh, vertex(splits[3].second), expected,
              std::string(name) + " with zero-length edges, source " + std::to_string(splits[3].second)
                + " (coincident with " + std::to_string(source_of_original) + ")");
    }
    EXPECT_EQ(n + splits.size(), num_vertices(mesh));
  }
}

// A closed cube (coordinates multiple of 1/4, so that edge midpoints are exact) in which several edges
// (a, b) of faces (a, b, c), (b, a, d) get a zero-area "sliver" (a, b, m), m being the midpoint of ab:
// (a, b, c) becomes (a, m, c), (m, b, c), and (b, a, d) stays, glued to the sliver along ab. The
// surface is unchanged: the expected distances come from CGAL's exact algorithm on the original cube,
// at the vertices and at the midpoints (as face locations), also from a midpoint as the source.
TEST(Degenerate, collinear_slivers_on_a_closed_cube)
{
  const Polygon_soup cube = subdivided_cube(4);
  const Surface_mesh original = to_mesh<Surface_mesh>(cube);
  Polygon_soup soup = cube;
  struct Sliver { std::size_t a, b, m; };
  std::vector<Sliver> slivers;
  for(const auto& e : spread_edges(cube, 7))
  {
    const std::size_t a = e.first, b = e.second, m = insert_sliver(soup, a, b);
    ASSERT_TRUE(CGAL::collinear(soup.points[a], soup.points[b], soup.points[m]));
    slivers.push_back({a, b, m});
  }
  ASSERT_GE(slivers.size(), 6u);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);

  // the halfedge a -> b of the original mesh, to place the midpoints for CGAL
  auto halfedge_of = [&](std::size_t a, std::size_t b) {
    const auto h = CGAL::halfedge(vertex(a), vertex(b), original);
    EXPECT_TRUE(h.second);
    return h.first;
  };
  auto expected_from = [&](const Smsp::Face_location& source) {
    Smsp shortest_path(original);
    shortest_path.add_source_point(source);
    shortest_path.build_sequence_tree();
    std::vector<double> expected;
    for(Vertex_index v : vertices(original))
      expected.push_back(CGAL::to_double(shortest_path.shortest_distance_to_source_points(v).first));
    for(const Sliver& s : slivers)
    {
      const Smsp::Face_location m = Smsp::face_location(halfedge_of(s.a, s.b), 0.5, original);
      expected.push_back(CGAL::to_double(shortest_path.shortest_distance_to_source_points(m.first, m.second).first));
    }
    return expected;
  };

  for(std::size_t s : {std::size_t(0), slivers[2].a, std::size_t(40)})
    check(mesh, vertex(s), expected_from(Smsp::face_location(vertex(s), original)),
          "cube with slivers, source " + std::to_string(s));
  const Sliver& middle = slivers[slivers.size() / 2];
  check(mesh, vertex(middle.m), expected_from(Smsp::face_location(halfedge_of(middle.a, middle.b), 0.5, original)),
        "cube with slivers, source on a sliver " + std::to_string(middle.m));
}

// ---------------------------------------------------------------------------------------------------
// Needles and caps
// ---------------------------------------------------------------------------------------------------

// A flat disk cut into 720 needles (apex angle 0.5 degree) around its center: the domain is convex, so
// the distances are Euclidean; also against CGAL's exact algorithm.
TEST(Needle_and_cap, fan_of_needles)
{
  const std::size_t sides = 720;
  Polygon_soup soup;
  soup.points.push_back(Point_3(0, 0, 0));
  for(std::size_t k = 0; k < sides; ++k)
    soup.points.push_back(Point_3(std::cos(2. * PI * double(k) / double(sides)),
                                  std::sin(2. * PI * double(k) / double(sides)), 0.));
  for(std::size_t k = 0; k < sides; ++k)
    soup.add_triangle(0, 1 + k, 1 + (k + 1) % sides);
  ASSERT_TRUE(is_valid_planar_soup(soup));
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(std::size_t s : {std::size_t(0), std::size_t(1), std::size_t(200)})
  {
    check(mesh, vertex(s), euclidean_distances(soup, s), "fan of needles, source " + std::to_string(s));
    check(mesh, vertex(s), shortest_path_reference_distances(mesh, vertex(s)),
          "fan of needles vs CGAL, source " + std::to_string(s));
  }
}

// A flat strip of caps (one angle close to 180 degrees): bottom row (k, 0), top row (k + 1/2, h); the
// domain (a trapezoid) is convex, so the distances are Euclidean. h = 1e-3 and 1e-6.
TEST(Needle_and_cap, strip_of_caps)
{
  for(double h : {1e-3, 1e-6})
  {
    const std::size_t n = 60;
    Polygon_soup soup;
    for(std::size_t k = 0; k <= n; ++k)
      soup.points.push_back(Point_3(double(k), 0, 0));
    for(std::size_t k = 0; k < n; ++k)
      soup.points.push_back(Point_3(double(k) + 0.5, h, 0));
    for(std::size_t k = 0; k < n; ++k)
    {
      soup.add_triangle(k, k + 1, n + 1 + k);
      if(k + 1 < n)
        soup.add_triangle(k + 1, n + 2 + k, n + 1 + k);
    }
    ASSERT_TRUE(is_valid_planar_soup(soup));
    const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    for(std::size_t s : {std::size_t(0), std::size_t(30), n + 1, 2 * n})
    {
      check(mesh, vertex(s), euclidean_distances(soup, s),
            "strip of caps h = " + std::to_string(h) + ", source " + std::to_string(s));
      check(mesh, vertex(s), shortest_path_reference_distances(mesh, vertex(s)),
            "strip of caps vs CGAL, h = " + std::to_string(h) + ", source " + std::to_string(s));
    }
  }
}

// The lateral surface of a prism over a regular 64-gon, of height 100 and one band: 128 needles of aspect
// ratio ~1000. Developable: unrolled, the distance is the minimum over the periodic images (see
// Analytic.open_prism_developable).
TEST(Needle_and_cap, tall_prism_of_needles)
{
  const int sides = 64;
  const double height = 100.;
  const Polygon_soup soup = open_prism(sides, 1, 1., height);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const double side = 2. * std::sin(PI / sides), perimeter = sides * side;
  for(std::size_t s : {std::size_t(0), std::size_t(sides + 5)})
  {
    std::vector<double> expected(soup.points.size());
    for(std::size_t i = 0; i < soup.points.size(); ++i)
    {
      const double du = side * (double(int(i % sides)) - double(int(s % sides)));
      const double dv = height * (double(int(i / sides)) - double(int(s / sides)));
      double best = INF;
      for(int wrap = -1; wrap <= 1; ++wrap)
        best = (std::min)(best, std::sqrt((du + wrap * perimeter) * (du + wrap * perimeter) + dv * dv));
      expected[i] = best;
    }
    check(mesh, vertex(s), expected, "tall prism, source " + std::to_string(s));
    check(mesh, vertex(s), shortest_path_reference_distances(mesh, vertex(s)),
          "tall prism vs CGAL, source " + std::to_string(s));
  }
}

// A curved height field whose rows are alternately 1 and 1e-4 apart (needles), with every fourth vertex
// of the thin rows moved to 1e-6 of the segment between its neighbors (caps): against CGAL.
TEST(Needle_and_cap, height_field_with_needles_and_caps_matches_cgal)
{
  const int nx = 14, ny = 10;
  Polygon_soup soup;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
    {
      const double y = double(j / 2) + (j % 2) * 1e-4;
      double x = double(i);
      if(j % 2 == 1 && i % 4 == 2)
        x += 0.5 - 1e-6; // next to the segment between (i-1) and (i+1) of the row below
      soup.points.push_back(Point_3(x, y, 0.4 * std::sin(0.7 * x) + 0.3 * std::cos(0.9 * y)));
    }
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      const std::size_t v00 = grid_vertex(nx, i, j);
      add_cell(soup, v00, v00 + 1, v00 + nx + 2, v00 + nx + 1, (i + j) % 2 == 1);
    }
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(std::size_t s : {grid_vertex(nx, 0, 0), grid_vertex(nx, 7, 5), grid_vertex(nx, 6, 3), grid_vertex(nx, 14, 10)})
    check(mesh, vertex(s), shortest_path_reference_distances(mesh, vertex(s)),
          "height field with needles and caps, source " + std::to_string(s));
}

// A flat 5 x 3 grid of squares of side 10 whose diagonals are all parallel (found by the fuzzer): the
// domain is a rectangle, so the distances are Euclidean. (CGAL 5.5's Surface_mesh_shortest_path gets
// 58.416 instead of sqrt(3400) = 58.3095 between the corners (-5,-5) and (45,25): its path bends at
// the vertex (15,5).)
TEST(Flat_domain, grid_with_parallel_diagonals)
{
  Polygon_soup soup;
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 6; ++i)
      soup.points.push_back(Point_3(-5 + 10 * i, -5 + 10 * j, -1));
  for(std::size_t j = 0; j < 3; ++j)
    for(std::size_t i = 0; i < 5; ++i)
      add_cell(soup, j * 6 + i, j * 6 + i + 1, j * 6 + i + 7, j * 6 + i + 6, false);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  for(std::size_t s = 0; s < soup.points.size(); ++s)
    check(mesh, vertex(s), euclidean_distances(soup, s), "flat grid with parallel diagonals, source " + std::to_string(s));
}

// ---------------------------------------------------------------------------------------------------
// Very large and very small coordinates
// ---------------------------------------------------------------------------------------------------

namespace {

// Scaling the mesh multiplies the distances by the same factor: d(scaled) / scale must equal d (to 1e-12
// relative), which itself matches CGAL's exact algorithm on the unscaled mesh.
void check_scale_invariance(const std::vector<double>& factors)
{
  const Surface_mesh& mesh = load_mesh("mushroom.off");
  const Vertex_index s(17);
  const std::vector<double> d = vtp_distances(mesh, s);
  ASSERT_TRUE(distances_near(d, shortest_path_reference_distances(mesh, s), EXACT_TOLERANCE, "mushroom, unscaled"));
  for(double scale : factors)
  {
    Surface_mesh scaled = mesh;
    for(Vertex_index v : vertices(scaled))
    {
      const Point_3& p = scaled.point(v);
      scaled.point(v) = Point_3(scale * p.x(), scale * p.y(), scale * p.z());
    }
    std::vector<double> ds = vtp_distances(scaled, s);
    std::ostringstream what;
    what << "mushroom scaled by " << scale;
    EXPECT_TRUE(satisfies_invariants(scaled, ds, s, what.str()));
    for(double& x : ds)
      x /= scale;
    what << ", distances divided by the scale";
    EXPECT_TRUE(distances_near(ds, d, EXACT_TOLERANCE, what.str()));
  }
}

} // namespace

TEST(Scale, factors_1e6_and_1e_minus_6) { check_scale_invariance({1e-6, 1e6, 1e-3, 1e3}); }

// Far ends of the double range that the solver accepts (squared lengths from 1e-181 to 1e181).
TEST(Scale, extreme_factors) { check_scale_invariance({1e-100, 1e100, 0x1p-300, 0x1p+300}); }

// ---------------------------------------------------------------------------------------------------
// A pinched (non-manifold) vertex, which Surface_mesh accepts: two triangles sharing one vertex only.
// ---------------------------------------------------------------------------------------------------

TEST(Non_manifold, two_fans_pinched_at_a_vertex)
{
  Surface_mesh mesh;
  const Vertex_index o = mesh.add_vertex(Point_3(0, 0, 0)), a = mesh.add_vertex(Point_3(1, 0, 0)),
                     b = mesh.add_vertex(Point_3(0, 1, 0)), c = mesh.add_vertex(Point_3(-2, 0, 0)),
                     e = mesh.add_vertex(Point_3(0, -2, 1));
  ASSERT_NE(mesh.add_face(o, a, b), Surface_mesh::null_face());
  ASSERT_NE(mesh.add_face(o, c, e), Surface_mesh::null_face());
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  const double r2 = std::sqrt(2.), r5 = std::sqrt(5.);
  // every shortest path between the two triangles goes through o
  check(mesh, a, {1, 0, r2, 3, 1 + r5}, "pinched vertex, source a");
  check(mesh, o, {0, 1, 1, 2, r5}, "pinched vertex, source o");
  check(mesh, e, {r5, 1 + r5, 1 + r5, 3, 0}, "pinched vertex, source e");
}

// ---------------------------------------------------------------------------------------------------
// Surface_mesh with removed elements, and elements added after the removal (which reuse the freed
// slots): the removed ones must be skipped and never written, the others match the oracle run on a
// compacted copy.
// ---------------------------------------------------------------------------------------------------

TEST(Removed_elements, removed_then_reused_slots)
{
  Surface_mesh mesh = load_mesh("three_peaks.off");
  auto remove_star = [&mesh](Vertex_index v) {
    std::vector<Surface_mesh::Face_index> around;
    for(Surface_mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(v), mesh))
      if(f != Surface_mesh::null_face())
        around.push_back(f);
    for(Surface_mesh::Face_index f : around)
      CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  };
  const Vertex_index removed(500), refilled(900);
  ASSERT_FALSE(mesh.is_border(removed));
  ASSERT_FALSE(mesh.is_border(refilled));
  const Point_3 refilled_point = mesh.point(refilled);
  // an edge of the link of `refilled`, which becomes a border halfedge of its hole
  const Surface_mesh::Halfedge_index link = mesh.next(mesh.next(mesh.halfedge(refilled)));
  const Vertex_index on_hole = mesh.source(mesh.halfedge(removed));

  remove_star(removed);                                        // removes the vertex with its faces
  CGAL::Euler::remove_face(mesh.halfedge(Surface_mesh::Face_index(2000)), mesh);
  remove_star(refilled);
  ASSERT_TRUE(mesh.is_removed(removed));
  ASSERT_TRUE(mesh.is_removed(refilled));
  ASSERT_TRUE(mesh.is_border(link));
  // fill the second hole again with a fan around a new vertex: new elements in freed slots
  CGAL::Euler::fill_hole(link, mesh);
  const Vertex_index center = mesh.target(CGAL::Euler::add_center_vertex(link, mesh));
  mesh.point(center) = refilled_point;
  ASSERT_TRUE(mesh.has_garbage());
  ASSERT_TRUE(mesh.is_removed(removed));
  ASSERT_TRUE(CGAL::is_triangle_mesh(mesh));

  std::vector<std::size_t> new_index;
  const Surface_mesh compact = to_mesh<Surface_mesh>(to_soup(mesh, &new_index));
  for(Vertex_index s : {vertex(0), on_hole, center})
  {
    ASSERT_FALSE(mesh.is_removed(s));
    const std::vector<double> reference = shortest_path_reference_distances(compact, vertex(new_index[s]));
    std::vector<double> expected(index_range(mesh), NOT_A_VERTEX);
    for(Vertex_index v : vertices(mesh))
      expected[v] = reference[new_index[v]];
    const std::vector<double> d = vtp_distances(mesh, s);
    EXPECT_TRUE(std::isnan(d[removed])) << "a removed vertex must not be written";
    EXPECT_TRUE(satisfies_invariants(mesh, d, s, "three peaks with removed elements"));
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE,
                               "three peaks with removed and reused elements, source " + std::to_string(std::size_t(s))));
  }
}

// ---------------------------------------------------------------------------------------------------
// Hard but valid input against CGAL::Surface_mesh_shortest_path: several components, an isolated vertex,
// removed elements
// ---------------------------------------------------------------------------------------------------

// Two connected components: the other component is unreachable (+infinity); the component of the source
// matches the oracle run on that component alone.
TEST(Hard_input, two_components)
{
  const Polygon_soup a = to_soup(load_mesh("three_peaks.off"));
  const Polygon_soup b = to_soup(load_mesh("sphere.off"));
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
  Polygon_soup soup = to_soup(load_mesh("sphere.off"));
  const std::size_t n = soup.points.size();
  soup.points.push_back(Point_3(0.1, 0.2, 0.3)); // inside the sphere, in no face
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  ASSERT_EQ(num_vertices(mesh), n + 1);
  ASSERT_TRUE(mesh.is_isolated(Vertex_index(static_cast<Surface_mesh::size_type>(n))));

  {
    const Surface_mesh sphere = to_mesh<Surface_mesh>(to_soup(load_mesh("sphere.off")));
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
  Surface_mesh mesh = load_mesh("elephant.off");
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
