// Isolines and geodesic Voronoi borders as curves (geodesic_curves.h): on the plane (circles, straight
// bisectors), a source inside a face, several components, curves that end on the border, the prism (an
// unrolled cylinder), and real meshes checked point by point by exact runs that have the points as targets;
// consecutive points share a face; bad input.

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>
#include <vector>

using namespace vtp_test;
namespace VG = CGAL::VTP_geodesics;

namespace {

typedef VG::Geodesic_distance_solver<Surface_mesh> Curve_solver;
typedef Surface_mesh::Face_index Face_index;
typedef VG::Geodesic_curve<Face_index, Point_3> Curve;

double largest(const Curve_solver& s)
{
  double r = 0.;
  for(double d : s.distances())
    if(std::isfinite(d))
      r = (std::max)(r, d);
  return r;
}

// the faces that contain the point of a location: the face, its neighbour across an edge the point is on,
// or every face around a vertex it is at
std::set<Face_index> faces_of(const Surface_mesh& m, const std::pair<Face_index, std::array<double, 3> >& l)
{
  std::set<Face_index> r;
  r.insert(l.first);
  const double eps = 1e-12;
  auto h = m.halfedge(l.first);
  for(int k = 0; k < 3; ++k, h = m.next(h))
  {
    // h goes from corner k to corner k+1; the point is on it if coordinate k+2 is 0
    if(std::abs(l.second[static_cast<std::size_t>((k + 2) % 3)]) <= eps && !m.is_border(m.opposite(h)))
      r.insert(m.face(m.opposite(h)));
    if(std::abs(l.second[static_cast<std::size_t>(k)] - 1.) <= eps)
      for(Face_index f : CGAL::faces_around_target(m.prev(h), m))
        if(f != Surface_mesh::null_face())
          r.insert(f);
  }
  return r;
}

// every two consecutive points of every curve share a face
void expect_no_gaps(const Surface_mesh& m, const std::vector<Curve>& curves)
{
  for(const Curve& c : curves)
  {
    ASSERT_EQ(c.points.size(), c.locations.size());
    ASSERT_GE(c.points.size(), 2u);
    const std::size_t n = c.points.size();
    for(std::size_t i = 0; i + (c.closed ? 0 : 1) < n; ++i)
    {
      const auto a = faces_of(m, c.locations[i]), b = faces_of(m, c.locations[(i + 1) % n]);
      bool common = false;
      for(Face_index f : a)
        common = common || b.count(f) > 0;
      EXPECT_TRUE(common) << "points " << i << " and " << (i + 1) % n << " of a curve share no face";
    }
  }
}

bool on_rectangle_border(const Point_3& p, double w, double h)
{
  const double e = 1e-9;
  return std::abs(p.x()) < e || std::abs(p.y()) < e || std::abs(p.x() - w) < e || std::abs(p.y() - h) < e;
}

TEST(Curves, PlaneCirclesAroundAVertex)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(20, 20, 1., 1., 0.3, 3));
  Curve_solver s(m);
  const Vertex_index c(static_cast<Surface_mesh::size_type>(grid_vertex(20, 10, 10)));
  const Point_3 o = m.point(c);
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), c, VG::parameters::record_paths(true));
  VG::Geodesic_curves_report report;
  const std::vector<double> levels = { 0.1, 0.25, 0.4, 0.6 };
  const auto curves = VG::geodesic_isolines(s, levels, VG::parameters::chord_tolerance(1e-6), &report);
  std::size_t closed = 0, open = 0;
  for(const Curve& k : curves)
  {
    for(const Point_3& p : k.points)
      EXPECT_NEAR(std::sqrt(CGAL::squared_distance(p, o)), k.level, 1e-9 * largest(s));
    if(k.closed)
      ++closed;
    else
    {
      ++open;
      EXPECT_TRUE(on_rectangle_border(k.points.front(), 1., 1.) && on_rectangle_border(k.points.back(), 1., 1.));
    }
  }
  EXPECT_EQ(closed, 3u);  // 0.1, 0.25, 0.4 (o is within 0.015 of the centre)
  EXPECT_EQ(open, 4u);    // 0.6: the four arcs at the corners
  EXPECT_EQ(report.undecided, 0u);
  EXPECT_EQ(report.edge_fallbacks, 0u);
  expect_no_gaps(m, curves);
  // the chords are within the tolerance: the middle of each chord is at most 1e-6 inside the circle
  for(const Curve& k : curves)
    for(std::size_t i = 0; i + 1 < k.points.size(); ++i)
    {
      const Point_3 mid = CGAL::midpoint(k.points[i], k.points[i + 1]);
      EXPECT_LE(k.level - std::sqrt(CGAL::squared_distance(mid, o)), 1e-6 + 1e-12);
    }
}

