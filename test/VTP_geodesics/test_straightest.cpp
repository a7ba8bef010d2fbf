// Straightest geodesics (the exponential map, Geodesic_distance_solver::straightest_geodesic()): the straight
// segment on a flat jittered grid, the unrolled line on a prism (a developable cylinder), the rule at the apex
// of a cone and at a saddle (half the angle sum on each side) and lines around them, walks that reach the border, and on real
// meshes exp(log(v)) = v: from the source along the first segment of v's exact path, for rho(v), to v.

#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

using namespace vtp_test;

namespace {

namespace SVP = CGAL::VTP_geodesics::parameters;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Surface_mesh> Walk_solver;
typedef std::pair<Surface_mesh::Face_index, std::array<double, 3> > Walk_location;
typedef std::array<double, 3> Dir3;
typedef std::array<double, 2> Dir2;

double walk_distance(const Point_3& a, const Point_3& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

Point_3 moved(const Point_3& p, const Vector_3& d, double t) { return p + t * d; }

Vector_3 unit_vector(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

// the corner points of face f, in CGAL's order
std::array<Point_3, 3> face_points(const Surface_mesh& mesh, Surface_mesh::Face_index f)
{
  const auto h = mesh.halfedge(f);
  return { { mesh.point(mesh.source(h)), mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h))) } };
}

// the 2D direction of the 3D vector d (in the plane of face f) in the frame of halfedge(f)
Dir2 face_frame_direction(const Surface_mesh& mesh, Surface_mesh::Face_index f, const Vector_3& d)
{
  const std::array<Point_3, 3> p = face_points(mesh, f);
  const Vector_3 e1 = unit_vector(p[1] - p[0]);
  const Vector_3 n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
  const Vector_3 e2 = unit_vector(CGAL::cross_product(n, e1));
  return { { d * e1, d * e2 } };
}

// The angle theta of the tangent frame at vertex c (the convention of the log map) of the 3D vector u, which
// lies in one of the faces around c: the corner angles from the reference edge (c to source(halfedge(c))),
// counter-clockwise, plus the angle inside the face, scaled by 2 pi / angle sum (pi / sum at the border).
double vertex_frame_angle(const Surface_mesh& mesh, Vertex_index c, const Vector_3& u)
{
  const Point_3& pc = mesh.point(c);
  // the half-edges leaving c, counter-clockwise from the reference
  Surface_mesh::Halfedge_index start = mesh.opposite(mesh.halfedge(c));
  bool border = mesh.is_border(c);
  if(border)
    for(auto h : CGAL::halfedges_around_source(c, mesh))
      if(mesh.is_border(mesh.opposite(h)) && !mesh.is_border(h))
        start = h;
  double sum = 0., phi = -1.;
  Surface_mesh::Halfedge_index h = start;
  do
  {
    const Vector_3 a = mesh.point(mesh.target(h)) - pc, b = mesh.point(mesh.source(mesh.prev(h))) - pc;
    auto angle = [](const Vector_3& x, const Vector_3& y) {
      return std::acos((std::max)(-1., (std::min)(1., x * y / std::sqrt(x.squared_length() * y.squared_length()))));
    };
    const double alpha = angle(a, b), ua = angle(u, a), ub = angle(u, b);
    if(phi < 0. && std::abs(ua + ub - alpha) < 1e-10)
      phi = sum + ua;
    sum += alpha;
    const auto o = mesh.opposite(mesh.prev(h));
    if(mesh.is_border(o))
      break;
    h = o;
  } while(h != start);
  return phi < 0. ? std::numeric_limits<double>::quiet_NaN() : phi * (border ? PI : 2. * PI) / sum;
}

// the face location of point p in face f (barycentric coordinates, in the plane)
Walk_location location_in(const Surface_mesh& mesh, Surface_mesh::Face_index f, const Point_3& p)
{
  const std::array<Point_3, 3> q = face_points(mesh, f);
  const Vector_3 n = CGAL::cross_product(q[1] - q[0], q[2] - q[0]);
  const double area = std::sqrt(n.squared_length());
  std::array<double, 3> b;
  for(int k = 0; k < 3; ++k)
    b[k] = (CGAL::cross_product(q[(k + 1) % 3] - p, q[(k + 2) % 3] - p) * n) / (area * area);
  return { f, b };
}

