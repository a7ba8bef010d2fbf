// Sources that are curves (issue 47): add_source_curve(), add_source_border(), add_source_edges() and the
// named parameter signed_distance, against analytic answers and invariants only:
// - a jittered flat unit square (81 x 81 vertices, boundary fixed): a closed polygon given as face locations
//   (unsigned = Euclidean distance to the polygon, signed = negative inside, walked clockwise the sign flips),
//   the border (= distance to the sides), an open curve crossing faces (Euclidean distance; the sign rule of
//   open curves of internal/source_curves/Curve_sign.h), pairs of loops that the sign rule accepts and rejects,
//   a distance limit and targets (signed vertex targets; targets inside faces refused when signed);
// - a regular grid: straight curves through vertices (the side of the vertices beside an open curve, PVTP = VTP
//   signed), a closed polygon through vertices;
// - the unit cube (12 x 12 squares a side): the ring z = 0.5 through four vertices that share no face (joined
//   by the library along shortest geodesics): |z - 0.5| on the sides, 0.5 + distance to the border on the top
//   and the bottom, signed negative above;
// - a torus: a loop around the tube does not separate (signed refused), two such loops bound a band;
// - the elephant: a curve through a saddle vertex against the distance from points sampled along it (the
//   invariant d_S - h/2 <= d <= d_S), several curves and a point = the minimum of single runs (labels =
//   argmin), a curve along edges = add_source_edges() of the same edges, the border of a region as edges (signed),
//   PVTP = VTP, AVTP never below VTP;
// - bad input: Invalid_input_error, never a crash.


#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <queue>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace vtp_test;
namespace VSC = CGAL::VTP_geodesics;
namespace VSCP = CGAL::VTP_geodesics::parameters;

namespace {

typedef VSC::Geodesic_distance_solver<Surface_mesh> Sc_solver;
typedef Surface_mesh::Face_index Sc_face;
typedef Surface_mesh::Halfedge_index Sc_halfedge;
typedef std::pair<Sc_face, std::array<double, 3> > Sc_location;

// ---------------------------------------------------------------------------------------------------------
// Meshes and runs

// The flat unit square, n x n vertices, cells of size h = 1/(n-1) split along alternating diagonals; the
// boundary vertices are not moved, each interior one by up to `jitter` h in x and in y (fixed seed).
Surface_mesh sc_jittered_square(int n = 81, double jitter = 0.25, std::uint32_t seed = 47)
{
  Polygon_soup soup;
  std::mt19937 generator(seed);
  const double h = 1. / (n - 1);
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      double x = (i == n - 1) ? 1. : i * h, y = (j == n - 1) ? 1. : j * h;
      const double dx = jitter * h * uniform_in_minus_one_one(generator);
      const double dy = jitter * h * uniform_in_minus_one_one(generator);
      if(i > 0 && i < n - 1 && j > 0 && j < n - 1)
      {
        x += dx;
        y += dy;
      }
      soup.points.push_back(Point_3(x, y, 0.));
    }
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i)
    {
      const std::size_t v00 = std::size_t(j) * n + i;
      add_cell(soup, v00, v00 + 1, v00 + n + 1, v00 + n, (i + j) % 2 == 1);
    }
  if(!is_valid_planar_soup(soup))
    throw std::runtime_error("the jittered square has a flipped triangle");
  return to_mesh<Surface_mesh>(soup);
}

const Surface_mesh& sc_square()
{
  static const Surface_mesh mesh = sc_jittered_square();
  return mesh;
}

// The face location of the point (x, y) of a planar mesh (z = 0), barycentric with respect to
// source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))) (brute force).
Sc_location sc_locate_2d(const Surface_mesh& m, double x, double y)
{
  for(Sc_face f : faces(m))
  {
    const Sc_halfedge h = m.halfedge(f);
    const Point_3 &a = m.point(m.source(h)), &b = m.point(m.target(h)), &c = m.point(m.target(m.next(h)));
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    const double l1 = ((x - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (y - a.y())) / det;
    const double l2 = ((b.x() - a.x()) * (y - a.y()) - (x - a.x()) * (b.y() - a.y())) / det;
    if(l1 >= 0. && l2 >= 0. && l1 + l2 <= 1.)
      return Sc_location(f, {{1. - l1 - l2, l1, l2}});
  }
  throw std::runtime_error("point not in the planar mesh");
}

std::vector<Sc_location> sc_locate_all(const Surface_mesh& m, const std::vector<std::array<double, 2> >& p)
{
  std::vector<Sc_location> r;
  for(const std::array<double, 2>& q : p)
    r.push_back(sc_locate_2d(m, q[0], q[1]));
  return r;
}

// The result of a run: distances and labels by vertex index, and the statistics.
struct Sc_result
{
  std::vector<double> d;
  std::vector<std::size_t> label;
};

// Runs `solver` on its source set; `parallel`: Parallel_tag on 2 threads.
template <class NP>
Sc_result sc_run(Sc_solver& solver, const Surface_mesh& m, const NP& np, bool parallel = false)
{
  Sc_result r;
  r.d.assign(num_vertices(m), NOT_A_VERTEX);
  r.label.assign(num_vertices(m), std::size_t(12345));
  auto dmap = boost::make_iterator_property_map(r.d.begin(), get(boost::vertex_index, m));
  auto lmap = boost::make_iterator_property_map(r.label.begin(), get(boost::vertex_index, m));
  if(parallel)
  {
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    solver.compute<CGAL::Parallel_tag>(dmap, np.nearest_source_map(lmap).number_of_threads(2));
#else
    ADD_FAILURE() << "no OpenMP";
#endif
  }
  else
    solver.compute(dmap, np.nearest_source_map(lmap));
  return r;
}

Sc_result sc_run(Sc_solver& solver, const Surface_mesh& m, bool parallel = false)
{
  return sc_run(solver, m, VSCP::lambda(INF), parallel);
}

// Largest |a - b| (infinite if one is infinite and not the other).
double sc_max_difference(const std::vector<double>& a, const std::vector<double>& b)
{
  double r = 0.;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(!(a[i] == b[i]))
      r = (std::max)(r, std::isfinite(a[i] - b[i]) ? std::abs(a[i] - b[i]) : INF);
  return r;
}

// ---------------------------------------------------------------------------------------------------------
// Planar geometry

double sc_segment_distance(double px, double py, const std::array<double, 2>& a, const std::array<double, 2>& b,
                           double* t_out = nullptr)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  double t = ((px - a[0]) * dx + (py - a[1]) * dy) / (dx * dx + dy * dy);
  t = (std::max)(0., (std::min)(1., t));
  if(t_out != nullptr)
    *t_out = t;
  return std::hypot(a[0] + t * dx - px, a[1] + t * dy - py);
}

// Distance from (x, y) to the polyline `p` (closed if its last point is its first).
double sc_polyline_distance(double x, double y, const std::vector<std::array<double, 2> >& p)
{
  double d = INF;
  for(std::size_t k = 0; k + 1 < p.size(); ++k)
    d = (std::min)(d, sc_segment_distance(x, y, p[k], p[k + 1]));
  return d;
}

