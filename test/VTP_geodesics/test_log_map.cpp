// The tangent frame shared by the log map and the straightest geodesics (internal/log_map/Tangent_frame.h): on the
// plane, the angles of the edges around an interior vertex (sum 2 pi, scale 1) and a border vertex (scaled
// to pi), the reference of a vertex (source(halfedge(v))) and of a face location (halfedge(f)), 3D
// directions projected.

#include "vtp_test_meshes.h"

#include <CGAL/VTP_geodesics.h>
#include <CGAL/VTP_geodesics/internal/log_map/Tangent_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_import.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

using namespace vtp_test;
namespace VI = CGAL::VTP_geodesics::internal;

namespace {

typedef VI::Mesh_index<Surface_mesh> Frame_test_index;

struct Frame_test_mesh
{
  Surface_mesh mesh;
  Frame_test_index index;
  explicit Frame_test_mesh(const Polygon_soup& soup) : mesh(to_mesh<Surface_mesh>(soup)), index(mesh)
  {
    VI::import_mesh(index, get(CGAL::vertex_point, mesh), CGAL::VTP_geodesics::Geodesic_traits_3<Kernel>(), 1);
  }
  VI::Index id(Vertex_index v) const { return get(index.vertex_id, v); }
  VI::Vector_3d point(VI::Index i) const
  {
    const Point_3& p = mesh.point(index.vertices[static_cast<std::size_t>(i)]);
    return {p.x(), p.y(), p.z()};
  }
  // the Euclidean direction (in the plane z = 0) of the half-edge h of the arrays
  double direction(VI::Index h) const
  {
    const VI::Vector_3d a = point(index.arrays.source[h]), b = point(index.arrays.target(h));
    return std::atan2(b[1] - a[1], b[0] - a[0]);
  }
};

double angle_difference(double a, double b) { return std::abs(std::remainder(a - b, 2. * PI)); }

// angle_in_0_2pi: its fast paths give fmod's values
TEST(TangentFrame, AngleIn0To2PiAsFmod)
{
  const double two_pi = 2. * 3.14159265358979323846;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-30., 30.);
  for(int i = 0; i < 200000; ++i)
  {
    const double t = i < 8 ? (i - 4) * two_pi : u(rng);
    double e = std::fmod(t, two_pi);
    if(e < 0.)
      e += two_pi;
    if(!(e < two_pi))
      e = 0.;
    ASSERT_EQ(VI::angle_in_0_2pi(t), e) << t;
  }
}

TEST(TangentFrame, InteriorVertexOfThePlane)
{
  const int n = 6;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 7);
  Frame_test_mesh m(soup);
  const Vertex_index v(static_cast<Surface_mesh::size_type>(grid_vertex(n, 3, 2)));
  const VI::Index c = m.id(v);
  const VI::Index r = VI::vertex_reference_halfedge(m.index, v);
  ASSERT_NE(r, VI::NO_INDEX);
  // the reference goes from v to source(halfedge(v))
  EXPECT_EQ(m.index.arrays.source[r], c);
  EXPECT_EQ(m.index.arrays.target(r), m.id(source(halfedge(v, m.mesh), m.mesh)));
  VI::Vertex_frame frame;
  ASSERT_TRUE(VI::make_vertex_frame(m.index.arrays, c, r, frame));
  EXPECT_FALSE(frame.border);
  EXPECT_NEAR(frame.angle_sum, 2. * PI, 1e-13);
  EXPECT_NEAR(frame.scale, 1., 1e-13);
  EXPECT_EQ(frame.halfedges.size(), static_cast<std::size_t>(degree(v, m.mesh)));
  const double reference = m.direction(r);
  for(std::size_t i = 0; i < frame.halfedges.size(); ++i)
  {
    const VI::Index h = frame.halfedges[i];
    // counter-clockwise, the Euclidean angle from the reference
    EXPECT_NEAR(angle_difference(frame.phi[i], m.direction(h) - reference), 0., 1e-13);
    EXPECT_EQ(VI::ccw_outgoing(m.index.arrays, h), frame.halfedges[(i + 1) % frame.halfedges.size()]);
    EXPECT_EQ(VI::cw_outgoing(m.index.arrays, frame.halfedges[(i + 1) % frame.halfedges.size()]), h);
    // a direction inside the face of h, there and back
    const double alpha = 0.4 * VI::corner_angle_of(m.index.arrays, h);
    const double theta = frame.theta(h, alpha);
    VI::Index g;
    double beta;
    frame.direction(theta, g, beta);
    EXPECT_EQ(g, h);
    EXPECT_NEAR(beta, alpha, 1e-13);
    // a 3D direction (with a normal component) projected: its Euclidean angle from the reference
    const double e = reference + theta;
    const VI::Vector_3d d{std::cos(e), std::sin(e), 0.7};
    EXPECT_NEAR(angle_difference(VI::vertex_theta_of_3d(m.index.arrays, frame, [&m](VI::Index i) { return m.point(i); }, d),
                                 theta), 0., 1e-12);
  }
}