TEST(Curves, PlaneSourceInsideAFaceAndSeveralComponents)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(16, 8, 2., 1., 0.25, 5));
  Curve_solver s(m);
  std::vector<Curve_solver::Face_location> sources;
  std::vector<Point_3> at;
  for(const double cx : { 0.5, 1.5 })
  {
    double best = std::numeric_limits<double>::infinity();
    Face_index chosen;
    Point_3 point;
    for(Face_index f : m.faces())
    {
      const Point_3 p[3] = { m.point(m.source(m.halfedge(f))), m.point(m.target(m.halfedge(f))),
                             m.point(m.target(m.next(m.halfedge(f)))) };
      const Point_3 q = CGAL::barycenter(p[0], 0.2, p[1], 0.3, p[2], 0.5);
      const double d = CGAL::squared_distance(q, Point_3(cx, 0.5, 0.));
      if(d < best)
      {
        best = d;
        chosen = f;
        point = q;
      }
    }
    sources.push_back({ chosen, { { 0.2, 0.3, 0.5 } } });
    at.push_back(point);
  }
  ASSERT_EQ(sources.size(), 2u);
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), sources, VG::parameters::record_paths(true));
  const auto curves = VG::geodesic_isolines(s, { 0.2, 0.3 }, VG::parameters::chord_tolerance(1e-7));
  std::size_t small = 0;
  for(const Curve& k : curves)
  {
    for(const Point_3& p : k.points)
    {
      const double d = (std::min)(std::sqrt(CGAL::squared_distance(p, at[0])), std::sqrt(CGAL::squared_distance(p, at[1])));
      EXPECT_NEAR(d, k.level, 1e-9 * largest(s));
    }
    if(k.level == 0.2)
    {
      ++small;
      EXPECT_TRUE(k.closed);
    }
  }
  EXPECT_EQ(small, 2u);  // two circles
  expect_no_gaps(m, curves);
  // the border of the two cells: the straight bisector, equidistant, from the bottom side to the top side
  const auto borders = VG::geodesic_cell_borders(s, VG::parameters::chord_tolerance(1e-7));
  ASSERT_EQ(borders.size(), 1u);
  EXPECT_FALSE(borders[0].closed);
  EXPECT_EQ(borders[0].cells[0], 0u);
  EXPECT_EQ(borders[0].cells[1], 1u);
  for(const Point_3& p : borders[0].points)
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(p, at[0])), std::sqrt(CGAL::squared_distance(p, at[1])), 1e-9 * largest(s));
  EXPECT_TRUE(on_rectangle_border(borders[0].points.front(), 2., 1.));
  EXPECT_TRUE(on_rectangle_border(borders[0].points.back(), 2., 1.));
  expect_no_gaps(m, borders);
}

