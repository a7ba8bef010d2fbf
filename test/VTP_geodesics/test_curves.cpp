// Isolines and geodesic Voronoi borders as curves (geodesic_curves.h): on the plane (circles, straight
// bisectors), a source inside a face, several components, curves that end on the border, the prism (an
// unrolled cylinder), and real meshes checked point by point by exact runs that have the points as targets;
// the exact borders from the kept field where cells meet or poke across edges (the elephant with three cells,
// a plane and a prism, analytic);
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

// Isolines of several sources from the kept field: where a border of the cells (the cut locus, a ridge of the
// field) comes near a chord, the line across it meets the curve twice, or the curve is not a graph over it; the
// points are still found on the level (the zero nearest to the chord, or the curve followed through the face).
// Every point of every isoline at its level to 1e-9 of the largest distance (the field's distance, itself exact:
// KeptField.RealMeshesEqualTargetedRuns), none left on its chord. Before: 278 of 100,621 points off, by up to
// 1.2% of the largest distance, on the elephant with 12 sets of 2 to 7 sources.
TEST(Curves, IsolinesOfSeveralSourcesAtTheirLevel)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off" })
  {
    const Surface_mesh m = load_mesh(name);
    Curve_solver s(m);
    const std::size_t n = m.number_of_vertices();
    const std::vector<std::vector<std::size_t> > source_sets = {
      { 0, 925, 1850 }, { 17, n / 2 }, { 3, n / 5, 2 * n / 5, 3 * n / 5, 4 * n / 5 },
      { 1, 100, 400, 900, 1600, 2000, n - 1 } };
    for(const auto& set : source_sets)
    {
      std::vector<Vertex_index> sources;
      for(std::size_t v : set)
        sources.push_back(Vertex_index(static_cast<Surface_mesh::size_type>(v)));
      s.compute(CGAL::Constant_property_map<Vertex_index, double>(), sources, VG::parameters::keep_field(true));
      const double r = largest(s);
      std::vector<double> levels;
      for(int i = 1; i <= 19; ++i)
        levels.push_back(r * i / 20.);
      VG::Geodesic_curves_report report;
      const auto curves = VG::geodesic_isolines(s, levels, VG::parameters::curves_report(report));
      expect_no_gaps(m, curves);
      EXPECT_EQ(report.undecided, 0u) << name << ", " << set.size() << " sources";
      std::size_t points = 0, off = 0;
      for(const auto& c : curves)
        for(const auto& location : c.locations)
        {
          ++points;
          off += std::abs(s.field_distance(location) - c.level) > 1e-9 * r ? 1 : 0;
        }
      EXPECT_GT(points, 1000u) << name;
      EXPECT_EQ(off, 0u) << name << ", " << set.size() << " sources, " << points << " points";
    }
  }
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

// The location of a point of the surface (within 1e-12 of a face's plane, inside it to 1e-12)
Curve_solver::Face_location locate_point(const Surface_mesh& m, const Point_3& p)
{
  for(Face_index f : m.faces())
  {
    const auto h = m.halfedge(f);
    const Point_3 a = m.point(m.source(h)), b = m.point(m.target(h)), c = m.point(m.target(m.next(h)));
    const Vector_3 u = b - a, v = c - a, w = p - a, n = CGAL::cross_product(u, v);
    const double n2 = n.squared_length();
    if(!(n2 > 0.) || std::abs(w * n) > 1e-12 * std::sqrt(n2))
      continue;
    const double l1 = CGAL::cross_product(w, v) * n / n2, l2 = CGAL::cross_product(u, w) * n / n2;
    const double l0 = 1. - l1 - l2;
    if(l0 >= -1e-12 && l1 >= -1e-12 && l2 >= -1e-12)
      return Curve_solver::Face_location(f, { { l0, l1, l2 } });
  }
  ADD_FAILURE() << "no face holds " << p;
  return Curve_solver::Face_location(*m.faces().begin(), { { 1., 0., 0. } });
}