TEST(TangentFrame, BorderVertexScaledToPi)
{
  const int n = 4;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.2, 3);
  Frame_test_mesh m(soup);
  // a vertex inside the bottom side (angle sum pi) and the corner (0, 0) (angle sum pi / 2)
  for(const std::size_t p : {grid_vertex(n, 2, 0), grid_vertex(n, 0, 0)})
  {
    const Vertex_index v(static_cast<Surface_mesh::size_type>(p));
    const VI::Index c = m.id(v);
    VI::Vertex_frame frame;
    ASSERT_TRUE(VI::make_vertex_frame(m.index.arrays, c, VI::vertex_reference_halfedge(m.index, v), frame));
    EXPECT_TRUE(frame.border);
    const double sum = (p == grid_vertex(n, 0, 0)) ? PI / 2. : PI;
    EXPECT_NEAR(frame.angle_sum, sum, 1e-13);
    EXPECT_NEAR(frame.scale, PI / sum, 1e-13);
    // the reference is the border half-edge along +x; the last direction (theta = pi) the other border edge
    EXPECT_EQ(m.index.arrays.opposite[frame.reference()], VI::NO_INDEX);
    EXPECT_NEAR(angle_difference(m.direction(frame.reference()), 0.), 0., 1e-13);
    EXPECT_NEAR(frame.phi.back() * frame.scale, PI, 1e-13);
    for(std::size_t i = 0; i < frame.halfedges.size(); ++i)
      EXPECT_NEAR(frame.phi[i], m.direction(frame.halfedges[i]), 1e-13);
    // directions: into the surface, then outside (clamped to the nearer border edge)
    const auto point = [&m](VI::Index i) { return m.point(i); };
    EXPECT_NEAR(VI::vertex_theta_of_3d(m.index.arrays, frame, point, {std::cos(0.3), std::sin(0.3), 1.}),
                0.3 * frame.scale, 1e-12);
    EXPECT_NEAR(VI::vertex_theta_of_3d(m.index.arrays, frame, point, {1., -0.1, 0.}), 0., 1e-12);
  }
}