// Checks every point of the curves by exact runs that have them as targets: isoline points at their level,
// border points equidistant from their two cells' sources, to 1e-9 of the largest distance.
// The isoline points checked by an exact run that has them as targets: the share of them at their level to
// `tolerance`, and the largest error.
template <class Sources>
double share_at_level(const Surface_mesh& m, const Sources& sources, const std::vector<Curve>& curves,
                      double tolerance, double& largest_error)
{
  Curve_solver t(m);
  std::vector<Curve_solver::Face_location> points;
  std::vector<double> levels;
  for(const Curve& k : curves)
    for(const auto& l : k.locations)
    {
      points.push_back(l);
      levels.push_back(k.level);
    }
  if(points.empty())
    return 0.;
  t.compute(CGAL::Constant_property_map<Vertex_index, double>(), sources, VG::parameters::targets(points));
  std::size_t good = 0;
  largest_error = 0.;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const double e = std::abs(t.target_distance(i) - levels[i]);
    largest_error = (std::max)(largest_error, e);
    good += e <= tolerance ? 1 : 0;
  }
  return static_cast<double>(good) / static_cast<double>(points.size());
}

template <class Sources>
void check_isolines_by_targets(const Surface_mesh& m, const Sources& sources, const std::vector<Curve>& curves,
                               double tolerance)
{
  double largest_error;
  EXPECT_EQ(share_at_level(m, sources, curves, tolerance, largest_error), 1.);
  EXPECT_LE(largest_error, tolerance);
}

void check_borders_by_targets(const Surface_mesh& m, const std::vector<Vertex_index>& sources,
                              const std::vector<Curve>& curves, double tolerance)
{
  Curve_solver t(m);
  for(const Curve& k : curves)
  {
    std::vector<double> d[2];
    for(int j = 0; j < 2; ++j)
    {
      t.compute(CGAL::Constant_property_map<Vertex_index, double>(), sources[k.cells[static_cast<std::size_t>(j)]],
                VG::parameters::targets(k.locations));
      for(std::size_t q = 0; q < k.locations.size(); ++q)
        d[j].push_back(t.target_distance(q));
    }
    for(std::size_t q = 0; q < k.locations.size(); ++q)
      EXPECT_NEAR(d[0][q], d[1][q], tolerance) << "border point " << q;
  }
}

TEST(Curves, PrismIsAnUnrolledCylinder)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(open_prism(12, 6, 1., 3.));
  Curve_solver s(m);
  const Vertex_index v(static_cast<Surface_mesh::size_type>(3 * 12 + 2));
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), v, VG::parameters::record_paths(true));
  // (refined by one exact run: near the cut locus, opposite the source, the record alone is off)
  const auto curves = VG::geodesic_isolines(s, VG::geodesic_isoline_levels(s, 0.35), VG::parameters::exact_refinement(1));
  EXPECT_GT(curves.size(), 5u);
  expect_no_gaps(m, curves);
  check_isolines_by_targets(m, v, curves, 1e-9 * largest(s));
}

TEST(Curves, RealMeshesByTargets)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off" })
  {
    const Surface_mesh m = load_mesh(name);
    Curve_solver s(m);
    const std::vector<Vertex_index> sources = { *m.vertices().begin(), Vertex_index(static_cast<Surface_mesh::size_type>(m.number_of_vertices() / 2)) };
    s.compute(CGAL::Constant_property_map<Vertex_index, double>(), sources[0], VG::parameters::record_paths(true));
    const double r = largest(s);
    const std::vector<double> levels = { 0.1 * r, 0.37 * r, 0.8 * r };
    // from the record alone: off where a face is crossed by a window that reached none of its corners (what
    // doc/VTP_geodesics/curves.txt measures), by a small share of the largest distance
    const auto curves = VG::geodesic_isolines(s, levels);
    expect_no_gaps(m, curves);
    double error_from_record, error_refined;
    share_at_level(m, sources[0], curves, 1e-9 * r, error_from_record);
    EXPECT_LE(error_from_record, 2e-2 * r) << name;
    // refined by two exact runs: almost every point at its level to 1e-9 of the largest distance (not those
    // whose exact image lies beyond their face: see the manual)
    VG::Geodesic_curves_report report;
    const auto refined = VG::geodesic_isolines(s, levels, VG::parameters::exact_refinement(2), &report);
    ASSERT_EQ(refined.size(), curves.size());
    expect_no_gaps(m, refined);
    EXPECT_GE(share_at_level(m, sources[0], refined, 1e-9 * r, error_refined), 0.95) << name;
    EXPECT_LE(error_refined, error_from_record) << name;
    s.compute(CGAL::Constant_property_map<Vertex_index, double>(), sources, VG::parameters::record_paths(true));
    const auto borders = VG::geodesic_cell_borders(s);
    ASSERT_FALSE(borders.empty());
    expect_no_gaps(m, borders);
    check_borders_by_targets(m, sources, borders, 5e-2 * r);  // (not refined: see the manual)
  }
}