// The points of the curves of cells (i, j) within `tolerance` of p
std::size_t points_near(const std::vector<Curve>& curves, std::size_t i, std::size_t j, const Point_3& p,
                        double tolerance)
{
  std::size_t n = 0;
  for(const Curve& k : curves)
    if(k.cells[0] == (std::min)(i, j) && k.cells[1] == (std::max)(i, j))
      for(const Point_3& q : k.points)
        n += distance(p, q) <= tolerance ? 1 : 0;
  return n;
}

// The area of the part of the rectangle [x0, x1] x [y0, y1] nearer to `site` than to the points `others` (of
// the plane: a convex polygon, the rectangle clipped by the half-planes of the bisectors)
double clipped_cell_area(double x0, double y0, double x1, double y1, const std::array<double, 2>& a,
                         const std::vector<std::array<double, 2> >& others)
{
  std::vector<std::array<double, 2> > poly = { { { x0, y0 } }, { { x1, y0 } }, { { x1, y1 } }, { { x0, y1 } } };
  for(const auto& b : others)
  {
    // kept: 2 x . (b - a) <= |b|^2 - |a|^2
    const double nx = 2. * (b[0] - a[0]), ny = 2. * (b[1] - a[1]);
    const double c = b[0] * b[0] + b[1] * b[1] - a[0] * a[0] - a[1] * a[1];
    std::vector<std::array<double, 2> > out;
    for(std::size_t k = 0; k < poly.size(); ++k)
    {
      const auto& p = poly[k];
      const auto& q = poly[(k + 1) % poly.size()];
      const double fp = nx * p[0] + ny * p[1] - c, fq = nx * q[0] + ny * q[1] - c;
      if(fp <= 0.)
        out.push_back(p);
      if((fp < 0.) != (fq < 0.) && fp != fq)
      {
        const double t = fp / (fp - fq);
        out.push_back({ { p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]) } });
      }
    }
    poly = out;
  }
  double twice = 0.;
  for(std::size_t k = 0; k < poly.size(); ++k)
    twice += poly[k][0] * poly[(k + 1) % poly.size()][1] - poly[(k + 1) % poly.size()][0] * poly[k][1];
  return 0.5 * twice;
}

// The area of the part of the unit square nearer to sources[i] than to the others (z = 0)
double flat_cell_area(const std::vector<Point_3>& sources, std::size_t i)
{
  std::vector<std::array<double, 2> > others;
  for(std::size_t j = 0; j < sources.size(); ++j)
    if(j != i)
      others.push_back({ { sources[j].x(), sources[j].y() } });
  return clipped_cell_area(0., 0., 1., 1., { { sources[i].x(), sources[i].y() } }, others);
}

// The borders from the kept field follow every change of the nearest source, not only the edges whose corners'
// labels differ: on the elephant with three sources (cells meeting in a face where the corner labels do not say
// so), every border point is equidistant from its two cells' sources to 1e-9 of the largest distance (exact
// targeted runs), and the cells' areas add up to the area of the mesh.
TEST(Curves, ExactBordersOfThreeCells)
{
  const Surface_mesh m = elephant();
  Curve_solver s(m);
  const std::vector<Vertex_index> sources = { Vertex_index(0), Vertex_index(99), Vertex_index(1000) };
  CGAL::Constant_property_map<Vertex_index, double> discard;
  s.compute(discard, sources, VG::parameters::keep_field(true));
  const double r = largest(s);
  VG::Geodesic_curves_report report;
  const auto borders = VG::geodesic_cell_borders(s, VG::parameters::default_values(), &report);
  ASSERT_EQ(borders.size(), 3u);
  expect_no_gaps(m, borders);
  check_borders_by_targets(m, sources, borders, 1e-9 * r);
  EXPECT_EQ(report.undecided, 0u);
  EXPECT_EQ(report.edge_fallbacks, 0u);
  EXPECT_EQ(report.junction_fallbacks, 0u);
  // the three borders meet at one point (the junction, an end of each)
  std::vector<Point_3> ends;
  for(const Curve& k : borders)
  {
    EXPECT_FALSE(k.closed);
    ends.push_back(k.points.front());
    ends.push_back(k.points.back());
  }
  std::size_t meeting = 0;
  for(const Point_3& p : ends)
  {
    std::size_t same = 0;
    for(const Point_3& q : ends)
      same += distance(p, q) <= 1e-12 ? 1 : 0;
    meeting = (std::max)(meeting, same);
  }
  EXPECT_EQ(meeting, 3u);
  const VG::Voronoi_cell_areas cells = VG::geodesic_voronoi_cell_areas(s);
  double total = 0., sum = 0.;
  for(Face_index f : m.faces())
    total += std::sqrt(CGAL::squared_area(m.point(m.source(m.halfedge(f))), m.point(m.target(m.halfedge(f))),
                                          m.point(m.target(m.next(m.halfedge(f))))));
  for(double x : cells.areas)
    sum += x;
  EXPECT_NEAR(sum, total, 1e-13 * total);
}