TEST(TangentFrame, FaceLocationReference)
{
  const int n = 3;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.25, 5);
  Frame_test_mesh m(soup);
  for(Surface_mesh::Face_index f : faces(m.mesh))
  {
    const VI::Index fi = m.index.face_index(f);
    const VI::Index h = VI::face_reference(fi);
    EXPECT_EQ(m.index.arrays.source[h], m.id(source(halfedge(f, m.mesh), m.mesh)));
    EXPECT_EQ(m.index.arrays.target(h), m.id(target(halfedge(f, m.mesh), m.mesh)));
    // the directions of the face's half-edges in its frame are their Euclidean angles from halfedge(f)
    for(VI::Index k = 0; k < 3; ++k)
    {
      const VI::Index g = 3 * fi + k;
      EXPECT_NEAR(angle_difference(VI::face_theta(m.index.arrays, fi, g, 0.), m.direction(g) - m.direction(h)), 0.,
                  1e-13);
      EXPECT_NEAR(VI::angle_in_halfedge_frame(m.index.arrays, fi, g, VI::face_theta(m.index.arrays, fi, g, 0.25)),
                  0.25, 1e-13);
    }
    const std::array<VI::Vector_3d, 3> corners{m.point(m.index.arrays.source[h]), m.point(m.index.arrays.target(h)),
                                               m.point(m.index.arrays.source[VI::Mesh_arrays::prev(h)])};
    const double e = m.direction(h) + 1.1;
    EXPECT_NEAR(angle_difference(VI::face_theta_of_3d(corners, {std::cos(e), std::sin(e), -2.}), 1.1), 0., 1e-12);
    EXPECT_THROW(VI::face_theta_of_3d(corners, {0., 0., 1.}), CGAL::VTP_geodesics::Invalid_input_error);
    EXPECT_THROW(VI::face_theta_of_3d(corners, {0., 0., 0.}), CGAL::VTP_geodesics::Invalid_input_error);
    EXPECT_THROW(VI::face_theta_of_3d(corners, {std::nan(""), 0., 0.}), CGAL::VTP_geodesics::Invalid_input_error);
  }
}

} // namespace

// ------------------------------------------------------------------------------------------------
// the log map (named parameters log_map, log_map_via, log_map_strict, reference_direction)
// ------------------------------------------------------------------------------------------------
#include "vtp_test_utils.h"

namespace {

namespace VP = CGAL::VTP_geodesics::parameters;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Surface_mesh> Log_solver;
typedef Surface_mesh::Face_index Log_face;
typedef std::pair<Log_face, std::array<double, 3> > Log_location;

// The log map of one run: per vertex (in index order) rho, theta and via.
struct Log_result
{
  std::vector<double> rho, theta;
  std::vector<Vertex_index> via;
};

template <class Tag = CGAL::Sequential_tag, class Sources, class NP>
Log_result log_map_of(Log_solver& solver, const Surface_mesh& mesh, const Sources& sources, const NP& np)
{
  const std::size_t n = index_range(mesh);
  std::vector<double> d(n, -1.);
  std::vector<std::array<double, 2> > x(n);
  std::vector<Vertex_index> via(n);
  auto dm = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  auto xm = boost::make_iterator_property_map(x.begin(), get(boost::vertex_index, mesh));
  auto vm = boost::make_iterator_property_map(via.begin(), get(boost::vertex_index, mesh));
  solver.template compute<Tag>(dm, sources, np.log_map(xm).log_map_via(vm));
  Log_result r;
  r.rho = d;
  r.via = via;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(d[i] < INF)
    {
      EXPECT_NEAR(std::hypot(x[i][0], x[i][1]), d[i], 1e-12 * (1. + d[i]));
    }
    r.theta.push_back(std::atan2(x[i][1], x[i][0]));
  }
  return r;
}

// the Euclidean direction of the edge from v to source(halfedge(v)) (the default reference of a vertex)
double reference_angle(const Surface_mesh& mesh, Vertex_index v)
{
  const Point_3 a = mesh.point(v), b = mesh.point(source(halfedge(v, mesh), mesh));
  return std::atan2(b.y() - a.y(), b.x() - a.x());
}

Point_3 location_point(const Surface_mesh& mesh, const Log_location& l)
{
  const auto h = halfedge(l.first, mesh);
  const Point_3 &p0 = mesh.point(source(h, mesh)), &p1 = mesh.point(target(h, mesh)),
                &p2 = mesh.point(target(next(h, mesh), mesh));
  return Point_3(l.second[0] * p0.x() + l.second[1] * p1.x() + l.second[2] * p2.x(),
                 l.second[0] * p0.y() + l.second[1] * p1.y() + l.second[2] * p2.y(),
                 l.second[0] * p0.z() + l.second[1] * p1.z() + l.second[2] * p2.z());
}