// Even-odd point in polygon (`p` closed: last = first).
bool sc_inside(double x, double y, const std::vector<std::array<double, 2> >& p)
{
  bool in = false;
  for(std::size_t k = 0; k + 1 < p.size(); ++k)
  {
    const double xi = p[k][0], yi = p[k][1], xj = p[k + 1][0], yj = p[k + 1][1];
    if((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
      in = !in;
  }
  return in;
}

std::vector<std::array<double, 2> > sc_reversed(std::vector<std::array<double, 2> > p)
{
  std::reverse(p.begin(), p.end());
  return p;
}

// The polygon of the issue, counterclockwise, closed.
const std::vector<std::array<double, 2> > sc_polygon = {
  {{0.31, 0.29}}, {{0.72, 0.33}}, {{0.69, 0.71}}, {{0.27, 0.66}}, {{0.31, 0.29}}};

// Expected distances on the planar mesh: `value(x, y)` per vertex.
template <class F>
std::vector<double> sc_expected(const Surface_mesh& m, const F& value)
{
  std::vector<double> e(num_vertices(m));
  for(Vertex_index v : vertices(m))
    e[std::size_t(v)] = value(m.point(v).x(), m.point(v).y());
  return e;
}

// ---------------------------------------------------------------------------------------------------------
// Sampling a curve on the surface

// The vertices of the support of a location (weights > 1e-12), with their weights.
std::vector<std::pair<Vertex_index, double> > sc_support(const Surface_mesh& m, const Sc_location& l)
{
  std::vector<std::pair<Vertex_index, double> > r;
  Sc_halfedge h = m.halfedge(l.first);
  const Vertex_index c[3] = { m.source(h), m.target(h), m.target(m.next(h)) };
  double sum = 0.;
  for(int k = 0; k < 3; ++k)
    if(l.second[k] > 1e-12)
    {
      r.push_back(std::make_pair(c[k], l.second[k]));
      sum += l.second[k];
    }
  for(auto& p : r)
    p.second /= sum;
  return r;
}

// The barycentric coordinates in face f of a point given by its support (whose vertices must be of f).
bool sc_in_face(const Surface_mesh& m, Sc_face f, const std::vector<std::pair<Vertex_index, double> >& s,
                std::array<double, 3>& w)
{
  Sc_halfedge h = m.halfedge(f);
  const Vertex_index c[3] = { m.source(h), m.target(h), m.target(m.next(h)) };
  w = {{0., 0., 0.}};
  for(const auto& p : s)
  {
    int k = 0;
    while(k < 3 && c[k] != p.first)
      ++k;
    if(k == 3)
      return false;
    w[k] += p.second;
  }
  return true;
}

// Samples of the polyline `locs` (consecutive locations share a face) at most `h` apart along it, both ends of
// each piece included, as face locations; false if two consecutive locations share no face.
bool sc_sample_polyline(const Surface_mesh& m, const std::vector<Sc_location>& locs, double h,
                        std::vector<Sc_location>& samples)
{
  for(std::size_t i = 0; i + 1 < locs.size(); ++i)
  {
    const auto sa = sc_support(m, locs[i]), sb = sc_support(m, locs[i + 1]);
    std::set<Sc_face> candidates;
    for(Sc_face f : faces_around_target(m.halfedge(sa[0].first), m))
      if(f != Surface_mesh::null_face())
        candidates.insert(f);
    bool found = false;
    std::array<double, 3> wa, wb;
    Sc_face face;
    for(Sc_face f : candidates)
      if(sc_in_face(m, f, sa, wa) && sc_in_face(m, f, sb, wb))
      {
        face = f;
        found = true;
        break;
      }
    if(!found)
      return false;
    const double length = distance(point_of(m, locs[i]), point_of(m, locs[i + 1]));
    const int n = (std::max)(1, static_cast<int>(std::ceil(length / h)));
    for(int k = 0; k <= n; ++k)
    {
      const double t = double(k) / n;
      samples.push_back(Sc_location(face, {{(1. - t) * wa[0] + t * wb[0], (1. - t) * wa[1] + t * wb[1],
                                            (1. - t) * wa[2] + t * wb[2]}}));
    }
  }
  return true;
}

// The polyline of the curve through `points` (vertices) as the library joins them: each pair by the path of an
// exact run from the first stopped at the second, traced back from the second.
std::vector<Sc_location> sc_joined_polyline(const Surface_mesh& m, const std::vector<Vertex_index>& points)
{
  std::vector<Sc_location> r;
  Sc_solver solver(m);
  for(std::size_t i = 0; i + 1 < points.size(); ++i)
  {
    solver.compute(Discard_map(0.), points[i],
                   VSCP::targets(std::vector<Vertex_index>(1, points[i + 1])).record_paths(true));
    std::vector<Sc_location> path;
    solver.shortest_path_locations(points[i + 1], std::back_inserter(path));  // points[i+1] ... points[i]
    std::reverse(path.begin(), path.end());
    r.insert(r.end(), path.begin() + (r.empty() ? 0 : 1), path.end());
  }
  return r;
}

// Vertices around `v` at graph distance exactly `k`.
std::vector<Vertex_index> sc_ring(const Surface_mesh& m, Vertex_index v, int k)
{
  std::vector<int> level(num_vertices(m), -1);
  std::queue<Vertex_index> q;
  level[std::size_t(v)] = 0;
  q.push(v);
  std::vector<Vertex_index> r;
  while(!q.empty())
  {
    const Vertex_index a = q.front();
    q.pop();
    if(level[std::size_t(a)] == k)
    {
      r.push_back(a);
      continue;
    }
    for(Vertex_index b : vertices_around_target(m.halfedge(a), m))
      if(level[std::size_t(b)] < 0)
      {
        level[std::size_t(b)] = level[std::size_t(a)] + 1;
        q.push(b);
      }
  }
  return r;
}

// The two vertices of `ring` farthest apart in space.
std::pair<Vertex_index, Vertex_index> sc_farthest_pair(const Surface_mesh& m, const std::vector<Vertex_index>& ring)
{
  std::pair<Vertex_index, Vertex_index> best(ring[0], ring[0]);
  double d = -1.;
  for(Vertex_index a : ring)
    for(Vertex_index b : ring)
      if(distance(m.point(a), m.point(b)) > d)
      {
        d = distance(m.point(a), m.point(b));
        best = std::make_pair(a, b);
      }
  return best;
}

// A curve on the elephant through its strongest saddle vertex: a, saddle, b (a and b 4 edges from it, far apart).
std::vector<Vertex_index> sc_saddle_curve(const Surface_mesh& m)
{
  const Vertex_index s = strongest_saddle_vertex(m);
  if(s == Surface_mesh::null_vertex())
    throw std::runtime_error("no saddle vertex");
  const auto ab = sc_farthest_pair(m, sc_ring(m, s, 4));
  return { ab.first, s, ab.second };
}

// A path of mesh edges from a to b (breadth first), as vertices.
std::vector<Vertex_index> sc_edge_path(const Surface_mesh& m, Vertex_index a, Vertex_index b)
{
  std::vector<Vertex_index> parent(num_vertices(m), Surface_mesh::null_vertex());
  std::queue<Vertex_index> q;
  parent[std::size_t(a)] = a;
  q.push(a);
  while(!q.empty() && parent[std::size_t(b)] == Surface_mesh::null_vertex())
  {
    const Vertex_index x = q.front();
    q.pop();
    for(Vertex_index y : vertices_around_target(m.halfedge(x), m))
      if(parent[std::size_t(y)] == Surface_mesh::null_vertex())
      {
        parent[std::size_t(y)] = x;
        q.push(y);
      }
  }
  std::vector<Vertex_index> r(1, b);
  while(r.back() != a)
    r.push_back(parent[std::size_t(r.back())]);
  std::reverse(r.begin(), r.end());
  return r;
}

// The half-edges from each vertex of `path` to the next.
std::vector<Sc_halfedge> sc_halfedges_of(const Surface_mesh& m, const std::vector<Vertex_index>& path)
{
  std::vector<Sc_halfedge> r;
  for(std::size_t i = 0; i + 1 < path.size(); ++i)
  {
    const auto h = CGAL::halfedge(path[i], path[i + 1], m);
    if(!h.second)
      throw std::runtime_error("not an edge");
    r.push_back(h.first);
  }
  return r;
}

} // namespace

// =========================================================================================================
// The flat square

TEST(Source_curves, square_polygon_unsigned_is_euclidean)
{
  const Surface_mesh& m = sc_square();
  Sc_solver solver(m);
  solver.add_source_curve(sc_locate_all(m, sc_polygon));
  const Sc_result r = sc_run(solver, m);
  const auto e = sc_expected(m, [](double x, double y) { return sc_polyline_distance(x, y, sc_polygon); });
  EXPECT_TRUE(distances_near(r.d, e, EXACT_TOLERANCE, "square, polygon, unsigned"));
  for(std::size_t l : r.label)
    ASSERT_EQ(l, std::size_t(0));
}

TEST(Source_curves, square_polygon_signed_negative_inside)
{
  const Surface_mesh& m = sc_square();
  for(bool clockwise : { false, true })
  {
    const std::vector<std::array<double, 2> > p = clockwise ? sc_reversed(sc_polygon) : sc_polygon;
    Sc_solver solver(m);
    solver.add_source_curve(sc_locate_all(m, p));
    const Sc_result r = sc_run(solver, m, VSCP::signed_distance(true));
    const double s = clockwise ? -1. : 1.;
    const auto e = sc_expected(m, [&](double x, double y) {
      const double d = sc_polyline_distance(x, y, p);
      return sc_inside(x, y, p) ? -s * d : s * d;
    });
    EXPECT_TRUE(distances_near(r.d, e, EXACT_TOLERANCE,
                               clockwise ? "square, polygon clockwise, signed" : "square, polygon, signed"));
    std::size_t negative = 0;
    for(double d : r.d)
      negative += d < 0.;
    EXPECT_GT(negative, std::size_t(100));
  }
}

TEST(Source_curves, square_border_is_distance_to_sides)
{
  const Surface_mesh& m = sc_square();
  Sc_solver solver(m);
  solver.add_source_border();
  const Sc_result r = sc_run(solver, m);
  const auto e = sc_expected(m, [](double x, double y) { return (std::min)({ x, y, 1. - x, 1. - y }); });
  EXPECT_TRUE(distances_near(r.d, e, EXACT_TOLERANCE, "square, border"));
  // signed: the border runs with the surface on its left: every vertex off the border is negative
  const Sc_result rs = sc_run(solver, m, VSCP::signed_distance(true));
  const auto es = sc_expected(m, [](double x, double y) { return -(std::min)({ x, y, 1. - x, 1. - y }); });
  EXPECT_TRUE(distances_near(rs.d, es, EXACT_TOLERANCE, "square, border, signed"));
}

// An open curve crossing faces (points in faces, joined along straight lines: the plane is convex):
// unsigned = Euclidean distance; signed, by the rule of Curve_sign.h for a curve that does not separate the
// surface: a vertex whose nearest point lies inside a piece has the side of that piece (negative on the left),
// a vertex nearest to an end or to a corner of the polyline is positive.
TEST(Source_curves, square_open_curve_crossing_faces)
{
  const Surface_mesh& m = sc_square();
  const std::vector<std::array<double, 2> > p = { {{0.2, 0.25}}, {{0.55, 0.45}}, {{0.8, 0.3}}, {{0.75, 0.8}} };
  Sc_solver solver(m);
  solver.add_source_curve(sc_locate_all(m, p));
  const Sc_result r = sc_run(solver, m);
  const auto e = sc_expected(m, [&](double x, double y) { return sc_polyline_distance(x, y, p); });
  EXPECT_TRUE(distances_near(r.d, e, EXACT_TOLERANCE, "square, open curve, unsigned"));

  const Sc_result rs = sc_run(solver, m, VSCP::signed_distance(true));
  std::vector<double> es(num_vertices(m), NOT_A_VERTEX);  // NaN: not compared (nearest point ambiguous)
  std::size_t left = 0, at_corner = 0;
  for(Vertex_index v : vertices(m))
  {
    const double x = m.point(v).x(), y = m.point(v).y();
    double best = INF, second = INF, t = 0.;
    std::size_t k_best = 0;
    for(std::size_t k = 0; k + 1 < p.size(); ++k)
    {
      double tk;
      const double dk = sc_segment_distance(x, y, p[k], p[k + 1], &tk);
      if(dk < best)
      {
        second = best;
        best = dk;
        k_best = k;
        t = tk;
      }
      else
        second = (std::min)(second, dk);
    }
    const double len = std::hypot(p[k_best + 1][0] - p[k_best][0], p[k_best + 1][1] - p[k_best][1]);
    if(best < 1e-9)
      es[std::size_t(v)] = 0.;
    else if(t * len > 1e-6 && (1. - t) * len > 1e-6 && second - best > 1e-9)
    {
      // inside piece k_best: left iff the cross product of the direction and (v - a) is positive
      const double cross = (p[k_best + 1][0] - p[k_best][0]) * (y - p[k_best][1])
                           - (p[k_best + 1][1] - p[k_best][1]) * (x - p[k_best][0]);
      es[std::size_t(v)] = cross > 0. ? -best : best;
      left += cross > 0.;
    }
    else if(t * len <= 1e-9 || (1. - t) * len <= 1e-9)
    {
      // nearest to an end: positive; to a corner: the side of the wedge beyond it, between the strips of the two
      // pieces on the outer side of the turn (the left if the curve turns right there)
      const std::size_t corner = t * len <= 1e-9 ? k_best : k_best + 1;
      double sign = 1.;
      if(corner > 0 && corner + 1 < p.size())
      {
        const double turn = (p[corner][0] - p[corner - 1][0]) * (p[corner + 1][1] - p[corner][1])
                            - (p[corner][1] - p[corner - 1][1]) * (p[corner + 1][0] - p[corner][0]);
        sign = turn < 0. ? -1. : 1.;
      }
      es[std::size_t(v)] = sign * best;
      ++at_corner;
    }
  }
  EXPECT_GT(left, std::size_t(100));
  EXPECT_GT(at_corner, std::size_t(100));
  EXPECT_TRUE(distances_near(rs.d, es, EXACT_TOLERANCE, "square, open curve, signed (rule of Curve_sign.h)"));
}

// On a regular grid, an open straight curve given as two vertices (joined along the straight line, through
// vertices of the mesh): every vertex whose nearest point lies strictly inside the curve (not at its ends) is on
// one side of it, negative on the left. The curve has one piece as given; the library splits it at the vertices and
// edges it passes, and here the foot of every vertex of the strip is such a split point (a tie between the pieces
// that meet there and the point itself). A closed polygon through vertices of the same grid, signed.
TEST(Source_curves, regular_grid_straight_curves_through_vertices)
{
  const int n = 40;
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1.));
  auto vertex = [&](int i, int j) { return Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, i, j))); };
  struct Case
  {
    const char* name;
    std::array<int, 4> ij;
  };
  for(const Case& c : { Case{ "horizontal, along edges", {{ 4, 20, 36, 20 }} },
                        Case{ "diagonal, through vertices", {{ 4, 4, 36, 36 }} } })
  {
    const std::array<double, 2> a = {{ double(c.ij[0]) / n, double(c.ij[1]) / n }},
                                b = {{ double(c.ij[2]) / n, double(c.ij[3]) / n }};
    Sc_solver solver(m);
    solver.add_source_curve(std::vector<Vertex_index>{ vertex(c.ij[0], c.ij[1]), vertex(c.ij[2], c.ij[3]) });
    const Sc_result u = sc_run(solver, m);
    EXPECT_TRUE(distances_near(u.d, sc_expected(m, [&](double x, double y) { return sc_segment_distance(x, y, a, b); }),
                               EXACT_TOLERANCE, std::string("regular grid, ") + c.name + ", unsigned"));
    const Sc_result r = sc_run(solver, m, VSCP::signed_distance(true));
    std::vector<double> e(num_vertices(m), NOT_A_VERTEX);
    std::size_t strip = 0, positive_on_left = 0;
    std::ostringstream examples;
    for(Vertex_index v : vertices(m))
    {
      const double x = m.point(v).x(), y = m.point(v).y();
      double t;
      const double d = sc_segment_distance(x, y, a, b, &t);
      if(d < 1e-12 || t <= 1e-9 || t >= 1. - 1e-9)
        continue;  // on the curve, or nearest to an end
      const double cross = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
      e[std::size_t(v)] = cross > 0. ? -d : d;
      ++strip;
      if(cross > 0. && r.d[std::size_t(v)] > 0. && positive_on_left++ < 6)
        examples << " (" << x * n << ", " << y * n << ")";
    }
    EXPECT_GT(strip, std::size_t(500));
    EXPECT_EQ(positive_on_left, std::size_t(0)) << c.name << ": vertices on the left of the curve, beside it, that "
                                                << "are positive, e.g. at grid points" << examples.str();
    EXPECT_TRUE(distances_near(r.d, e, EXACT_TOLERANCE,
                               std::string("regular grid, ") + c.name + ", signed, the strip"));
  }
  // a closed polygon through vertices of the grid (and along edges): negative inside
  const std::vector<std::array<int, 2> > corners = { {{ 10, 10 }}, {{ 30, 12 }}, {{ 30, 30 }}, {{ 12, 26 }},
                                                     {{ 10, 10 }} };
  std::vector<Vertex_index> loop;
  std::vector<std::array<double, 2> > polygon;
  for(const auto& q : corners)
  {
    loop.push_back(vertex(q[0], q[1]));
    polygon.push_back({{ double(q[0]) / n, double(q[1]) / n }});
  }
  Sc_solver solver(m);
  solver.add_source_curve(loop);
  const Sc_result r = sc_run(solver, m, VSCP::signed_distance(true));
  EXPECT_TRUE(distances_near(r.d, sc_expected(m, [&](double x, double y) {
    const double d = sc_polyline_distance(x, y, polygon);
    return sc_inside(x, y, polygon) && d > 1e-12 ? -d : d; }),
    EXACT_TOLERANCE, "regular grid, polygon through vertices, signed"));
}