// On a flat jittered grid the cells are the Voronoi cells of the sources (straight bisectors): three sources
// around a point J just beyond an edge pq, so that the cell of the third (C, below) reaches across pq between
// p (in cell A) and q (in cell B), and the three cells meet at J, the circumcentre of the sources, in a face
// whose corners are in A and B only. Every border point lies on its bisector and in no nearer cell, the A|C and
// B|C borders cross pq where the bisectors do, the three borders end at the circumcentre, to 1e-12; the cells'
// areas are those of the Voronoi cells clipped to the square, to 1e-12.
TEST(Curves, ExactBordersOnAPlaneThirdCellAcrossAnEdge)
{
  const int n = 20;
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1., 0.2, 11));
  const Vertex_index p(static_cast<Surface_mesh::size_type>(grid_vertex(n, 10, 10)));
  const Vertex_index q(static_cast<Surface_mesh::size_type>(grid_vertex(n, 11, 10)));
  const Point_3 pp = m.point(p), pq = m.point(q);
  const double h = 1. / n, len = distance(pp, pq);
  const double ex = (pq.x() - pp.x()) / len, ey = (pq.y() - pp.y()) / len;  // along pq, and (-ey, ex) across
  const double delta = 0.15 * h, radius = 3. * h;
  const double jx = 0.5 * (pp.x() + pq.x()) - delta * ey, jy = 0.5 * (pp.y() + pq.y()) + delta * ex;
  std::vector<Curve_solver::Face_location> at;
  std::vector<Point_3> src;
  for(double angle : { 150., 30., 270. })  // A, B, C (in the frame of pq)
  {
    const double a = angle * PI / 180., c = std::cos(a), d = std::sin(a);
    at.push_back(locate_point(m, Point_3(jx + radius * (c * ex - d * ey), jy + radius * (c * ey + d * ex), 0.)));
    src.push_back(point_of(m, at.back()));
  }
  const Point_3 j = CGAL::circumcenter(src[0], src[1], src[2]);
  Curve_solver s(m);
  CGAL::Constant_property_map<Vertex_index, double> discard;
  s.compute(discard, at, VG::parameters::keep_field(true));
  // p in A, q in B; the face beyond pq (holding the junction) has no corner in C
  ASSERT_EQ(s.field_nearest_source(p), 0u);
  ASSERT_EQ(s.field_nearest_source(q), 1u);
  const auto hpq = m.halfedge(p, q);
  ASSERT_TRUE(hpq != Surface_mesh::null_halfedge());
  const bool left =
    CGAL::orientation(Point_2(pp.x(), pp.y()), Point_2(pq.x(), pq.y()), Point_2(jx, jy)) == CGAL::LEFT_TURN;
  const auto beyond = left ? hpq : m.opposite(hpq);
  EXPECT_NE(s.field_nearest_source(m.target(m.next(beyond))), 2u);
  VG::Geodesic_curves_report report;
  const auto borders = VG::geodesic_cell_borders(s, VG::parameters::default_values(), &report);
  EXPECT_EQ(borders.size(), 3u);
  expect_no_gaps(m, borders);
  EXPECT_EQ(report.undecided + report.edge_fallbacks + report.junction_fallbacks, 0u);
  for(const Curve& k : borders)
  {
    ASSERT_FALSE(k.closed);
    const std::size_t a = k.cells[0], b = k.cells[1], c = 3 - a - b;
    for(const Point_3& x : k.points)
    {
      const double da = distance(x, src[a]), db = distance(x, src[b]), dc = distance(x, src[c]);
      EXPECT_NEAR(da, db, 1e-12) << "border " << a << "|" << b << " at " << x;
      EXPECT_LE(da, dc + 1e-12) << "border " << a << "|" << b << " at " << x;
    }
    // one end at the junction, the other on the square's side
    const double to_j = (std::min)(distance(k.points.front(), j), distance(k.points.back(), j));
    EXPECT_LE(to_j, 1e-12) << "border " << a << "|" << b;
  }
  // where the bisectors of A, C and of B, C cross pq: inside it, both borders through there
  for(std::size_t a : { std::size_t(0), std::size_t(1) })
  {
    const Point_3& x = src[a];
    const Point_3& c = src[2];
    // |pp + t (pq - pp) - x| = |... - c|: linear in t
    const Vector_3 d = pq - pp, cx = c - x;
    const double t = ((c - CGAL::ORIGIN).squared_length() - (x - CGAL::ORIGIN).squared_length()
                      - 2. * ((pp - CGAL::ORIGIN) * cx)) / (2. * (d * cx));
    ASSERT_GT(t, 0.);
    ASSERT_LT(t, 1.);
    EXPECT_EQ(points_near(borders, a, 2, pp + t * d, 1e-12), 1u) << "border " << a << "|2 on pq";
  }
  const VG::Voronoi_cell_areas cells = VG::geodesic_voronoi_cell_areas(s);
  ASSERT_EQ(cells.areas.size(), 3u);
  for(std::size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(cells.areas[i], flat_cell_area(src, i), 1e-12) << "cell " << i;
}