// On the plane: rho = |v - c|, theta = the Euclidean angle of v - c minus `reference`, to 1e-12.
void expect_euclidean(const Surface_mesh& mesh, const Log_result& r, const Point_3& c, double reference)
{
  for(Vertex_index v : vertices(mesh))
  {
    const Point_3 p = mesh.point(v);
    const double rho = std::hypot(p.x() - c.x(), p.y() - c.y());
    EXPECT_NEAR(r.rho[v], rho, 1e-12) << "vertex " << std::size_t(v);
    if(rho > 1e-9)
    {
      EXPECT_NEAR(angle_difference(r.theta[v], std::atan2(p.y() - c.y(), p.x() - c.x()) - reference), 0., 1e-12)
        << "vertex " << std::size_t(v);
    }
  }
}

TEST(LogMap, FlatJitteredGridFromAVertex)
{
  const int n = 12;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1., 0.3, 11));
  Log_solver solver(mesh);
  const Vertex_index c(static_cast<Surface_mesh::size_type>(grid_vertex(n, 5, 7)));
  for(const bool strict : {false, true})
  {
    const Log_result r = log_map_of(solver, mesh, c, VP::log_map_strict(strict));
    expect_euclidean(mesh, r, mesh.point(c), reference_angle(mesh, c));
    for(Vertex_index v : vertices(mesh))
      EXPECT_EQ(r.via[v], Vertex_index());  // the plane is convex: no geodesic passes through a vertex it turns at
  }
  // a reference direction (projected onto the plane)
  const Log_result r = log_map_of(solver, mesh, c, VP::reference_direction(std::array<double, 3>{1., 1., 5.}));
  expect_euclidean(mesh, r, mesh.point(c), PI / 4.);
  // a border vertex: angles scaled by pi / pi
  const Vertex_index b(static_cast<Surface_mesh::size_type>(grid_vertex(n, 4, 0)));
  expect_euclidean(mesh, log_map_of(solver, mesh, b, VP::maximum_distance(INF)), mesh.point(b), 0.);
}

TEST(LogMap, FlatGridFromPointsOfFacesAndEdges)
{
  const int n = 10;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1., 0.25, 4));
  Log_solver solver(mesh);
  int checked = 0;
  for(Log_face f : faces(mesh))
  {
    if(std::size_t(f) % 37 != 5)
      continue;
    const auto h = halfedge(f, mesh);
    const Point_3 a = mesh.point(source(h, mesh)), b = mesh.point(target(h, mesh));
    const double reference = std::atan2(b.y() - a.y(), b.x() - a.x());
    for(const std::array<double, 3>& bary : {std::array<double, 3>{0.2, 0.3, 0.5}, std::array<double, 3>{0.35, 0.65, 0.},
                                              std::array<double, 3>{0., 0.7, 0.3}})
    {
      const Log_location l(f, bary);
      expect_euclidean(mesh, log_map_of(solver, mesh, l, VP::log_map_strict(false)), location_point(mesh, l), reference);
      ++checked;
    }
  }
  EXPECT_GT(checked, 3);
}

// The lateral surface of a regular pyramid (apex 0, rings 1..k on its lateral edges): developable, all its
// curvature at the apex; its unrolling is a fan of angle S (the sum of the apex's angles). From the apex:
// rho = the distance along the generators, theta = the unrolled angle scaled by 2 pi / S.
TEST(LogMap, ConeScaledByItsAngle)
{
  const int sides = 7, rings = 5;
  const double height = 1.3, radius = 0.8;
  Polygon_soup soup;
  soup.points.push_back(Point_3(0., 0., height));
  for(int r = 1; r <= rings; ++r)
    for(int k = 0; k < sides; ++k)
    {
      const double t = double(r) / rings, a = 2. * PI * k / sides;
      soup.points.push_back(Point_3(t * radius * std::cos(a), t * radius * std::sin(a), height * (1. - t)));
    }
  const auto id = [&](int r, int k) { return r == 0 ? std::size_t(0) : std::size_t(1 + (r - 1) * sides + (k % sides)); };
  for(int k = 0; k < sides; ++k)
    soup.add_triangle(0, id(1, k), id(1, k + 1));
  for(int r = 1; r < rings; ++r)
    for(int k = 0; k < sides; ++k)
    {
      soup.add_triangle(id(r, k), id(r + 1, k), id(r + 1, k + 1));
      soup.add_triangle(id(r, k), id(r + 1, k + 1), id(r, k + 1));
    }
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  Log_solver solver(mesh);
  const Vertex_index apex(0);
  const double slant = std::hypot(radius, height);
  const double chord = 2. * radius * std::sin(PI / sides);
  const double alpha = 2. * std::asin(0.5 * chord / slant);  // the apex angle of one lateral face
  const double S = sides * alpha;
  // the unrolled angle of ring vertex k: k alpha (counter-clockwise seen from outside: the faces' orientation)
  const int k_ref = static_cast<int>(std::size_t(source(halfedge(apex, mesh), mesh)) - 1) % sides;
  const Log_result r = log_map_of(solver, mesh, apex, VP::log_map_strict(false));
  for(int ring = 1; ring <= rings; ++ring)
    for(int k = 0; k < sides; ++k)
    {
      const Vertex_index v(static_cast<Surface_mesh::size_type>(id(ring, k)));
      EXPECT_NEAR(r.rho[v], slant * ring / rings, 1e-12);
      EXPECT_NEAR(angle_difference(r.theta[v], (k - k_ref) * alpha * 2. * PI / S), 0., 1e-12) << ring << " " << k;
    }
}