Surface_mesh::Face_index face_containing(const Surface_mesh& mesh, const Point_3& p)
{
  for(auto f : faces(mesh))
  {
    const Walk_location l = location_in(mesh, f, p);
    if(l.second[0] > 1e-9 && l.second[1] > 1e-9 && l.second[2] > 1e-9 && walk_distance(point_of(mesh, l), p) < 1e-13)
      return f;
  }
  return Surface_mesh::null_face();
}

} // namespace

TEST(StraightestGeodesic, FlatJitteredGridGivesTheSegment)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(24, 24, 1., 1., 0.3, 7));
  const Walk_solver solver(mesh);
  std::mt19937 generator(11);
  int walks = 0;
  for(int i = 0; i < 200; ++i)
  {
    const Point_3 p(0.3 + 0.4 * (uniform_in_minus_one_one(generator) + 1.) / 2.,
                    0.3 + 0.4 * (uniform_in_minus_one_one(generator) + 1.) / 2., 0.);
    const double a = PI * uniform_in_minus_one_one(generator), length = 0.125 * (uniform_in_minus_one_one(generator) + 1.);
    const Vector_3 d(std::cos(a), std::sin(a), 0.);
    const Surface_mesh::Face_index f = face_containing(mesh, p);
    ASSERT_NE(f, Surface_mesh::null_face());
    const Walk_location start = location_in(mesh, f, p);
    const Point_3 expected = moved(p, d, length);
    // a 3D direction, and the same as a 2D one in the frame of halfedge(f)
    for(int form = 0; form < 2; ++form)
    {
      const auto w = form == 0 ? solver.straightest_geodesic(start, Dir3{ { d.x(), d.y(), 0. } }, length)
                               : solver.straightest_geodesic(start, face_frame_direction(mesh, f, d), length);
      EXPECT_LT(walk_distance(w.end_point, expected), 1e-12) << "walk " << i << " form " << form;
      EXPECT_LT(walk_distance(point_of(mesh, w.end_location), expected), 1e-12);
      EXPECT_NEAR(w.length, length, 1e-14);
      EXPECT_FALSE(w.reached_border);
      EXPECT_NEAR(w.end_direction[0], d.x(), 1e-12);
      EXPECT_NEAR(w.end_direction[1], d.y(), 1e-12);
      EXPECT_NEAR(polyline_length(w.points), length, 1e-12);
      for(std::size_t k = 0; k < w.points.size(); ++k)  // every point on the segment, in its face
      {
        const Vector_3 r = w.points[k] - p;
        EXPECT_LT(std::abs(CGAL::cross_product(d, r).z()), 1e-12);
        EXPECT_LT(walk_distance(point_of(mesh, w.locations[k]), w.points[k]), 1e-12);
      }
      ++walks;
    }
  }
  EXPECT_EQ(walks, 400);
}