// The lateral surface of a prism is a flat strip rolled up (distances: Euclidean in the strip, around the
// shorter way). Source A low, B high on the line opposite A (A's cut line): below some height the cut line
// separates the two ways to A; above it, B's cell is a wedge, here narrower than the ring edge it crosses, so
// that both corners of that edge are nearest to A (each the other way around) and B's cell pokes across it
// between them. Every border point is equidistant to 1e-12, and the border crosses that edge where the two
// bisectors of B and the two images of A do.
TEST(Curves, ExactBordersOnAPrismCellAcrossAnEdgeOfOneLabel)
{
  const int sides = 12, bands = 6;
  const double radius = 0.5, height = 3.;
  const Surface_mesh m = to_mesh<Surface_mesh>(open_prism(sides, bands, radius, height));
  const double side = 2. * radius * std::sin(PI / sides), perimeter = sides * side;
  auto abscissa = [&](const Point_3& x) {
    double angle = std::atan2(x.y(), x.x());
    if(angle < 0.)
      angle += 2. * PI;
    const int k = static_cast<int>(std::floor(angle / (2. * PI / sides) + 1e-12)) % sides;
    const double c = 2. * PI * k / sides;
    return k * side + std::hypot(x.x() - radius * std::cos(c), x.y() - radius * std::sin(c));
  };
  auto on_strip = [&](double u, double z) {  // the point at abscissa u (in [0, perimeter)), height z
    const int k = static_cast<int>(std::floor(u / side));
    const double t = u / side - k, a0 = 2. * PI * k / sides, a1 = 2. * PI * (k + 1) / sides;
    return Point_3(radius * ((1. - t) * std::cos(a0) + t * std::cos(a1)),
                   radius * ((1. - t) * std::sin(a0) + t * std::sin(a1)), z);
  };
  // A at abscissa 2.5 sides; its cut line at 8.5 sides, the middle of the ring edges between corners 8 and 9;
  // the tip of B's cell just below ring 2 (height 1): z* = zb - sqrt((z* - za)^2 + (perimeter / 2)^2)
  const double za = 0.1, tip = 0.96, ua = 2.5 * side, uc = ua + 0.5 * perimeter;
  const double zb = tip + std::sqrt((tip - za) * (tip - za) + 0.25 * perimeter * perimeter);
  ASSERT_LT(zb, height);
  const std::vector<Curve_solver::Face_location> at = { locate_point(m, on_strip(ua, za)),
                                                        locate_point(m, on_strip(uc, zb)) };
  const Point_3 a = point_of(m, at[0]), b = point_of(m, at[1]);
  auto strip_distance = [&](const Point_3& x, const Point_3& o) {
    const double du = std::abs(abscissa(x) - abscissa(o));
    return std::hypot((std::min)(du, perimeter - du), x.z() - o.z());
  };
  Curve_solver s(m);
  CGAL::Constant_property_map<Vertex_index, double> discard;
  s.compute(discard, at, VG::parameters::keep_field(true));
  // the ring edge at height 1 across the cut line: both corners in A
  const Vertex_index v8(static_cast<Surface_mesh::size_type>(2 * sides + 8));
  const Vertex_index v9(static_cast<Surface_mesh::size_type>(2 * sides + 9));
  ASSERT_EQ(s.field_nearest_source(v8), 0u);
  ASSERT_EQ(s.field_nearest_source(v9), 0u);
  ASSERT_NE(m.halfedge(v8, v9), Surface_mesh::null_halfedge());
  VG::Geodesic_curves_report report;
  const auto borders = VG::geodesic_cell_borders(s, VG::parameters::default_values(), &report);
  ASSERT_FALSE(borders.empty());
  expect_no_gaps(m, borders);
  EXPECT_EQ(report.undecided + report.edge_fallbacks + report.junction_fallbacks, 0u);
  for(const Curve& k : borders)
    for(const Point_3& x : k.points)
      EXPECT_NEAR(strip_distance(x, a), strip_distance(x, b), 1e-12) << x;
  // at height 1, the bisector of B and the image of A on either side is off the cut line by
  // x = (perimeter^2 / 4 + (1 - za)^2 - (zb - 1)^2) / perimeter, less than half the edge
  const double za1 = a.z(), zb1 = b.z();
  const double x = (0.25 * perimeter * perimeter + (1. - za1) * (1. - za1) - (zb1 - 1.) * (zb1 - 1.)) / perimeter;
  ASSERT_GT(x, 0.);
  ASSERT_LT(x, 0.5 * side);
  const double u_cut = abscissa(b);
  for(double u : { u_cut - x, u_cut + x })
    EXPECT_EQ(points_near(borders, 0, 1, on_strip(u, 1.), 1e-12), 1u) << "the border on the ring edge at " << u;
  // the areas: B's cell is, unrolled around B, the strip's period clipped by the bisectors of B and A's images
  // (it has corners where B's border crosses A's cut line: kinks, followed to the chord tolerance); they add up
  const VG::Voronoi_cell_areas cells = VG::geodesic_voronoi_cell_areas(s, VG::parameters::chord_tolerance(1e-6));
  ASSERT_EQ(cells.areas.size(), 2u);
  std::vector<std::array<double, 2> > images;
  for(int k = -1; k <= 2; ++k)
    images.push_back({ { abscissa(a) + k * perimeter, a.z() } });
  const double ub = abscissa(b);
  const double cell_b =
    clipped_cell_area(ub - 0.5 * perimeter, 0., ub + 0.5 * perimeter, height, { { ub, b.z() } }, images);
  EXPECT_NEAR(cells.areas[1], cell_b, cells.uncertainty[1] + 1e-12);
  EXPECT_NEAR(cells.areas[0] + cells.areas[1], perimeter * height, 1e-12 * perimeter * height);
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