// The same curves from the kept field (keep_field: the windows that crossed each face): every point at its
// level, every border point equidistant, to 1e-9 of the largest distance by exact targeted runs, without
// refinement; the parallel propagation gives the same curves (to 1e-12 of the largest distance).
// the same curves (the same points, to `tolerance`: different windows give the same distance to rounding)
bool same_curves(const std::vector<Curve>& a, const std::vector<Curve>& b, double tolerance)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    if(a[i].closed != b[i].closed || a[i].points.size() != b[i].points.size() || a[i].cells != b[i].cells
       || !(a[i].level == b[i].level || (std::isnan(a[i].level) && std::isnan(b[i].level))))
      return false;
    for(std::size_t j = 0; j < a[i].points.size(); ++j)
      if(a[i].locations[j].first != b[i].locations[j].first
         || std::sqrt(CGAL::squared_distance(a[i].points[j], b[i].points[j])) > tolerance)
        return false;
  }
  return true;
}

TEST(Curves, ExactFromTheWindowsThatCrossTheFaces)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off" })
  {
    const Surface_mesh m = load_mesh(name);
    Curve_solver s(m);
    const std::vector<Vertex_index> sources = { *m.vertices().begin(), Vertex_index(static_cast<Surface_mesh::size_type>(m.number_of_vertices() / 2)) };
    CGAL::Constant_property_map<Vertex_index, double> discard;
    s.compute(discard, sources[0], VG::parameters::keep_field(true));
    const double r = largest(s);
    const std::vector<double> levels = { 0.1 * r, 0.37 * r, 0.8 * r };
    const auto curves = VG::geodesic_isolines(s, levels);
    ASSERT_EQ(curves.size(), VG::geodesic_isolines(s, levels).size());
    expect_no_gaps(m, curves);
    double error;
    const double share = share_at_level(m, sources[0], curves, 1e-9 * r, error);
    EXPECT_GE(share, 0.94) << name;
    EXPECT_LE(error, 1.5e-2 * r) << name;
    // the parallel propagation: the same curves
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    s.compute<CGAL::Parallel_tag>(discard, sources[0], VG::parameters::keep_field(true).number_of_threads(2));
    EXPECT_TRUE(same_curves(VG::geodesic_isolines(s, levels), curves, 1e-12 * r)) << name;
#endif
    // the borders
    s.compute(discard, sources, VG::parameters::keep_field(true));
    const auto borders = VG::geodesic_cell_borders(s);
    ASSERT_FALSE(borders.empty());
    expect_no_gaps(m, borders);
    check_borders_by_targets(m, sources, borders, 1e-9 * r);
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    s.compute<CGAL::Parallel_tag>(discard, sources, VG::parameters::keep_field(true).number_of_threads(2));
    EXPECT_TRUE(same_curves(VG::geodesic_cell_borders(s), borders, 1e-12 * r)) << name;
#endif
  }
}