// The lateral surface of a prism (flat, unrolled into a strip of width the perimeter, wrapping around):
// rho and theta are those of the strip, through the nearer image of the source.
TEST(LogMap, CylinderUnrolled)
{
  const int sides = 9, bands = 6;
  const double radius = 1., height = 2.;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(open_prism(sides, bands, radius, height));
  Log_solver solver(mesh);
  const double side = 2. * radius * std::sin(PI / sides), perimeter = sides * side;
  const int k0 = 2, r0 = 3;
  const Vertex_index c(static_cast<Surface_mesh::size_type>(r0 * sides + k0));
  const auto unrolled = [&](Vertex_index v, double& x, double& y) {
    const int k = int(std::size_t(v)) % sides, r = int(std::size_t(v)) / sides;
    x = std::remainder((k - k0) * side, perimeter);
    y = (r - r0) * height / bands;
  };
  double xr, yr;
  unrolled(source(halfedge(c, mesh), mesh), xr, yr);
  const Log_result r = log_map_of(solver, mesh, c, VP::log_map_strict(false));
  for(Vertex_index v : vertices(mesh))
  {
    double x, y;
    unrolled(v, x, y);
    EXPECT_NEAR(r.rho[v], std::hypot(x, y), 1e-12);
    if(v != c)
    {
      EXPECT_NEAR(angle_difference(r.theta[v], std::atan2(y, x) - std::atan2(yr, xr)), 0., 1e-12) << std::size_t(v);
    }
  }
}

// theta of the direction d (3D) at vertex c, in c's frame computed from the 3D points of the mesh (independently
// of Tangent_frame.h): faces counter-clockwise from the edge c -> source(halfedge(c)), scaled to the circle.
double theta_of_direction(const Surface_mesh& mesh, Vertex_index c, const Vector_3& d, bool& found)
{
  const auto angle = [](const Vector_3& a, const Vector_3& b) {
    return std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
  };
  auto h = opposite(halfedge(c, mesh), mesh);  // c -> source(halfedge(c))
  bool border = false;
  for(auto g : CGAL::halfedges_around_source(c, mesh))
    if(!is_border(g, mesh) && is_border(opposite(g, mesh), mesh))
    {
      h = g;  // at the border: the border edge with the surface counter-clockwise of it
      border = true;
    }
  double before = 0., at = 0., sum = 0.;
  found = false;
  for(std::size_t k = 0; k < degree(c, mesh) && !is_border(h, mesh); ++k)
  {
    const Vector_3 e0 = mesh.point(target(h, mesh)) - mesh.point(c);
    const Vector_3 e1 = mesh.point(source(prev(h, mesh), mesh)) - mesh.point(c);
    const double corner = angle(e0, e1), a0 = angle(e0, d), a1 = angle(d, e1);
    const Vector_3 normal = CGAL::cross_product(e0, e1);
    if(!found && std::abs(a0 + a1 - corner) < 1e-9 && std::abs(d * normal) < 1e-9 * std::sqrt(d.squared_length() * normal.squared_length()))
    {
      found = true;
      at = before + a0;
    }
    before += corner;
    sum += corner;
    h = opposite(prev(h, mesh), mesh);
  }
  return at * (border ? PI : 2. * PI) / sum;
}