// PVTP = VTP to 1e-12 with signed_distance too, on the same open curves of the regular grid (where the side of a
// vertex beside the curve is decided between pieces at equal distance).
TEST(Source_curves, regular_grid_open_curves_signed_pvtp_equals_vtp)
{
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
  const int n = 40;
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1.));
  auto vertex = [&](int i, int j) { return Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(n, i, j))); };
  for(const std::array<int, 4>& c : { std::array<int, 4>{{ 4, 20, 36, 20 }}, std::array<int, 4>{{ 4, 4, 36, 36 }} })
  {
    Sc_solver solver(m);
    solver.add_source_curve(std::vector<Vertex_index>{ vertex(c[0], c[1]), vertex(c[2], c[3]) });
    Sc_result a = sc_run(solver, m, VSCP::signed_distance(true)), b = sc_run(solver, m, VSCP::signed_distance(true), true);
    // (a vertex nearest to an end of the curve and, at the same distance, to the strip of the piece there -- on the
    // perpendicular to the curve at its end -- is positive or on the side of the piece: either, whichever reached
    // it first; not compared)
    const std::array<double, 2> p0 = {{ double(c[0]) / n, double(c[1]) / n }}, p1 = {{ double(c[2]) / n, double(c[3]) / n }};
    std::size_t compared = 0;
    for(Vertex_index v : vertices(m))
    {
      double t;
      sc_segment_distance(m.point(v).x(), m.point(v).y(), p0, p1, &t);
      if(t <= 1e-9 || t >= 1. - 1e-9)
        a.d[std::size_t(v)] = b.d[std::size_t(v)] = std::abs(a.d[std::size_t(v)]);
      else
        ++compared;
    }
    EXPECT_GT(compared, std::size_t(500));
    EXPECT_TRUE(distances_near(b.d, a.d, EXACT_TOLERANCE, "regular grid, open curve, signed, PVTP = VTP"));
  }