TEST(StraightestGeodesic, ThroughVerticesAndAlongEdgesOfAFlatGrid)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(10, 10, 1., 1., 0.25, 3));
  const Walk_solver solver(mesh);
  const Vertex_index a(static_cast<Vertex_index::size_type>(grid_vertex(10, 3, 3)));
  // towards other vertices (through them: a flat vertex lets the line go straight on), and along each edge
  std::vector<Vertex_index> targets = { Vertex_index(static_cast<Vertex_index::size_type>(grid_vertex(10, 5, 5))),
                                        Vertex_index(static_cast<Vertex_index::size_type>(grid_vertex(10, 6, 4))) };
  for(auto h : CGAL::halfedges_around_source(a, mesh))
    targets.push_back(mesh.target(h));
  for(Vertex_index b : targets)
  {
    const Vector_3 d = unit_vector(mesh.point(b) - mesh.point(a));
    const double length = 0.8 * walk_distance(mesh.point(a), mesh.point(b)) + 0.1;
    const double theta = vertex_frame_angle(mesh, a, mesh.point(b) - mesh.point(a));
    ASSERT_TRUE(std::isfinite(theta));
    const auto w3 = solver.straightest_geodesic(a, Dir3{ { d.x(), d.y(), d.z() } }, length);
    const auto w2 = solver.straightest_geodesic(a, Dir2{ { std::cos(theta), std::sin(theta) } }, length);
    for(const auto& w : { w3, w2 })
    {
      EXPECT_LT(walk_distance(w.end_point, moved(mesh.point(a), d, length)), 1e-12) << "towards " << b;
      EXPECT_NEAR(w.length, length, 1e-14);
    }
    // exactly to the vertex: the end is the vertex
    const auto e = solver.straightest_geodesic(a, Dir2{ { std::cos(theta), std::sin(theta) } },
                                               walk_distance(mesh.point(a), mesh.point(b)));
    EXPECT_LT(walk_distance(e.end_point, mesh.point(b)), 1e-13);
  }
  // length 0: the start
  const auto z = solver.straightest_geodesic(a, Dir2{ { 1., 0. } }, 0.);
  EXPECT_EQ(z.points.size(), 1u);
  EXPECT_EQ(z.end_point, mesh.point(a));
  EXPECT_EQ(z.length, 0.);
}

TEST(StraightestGeodesic, EndsExactlyOnTheBorder)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(16, 16, 1., 1., 0.3, 5));
  const Walk_solver solver(mesh);
  std::mt19937 generator(3);
  for(int i = 0; i < 100; ++i)
  {
    const Point_3 p(0.5 + 0.2 * uniform_in_minus_one_one(generator), 0.5 + 0.2 * uniform_in_minus_one_one(generator), 0.);
    const double a = PI * uniform_in_minus_one_one(generator);
    const Vector_3 d(std::cos(a), std::sin(a), 0.);
    const Walk_location start = location_in(mesh, face_containing(mesh, p), p);
    const auto w = solver.straightest_geodesic(start, Dir3{ { d.x(), d.y(), 0. } }, 5.);
    ASSERT_TRUE(w.reached_border);
    // the exit of the square [0,1]^2
    double t = std::numeric_limits<double>::infinity();
    t = (std::min)(t, d.x() > 0. ? (1. - p.x()) / d.x() : d.x() < 0. ? -p.x() / d.x() : t);
    t = (std::min)(t, d.y() > 0. ? (1. - p.y()) / d.y() : d.y() < 0. ? -p.y() / d.y() : t);
    EXPECT_LT(walk_distance(w.end_point, moved(p, d, t)), 1e-12);
    EXPECT_NEAR(w.length, t, 1e-12);
    const double x = w.end_point.x(), y = w.end_point.y();
    EXPECT_LT((std::min)((std::min)(std::abs(x), std::abs(1. - x)), (std::min)(std::abs(y), std::abs(1. - y))), 1e-15);
    const std::array<double, 3>& b = w.end_location.second;
    EXPECT_TRUE(b[0] == 0. || b[1] == 0. || b[2] == 0.);  // on an edge of its face
  }
  // at a border vertex, the walk ends there
  const Vertex_index corner(static_cast<Vertex_index::size_type>(grid_vertex(16, 16, 16)));
  const Vertex_index inside(static_cast<Vertex_index::size_type>(grid_vertex(16, 12, 12)));
  const Vector_3 d = mesh.point(corner) - mesh.point(inside);
  const auto w = solver.straightest_geodesic(inside, Dir3{ { d.x(), d.y(), d.z() } }, 3.);
  EXPECT_TRUE(w.reached_border);
  EXPECT_LT(walk_distance(w.end_point, mesh.point(corner)), 1e-14);
  EXPECT_NEAR(w.length, std::sqrt(d.squared_length()), 1e-13);
  // a start at a border vertex going out of the surface: the frame takes the nearer border edge (here the
  // reference, the border edge leaving the vertex), along which the walk goes to the next border vertex
  const Vertex_index side(static_cast<Vertex_index::size_type>(grid_vertex(16, 5, 0)));
  const Vertex_index next_side(static_cast<Vertex_index::size_type>(grid_vertex(16, 6, 0)));
  const auto out = solver.straightest_geodesic(side, Dir3{ { 0., -1., 0. } }, 1.);
  EXPECT_TRUE(out.reached_border);
  EXPECT_EQ(out.end_point, mesh.point(next_side));
  EXPECT_NEAR(out.length, walk_distance(mesh.point(side), mesh.point(next_side)), 1e-15);
  // a start on a border edge going out of the surface: a walk of length 0
  const Walk_location on_edge = location_in(mesh, face_containing(mesh, Point_3(0.5, 0.01, 0.)), Point_3(0.5, 0.01, 0.));
  const auto h = mesh.halfedge(on_edge.first);
  const Point_3 a = mesh.point(mesh.source(h)), b = mesh.point(mesh.target(h));
  if(a.y() == 0. && b.y() == 0.)  // halfedge(f) on the border: a point of it
  {
    const auto e = solver.straightest_geodesic(Walk_location(on_edge.first, { { 0.5, 0.5, 0. } }), Dir3{ { 0.2, -1., 0. } }, 1.);
    EXPECT_TRUE(e.reached_border);
    EXPECT_EQ(e.length, 0.);
    EXPECT_EQ(e.points.size(), 1u);
  }
}

