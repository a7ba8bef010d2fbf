// The kept field (named parameter keep_field, Geodesic_distance_solver::field_distance() and
// field_nearest_source()): the exact distance and the nearest source at any point of the surface after one run.
// Expected values from analytic cases (the plane: Euclidean distances and straight bisectors; a prism and a
// pyramid, unrolled), from exact targeted runs (the points as targets) on real meshes, and from invariants
// (PVTP's field gives VTP's values; several sources = the least of single runs); bad input.

#include <CGAL/VTP_geodesics.h>

#include <gtest/gtest.h>

#include "vtp_field_envelope.h"
#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

using namespace vtp_test;
namespace VG = CGAL::VTP_geodesics;

namespace {

typedef VG::Geodesic_distance_solver<Surface_mesh> Field_solver;
typedef Surface_mesh::Face_index Face_index;
typedef Field_solver::Face_location Location;
const CGAL::Constant_property_map<Vertex_index, double> discard;

// `n` random points of random faces (uniform barycentric coordinates), from `seed`
std::vector<Location> random_locations(const Surface_mesh& m, std::size_t n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0., 1.);
  std::uniform_int_distribution<std::size_t> face(0, m.number_of_faces() - 1);
  std::vector<Location> r;
  for(std::size_t i = 0; i < n; ++i)
  {
    double a = u(g), b = u(g);
    if(a + b > 1.)
    {
      a = 1. - a;
      b = 1. - b;
    }
    r.emplace_back(Face_index(static_cast<Surface_mesh::size_type>(face(g))), std::array<double, 3>{ { 1. - a - b, a, b } });
  }
  return r;
}

double largest(const Field_solver& s)
{
  double r = 0.;
  for(double d : s.distances())
    if(std::isfinite(d))
      r = (std::max)(r, d);
  return r;
}

// the point of a location that is a source in a face
Point_3 location_point(const Surface_mesh& m, const Location& l) { return point_of(m, l); }

} // namespace

// On a jittered plane (a convex domain), the field is the Euclidean distance to the nearest source at every
// point, with sources at a vertex and inside a face; the nearest source is the nearer one wherever the two
// differ by more than 1e-12.
TEST(KeptField, PlaneEuclideanDistanceAndNearestSource)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(20, 20, 1., 1., 0.3, 7));
  Field_solver s(m);
  const Vertex_index v(static_cast<Surface_mesh::size_type>(grid_vertex(20, 4, 5)));
  const Location inside(Face_index(500), { { 0.2, 0.3, 0.5 } });
  s.add_source(v);
  s.add_source(inside);
  s.compute(discard, VG::parameters::keep_field(true));
  ASSERT_TRUE(s.has_kept_field());
  EXPECT_GT(s.field_bytes(), 0u);
  EXPECT_EQ(s.statistics().field_bytes, s.field_bytes());
  const Point_3 a = m.point(v), b = location_point(m, inside);
  std::size_t labelled = 0;
  for(const Location& l : random_locations(m, 2000, 1))
  {
    const Point_3 p = point_of(m, l);
    const double da = distance(p, a), db = distance(p, b);
    EXPECT_NEAR(s.field_distance(l), (std::min)(da, db), 1e-12);
    if(std::abs(da - db) > 1e-12)
    {
      EXPECT_EQ(s.field_nearest_source(l), da < db ? 0u : 1u);
      ++labelled;
    }
  }
  EXPECT_GT(labelled, 1900u);
  // at the vertices: the distances of the run
  for(Vertex_index w : m.vertices())
    EXPECT_EQ(s.field_distance(w), s.distance(w));
}

// The cells of two sources placed symmetrically on a flat unit square: each is half of it, to 1e-12, and the
// border between them is the straight bisector.
TEST(KeptField, TwoCellsOfAUnitSquareAreHalves)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(16, 16, 1., 1., 0.25, 3));
  Field_solver s(m);
  const Vertex_index a(static_cast<Surface_mesh::size_type>(grid_vertex(16, 0, 0)));
  const Vertex_index b(static_cast<Surface_mesh::size_type>(grid_vertex(16, 16, 16)));
  s.compute(discard, std::vector<Vertex_index>{ a, b }, VG::parameters::keep_field(true));
  const VG::Voronoi_cell_areas cells = VG::geodesic_voronoi_cell_areas(s);
  ASSERT_EQ(cells.areas.size(), 2u);
  EXPECT_NEAR(cells.areas[0], 0.5, 1e-12);
  EXPECT_NEAR(cells.areas[1], 0.5, 1e-12);
  const auto borders = VG::geodesic_cell_borders(s);
  ASSERT_EQ(borders.size(), 1u);
  for(const Point_3& p : borders[0].points)
    EXPECT_NEAR(p.x() + p.y(), 1., 1e-12);  // (the bisector of (0,0) and (1,1))
}