#else
  GTEST_SKIP() << "no OpenMP";
#endif
}

// Two loops: the sign rule (Curve_sign.h) takes curves that bound parts consistently (an annulus: outer loop
// counterclockwise, inner clockwise; two disjoint loops, both counterclockwise) and rejects the others (two nested
// loops both counterclockwise: the annulus is left of the outer one and right of the inner one; two disjoint loops
// of opposite orientations: the outside is right of one and left of the other).
TEST(Source_curves, square_two_loops_sign_rule)
{
  const Surface_mesh& m = sc_square();
  auto square = [](double x0, double y0, double x1, double y1) {
    return std::vector<std::array<double, 2> >{ {{x0, y0}}, {{x1, y0}}, {{x1, y1}}, {{x0, y1}}, {{x0, y0}} };
  };
  const auto outer = square(0.13, 0.12, 0.87, 0.86), inner = square(0.36, 0.37, 0.62, 0.61);
  const auto left_box = square(0.11, 0.13, 0.43, 0.84), right_box = square(0.57, 0.16, 0.88, 0.82);

  {  // annulus: accepted, negative between the loops
    Sc_solver solver(m);
    solver.add_source_curve(sc_locate_all(m, outer));
    solver.add_source_curve(sc_locate_all(m, sc_reversed(inner)));
    const Sc_result r = sc_run(solver, m, VSCP::signed_distance(true));
    const auto e = sc_expected(m, [&](double x, double y) {
      const double d = (std::min)(sc_polyline_distance(x, y, outer), sc_polyline_distance(x, y, inner));
      return sc_inside(x, y, outer) && !sc_inside(x, y, inner) ? -d : d;
    });
    EXPECT_TRUE(distances_near(r.d, e, EXACT_TOLERANCE, "square, annulus, signed"));
  }
  {  // two disjoint counterclockwise loops: accepted, negative inside each
    Sc_solver solver(m);
    solver.add_source_curve(sc_locate_all(m, left_box));
    solver.add_source_curve(sc_locate_all(m, right_box));
    const Sc_result r = sc_run(solver, m, VSCP::signed_distance(true));
    const auto e = sc_expected(m, [&](double x, double y) {
      const double d = (std::min)(sc_polyline_distance(x, y, left_box), sc_polyline_distance(x, y, right_box));
      return sc_inside(x, y, left_box) || sc_inside(x, y, right_box) ? -d : d;
    });
    EXPECT_TRUE(distances_near(r.d, e, EXACT_TOLERANCE, "square, two disjoint loops, signed"));
    for(std::size_t i = 0; i < r.d.size(); ++i)  // labels: the nearest loop
    {
      const Point_3& q = m.point(Vertex_index(static_cast<Surface_mesh::size_type>(i)));
      const double a = sc_polyline_distance(q.x(), q.y(), left_box), b = sc_polyline_distance(q.x(), q.y(), right_box);
      if(std::abs(a - b) > 1e-9)
      {
        ASSERT_EQ(r.label[i], a < b ? std::size_t(0) : std::size_t(1)) << "vertex " << i;
      }
    }
  }
  {  // nested, both counterclockwise: rejected
    Sc_solver solver(m);
    solver.add_source_curve(sc_locate_all(m, outer));
    solver.add_source_curve(sc_locate_all(m, inner));
    EXPECT_THROW(sc_run(solver, m, VSCP::signed_distance(true)), VSC::Invalid_input_error);
    // unsigned, the same curves are fine
    const Sc_result r = sc_run(solver, m);
    EXPECT_TRUE(distances_near(r.d, sc_expected(m, [&](double x, double y) {
      return (std::min)(sc_polyline_distance(x, y, outer), sc_polyline_distance(x, y, inner)); }),
      EXACT_TOLERANCE, "square, nested loops, unsigned"));
  }
  {  // disjoint, opposite orientations: rejected
    Sc_solver solver(m);
    solver.add_source_curve(sc_locate_all(m, left_box));
    solver.add_source_curve(sc_locate_all(m, sc_reversed(right_box)));
    EXPECT_THROW(sc_run(solver, m, VSCP::signed_distance(true)), VSC::Invalid_input_error);
  }
}