// A prism over a regular polygon (developable: the walk is the line of the unrolled strip, a helix).
TEST(StraightestGeodesic, PrismGivesTheUnrolledLine)
{
  const int sides = 12, bands = 8;
  const double radius = 1., height = 4.;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(open_prism(sides, bands, radius, height));
  const Walk_solver solver(mesh);
  std::vector<Point_3> ring(sides);
  for(int k = 0; k < sides; ++k)
    ring[k] = Point_3(radius * std::cos(2. * PI * k / sides), radius * std::sin(2. * PI * k / sides), 0.);
  const double edge = walk_distance(ring[0], ring[1]);
  // (s, z) of the strip, s along the perimeter, to a point of the prism
  auto point = [&](double s, double z) {
    s = std::fmod(s, sides * edge);
    if(s < 0.)
      s += sides * edge;
    const int k = (std::min)(sides - 1, static_cast<int>(std::floor(s / edge)));
    const double u = s / edge - k;
    const Point_3& a = ring[k];
    const Point_3& b = ring[(k + 1) % sides];
    return Point_3(a.x() + u * (b.x() - a.x()), a.y() + u * (b.y() - a.y()), z);
  };
  for(int i = 0; i < 8; ++i)
  {
    const double s0 = 0.37 + 0.9 * i, z0 = 0.31 + 0.05 * i, a = 0.05 + 0.021 * i, length = 3.1 / std::sin(a) * 0.9;
    const double l = (std::min)(length, 25.);
    const Point_3 p = point(s0, z0), q = point(s0 + 1e-3 * std::cos(a), z0 + 1e-3 * std::sin(a));
    const Vector_3 d = unit_vector(q - p);
    const Surface_mesh::Face_index f = face_containing(mesh, p);
    ASSERT_NE(f, Surface_mesh::null_face()) << p;
    const auto w = solver.straightest_geodesic(location_in(mesh, f, p), Dir3{ { d.x(), d.y(), d.z() } }, l);
    EXPECT_FALSE(w.reached_border);
    EXPECT_LT(walk_distance(w.end_point, point(s0 + l * std::cos(a), z0 + l * std::sin(a))), 1e-11) << "walk " << i;
    EXPECT_NEAR(w.end_direction[2], std::sin(a), 1e-12);
    EXPECT_GT(w.points.size(), std::size_t(sides));  // around the prism at least once
  }
}