// The lateral surface of a prism is a flat strip rolled up: the field from a point inside a face is the
// Euclidean distance in the strip, going around the shorter way.
TEST(KeptField, PrismIsAnUnrolledCylinder)
{
  const int sides = 12;
  const double radius = 1., height = 3.;
  const Surface_mesh m = to_mesh<Surface_mesh>(open_prism(sides, 6, radius, height));
  const double side = 2. * radius * std::sin(PI / sides), perimeter = sides * side;
  // the abscissa along the perimeter of a point of the surface
  auto abscissa = [&](const Point_3& p) {
    double angle = std::atan2(p.y(), p.x());
    if(angle < 0.)
      angle += 2. * PI;
    int k = static_cast<int>(std::floor(angle / (2. * PI / sides) + 1e-12)) % sides;
    const double c = 2. * PI * k / sides;
    return k * side + std::hypot(p.x() - radius * std::cos(c), p.y() - radius * std::sin(c));
  };
  Field_solver s(m);
  const Location source(Face_index(40), { { 0.3, 0.3, 0.4 } });
  s.compute(discard, source, VG::parameters::keep_field(true));
  const Point_3 o = point_of(m, source);
  const double uo = abscissa(o);
  for(const Location& l : random_locations(m, 1000, 2))
  {
    const Point_3 p = point_of(m, l);
    const double du = std::abs(abscissa(p) - uo), along = (std::min)(du, perimeter - du);
    EXPECT_NEAR(s.field_distance(l), std::hypot(along, p.z() - o.z()), 1e-12);
  }
}

// A pyramid over a regular 10-gon whose apex angle sum is below pi is a cone: unrolled, a sector, and the
// field from a point is the Euclidean distance in the sector (the segment stays in it).
TEST(KeptField, PyramidIsAnUnrolledCone)
{
  const int sides = 10, rings = 6;
  const double radius = 1., height = 3.;
  Polygon_soup soup;
  soup.points.push_back(Point_3(0., 0., height));  // the apex
  for(int r = 1; r <= rings; ++r)
    for(int k = 0; k < sides; ++k)
    {
      const double t = static_cast<double>(r) / rings, angle = 2. * PI * k / sides;
      soup.points.push_back(Point_3(t * radius * std::cos(angle), t * radius * std::sin(angle), height * (1. - t)));
    }
  auto vertex = [&](int r, int k) { return r == 0 ? std::size_t(0) : std::size_t(1 + (r - 1) * sides + (k % sides)); };
  for(int k = 0; k < sides; ++k)
  {
    soup.polygons.push_back({ vertex(0, 0), vertex(1, k), vertex(1, k + 1) });
    for(int r = 1; r < rings; ++r)
      add_cell(soup, vertex(r, k), vertex(r + 1, k), vertex(r + 1, k + 1), vertex(r, k + 1), (r + k) % 2 == 1);
  }
  const Surface_mesh m = to_mesh<Surface_mesh>(soup);
  const Point_3 apex(0., 0., height);
  const Point_3 corner0(radius, 0., 0.);
  const double slant = distance(apex, corner0);
  const double beta = 2. * std::asin(radius * std::sin(PI / sides) / slant);  // the apex angle of a side
  ASSERT_LT(sides * beta, PI);
  // the point in the unrolled sector (polar: distance to the apex, angle from the first edge)
  auto unrolled = [&](const Point_3& p, double& rho, double& phi) {
    double angle = std::atan2(p.y(), p.x());
    if(angle < 0.)
      angle += 2. * PI;
    const int k = static_cast<int>(std::floor(angle / (2. * PI / sides) + 1e-12)) % sides;
    const double c = 2. * PI * k / sides;
    const Point_3 ck(radius * std::cos(c), radius * std::sin(c), 0.);
    rho = distance(apex, p);
    const auto cross = CGAL::cross_product(p - apex, ck - apex);
    phi = k * beta + std::atan2(std::sqrt(cross.squared_length()), (p - apex) * (ck - apex));
  };
  Field_solver s(m);
  const Location source(Face_index(25), { { 0.5, 0.25, 0.25 } });
  s.compute(discard, source, VG::parameters::keep_field(true));
  double ro, po;
  unrolled(point_of(m, source), ro, po);
  const double sector = sides * beta;
  for(const Location& l : random_locations(m, 1000, 3))
  {
    double r, p;
    unrolled(point_of(m, l), r, p);
    const double dphi = (std::min)(std::abs(p - po), sector - std::abs(p - po));
    const double expected = std::sqrt((std::max)(0., r * r + ro * ro - 2. * r * ro * std::cos(dphi)));
    EXPECT_NEAR(s.field_distance(l), expected, 1e-12);
  }
}

