// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the VTP_geodesics package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_PIECES_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_PIECES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/curves/Curve_field.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A point of a curve: face f and its barycentric coordinates (corners source(3f + k)).
struct Curve_point
{
  Index face;
  double b[3];
};

// The part of a curve inside one face, from an end to the other; an end is an edge point (key: twice the lower
// half-edge of the edge, plus 1 for the second crossing of an edge along it) or a junction of three cells
// (key: twice the number of half-edges, plus the face).
struct Curve_piece
{
  Index set;
  Index key[2];
  std::vector<Curve_point> points;
};

// the area of face f (from its frame)
inline double face_area(const Mesh_arrays& m, Index f)
{
  const Halfedge_geometry g = m.geometry[3 * f];
  return 0.5 * g.length * g.cy;
}

inline void frame_point(const Face_frame& fr, const Curve_point& p, double& x, double& y)
{
  x = p.b[1] * fr.x[1] + p.b[2] * fr.x[2];
  y = p.b[2] * fr.y[2];
}

// the area of the polygon of corner k of face f, the points of `first` in order, then those of `second`
// backwards (if not null)
inline double polygon_area(const Mesh_arrays& m, Index f, int k, const std::vector<Curve_point>& first,
                         const std::vector<Curve_point>* second)
{
  const Face_frame fr(m, f);
  std::vector<std::pair<double, double> > q;
  q.emplace_back(fr.x[k], fr.y[k]);
  double x, y;
  for(const Curve_point& p : first)
  {
    frame_point(fr, p, x, y);
    q.emplace_back(x, y);
  }
  if(second != nullptr)
    for(std::size_t i = second->size(); i-- > 0;)
    {
      frame_point(fr, (*second)[i], x, y);
      q.emplace_back(x, y);
    }
  double twice = 0.;
  for(std::size_t i = 0; i < q.size(); ++i)
  {
    const std::pair<double, double>& a = q[i];
    const std::pair<double, double>& b = q[(i + 1) % q.size()];
    twice += a.first * b.second - a.second * b.first;
  }
  return 0.5 * std::abs(twice);
}

inline double polyline_length(const Mesh_arrays& m, Index f, const std::vector<Curve_point>& points)
{
  const Face_frame fr(m, f);
  double length = 0., x0 = 0., y0 = 0., x, y;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    frame_point(fr, points[i], x, y);
    if(i > 0)
      length += std::hypot(x - x0, y - y0);
    x0 = x;
    y0 = y;
  }
  return length;
}

// The abscissa u nearest to `near` where b + |(px, py) + u (dx, dy) - (cx, cy)| = level, the level of a circle's
// distance along a line (NaN: the line does not reach that level).
inline double circle_on_line(double px, double py, double dx, double dy, double cx, double cy, double b, double level,
                             double near)
{
  const double r = level - b;
  const double qx = px - cx, qy = py - cy;
  const double a2 = dx * dx + dy * dy, bq = qx * dx + qy * dy, cq = qx * qx + qy * qy - r * r;
  const double disc = bq * bq - a2 * cq;
  if(!(r >= 0.) || !(disc >= 0.) || !(a2 > 0.))
    return std::numeric_limits<double>::quiet_NaN();
  const double q = -(bq + (bq < 0. ? -1. : 1.) * std::sqrt(disc));  // (the two roots without cancellation)
  const double u1 = q / a2, u2 = q != 0. ? cq / q : u1;
  return std::abs(u1 - near) <= std::abs(u2 - near) ? u1 : u2;
}

// The zero of g on [a, b], where g(a) and g(b) have opposite signs and g is, around each abscissa, the distance
// of one circle along a line minus a level (the field of a face along a line: the least of its candidates):
// `g(u, next)` returns g(u) and sets `next` to where the circle that holds at u reaches the level
// (circle_on_line(); NaN if unknown). Each step goes there if it stays inside the bracket (exact in one step
// when the same circle holds at the zero), else takes the Illinois step (regula falsi, the value at an end that
// stays twice halved); it stops when |g| is at most `tolerance_g` or the bracket at most `tolerance`.
template <class G>
double circle_zero(G g, double a, double b, double fa, double fb, double tolerance, double tolerance_g)
{
  double u = (fa * b - fb * a) / (fa - fb);
  int side = 0;
  for(int i = 0; i < 100; ++i)
  {
    if(!(u > a && u < b))
      u = 0.5 * (a + b);
    double next;
    const double fu = g(u, next);
    if(!(fu == fu))
      return 0.5 * (a + b);
    if(std::abs(fu) <= tolerance_g)
      return u;
    if((fu < 0.) == (fb < 0.))
    {
      b = u;
      fb = fu;
      if(side == -1)
        fa *= 0.5;
      side = -1;
    }
    else
    {
      a = u;
      fa = fu;
      if(side == 1)
        fb *= 0.5;
      side = 1;
    }
    if(std::abs(b - a) <= tolerance)
      return std::abs(fa) <= std::abs(fb) ? a : b;
    u = next > a && next < b ? next : (fa * b - fb * a) / (fa - fb);
  }
  return 0.5 * (a + b);
}