// theta against the first segment of the trace-back path (the solver's path queries): at every vertex whose
// path passes through no vertex, and with strict at every vertex (the first segment leads to the first vertex).
void expect_log_map_follows_paths(const Surface_mesh& mesh, Vertex_index c, bool strict, std::size_t& compared)
{
  Log_solver solver(mesh);
  const Log_result r = log_map_of(solver, mesh, c, VP::log_map_strict(strict).record_paths(true));
  for(Vertex_index v : vertices(mesh))
  {
    if(v == c || !(r.rho[v] < INF))
      continue;
    std::vector<Point_3> points;
    solver.shortest_path_points(v, std::back_inserter(points));
    std::vector<Log_location> locations;
    solver.shortest_path_locations(v, std::back_inserter(locations));
    bool through_vertex = false;
    for(std::size_t i = 1; i + 1 < locations.size(); ++i)
      for(double b : locations[i].second)
        through_vertex = through_vertex || b > 1. - 1e-12;
    if(through_vertex && !strict)
      continue;
    ASSERT_GE(points.size(), 2u);
    const Vector_3 d = points[points.size() - 2] - points.back();
    bool found = false;
    const double t = theta_of_direction(mesh, c, d, found);
    ASSERT_TRUE(found) << "vertex " << std::size_t(v);
    EXPECT_NEAR(angle_difference(r.theta[v], t), 0., 1e-9) << "vertex " << std::size_t(v) << (strict ? " strict" : "");
    ++compared;
  }
}

TEST(LogMap, ThetaIsTheDirectionOfThePath)
{
  // (not three_peaks.off: its grid of nearly collinear vertices makes paths through a vertex and beside it tie
  // to 1e-12, the trace-back and the log map then may take either)
  for(const char* name : {"elephant_395.off", "sphere.off", "elephant-with-holes_565.off"})
  {
    const Surface_mesh mesh = load_mesh(name);
    for(const bool strict : {false, true})
    {
      std::size_t compared = 0;
      expect_log_map_follows_paths(mesh, Vertex_index(3), strict, compared);
      EXPECT_GT(compared, strict ? num_vertices(mesh) / 2 : std::size_t(5)) << name;
    }
  }
}

// The unscaled angle of the direction d (3D) in the fan of c, counter-clockwise from the reference half-edge
// of theta_of_direction() (at the border, the border edge); `sum` the angle sum, `border` whether c is on
// the border; found if d lies in a face of c.
double fan_angle_of_direction(const Surface_mesh& mesh, Vertex_index c, const Vector_3& d, double& sum, bool& border,
                              bool& found)
{
  const auto angle = [](const Vector_3& a, const Vector_3& b) {
    return std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
  };
  auto h = opposite(halfedge(c, mesh), mesh);
  border = false;
  for(auto g : CGAL::halfedges_around_source(c, mesh))
    if(!is_border(g, mesh) && is_border(opposite(g, mesh), mesh))
    {
      h = g;
      border = true;
    }
  double at = 0., best = INF;
  sum = 0.;
  for(std::size_t k = 0; k < degree(c, mesh) && !is_border(h, mesh); ++k)
  {
    const Vector_3 e0 = mesh.point(target(h, mesh)) - mesh.point(c);
    const Vector_3 e1 = mesh.point(source(prev(h, mesh), mesh)) - mesh.point(c);
    const double corner = angle(e0, e1), a0 = angle(e0, d), a1 = angle(d, e1);
    if(std::abs(a0 + a1 - corner) < best)
    {
      best = std::abs(a0 + a1 - corner);
      at = sum + a0;
    }
    sum += corner;
    h = opposite(prev(h, mesh), mesh);
  }
  found = best < 1e-7;
  return at;
}