// Two components: the one without a source is unreached (+infinity, no_source); a distance limit gives
// +infinity beyond it and the exact distance within it.
TEST(KeptField, UnreachedComponentAndDistanceLimit)
{
  Polygon_soup soup = planar_grid(8, 8, 1., 1., 0.2, 4);
  const Polygon_soup other = planar_grid(8, 8, 1., 1., 0.2, 5);
  const std::size_t offset = soup.points.size();
  for(const Point_3& p : other.points)
    soup.points.push_back(Point_3(p.x() + 3., p.y(), 0.));
  for(auto f : other.polygons)
  {
    for(auto& i : f)
      i += offset;
    soup.polygons.push_back(f);
  }
  const Surface_mesh m = to_mesh<Surface_mesh>(soup);
  Field_solver s(m);
  const Vertex_index v(0);
  s.compute(discard, v, VG::parameters::keep_field(true));
  const std::size_t first_faces = m.number_of_faces() / 2;
  for(const Location& l : random_locations(m, 500, 4))
  {
    const Point_3 p = point_of(m, l);
    if(static_cast<std::size_t>(l.first) < first_faces)
    {
      EXPECT_NEAR(s.field_distance(l), distance(p, m.point(v)), 1e-12);
      EXPECT_EQ(s.field_nearest_source(l), 0u);
    }
    else
    {
      EXPECT_EQ(s.field_distance(l), std::numeric_limits<double>::infinity());
      EXPECT_EQ(s.field_nearest_source(l), VG::no_source);
    }
  }
  s.compute(discard, v, VG::parameters::keep_field(true).maximum_distance(0.6));
  for(const Location& l : random_locations(m, 500, 5))
  {
    const double d = distance(point_of(m, l), m.point(v));
    if(static_cast<std::size_t>(l.first) >= first_faces || d > 0.6 + 1e-12)
    {
      EXPECT_EQ(s.field_distance(l), std::numeric_limits<double>::infinity());
    }
    else if(d < 0.6 - 1e-12)
    {
      EXPECT_NEAR(s.field_distance(l), d, 1e-12);
    }
  }
}

// On real meshes (the elephant, with and without holes: saddles, the border): at random points of faces the
// field equals an exact run that has the points as targets, to 1e-12 of the largest distance; its nearest
// source is the nearer of two single runs wherever they differ by more than that; PVTP's field gives VTP's
// values.
TEST(KeptField, RealMeshesEqualTargetedRuns)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off" })
  {
    const Surface_mesh m = load_mesh(name);
    const std::vector<Vertex_index> sources = { Vertex_index(0), Vertex_index(static_cast<Surface_mesh::size_type>(m.number_of_vertices() / 2)) };
    const std::vector<Location> points = random_locations(m, 400, 6);
    Field_solver s(m), exact(m);
    s.compute(discard, sources, VG::parameters::keep_field(true));
    const double r = largest(s);
    std::vector<double> single[2];
    for(int i = 0; i < 2; ++i)
    {
      exact.compute(discard, sources[static_cast<std::size_t>(i)], VG::parameters::targets(points));
      for(std::size_t k = 0; k < points.size(); ++k)
        single[i].push_back(exact.target_distance(k));
    }
    exact.compute(discard, sources, VG::parameters::targets(points));
    std::size_t labelled = 0;
    std::vector<double> field(points.size());
    for(std::size_t k = 0; k < points.size(); ++k)
    {
      field[k] = s.field_distance(points[k]);
      EXPECT_NEAR(field[k], exact.target_distance(k), 1e-12 * r) << name << " point " << k;
      EXPECT_NEAR(exact.target_distance(k), (std::min)(single[0][k], single[1][k]), 1e-12 * r);
      if(std::abs(single[0][k] - single[1][k]) > 1e-12 * r)
      {
        EXPECT_EQ(s.field_nearest_source(points[k]), single[0][k] < single[1][k] ? 0u : 1u) << name << " point " << k;
        ++labelled;
      }
    }
    EXPECT_GT(labelled, 390u);
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    s.compute<CGAL::Parallel_tag>(discard, sources, VG::parameters::keep_field(true).number_of_threads(2));
    for(std::size_t k = 0; k < points.size(); ++k)
      EXPECT_NEAR(s.field_distance(points[k]), field[k], 1e-12 * r) << name << " point " << k;
#endif
  }
}