// The zero of f on [a, b] where f(a) and f(b) have opposite signs: the Illinois steps of circle_zero() alone.
template <class F>
double bracketed_zero(F f, double a, double b, double fa, double fb, double tolerance)
{
  return circle_zero(
    [&f](double u, double& next) {
      next = std::numeric_limits<double>::quiet_NaN();
      return f(u);
    },
    a, b, fa, fb, tolerance, tolerance * 1e-3);
}

// The pieces of the curves in the faces: the points where they cross edges (computed once per edge, from
// the candidates of its two faces, in the same way from either face) and the points in between, each on
// the curve along a line across the chord of the piece.
class Curve_pieces
{
public:
  Curve_pieces(const Curve_field& field, double tolerance) : m_field(field), m_mesh(field.mesh()), m_tolerance(tolerance) {}

  // samples placed on the chord (no sign change across it: the field of the face disagrees with the ends)
  std::size_t undecided = 0;
  // edge points placed by linear interpolation (the candidates did not bracket the level on the edge)
  std::size_t edge_fallbacks = 0;

  // The value along edge e = (lower half-edge c) at abscissa t in [0, 1] from source(c): phi(candidates of
  // the face, point in its frame) over both faces.
  template <class Phi>
  double edge_value(Index c, double t, const std::vector<Curve_candidate>& cf, const std::vector<Curve_candidate>& cg,
                    Phi phi) const
  {
    double x, y;
    edge_point(c, t, x, y);
    double v = phi(cf, x, y);
    const Index o = m_mesh.opposite[c];
    if(o != NO_INDEX)
    {
      edge_point(o, 1. - t, x, y);
      v = (std::min)(v, phi(cg, x, y));
    }
    return v;
  }

  // the point at abscissa s (share of its length) of half-edge h, in the frame of its face
  void edge_point(Index h, double s, double& x, double& y) const
  {
    const Face_frame fr(m_mesh, Mesh_arrays::face(h));
    const int k = static_cast<int>(h % 3), j = (k + 1) % 3;
    x = fr.x[k] + s * (fr.x[j] - fr.x[k]);
    y = fr.y[k] + s * (fr.y[j] - fr.y[k]);
  }

  // The least candidate distance of `c` (candidates of face(h)) on half-edge h, and its abscissa (share of the
  // length of h): the least over the candidates of base + distance from the image to the segment.
  double least_on_halfedge(Index h, const std::vector<Curve_candidate>& c, double& at) const
  {
    double ax, ay, bx, by;
    edge_point(h, 0., ax, ay);
    edge_point(h, 1., bx, by);
    const double ex = bx - ax, ey = by - ay, e2 = ex * ex + ey * ey;
    double best = std::numeric_limits<double>::infinity();
    at = 0.;
    for(const Curve_candidate& q : c)
    {
      double t = e2 > 0. ? ((q.x - ax) * ex + (q.y - ay) * ey) / e2 : 0.;
      t = t < 0. ? 0. : (t > 1. ? 1. : t);
      const double d = q.base + std::hypot(ax + t * ex - q.x, ay + t * ey - q.y);
      if(d < best)
      {
        best = d;
        at = t;
      }
    }
    return best;
  }

  // The candidates of the faces of the lower half-edge c (m_cf, and m_cg of the face of its opposite, if any),
  // and the edge in the frames of these faces: line[i] = {x, y, dx, dy}, the point (x, y) + u (dx, dy) at
  // abscissa u from source(c)
  void edge_candidates(Index c, double line[2][4])
  {
    const Index o = m_mesh.opposite[c];
    m_field.candidates(Mesh_arrays::face(c), m_cf);
    edge_point(c, 0., line[0][0], line[0][1]);
    edge_point(c, 1., line[0][2], line[0][3]);
    m_cg.clear();
    if(o != NO_INDEX)
    {
      m_field.candidates(Mesh_arrays::face(o), m_cg);
      edge_point(o, 1., line[1][0], line[1][1]);
      edge_point(o, 0., line[1][2], line[1][3]);
    }
    for(int i = 0; i < (o != NO_INDEX ? 2 : 1); ++i)
    {
      line[i][2] -= line[i][0];
      line[i][3] -= line[i][1];
    }
  }