// Behind a saddle or border vertex s whose own geodesic comes straight from the source, the default log map
// goes on from P(s) = rho(s) (cos theta(s), sin theta(s)) along the path's last stretch, turned at s as the
// path turns there: P(v) = P(s) + (rho(v) - rho(s)) (cos(theta(s) + delta), sin(theta(s) + delta)), delta the
// angle between the path's way out of s and the straight continuation of its way in (the side angles of the
// path at s less S / 2 each; at a border vertex, the angle to the incoming line less pi). So theta(v) -
// theta(s) is at most |delta| <= |S - 2 pi| / 2 at an interior saddle. (The turn used to be taken modulo 2 pi
// instead of the fan's angle S: off by the excess of s behind 553 of the 773 vertices of the elephant checked.)
TEST(LogMap, DefaultGoesOnStraightThroughSaddles)
{
  const std::pair<const char*, std::size_t> meshes[] = {{"elephant.off", 700}, {"elephant-with-holes_565.off", 40}};
  for(const auto& mesh_and_count : meshes)
  {
    const char* name = mesh_and_count.first;
    const Surface_mesh mesh = load_mesh(name);
    Log_solver solver(mesh);
    const Log_result r = log_map_of(solver, mesh, Vertex_index(0), VP::log_map_strict(false).record_paths(true));
    std::size_t checked = 0;
    for(Vertex_index v : vertices(mesh))
    {
      const Vertex_index s = r.via[v];
      if(s == Vertex_index() || r.via[s] != Vertex_index() || s == Vertex_index(0))
        continue;
      std::vector<Point_3> points;
      solver.shortest_path_points(v, std::back_inserter(points));
      std::vector<Log_location> locations;
      solver.shortest_path_locations(v, std::back_inserter(locations));
      ASSERT_EQ(points.size(), locations.size());
      std::size_t at = 0, through = 0;  // the position of s on the path, the vertices the path passes through
      for(std::size_t i = 1; i + 1 < locations.size(); ++i)
        for(double b : locations[i].second)
          if(b > 1. - 1e-12)
          {
            ++through;
            at = points[i] == mesh.point(s) ? i : at;
          }
      if(through != 1 || at == 0)
        continue;  // (the path grazes another vertex too: a tie)
      double sum_in, sum_out;
      bool border, border_out, found_in, found_out;
      const double in = fan_angle_of_direction(mesh, s, points[at + 1] - points[at], sum_in, border, found_in);
      const double out = fan_angle_of_direction(mesh, s, points[at - 1] - points[at], sum_out, border_out, found_out);
      ASSERT_TRUE(found_in && found_out) << "vertex " << std::size_t(v);
      const double delta = border ? out - in - PI : std::remainder(out - in - 0.5 * sum_in, sum_in);
      const double a = r.theta[s] + delta, run = r.rho[v] - r.rho[s];
      const double expected = std::atan2(r.rho[s] * std::sin(r.theta[s]) + run * std::sin(a),
                                         r.rho[s] * std::cos(r.theta[s]) + run * std::cos(a));
      EXPECT_NEAR(angle_difference(r.theta[v], expected), 0., 1e-6) << name << ": vertex " << std::size_t(v)
                                                                     << " behind " << std::size_t(s);
      if(!border)
      {
        EXPECT_LE(angle_difference(r.theta[v], r.theta[s]), 0.5 * std::abs(sum_in - 2. * PI) + 1e-6)
          << name << ": vertex " << std::size_t(v) << " behind " << std::size_t(s);
      }
      ++checked;
    }
    EXPECT_GE(checked, mesh_and_count.second) << name;
  }
}