// =========================================================================================================
// The cube

TEST(Source_curves, cube_ring)
{
  const Surface_mesh m = to_mesh<Surface_mesh>(subdivided_cube(12));
  std::vector<Vertex_index> ring;
  for(const Point_3& p : { Point_3(0, 0, 0.5), Point_3(1, 0, 0.5), Point_3(1, 1, 0.5), Point_3(0, 1, 0.5),
                           Point_3(0, 0, 0.5) })
  {
    ring.push_back(find_vertex(m, p));
    ASSERT_NE(ring.back(), Surface_mesh::null_vertex());
  }
  auto expected = [&](bool sign) {
    std::vector<double> e(num_vertices(m));
    for(Vertex_index v : vertices(m))
    {
      const Point_3& q = m.point(v);
      double d;
      if(q.z() == 1. || q.z() == 0.)
        d = 0.5 + (std::min)({ q.x(), 1. - q.x(), q.y(), 1. - q.y() });
      else
        d = std::abs(q.z() - 0.5);
      e[std::size_t(v)] = sign && q.z() > 0.5 ? -d : d;
    }
    return e;
  };
  Sc_solver solver(m);
  solver.add_source_curve(ring);
  EXPECT_TRUE(distances_near(sc_run(solver, m).d, expected(false), EXACT_TOLERANCE, "cube, ring"));
  EXPECT_TRUE(distances_near(sc_run(solver, m, VSCP::signed_distance(true)).d, expected(true), EXACT_TOLERANCE,
                             "cube, ring, signed (negative above)"));
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
  EXPECT_TRUE(distances_near(sc_run(solver, m, true).d, expected(false), EXACT_TOLERANCE, "cube, ring, PVTP"));
  EXPECT_TRUE(distances_near(sc_run(solver, m, VSCP::signed_distance(true), true).d, expected(true), EXACT_TOLERANCE,
                             "cube, ring, signed, PVTP"));
#endif
  // walked the other way: the sign flips
  Sc_solver reversed(m);
  reversed.add_source_curve(std::vector<Vertex_index>(ring.rbegin(), ring.rend()));
  std::vector<double> flipped = expected(true);
  for(double& d : flipped)
    d = -d;
  EXPECT_TRUE(distances_near(sc_run(reversed, m, VSCP::signed_distance(true)).d, flipped, EXACT_TOLERANCE,
                             "cube, ring walked clockwise seen from above, signed (negative below)"));
  // the closed cube has no border
  EXPECT_THROW(solver.add_source_border(), VSC::Invalid_input_error);
}

// =========================================================================================================
// A torus: loops that do not separate the surface

// Torus (R = 1, r = 0.3), n columns around the axis (u) and m rows around the tube (v), cells split alternately,
// outward oriented; vertex (i, j) has index j * n + i.
Surface_mesh sc_torus(int n, int m)
{
  Polygon_soup soup;
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i)
    {
      const double u = 2. * PI * i / n, v = 2. * PI * j / m;
      soup.points.push_back(Point_3((1. + 0.3 * std::cos(v)) * std::cos(u), (1. + 0.3 * std::cos(v)) * std::sin(u),
                                    0.3 * std::sin(v)));
    }
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i)
    {
      auto id = [&](int a, int b) { return std::size_t((b % m) * n + (a % n)); };
      add_cell(soup, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), (i + j) % 2 == 1);
    }
  return to_mesh<Surface_mesh>(soup);
}

// The loop around the tube at column i (a meridian), walked with v increasing (its left: u decreasing) or not.
std::vector<Vertex_index> sc_meridian(int n, int m, int i, bool increasing)
{
  std::vector<Vertex_index> r;
  for(int k = 0; k <= m; ++k)
  {
    const int j = increasing ? k % m : (m - k) % m;
    r.push_back(Vertex_index(static_cast<Surface_mesh::size_type>(j * n + i)));
  }
  return r;
}

// One meridian is closed and does not separate the torus: signed is rejected (the rule of Curve_sign.h: every
// curve closed, a part on both sides), unsigned is fine. Two meridians walked in opposite directions bound a band:
// accepted, negative on the band on their left. Walked in the same direction: rejected.
TEST(Source_curves, torus_loops_that_do_not_separate)
{
  const int n = 48, m = 16, i0 = 10, i1 = 30;
  const Surface_mesh t = sc_torus(n, m);
  {
    Sc_solver solver(t);
    solver.add_source_curve(sc_meridian(n, m, i0, true));
    const Sc_result r = sc_run(solver, t);
    for(int j = 0; j < m; ++j)
      EXPECT_EQ(r.d[std::size_t(j * n + i0)], 0.);
    EXPECT_THROW(sc_run(solver, t, VSCP::signed_distance(true)), VSC::Invalid_input_error);
  }
  {
    Sc_solver same(t);
    same.add_source_curve(sc_meridian(n, m, i0, true));
    same.add_source_curve(sc_meridian(n, m, i1, true));
    EXPECT_THROW(sc_run(same, t, VSCP::signed_distance(true)), VSC::Invalid_input_error);
  }
  Sc_solver band(t);
  band.add_source_curve(sc_meridian(n, m, i0, false));  // left: u increasing, into the band
  band.add_source_curve(sc_meridian(n, m, i1, true));   // left: u decreasing, into the band
  const Sc_result u = sc_run(band, t), s = sc_run(band, t, VSCP::signed_distance(true));
  std::vector<double> e(u.d.size());
  std::size_t negative = 0;
  for(std::size_t v = 0; v < u.d.size(); ++v)
  {
    const int i = int(v % n);
    e[v] = i > i0 && i < i1 ? -u.d[v] : u.d[v];
    negative += e[v] < 0.;
  }
  EXPECT_GT(negative, std::size_t(100));
  EXPECT_TRUE(identical(s.d, e)) << "the band between the two meridians negative, the rest positive";
  // an open curve on the torus: accepted (its sign: the side of the nearest piece, or positive)
  Sc_solver open(t);
  open.add_source_curve(std::vector<Vertex_index>{ Vertex_index(5), Vertex_index(5 * n + 20) });
  EXPECT_NO_THROW(sc_run(open, t, VSCP::signed_distance(true)));
}

// =========================================================================================================
// A distance limit and targets with a curve