// A pyramid over a regular n-gon (apex angle sum below 2 pi), developed into a fan of angle sum: a walk
// through the apex leaves it half the sum further round; a walk around the apex is the line of the fan.
TEST(StraightestGeodesic, ConeApexRuleAndLinesAround)
{
  for(int n : { 4, 5, 7 })
  {
    Polygon_soup soup;
    const double apex_height = 0.8;
    soup.points.push_back(Point_3(0., 0., apex_height));
    for(int k = 0; k < n; ++k)
      soup.points.push_back(Point_3(std::cos(2. * PI * k / n), std::sin(2. * PI * k / n), 0.));
    for(int k = 0; k < n; ++k)
      soup.add_triangle(0, 1 + k, 1 + (k + 1) % n);
    const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
    const Walk_solver solver(mesh);
    const Point_3 apex = soup.points[0];
    const Vector_3 e0 = soup.points[1] - apex, e1 = soup.points[2] - apex;
    const double alpha = std::acos(e0 * e1 / e0.squared_length()), sum = n * alpha;
    // the unit generator at the angle psi of the fan (face j = floor(psi / alpha))
    auto generator = [&](double psi) {
      psi = std::fmod(psi, sum);
      if(psi < 0.)
        psi += sum;
      const int j = (std::min)(n - 1, static_cast<int>(std::floor(psi / alpha)));
      const Vector_3 a = unit_vector(soup.points[1 + j] - apex);
      const Vector_3 b0 = soup.points[1 + (j + 1) % n] - apex;
      const Vector_3 b = unit_vector(b0 - (b0 * a) * a);
      const double u = psi - j * alpha;
      return std::cos(u) * a + std::sin(u) * b;
    };
    auto point = [&](double r, double psi) { return apex + r * generator(psi); };
    const double slant = std::sqrt(1. + apex_height * apex_height) * std::cos(alpha / 2.);  // apex to a base edge
    for(double psi0 : { 0.3 * alpha, 1.55 * alpha, 2.2 * alpha })
    {
      // through the apex
      const double r0 = 0.4 * slant, r1 = 0.5 * slant;
      const Point_3 p = point(r0, psi0);
      const Vector_3 d = apex - p;
      const Walk_location start = location_in(mesh, face_containing(mesh, p), p);
      const auto w = solver.straightest_geodesic(start, Dir3{ { d.x(), d.y(), d.z() } }, r0 + r1);
      EXPECT_LT(walk_distance(w.end_point, point(r1, psi0 + sum / 2.)), 1e-12) << "n " << n << " psi " << psi0;
      EXPECT_NEAR(w.length, r0 + r1, 1e-13);
      // around the apex: the line of the fan, in the fan's plane with the apex at the origin (rotated by c),
      // from (0.1, -0.3) slant to (0.1, 0.3) slant: it turns about 2.5 rad round the apex
      const double c = psi0;
      auto developed = [&](double x, double y) { return point(std::sqrt(x * x + y * y), c + std::atan2(y, x)); };
      const double xs = 0.1 * slant, ys = -0.3 * slant, length = 0.6 * slant;
      const Point_3 s = developed(xs, ys);
      const Vector_3 ds = unit_vector(developed(xs, ys + 1e-4 * slant) - s);  // one face: exact direction
      const Walk_location st = location_in(mesh, face_containing(mesh, s), s);
      const auto v = solver.straightest_geodesic(st, Dir3{ { ds.x(), ds.y(), ds.z() } }, length);
      const Point_3 re = developed(xs, ys + length);
      EXPECT_LT(walk_distance(v.end_point, re), 1e-12) << "around, n " << n << " psi " << psi0;
    }
  }
}