// Why the field keeps every window that crossed a face (field/Kept_field.h): nearly each is the least candidate
// somewhere in its face. On the elephant from vertex 0, the windows that are nowhere the least (decided on their
// interval, vtp_field_envelope.h) are at most 5%: the lower envelope is at least 95% of the field (97.6%
// measured); dropping those changes the field at no point (random points of every face, to 1e-15 relative).
TEST(KeptField, NearlyEveryPieceIsTheLeastSomewhere)
{
  const Surface_mesh& m = elephant();
  Field_solver s(m);
  s.compute(discard, Vertex_index(0), VG::parameters::keep_field(true));
  const double r = largest(s) / s.mesh_index().length_scale;  // (the field of the faces is in the engine's unit)
  const auto& field = s.field_queries().field();
  Field_envelope envelope;
  std::vector<CGAL::VTP_geodesics::internal::Curve_candidate> all, least;
  std::size_t windows = 0, kept = 0;
  std::mt19937 g(8);
  std::uniform_real_distribution<double> u(0., 1.);
  for(CGAL::VTP_geodesics::internal::Index f = 0; f < static_cast<CGAL::VTP_geodesics::internal::Index>(m.number_of_faces()); ++f)
  {
    field.build_candidates(f, all);
    least = all;
    envelope.keep_least(least, 1e-15 * r);
    for(const auto& c : all)
      windows += c.window ? 1 : 0;
    for(const auto& c : least)
      kept += c.window ? 1 : 0;
    const CGAL::VTP_geodesics::internal::Face_frame frame(s.mesh_arrays(), f);
    for(int i = 0; i < 4; ++i)
    {
      double a = u(g), b = u(g);
      if(a + b > 1.)
      {
        a = 1. - a;
        b = 1. - b;
      }
      const double x = frame.x[0] + a * (frame.x[1] - frame.x[0]) + b * (frame.x[2] - frame.x[0]);
      const double y = frame.y[0] + a * (frame.y[1] - frame.y[0]) + b * (frame.y[2] - frame.y[0]);
      const double v = CGAL::VTP_geodesics::internal::Curve_field::value(all, x, y);
      ASSERT_NEAR(CGAL::VTP_geodesics::internal::Curve_field::value(least, x, y), v, 1e-15 * r) << "face " << f;
    }
  }
  ASSERT_GT(windows, 0u);
  EXPECT_GE(static_cast<double>(kept), 0.95 * static_cast<double>(windows)) << kept << " of " << windows;
  EXPECT_LT(kept, windows);  // (the test can drop some: it is not vacuous)
}

// Bad input: a query without a kept field (none yet, or a run without it), a location outside the mesh or
// with bad coordinates, the approximate methods.
TEST(KeptField, BadInput)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  Field_solver s(m);
  const Location inside(Face_index(3), { { 0.2, 0.3, 0.5 } });
  EXPECT_FALSE(s.has_kept_field());
  EXPECT_THROW(s.field_distance(inside), VG::Invalid_input_error);  // no run
  s.compute(discard, Vertex_index(0));
  EXPECT_THROW(s.field_distance(inside), VG::Invalid_input_error);  // a run without the field
  EXPECT_THROW(s.field_nearest_source(Vertex_index(1)), VG::Invalid_input_error);
  s.compute(discard, Vertex_index(0), VG::parameters::keep_field(true));
  EXPECT_NO_THROW(s.field_distance(inside));
  EXPECT_THROW(s.field_distance(Location(Face_index(1000), { { 0.2, 0.3, 0.5 } })), VG::Invalid_input_error);
  EXPECT_THROW(s.field_distance(Location(Face_index(3), { { 0.7, 0.7, 0.5 } })), VG::Invalid_input_error);
  EXPECT_THROW(s.field_distance(Vertex_index(1000)), VG::Invalid_input_error);
  EXPECT_THROW(s.compute(discard, Vertex_index(0), VG::parameters::keep_field(true).lambda(8.)), VG::Invalid_input_error);
  EXPECT_THROW(s.compute(discard, Vertex_index(0), VG::parameters::keep_field(true).virtual_sources(true)),
               VG::Invalid_input_error);
  EXPECT_THROW(s.farthest_point_sampling(2, VG::parameters::keep_field(true)), VG::Invalid_input_error);
  EXPECT_TRUE(s.has_kept_field());  // (a refused run changes nothing: the field of the run before answers)
  EXPECT_NO_THROW(s.field_distance(inside));
}