TEST(Source_curves, square_polygon_distance_limit_and_targets)
{
  const Surface_mesh& m = sc_square();
  Sc_solver solver(m);
  solver.add_source_curve(sc_locate_all(m, sc_polygon));
  const auto e = sc_expected(m, [](double x, double y) { return sc_polyline_distance(x, y, sc_polygon); });
  const double limit = 0.1;
  for(bool parallel : { false, true })
  {
#ifndef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    if(parallel)
      continue;
#endif
    const Sc_result r = sc_run(solver, m, VSCP::maximum_distance(limit), parallel);
    std::size_t within = 0, beyond = 0;
    for(std::size_t v = 0; v < e.size(); ++v)
      if(e[v] < limit - 1e-9)
      {
        ++within;
        EXPECT_NEAR(r.d[v], e[v], 1e-12) << "vertex " << v << (parallel ? " (PVTP)" : "");
      }
      else if(e[v] > limit + 1e-9)
      {
        ++beyond;
        EXPECT_EQ(r.d[v], INF) << "vertex " << v << (parallel ? " (PVTP)" : "");
        EXPECT_EQ(r.label[v], VSC::no_source);
      }
    EXPECT_GT(within, std::size_t(1000));
    EXPECT_GT(beyond, std::size_t(1000));
  }
  // targets: vertices and points of faces, their distances exact
  const std::vector<Sc_location> targets = { sc_locate_2d(m, 0.05, 0.93), sc_locate_2d(m, 0.5, 0.5),
                                             sc_locate_2d(m, 0.71, 0.5) };
  solver.compute(Discard_map(0.), VSCP::targets(targets));
  ASSERT_EQ(solver.number_of_targets(), targets.size());
  for(std::size_t k = 0; k < targets.size(); ++k)
  {
    const Point_3 q = point_of(m, targets[k]);
    EXPECT_NEAR(solver.target_distance(k), sc_polyline_distance(q.x(), q.y(), sc_polygon), 1e-12) << "target " << k;
  }
}

// With signed_distance, the distances of the targets are signed as those of the vertices are (negative inside a
// counterclockwise polygon), or the combination is refused; it is not the unsigned distance. Targets that are
// vertices and targets that are points of faces.
TEST(Source_curves, square_polygon_signed_distance_of_targets)
{
  const Surface_mesh& m = sc_square();
  Sc_solver solver(m);
  solver.add_source_curve(sc_locate_all(m, sc_polygon));
  const std::vector<Sc_location> targets = { sc_locate_2d(m, 0.05, 0.93), sc_locate_2d(m, 0.5, 0.5) };
  // targets inside faces are not signed: refused with signed_distance; unsigned, their distances are right
  EXPECT_THROW(sc_run(solver, m, VSCP::targets(targets).signed_distance(true)), VSC::Invalid_input_error);
  sc_run(solver, m, VSCP::targets(targets));
  for(std::size_t k = 0; k < targets.size(); ++k)
  {
    const Point_3 q = point_of(m, targets[k]);
    EXPECT_NEAR(solver.target_distance(k), sc_polyline_distance(q.x(), q.y(), sc_polygon), 1e-12)
      << "target " << k << " at (" << q.x() << ", " << q.y() << "), a point of a face";
  }
  {
    // vertex targets: the vertex nearest to (0.5, 0.5), inside, and a corner of the square, outside
    Vertex_index centre = *vertices(m).begin();
    for(Vertex_index v : vertices(m))
      if(distance(m.point(v), Point_3(0.5, 0.5, 0.)) < distance(m.point(centre), Point_3(0.5, 0.5, 0.)))
        centre = v;
    const std::vector<Vertex_index> vertex_targets = { centre, Vertex_index(0) };
    sc_run(solver, m, VSCP::targets(vertex_targets).signed_distance(true));
    for(std::size_t k = 0; k < vertex_targets.size(); ++k)
    {
      const Point_3& q = m.point(vertex_targets[k]);
      const double d = sc_polyline_distance(q.x(), q.y(), sc_polygon);
      EXPECT_NEAR(solver.target_distance(k), sc_inside(q.x(), q.y(), sc_polygon) ? -d : d, 1e-12)
        << "vertex target " << k << " at (" << q.x() << ", " << q.y() << "), signed";
    }
  }
}

// =========================================================================================================
// The elephant: invariants

// d_S - h/2 <= d <= d_S, d_S the distance from points sampled at most h apart along the curve (one run).
TEST(Source_curves, elephant_saddle_curve_between_sampled_points)
{
  const Surface_mesh& m = elephant();
  const std::vector<Vertex_index> curve = sc_saddle_curve(m);
  const std::vector<Sc_location> polyline = sc_joined_polyline(m, curve);
  Sc_solver solver(m);
  const double h = solver.mean_edge_length() / 2.;
  std::vector<Sc_location> samples;
  ASSERT_TRUE(sc_sample_polyline(m, polyline, h, samples));
  std::cout << "  saddle " << std::size_t(curve[1]) << " (angle sum " << angle_sum(m, curve[1]) << "), curve "
            << std::size_t(curve[0]) << " - " << std::size_t(curve[1]) << " - " << std::size_t(curve[2]) << ", "
            << polyline.size() << " points, " << samples.size() << " samples, h " << h << std::endl;
  solver.add_source_curve(curve);
  const Sc_result r = sc_run(solver, m);
  Sc_solver sampled(m);
  sampled.add_sources(samples);
  const Sc_result rs = sc_run(sampled, m);
  const double scale = max_finite(rs.d), tolerance = 1e-9 * scale;
  std::size_t above = 0, below = 0;
  double worst_above = 0., worst_below = 0.;
  for(std::size_t i = 0; i < r.d.size(); ++i)
  {
    worst_above = (std::max)(worst_above, r.d[i] - rs.d[i]);
    worst_below = (std::max)(worst_below, rs.d[i] - h / 2. - r.d[i]);
    above += r.d[i] > rs.d[i] + tolerance;
    below += r.d[i] < rs.d[i] - h / 2. - tolerance;
  }
  std::cout << "  d - d_S at most " << worst_above / scale << ", d_S - h/2 - d at most " << worst_below / scale
            << " (of the largest distance)" << std::endl;
  EXPECT_EQ(above, std::size_t(0)) << "vertices farther from the curve than from a point sampled on it";
  EXPECT_EQ(below, std::size_t(0)) << "vertices nearer to the curve than d_S - h/2";
  // the saddle and the ends are on the curve
  for(Vertex_index v : curve)
    EXPECT_EQ(r.d[std::size_t(v)], 0.);
}

// Two curves and a point as three sources = the minimum of three single runs; labels = the argmin.
TEST(Source_curves, elephant_curves_and_point_are_the_minimum_of_single_runs)
{
  const Surface_mesh& m = elephant();
  const std::vector<Vertex_index> a = sc_saddle_curve(m);
  const std::vector<Vertex_index> b = { Vertex_index(100), Vertex_index(700), Vertex_index(1500) };
  const std::vector<Sc_location> c = { Sc_location(Sc_face(2000), {{0.2, 0.3, 0.5}}),
                                       Sc_location(Sc_face(2001), {{0.6, 0.2, 0.2}}) };  // second curve: faces
  const Vertex_index point(2500);
  Sc_solver all(m);
  all.add_source_curve(a);
  all.add_source_curve(c);
  all.add_source(point);
  all.add_source_curve(b);
  ASSERT_EQ(all.number_of_sources(), std::size_t(4));
  std::vector<Sc_result> single;
  for(int k = 0; k < 4; ++k)
  {
    Sc_solver s(m);
    if(k == 0)
      s.add_source_curve(a);
    else if(k == 1)
      s.add_source_curve(c);
    else if(k == 2)
      s.add_source(point);
    else
      s.add_source_curve(b);
    single.push_back(sc_run(s, m));
  }
  for(bool parallel : { false, true })
  {
#ifndef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    if(parallel)
      continue;
#endif
    const Sc_result r = sc_run(all, m, parallel);
    std::vector<double> e(r.d.size());
    std::size_t compared = 0;
    for(std::size_t i = 0; i < r.d.size(); ++i)
    {
      std::size_t best = 0;
      double dmin = INF, second = INF;
      for(std::size_t k = 0; k < 4; ++k)
        if(single[k].d[i] < dmin)
        {
          second = dmin;
          dmin = single[k].d[i];
          best = k;
        }
        else
          second = (std::min)(second, single[k].d[i]);
      e[i] = dmin;
      if(second - dmin > 1e-9)
      {
        ++compared;
        EXPECT_EQ(r.label[i], best) << "vertex " << i << (parallel ? " (PVTP)" : "");
      }
    }
    EXPECT_GT(compared, r.d.size() * 9 / 10);
    EXPECT_TRUE(distances_near(r.d, e, EXACT_TOLERANCE, parallel ? "elephant, 4 sources = min of single runs, PVTP"
                                                                  : "elephant, 4 sources = min of single runs"));
  }
}