  // The crossings of the level on the lower half-edge c (abscissae from source(c), increasing; at most 4) from
  // the field of the windows that crossed the faces (Curve_field::from_crossings()): each candidate of the two
  // faces is below the level on one interval of the edge (Curve_candidate::below_on_line()), the field on their
  // union; the crossings are the ends of the union inside the edge: where the field dips below the level
  // between two vertices above it, and where it rises above it between two below it (a cut locus). Exact up
  // to the roots of the circles. Returns -1 if the union does not agree with the vertex distances da and db
  // (an odd number of crossings for ends on the same side) or has more than 4.
  int exact_isoline_crossings(Index c, double level, double da, double db, double t[4])
  {
    const Index o = m_mesh.opposite[c];
    double line[2][4];
    edge_candidates(c, line);
    m_intervals.clear();
    for(int side = 0; side < (o != NO_INDEX ? 2 : 1); ++side)
    {
      const double* l = line[side];
      for(const Curve_candidate& q : side == 0 ? m_cf : m_cg)
      {
        double lo, hi;
        if(q.below_on_line(l[0], l[1], l[2], l[3], level, lo, hi) && hi > 0. && lo < 1.)
          m_intervals.emplace_back(lo, hi);
      }
    }
    std::sort(m_intervals.begin(), m_intervals.end());
    int n = 0;
    bool below_a = false;
    double reach = -std::numeric_limits<double>::infinity();  // the end of the union so far
    for(const auto& iv : m_intervals)
    {
      if(iv.first > reach)
      {
        // a gap before iv: reach (if inside) ends a part below, iv.first starts one
        if(reach > 0. && reach < 1.)
        {
          if(n == 4)
            return -1;
          t[n++] = reach;
        }
        if(iv.first > 0.)
        {
          if(n == 4)
            return -1;
          t[n++] = iv.first;
        }
        else
          below_a = true;
      }
      reach = (std::max)(reach, iv.second);
    }
    if(reach > 0. && reach < 1.)
    {
      if(n == 4)
        return -1;
      t[n++] = reach;
    }
    const bool below_b = reach >= 1.;
    if(below_a != (da < level) || below_b != (db < level))
      return -1;
    return n;
  }

  // The crossings of the level on the lower half-edge c (abscissae from source(c), increasing; at most two),
  // where the vertex distances at its ends are da and db: one if the level is between them; two if both are
  // above and the field dips below the level in between (a circle that cuts the edge twice); none else.
  int isoline_crossings(Index c, double level, double da, double db, double t[2])
  {
    const bool below_a = da < level, below_b = db < level;
    if(below_a && below_b)
      return 0;
    const Index o = m_mesh.opposite[c];
    double line[2][4];
    edge_candidates(c, line);
    auto g = [&](double u, double& next) {
      double best = std::numeric_limits<double>::infinity();
      int best_side = -1, best_which = -1;
      for(int side = 0; side < (o != NO_INDEX ? 2 : 1); ++side)
      {
        int which;
        const double v = Curve_field::value(side == 0 ? m_cf : m_cg, line[side][0] + u * line[side][2],
                                            line[side][1] + u * line[side][3], NO_INDEX, which);
        if(v < best)
        {
          best = v;
          best_side = side;
          best_which = which;
        }
      }
      next = std::numeric_limits<double>::quiet_NaN();
      if(best_which >= 0)
      {
        const double* l = line[best_side];
        double cx, cy, b;
        (best_side == 0 ? m_cf : m_cg)[static_cast<std::size_t>(best_which)].active_circle(l[0] + u * l[2],
                                                                                          l[1] + u * l[3], cx, cy, b);
        next = circle_on_line(l[0], l[1], l[2], l[3], cx, cy, b, level, u);
      }
      return best - level;
    };
    auto f = [&](double u) {
      double next;
      return g(u, next);
    };
    const double tolerance_g = 4e-15 * (level + m_mesh.geometry[c].length);
    if(below_a != below_b)
    {
      const double f0 = f(0.), f1 = f(1.);
      const double lin = std::isfinite(db) && std::isfinite(da) ? (level - da) / (db - da) : (below_a ? 1. : 0.);
      if(!((f0 < 0.) == below_a && (f1 < 0.) == below_b) || !std::isfinite(f0) || !std::isfinite(f1))
      {
        ++edge_fallbacks;
        t[0] = (std::min)((std::max)(lin, 0.), 1.);
      }
      else
        t[0] = circle_zero(g, 0., 1., f0, f1, 1e-15, tolerance_g);
      return 1;
    }
    // both above: a dip below the level?
    double at_c, at_g = 0.;
    double least = least_on_halfedge(c, m_cf, at_c), u = at_c;
    if(o != NO_INDEX)
    {
      const double lg = least_on_halfedge(o, m_cg, at_g);
      if(lg < least)
      {
        least = lg;
        u = 1. - at_g;
      }
    }
    if(!(least < level) || !(u > 0. && u < 1.))
      return 0;
    const double f0 = f(0.), fu = f(u), f1 = f(1.);
    if(!(f0 >= 0. && fu < 0. && f1 >= 0.))
      return 0;
    t[0] = circle_zero(g, 0., u, f0, fu, 1e-15, tolerance_g);
    t[1] = circle_zero(g, u, 1., fu, f1, 1e-15, tolerance_g);
    return 2;
  }