TEST(LogMap, SeveralSourcesRelativeToTheNearest)
{
  const int n = 12;
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1., 0.3, 13));
  Log_solver solver(mesh);
  const std::vector<Vertex_index> sources{Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, 3, 3))),
                                          Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, 9, 8)))};
  std::vector<std::size_t> labels(index_range(mesh));
  const Log_result r = log_map_of(solver, mesh, sources,
                                  VP::nearest_source_map(boost::make_iterator_property_map(labels.begin(), get(boost::vertex_index, mesh))));
  for(Vertex_index v : vertices(mesh))
  {
    const Vertex_index c = sources[labels[v]];
    const Point_3 p = mesh.point(v), q = mesh.point(c);
    EXPECT_NEAR(r.rho[v], std::hypot(p.x() - q.x(), p.y() - q.y()), 1e-12);
    if(v != c)
    {
      EXPECT_NEAR(angle_difference(r.theta[v], std::atan2(p.y() - q.y(), p.x() - q.x()) - reference_angle(mesh, c)), 0.,
                  1e-12);
    }
  }
}

#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
// PVTP: the same distances; the same theta (strict: at every vertex; default: at all but a few vertices, where
// the order of the offers decides between two within rounding of each other, Direction_record::on_offer()).
TEST(LogMap, ParallelAgreesWithSequential)
{
  const Surface_mesh mesh = load_mesh("elephant.off");
  for(const bool strict : {false, true})
  {
    Log_solver solver(mesh);
    const Log_result a = log_map_of(solver, mesh, Vertex_index(0), VP::log_map_strict(strict));
    const Log_result b =
      log_map_of<CGAL::Parallel_tag>(solver, mesh, Vertex_index(0), VP::log_map_strict(strict).number_of_threads(3));
    std::size_t differ = 0;
    for(Vertex_index v : vertices(mesh))
    {
      EXPECT_NEAR(a.rho[v], b.rho[v], 1e-12 * (1. + a.rho[v]));
      EXPECT_EQ(a.via[v], b.via[v]);
      differ += a.rho[v] > 0. && angle_difference(a.theta[v], b.theta[v]) > 1e-9;
    }
    if(strict)
      EXPECT_EQ(differ, 0u);
    else
      EXPECT_LE(differ, num_vertices(mesh) / 1000 + 1);
  }
}
#endif

TEST(LogMap, RejectedInput)
{
  const Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  Log_solver solver(mesh);
  const Vertex_index c(6);
  const std::array<double, 3> zero{0., 0., 0.}, nan{std::nan(""), 0., 1.}, normal{0., 0., 1.};
  EXPECT_THROW(log_map_of(solver, mesh, c, VP::reference_direction(zero)), CGAL::VTP_geodesics::Invalid_input_error);
  EXPECT_THROW(log_map_of(solver, mesh, c, VP::reference_direction(nan)), CGAL::VTP_geodesics::Invalid_input_error);
  EXPECT_THROW(log_map_of(solver, mesh, c, VP::reference_direction(normal)), CGAL::VTP_geodesics::Invalid_input_error);
  EXPECT_THROW(log_map_of(solver, mesh, Log_location(Log_face(2), {0.2, 0.3, 0.5}), VP::reference_direction(normal)),
               CGAL::VTP_geodesics::Invalid_input_error);
  EXPECT_THROW(log_map_of(solver, mesh, c, VP::lambda(8.)), CGAL::VTP_geodesics::Invalid_input_error);
  EXPECT_THROW(log_map_of(solver, mesh, c, VP::virtual_sources(true)), CGAL::VTP_geodesics::Invalid_input_error);
  EXPECT_THROW(log_map_of(solver, mesh, Vertex_index(1000), VP::log_map_strict(false)), CGAL::VTP_geodesics::Invalid_input_error);
}

// A source vertex in no face has no tangent frame: a clear error (it used to read the null half-edge).
TEST(LogMap, IsolatedSourceVertex)
{
  Surface_mesh mesh = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  const Vertex_index isolated = mesh.add_vertex(Point_3(5., 5., 0.));
  Log_solver solver(mesh);
  EXPECT_THROW(log_map_of(solver, mesh, isolated, VP::log_map_strict(false)), CGAL::VTP_geodesics::Invalid_input_error);
  EXPECT_THROW(solver.straightest_geodesic(isolated, std::array<double, 3>{1., 0., 0.}, 1.),
               CGAL::VTP_geodesics::Invalid_input_error);
}

} // namespace