// A curve along mesh edges, given as the vertices of a path of edges, = add_source_edges() of its half-edges (open
// and closed, unsigned and signed); and a closed loop of edges around a vertex: that vertex is on its left.
TEST(Source_curves, elephant_curve_along_edges_equals_add_source_edges)
{
  const Surface_mesh& m = elephant();
  const std::vector<Vertex_index> path = sc_edge_path(m, Vertex_index(10), Vertex_index(900));
  ASSERT_GT(path.size(), std::size_t(5));
  // the link of a vertex: the edges opposite it in its faces, each with its face (the vertex on the left)
  const Vertex_index centre(1234);
  std::vector<Sc_halfedge> link;
  for(Sc_halfedge h : halfedges_around_target(m.halfedge(centre), m))
    link.push_back(m.next(h));  // h: -> centre; next(h): from centre; the edge opposite is next(next(h))
  for(Sc_halfedge& h : link)
    h = m.next(h);
  // in order around the centre, as a closed curve of vertices
  std::vector<Vertex_index> loop;
  {
    Sc_halfedge h = link[0];
    for(std::size_t k = 0; k < link.size(); ++k)
    {
      loop.push_back(m.source(h));
      // the next link edge starts where this one ends
      for(Sc_halfedge g : link)
        if(m.source(g) == m.target(h))
        {
          h = g;
          break;
        }
    }
    loop.push_back(loop[0]);
  }
  struct Case
  {
    const char* name;
    std::vector<Vertex_index> vertices;
  };
  for(const Case& c : { Case{ "open path of edges", path }, Case{ "closed link of a vertex", loop } })
  {
    Sc_solver as_curve(m), as_edges(m);
    as_curve.add_source_curve(c.vertices);
    as_edges.add_source_edges(sc_halfedges_of(m, c.vertices));
    for(bool sign : { false, true })
    {
      const Sc_result r1 = sc_run(as_curve, m, VSCP::signed_distance(sign));
      const Sc_result r2 = sc_run(as_edges, m, VSCP::signed_distance(sign));
      const std::string what = std::string("elephant, ") + c.name + (sign ? ", signed" : ", unsigned");
      std::cout << "  [" << what << "] curve vs edges: " << (identical(r1.d, r2.d) ? "the same bits" : "not bitwise")
                << ", max difference " << sc_max_difference(r1.d, r2.d) << std::endl;
      EXPECT_TRUE(distances_near(r1.d, r2.d, EXACT_TOLERANCE, what));
      for(Vertex_index v : c.vertices)
        EXPECT_EQ(r1.d[std::size_t(v)], 0.) << what;
    }
  }
  Sc_solver around(m);
  around.add_source_curve(loop);
  const Sc_result r = sc_run(around, m, VSCP::signed_distance(true));
  EXPECT_LT(r.d[std::size_t(centre)], 0.) << "the vertex inside its link, on the left of the loop";
  Sc_solver unsigned_run(m);
  unsigned_run.add_source_curve(loop);
  EXPECT_EQ(r.d[std::size_t(centre)], -sc_run(unsigned_run, m).d[std::size_t(centre)]);
}

// A closed curve of edges (add_source_edges, in no order): the border of the faces within k edges of a vertex, with
// the faces on the left: negative inside (the vertices nearer than k edges), positive outside, |signed| = unsigned
// bit for bit; the opposite half-edges: the signs flip.
TEST(Source_curves, elephant_border_of_a_region_as_edges_signed)
{
  const Surface_mesh& m = elephant();
  const Vertex_index centre(1234);
  std::vector<int> level(num_vertices(m), -1);
  std::queue<Vertex_index> q;
  level[std::size_t(centre)] = 0;
  q.push(centre);
  while(!q.empty())
  {
    const Vertex_index x = q.front();
    q.pop();
    for(Vertex_index y : vertices_around_target(m.halfedge(x), m))
      if(level[std::size_t(y)] < 0)
      {
        level[std::size_t(y)] = level[std::size_t(x)] + 1;
        q.push(y);
      }
  }
  for(int k : { 3, 10 })
  {
    auto in_region = [&](Sc_face f) {
      if(f == Surface_mesh::null_face())
        return false;
      for(Vertex_index v : vertices_around_face(m.halfedge(f), m))
        if(level[std::size_t(v)] < 0 || level[std::size_t(v)] > k)
          return false;
      return true;
    };
    std::vector<Sc_halfedge> edges, reversed;
    for(Sc_halfedge h : halfedges(m))
      if(in_region(m.face(h)) && !in_region(m.face(m.opposite(h))))
      {
        edges.push_back(h);
        reversed.push_back(m.opposite(h));
      }
    for(bool flip : { false, true })
    {
      Sc_solver solver(m);
      solver.add_source_edges(flip ? reversed : edges);
      const Sc_result u = sc_run(solver, m), s = sc_run(solver, m, VSCP::signed_distance(true));
      std::size_t inside = 0, wrong = 0, not_abs = 0;
      for(std::size_t v = 0; v < u.d.size(); ++v)
      {
        not_abs += !(std::abs(s.d[v]) == u.d[v]);
        if(level[v] >= 0 && level[v] < k)
        {
          ++inside;
          wrong += !(flip ? s.d[v] > 0. : s.d[v] < 0.);
        }
        else if(level[v] < 0 || level[v] > k)
          wrong += !(flip ? s.d[v] < 0. : s.d[v] > 0.);
      }
      EXPECT_GT(inside, std::size_t(10));
      EXPECT_EQ(wrong, std::size_t(0)) << "k = " << k << (flip ? ", reversed" : "");
      EXPECT_EQ(not_abs, std::size_t(0)) << "k = " << k << (flip ? ", reversed" : "");
    }
  }
}