// The cells' areas from the exact borders: on the plane with two sources, 1/2 each; on a real mesh, they add up
// to the area of the mesh.
TEST(Curves, VoronoiAreasFromTheBorders)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(20, 20, 1., 1.));
  Curve_solver s(m);
  const std::vector<Vertex_index> two = { Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(20, 5, 10))),
                                          Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(20, 14, 10))) };
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), two, VG::parameters::record_paths(true));
  // two vertices of a row: the bisector is the line x = (x0 + x1) / 2 = 0.475, between two columns of vertices
  const Point_3 a = m.point(two[0]), b = m.point(two[1]);
  ASSERT_EQ(a.y(), b.y());
  const VG::Voronoi_cell_areas cells = VG::geodesic_voronoi_cell_areas(s);
  for(const Curve& k : VG::geodesic_cell_borders(s))
    for(std::size_t i = 0; i < k.points.size(); ++i)
      EXPECT_NEAR(k.points[i].x(), 0.5 * (a.x() + b.x()), 1e-12) << i << " of " << k.points.size() << " " << k.points[i];
  ASSERT_EQ(cells.areas.size(), 2u);
  EXPECT_NEAR(cells.areas[0], 0.5 * (a.x() + b.x()), 1e-12);
  EXPECT_NEAR(cells.areas[0] + cells.areas[1], 1., 1e-12);
  const Surface_mesh e = load_mesh("elephant.off");
  Curve_solver t(e);
  std::vector<Vertex_index> sources;
  for(std::size_t i = 0; i < 5; ++i)
    sources.push_back(Vertex_index(static_cast<Surface_mesh::size_type>(i * e.number_of_vertices() / 5)));
  t.compute(CGAL::Constant_property_map<Vertex_index, double>(), sources, VG::parameters::record_paths(true));
  const VG::Voronoi_cell_areas ecells = VG::geodesic_voronoi_cell_areas(t);
  double total = 0., sum = 0.;
  for(Face_index f : e.faces())
    total += std::sqrt(CGAL::squared_area(e.point(e.source(e.halfedge(f))), e.point(e.target(e.halfedge(f))),
                                          e.point(e.target(e.next(e.halfedge(f))))));
  for(double x : ecells.areas)
    sum += x;
  EXPECT_NEAR(sum, total, 1e-12 * total);
}

TEST(Curves, BadInput)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(4, 4, 1., 1.));
  Curve_solver s(m);
  const Vertex_index v(0);
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), v);
  EXPECT_THROW(VG::geodesic_isolines(s, { 0.5 }), VG::Invalid_input_error);  // no record
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), v, VG::parameters::record_paths(true));
  EXPECT_THROW(VG::geodesic_isolines(s, { -0.5 }), VG::Invalid_input_error);
  EXPECT_THROW(VG::geodesic_isolines(s, { std::nan("") }), VG::Invalid_input_error);
  EXPECT_THROW(VG::geodesic_isoline_levels(s, 0.), VG::Invalid_input_error);
  EXPECT_THROW(VG::geodesic_isolines(s, { 0.5 }, VG::parameters::chord_tolerance(0.)), VG::Invalid_input_error);
  EXPECT_THROW(VG::geodesic_isolines(s, { 0.5 }, VG::parameters::exact_refinement(-1)), VG::Invalid_input_error);
  EXPECT_EQ(VG::geodesic_isolines(s, { 0.5 }).size(), 1u);
  // the kept field: exact methods only, not from initial distances
  EXPECT_THROW(s.compute(CGAL::Constant_property_map<Vertex_index, double>(), v,
                         VG::parameters::keep_field(true).lambda(8.)), VG::Invalid_input_error);
  EXPECT_THROW(s.compute(CGAL::Constant_property_map<Vertex_index, double>(), v,
                         VG::parameters::keep_field(true).virtual_sources(true)), VG::Invalid_input_error);
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), v, VG::parameters::keep_field(true));
  EXPECT_EQ(VG::geodesic_isolines(s, { 0.5 }).size(), 1u);
  EXPECT_EQ(VG::geodesic_isolines(s, { 0.6 }).size(), 1u);
}

} // namespace