  // The piece of face f from the point (x0, y0) to (x1, y1) (frame of f) along the zero set of phi over the
  // candidates `c` of f: `n` pieces, each interior point found on the line across the chord.
  // `phi(c, px, py, dx, dy, u, next)`: phi at (px, py) + u (dx, dy), with in `next` a better guess of its zero
  // on that line (circle_zero(); NaN if none).
  template <class Phi>
  void interior(Index f, const std::vector<Curve_candidate>& c, double x0, double y0, double x1, double y1, int n,
                Phi phi, std::vector<Curve_point>& out)
  {
    const Face_frame fr(m_mesh, f);
    const double dx = x1 - x0, dy = y1 - y0;
    const double len = std::sqrt(dx * dx + dy * dy);
    if(!(len > 0.))
      return;
    const double nx = -dy / len, ny = dx / len;
    for(int i = 1; i < n; ++i)
    {
      const double s = static_cast<double>(i) / n;
      const double qx = x0 + s * dx, qy = y0 + s * dy;
      // the line q + u (nx, ny) inside the face: left of each edge
      double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
      for(int k = 0; k < 3; ++k)
      {
        const int j = (k + 1) % 3;
        const double ex = fr.x[j] - fr.x[k], ey = fr.y[j] - fr.y[k];
        const double alpha = ex * (qy - fr.y[k]) - ey * (qx - fr.x[k]), beta = ex * ny - ey * nx;
        if(beta > 0.)
          lo = (std::max)(lo, -alpha / beta);
        else if(beta < 0.)
          hi = (std::min)(hi, -alpha / beta);
      }
      double px = qx, py = qy;
      if(lo < hi && std::isfinite(lo) && std::isfinite(hi))
      {
        auto g = [&](double u, double& next) { return phi(c, qx, qy, nx, ny, u, next); };
        double next;
        const double glo = g(lo, next), ghi = g(hi, next);
        if(((glo < 0.) != (ghi < 0.)) && std::isfinite(glo) && std::isfinite(ghi))
        {
          const double u = circle_zero(g, lo, hi, glo, ghi, 1e-15 * (hi - lo + len), m_tolerance_g);
          px = qx + u * nx;
          py = qy + u * ny;
        }
        else
          ++undecided;
      }
      else
        ++undecided;
      out.push_back(point_in_face(f, fr, px, py));
    }
  }

  // the point (x, y) of the frame of f as a curve point
  static Curve_point point_in_face(Index f, const Face_frame& fr, double x, double y)
  {
    Curve_point p;
    p.face = f;
    const double b2 = fr.y[2] != 0. ? y / fr.y[2] : 0.;
    const double b1 = fr.x[1] != 0. ? (x - b2 * fr.x[2]) / fr.x[1] : 0.;
    p.b[0] = 1. - b1 - b2;
    p.b[1] = b1;
    p.b[2] = b2;
    return p;
  }

  // the edge point at abscissa t of the lower half-edge c, seen from face(h) (h = c or its opposite)
  static Curve_point edge_curve_point(Index h, Index c, double t)
  {
    Curve_point p;
    p.face = Mesh_arrays::face(h);
    const double s = h == c ? t : 1. - t;
    const int k = static_cast<int>(h % 3);
    p.b[k] = 1. - s;
    p.b[(k + 1) % 3] = s;
    p.b[(k + 2) % 3] = 0.;
    return p;
  }

  // the number of chords of a piece of length `chord` on arcs of radius at least `radius`, so that the
  // chords are within the tolerance of the arcs
  // |phi| small enough for interior points (circle_zero(); 0: only the bracket's width counts)
  void set_value_tolerance(double t) { m_tolerance_g = t; }

  int number_of_chords(double chord, double radius) const
  {
    if(!(radius > 0.) || !(m_tolerance > 0.) || !(chord > 0.))
      return 1;
    const double n = std::ceil(chord / std::sqrt(4. * radius * m_tolerance));  // (8 r tol, halved: the points are
    // spread evenly along the chord, not along the arc)
    return n < 1. ? 1 : (n > 256. ? 256 : static_cast<int>(n));
  }

  const Curve_field& field() const { return m_field; }

private:
  const Curve_field& m_field;
  const Mesh_arrays& m_mesh;
  double m_tolerance;
  double m_tolerance_g = 0.;
  std::vector<Curve_candidate> m_cf, m_cg;
  std::vector<std::pair<double, double> > m_intervals;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_PIECES_H