// PVTP (2 threads) = VTP to 1e-12 of the largest distance (the package claims bitwise equality for PVSP only;
// whether the bits are the same is printed); AVTP (lambda 8) never below VTP.
TEST(Source_curves, elephant_pvtp_equals_vtp_and_avtp_never_below)
{
  const Surface_mesh& m = elephant();
  Sc_solver solver(m);
  solver.add_source_curve(sc_saddle_curve(m));
  solver.add_source_curve(std::vector<Vertex_index>{ Vertex_index(100), Vertex_index(700), Vertex_index(1500) });
  solver.add_source(Vertex_index(2500));
  for(bool sign : { false, true })
  {
    const Sc_result exact = sc_run(solver, m, VSCP::signed_distance(sign));
    const std::string what = sign ? "elephant, signed" : "elephant, unsigned";
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    const Sc_result par = sc_run(solver, m, VSCP::signed_distance(sign), true);
    std::cout << "  [" << what << "] PVTP vs VTP: " << (identical(par.d, exact.d) ? "the same bits" : "not bitwise")
              << ", max difference " << sc_max_difference(par.d, exact.d) << std::endl;
    EXPECT_TRUE(distances_near(par.d, exact.d, EXACT_TOLERANCE, what + ", PVTP = VTP"));
#endif
    if(sign)
      continue;
    for(bool parallel : { false, true })
    {
#ifndef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
      if(parallel)
        continue;
#endif
      const Sc_result approx = sc_run(solver, m, VSCP::lambda(8.), parallel);
      const double tolerance = EXACT_TOLERANCE * max_finite(exact.d);
      std::size_t below = 0, larger = 0;
      double worst = 0.;
      for(std::size_t i = 0; i < exact.d.size(); ++i)
      {
        below += approx.d[i] < exact.d[i] - tolerance;
        larger += approx.d[i] > exact.d[i] + tolerance;
        worst = (std::max)(worst, (approx.d[i] - exact.d[i]) / max_finite(exact.d));
      }
      std::cout << "  [" << what << (parallel ? ", PAVTP" : ", AVTP") << " lambda 8] " << larger
                << " vertices above the exact distance, largest excess " << worst << " of the largest distance"
                << std::endl;
      EXPECT_EQ(below, std::size_t(0)) << (parallel ? "PAVTP" : "AVTP") << " below the exact distance";
    }
  }
  // the square polygon: PVTP = VTP, signed too
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
  const Surface_mesh& sq = sc_square();
  Sc_solver ssq(sq);
  ssq.add_source_curve(sc_locate_all(sq, sc_polygon));
  const Sc_result a = sc_run(ssq, sq, VSCP::signed_distance(true)),
                  b = sc_run(ssq, sq, VSCP::signed_distance(true), true);
  std::cout << "  [square, polygon, signed] PVTP vs VTP: " << (identical(a.d, b.d) ? "the same bits" : "not bitwise")
            << std::endl;
  EXPECT_TRUE(distances_near(b.d, a.d, EXACT_TOLERANCE, "square, polygon, signed, PVTP = VTP"));
#endif
}

// =========================================================================================================
// Bad input

TEST(Source_curves, bad_input_is_rejected)
{
  const Surface_mesh& m = sc_square();
  Sc_solver solver(m);
  const Sc_location good = sc_locate_2d(m, 0.5, 0.5), good2 = sc_locate_2d(m, 0.7, 0.6);
  const Sc_face no_face(static_cast<Surface_mesh::size_type>(num_faces(m) + 10));
  // a point off the surface: a face that is not a face of the mesh, barycentric coordinates that are negative,
  // do not sum to 1, or are not finite; a vertex that is not a vertex of the mesh
  EXPECT_THROW(solver.add_source_curve(std::vector<Sc_location>{ good, Sc_location(no_face, {{0.3, 0.3, 0.4}}) }),
               VSC::Invalid_input_error);
  EXPECT_THROW(solver.add_source_curve(
                 std::vector<Sc_location>{ good, Sc_location(good2.first, {{1.5, -0.25, -0.25}}) }),
               VSC::Invalid_input_error);
  EXPECT_THROW(solver.add_source_curve(std::vector<Sc_location>{ good, Sc_location(good2.first, {{0.5, 0.5, 0.5}}) }),
               VSC::Invalid_input_error);
  EXPECT_THROW(solver.add_source_curve(
                 std::vector<Sc_location>{ good, Sc_location(good2.first, {{std::nan(""), 0.5, 0.5}}) }),
               VSC::Invalid_input_error);
  const Vertex_index no_vertex(static_cast<Surface_mesh::size_type>(num_vertices(m) + 3));
  EXPECT_THROW(solver.add_source_curve(std::vector<Vertex_index>{ Vertex_index(0), no_vertex }),
               VSC::Invalid_input_error);
  // fewer than two distinct points
  EXPECT_THROW(solver.add_source_curve(std::vector<Sc_location>{ good }), VSC::Invalid_input_error);
  EXPECT_THROW(solver.add_source_curve(std::vector<Sc_location>{ good, good, good }), VSC::Invalid_input_error);
  EXPECT_THROW(solver.add_source_curve(std::vector<Vertex_index>{ Vertex_index(5), Vertex_index(5) }),
               VSC::Invalid_input_error);
  EXPECT_THROW(solver.add_source_curve(std::vector<Vertex_index>{}), VSC::Invalid_input_error);
  // no edge
  EXPECT_THROW(solver.add_source_edges(std::vector<Sc_halfedge>{}), VSC::Invalid_input_error);
  EXPECT_EQ(solver.number_of_sources(), std::size_t(0)) << "a rejected curve is not added";
  // signed_distance without a curve
  solver.add_source(Vertex_index(7));
  EXPECT_THROW(sc_run(solver, m, VSCP::signed_distance(true)), VSC::Invalid_input_error);
  EXPECT_THROW(solver.compute(Discard_map(0.), Vertex_index(7), VSCP::signed_distance(true)), VSC::Invalid_input_error);
  // curves with what they do not support: virtual sources, the log map (its own test below), initial distances
  solver.clear_sources();
  solver.add_source_curve(std::vector<Sc_location>{ good, good2 });
  EXPECT_THROW(sc_run(solver, m, VSCP::virtual_sources(true)), VSC::Invalid_input_error);
  // (the kept field works with curves: the field on the curve is 0)
  sc_run(solver, m, VSCP::keep_field(true));
  EXPECT_NEAR(solver.field_distance(good), 0., 1e-12);
  // (the log map: its own test below)
  std::vector<double> known(num_vertices(m), INF);
  known[0] = 0.5;
  EXPECT_THROW(sc_run(solver, m, VSCP::initial_distances(boost::make_iterator_property_map(known.begin(),
                                                                                           get(boost::vertex_index, m)))),
               VSC::Invalid_input_error);
  // the solver still works after all that
  const Sc_result r = sc_run(solver, m);
  const Point_3 a = point_of(m, good), b = point_of(m, good2);
  const std::array<double, 2> pa = {{a.x(), a.y()}}, pb = {{b.x(), b.y()}};
  EXPECT_TRUE(distances_near(r.d, sc_expected(m, [&](double x, double y) { return sc_segment_distance(x, y, pa, pb); }),
                             EXACT_TOLERANCE, "square, a segment in the plane after rejected input"));

  // two consecutive points on different connected components
  Polygon_soup two = planar_grid(4, 4, 1., 1.);
  two.append(planar_grid(4, 4, 1., 1.), Vector_3(3., 0., 0.));
  const Surface_mesh m2 = to_mesh<Surface_mesh>(two);
  Sc_solver s2(m2);
  EXPECT_THROW(s2.add_source_curve(std::vector<Vertex_index>{ Vertex_index(0), Vertex_index(3), Vertex_index(30) }),
               VSC::Invalid_input_error);
  EXPECT_EQ(s2.number_of_sources(), std::size_t(0));
  // a curve on one component: the other is unreached (+infinity)
  s2.add_source_curve(std::vector<Vertex_index>{ Vertex_index(0), Vertex_index(24) });  // (0,0) to (1,1)
  const Sc_result r2 = sc_run(s2, m2);
  EXPECT_EQ(r2.d[30], INF);
  EXPECT_EQ(r2.label[30], VSC::no_source);
  EXPECT_NEAR(r2.d[4], std::sqrt(0.5), 1e-12);  // (1,0)
}

// The log map with a curve: rejected (Invalid_input_error), as virtual sources are. In its own
// test, last: it crashed (a segmentation fault in internal::prepare_log_map(), before the check).
TEST(Source_curves, log_map_with_a_curve_is_rejected)
{
  const Surface_mesh& m = sc_square();
  Sc_solver solver(m);
  solver.add_source_curve(std::vector<Sc_location>{ sc_locate_2d(m, 0.5, 0.5), sc_locate_2d(m, 0.7, 0.6) });
  std::vector<std::array<double, 2> > polar(num_vertices(m));
  EXPECT_THROW(sc_run(solver, m, VSCP::log_map(boost::make_iterator_property_map(polar.begin(),
                                                                                 get(boost::vertex_index, m)))),
               VSC::Invalid_input_error);
}