// A saddle vertex (a fan of 6 faces whose ring zigzags up and down: angle sum above 2 pi), developed corner by
// corner: a walk through it leaves half the sum further round; a walk around it is the line of the development.
TEST(StraightestGeodesic, SaddleRuleAndLinesAround)
{
  const int n = 6;
  Polygon_soup soup;
  soup.points.push_back(Point_3(0., 0., 0.));
  for(int k = 0; k < n; ++k)
    soup.points.push_back(Point_3(std::cos(2. * PI * k / n), std::sin(2. * PI * k / n), k % 2 == 0 ? 0.45 : -0.45));
  for(int k = 0; k < n; ++k)
    soup.add_triangle(0, 1 + k, 1 + (k + 1) % n);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const Walk_solver solver(mesh);
  const Point_3 apex = soup.points[0];
  std::vector<double> start_angle(n + 1, 0.);  // the angle of the development where corner j starts
  for(int j = 0; j < n; ++j)
  {
    const Vector_3 a = soup.points[1 + j] - apex, b = soup.points[1 + (j + 1) % n] - apex;
    start_angle[j + 1] = start_angle[j] + std::acos(a * b / std::sqrt(a.squared_length() * b.squared_length()));
  }
  const double sum = start_angle[n];
  ASSERT_GT(sum, 2. * PI + 0.1);
  // the unit vector at the angle phi of the development, in the face of the development's angle psi
  auto vector_at = [&](double psi, double phi) {
    const double shift = std::floor(psi / sum) * sum;  // psi and phi turned by the same whole turns
    psi -= shift;
    phi -= shift;
    int j = 0;
    while(j + 1 < n && start_angle[j + 1] <= psi)
      ++j;
    const Vector_3 a = unit_vector(soup.points[1 + j] - apex);
    const Vector_3 b0 = soup.points[1 + (j + 1) % n] - apex;
    const Vector_3 b = unit_vector(b0 - (b0 * a) * a);
    const double u = phi - start_angle[j];
    return std::cos(u) * a + std::sin(u) * b;
  };
  auto point = [&](double r, double psi) {
    psi = std::fmod(psi, sum);
    if(psi < 0.)
      psi += sum;
    return apex + r * vector_at(psi, psi);
  };
  const double reach = 0.4;  // well inside the fan (its ring is at distance about 0.8 or more)
  for(double psi0 : { 0.4, 1.3, 2.9, 4.4, 5.9 })
  {
    // through the saddle
    const Point_3 p = point(reach, psi0);
    const Vector_3 d = apex - p;
    const Walk_location start = location_in(mesh, face_containing(mesh, p), p);
    const auto w = solver.straightest_geodesic(start, Dir3{ { d.x(), d.y(), d.z() } }, 2. * reach);
    EXPECT_LT(walk_distance(w.end_point, point(reach, psi0 + sum / 2.)), 1e-12) << "psi " << psi0;
    // around it: a line at distance 0.08 from the saddle, over about 2.6 rad of the development
    auto developed = [&](double x, double y) { return point(std::sqrt(x * x + y * y), psi0 + std::atan2(y, x)); };
    const double xs = 0.08, ys = -0.25, length = 0.5;
    const Point_3 s = developed(xs, ys);
    const Vector_3 ds = vector_at(psi0 + std::atan2(ys, xs), psi0 + PI / 2.);  // (0, 1) of the rotated development
    const auto v = solver.straightest_geodesic(location_in(mesh, face_containing(mesh, s), s),
                                               Dir3{ { ds.x(), ds.y(), ds.z() } }, length);
    EXPECT_LT(walk_distance(v.end_point, developed(xs, ys + length)), 1e-12) << "around, psi " << psi0;
    // from the saddle itself, at the angle theta of its frame: the generator at theta * sum / (2 pi) from the
    // reference (the edge to source(halfedge(apex))), as the point of the development
    const Vertex_index c(0);
    const double theta = 1.1;
    const auto from = solver.straightest_geodesic(c, Dir2{ { std::cos(theta), std::sin(theta) } }, reach);
    const Vertex_index reference = mesh.source(mesh.halfedge(c));
    const double psi_ref = start_angle[static_cast<std::size_t>(reference) - 1];
    EXPECT_LT(walk_distance(from.end_point, point(reach, psi_ref + theta * sum / (2. * PI))), 1e-12);
  }
}

// On real meshes: for every vertex v whose exact geodesic path from the source passes through no other vertex,
// the walk from the source along the first segment of the path (its angle in the tangent frame), for rho(v),
// ends at v.
TEST(StraightestGeodesic, ExpOfLogOnRealMeshes)
{
  for(const char* name : { "elephant.off", "three_peaks.off", "elephant-with-holes.off" })
  {
    const Surface_mesh mesh = load_mesh(name);
    Walk_solver solver(mesh);
    const Vertex_index s = *vertices(mesh).begin();
    std::vector<double> rho(index_range(mesh));
    solver.compute(boost::make_iterator_property_map(rho.begin(), get(boost::vertex_index, mesh)), s,
                   SVP::record_paths(true));
    const double largest = max_finite(rho);
    std::vector<Vertex_index> starts;
    std::vector<Dir2> directions;
    std::vector<double> lengths;
    std::vector<Vertex_index> ends;
    for(Vertex_index v : vertices(mesh))
    {
      if(v == s || !std::isfinite(rho[v]))
        continue;
      std::vector<Walk_location> path;
      solver.shortest_path_locations(v, std::back_inserter(path));
      std::vector<Point_3> points;
      solver.shortest_path_points(v, std::back_inserter(points));
      bool through_vertex = false;
      for(std::size_t k = 1; k + 1 < path.size(); ++k)
        for(double b : path[k].second)
          through_vertex = through_vertex || b == 1.;
      if(through_vertex || points.size() < 2)
        continue;
      // a border vertex reached at a grazing angle to the border (under 1e-4 rad): the point where the line
      // meets the border moves by the rounding across it divided by that angle (ill-conditioned: skipped)
      if(mesh.is_border(v))
      {
        bool grazing = false;
        const Vector_3 last = points[1] - points[0];
        for(auto h : CGAL::halfedges_around_source(v, mesh))
          if(mesh.is_border(mesh.edge(h)))
          {
            const Vector_3 e = mesh.point(mesh.target(h)) - mesh.point(v);
            const double c = std::abs(last * e) / std::sqrt(last.squared_length() * e.squared_length());
            grazing = grazing || c > std::cos(1e-4);
          }
        if(grazing)
          continue;
      }
      const double theta = vertex_frame_angle(mesh, s, points[points.size() - 2] - points.back());
      if(!std::isfinite(theta))
        continue;
      starts.push_back(s);
      directions.push_back({ { std::cos(theta), std::sin(theta) } });
      lengths.push_back(rho[v]);
      ends.push_back(v);
    }
    ASSERT_GT(starts.size(), 50u) << name;
    const auto walks = solver.straightest_geodesics(starts, directions, lengths);
    std::size_t bad = 0;
    double worst = 0.;
    for(std::size_t i = 0; i < walks.size(); ++i)
    {
      const double e = walk_distance(walks[i].end_point, mesh.point(ends[i]));
      worst = (std::max)(worst, e);
      bad += e > 1e-9 * largest ? 1 : 0;
    }
    EXPECT_EQ(bad, 0u) << name << ": " << bad << " of " << walks.size() << " walks off v, worst " << worst / largest;
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    // many walks on threads: the same bits
    const auto parallel = solver.straightest_geodesics<CGAL::Parallel_tag>(starts, directions, lengths,
                                                                           SVP::number_of_threads(2));
    ASSERT_EQ(parallel.size(), walks.size());
    for(std::size_t i = 0; i < walks.size(); ++i)
      EXPECT_TRUE(parallel[i].points == walks[i].points && parallel[i].end_direction == walks[i].end_direction);
#endif
  }
}

// Hard meshes (zero-length edges, faces of zero area, needles, borders): eight walks of 30 mean edge lengths from
// every vertex; none fails, each polyline (in space) has the length walked (in the faces' frames), a walk that is
// not stopped by the border or a face of zero area walks its whole length, the end direction is a unit vector.
TEST(StraightestGeodesic, HardMeshesWalkConsistently)
{
  for(const char* name : { "degenerate_zero_length_edges.off", "nearly_collinear_flat.off",
                           "nearly_collinear_height_field.off", "mushroom.off", "knot1.off" })
  {
    const Surface_mesh mesh = load_mesh(name);
    const Walk_solver solver(mesh);
    std::vector<Vertex_index> starts;
    std::vector<Dir2> directions;
    for(Vertex_index v : vertices(mesh))
      for(int j = 0; j < 8 && !mesh.is_isolated(v); ++j)
      {
        const double a = 2.39996 * double(starts.size());
        starts.push_back(v);
        directions.push_back({ { std::cos(a), std::sin(a) } });
      }
    const double length = 30. * solver.mean_edge_length();
    const auto walks = solver.straightest_geodesics(starts, directions, std::vector<double>(starts.size(), length));
    for(std::size_t i = 0; i < walks.size(); ++i)
    {
      const auto& w = walks[i];
      EXPECT_NEAR(polyline_length(w.points), w.length, 1e-9 * length) << name << " walk " << i;
      if(!w.reached_border && !w.reached_degenerate_face)
      {
        EXPECT_NEAR(w.length, length, 1e-12 * length) << name << " walk " << i;
      }
      const auto& d = w.end_direction;
      EXPECT_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1., 1e-12);
    }
    EXPECT_GT(walks.size(), 0u);
  }
}

TEST(StraightestGeodesic, BadInputIsRejected)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  const Vertex_index isolated = mesh.add_vertex(Point_3(5., 5., 5.));
  const Walk_solver solver(mesh);
  const Vertex_index v(6);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  typedef CGAL::VTP_geodesics::Invalid_input_error Error;
  EXPECT_THROW(solver.straightest_geodesic(v, Dir2{ { 0., 0. } }, 1.), Error);
  EXPECT_THROW(solver.straightest_geodesic(v, Dir2{ { nan, 1. } }, 1.), Error);
  EXPECT_THROW(solver.straightest_geodesic(v, Dir3{ { 1., inf, 0. } }, 1.), Error);
  EXPECT_THROW(solver.straightest_geodesic(v, Dir3{ { 0., 0., 1. } }, 1.), Error);  // orthogonal to the plane
  EXPECT_THROW(solver.straightest_geodesic(v, Dir2{ { 1., 0. } }, -1.), Error);
  EXPECT_THROW(solver.straightest_geodesic(v, Dir2{ { 1., 0. } }, nan), Error);
  EXPECT_THROW(solver.straightest_geodesic(v, Dir2{ { 1., 0. } }, inf), Error);
  EXPECT_THROW(solver.straightest_geodesic(Vertex_index(1000), Dir2{ { 1., 0. } }, 1.), Error);
  EXPECT_THROW(solver.straightest_geodesic(isolated, Dir2{ { 1., 0. } }, 1.), Error);
  const Surface_mesh::Face_index f = *faces(mesh).begin();
  EXPECT_THROW(solver.straightest_geodesic(Walk_location(Surface_mesh::Face_index(999), { { 1., 0., 0. } }),
                                           Dir2{ { 1., 0. } }, 1.), Error);
  EXPECT_THROW(solver.straightest_geodesic(Walk_location(f, { { 0.5, 0.6, 0. } }), Dir2{ { 1., 0. } }, 1.), Error);
  EXPECT_THROW(solver.straightest_geodesic(Walk_location(f, { { nan, 0.5, 0.5 } }), Dir2{ { 1., 0. } }, 1.), Error);
  const std::vector<Vertex_index> starts = { v, v };
  const std::vector<Dir2> directions = { { { 1., 0. } }, { { 0., 0. } } };
  const std::vector<double> lengths = { 1., 1. };
  try
  {
    solver.straightest_geodesics(starts, directions, lengths);
    ADD_FAILURE() << "no error for walk 1";
  }
  catch(const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("walk 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(solver.straightest_geodesics(starts, directions, std::vector<double>(3, 1.)), Error);
}
