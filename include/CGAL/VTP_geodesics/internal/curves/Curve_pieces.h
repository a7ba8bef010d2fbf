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

#include <CGAL/VTP_geodesics/internal/field/Curve_field.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_envelope.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_polylines.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_roots.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

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
  // junctions of three cells whose Newton step left the face (junction())
  std::size_t junction_fallbacks = 0;

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
        const Curve_candidate& q = (best_side == 0 ? m_cf : m_cg)[static_cast<std::size_t>(best_which)];
        if(q.front_at(l[0] + u * l[2], l[1] + u * l[3]))
          next = q.front_on_line(l[0], l[1], l[2], l[3], level, u);
        else
        {
          double cx, cy, b;
          q.active_circle(l[0] + u * l[2], l[1] + u * l[3], cx, cy, b);
          next = circle_on_line(l[0], l[1], l[2], l[3], cx, cy, b, level, u);
        }
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
      // the line q + u (nx, ny) inside the face
      double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
      fr.clip_line(qx, qy, nx, ny, lo, hi);
      double px = qx, py = qy;
      if(lo < hi && std::isfinite(lo) && std::isfinite(hi))
      {
        auto g = [&](double u, double& next) { return phi(c, qx, qy, nx, ny, u, next); };
        double next;
        double a = lo, b = hi, ga = g(lo, next), gb = g(hi, next);
        if(!((ga < 0.) != (gb < 0.)) && std::isfinite(ga) && std::isfinite(gb))
          bracket_near(g, lo, hi, a, b, ga, gb);  // the same sign at both ends: two zeros, or none, on the line
        if(((ga < 0.) != (gb < 0.)) && std::isfinite(ga) && std::isfinite(gb))
        {
          const double u = circle_zero(g, a, b, ga, gb, 1e-15 * (hi - lo + len), m_tolerance_g);
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

  // A sign change of g on [lo, hi], whose ends have the same sign, nearest to u = 0 (the chord): from 32 samples
  // (where a ridge of the field, the cut locus, comes near the chord, the line meets the curve twice); (a, b)
  // and g there, or left as they are if no sample changes sign.
  template <class G>
  static void bracket_near(G& g, double lo, double hi, double& a, double& b, double& ga, double& gb)
  {
    const int samples = 32;
    double best = std::numeric_limits<double>::infinity();
    double u0 = lo, g0 = ga, next;
    for(int k = 1; k <= samples; ++k)
    {
      const double u1 = k == samples ? hi : lo + (hi - lo) * k / samples;
      const double g1 = k == samples ? gb : g(u1, next);
      if(!std::isfinite(g1))
        return;
      const double away = (std::min)(std::abs(u0), std::abs(u1));
      if((g0 < 0.) != (g1 < 0.) && away < best)
      {
        best = away;
        a = u0;
        b = u1;
        ga = g0;
        gb = g1;
      }
      u0 = u1;
      g0 = g1;
    }
  }

  // The junction of three cells in face f: Newton's method on (value_l0 - value_l1, value_l1 - value_l2) = 0
  // from (x, y), kept in the face
  void junction(Index f, const std::vector<Curve_candidate>& c, const Index l[3], double& x, double& y)
  {
    const Face_frame fr(m_mesh, f);
    auto g = [&](double px, double py, double& g0, double& g1) {
      const double v0 = Curve_field::value(c, px, py, l[0]), v1 = Curve_field::value(c, px, py, l[1]),
                   v2 = Curve_field::value(c, px, py, l[2]);
      g0 = v0 - v1;
      g1 = v1 - v2;
    };
    const double scale = std::abs(fr.x[1]) + std::abs(fr.x[2]) + std::abs(fr.y[2]);
    const double step = 1e-7 * scale;
    for(int i = 0; i < 30; ++i)
    {
      double g0, g1, a0, a1, b0, b1;
      g(x, y, g0, g1);
      if(std::abs(g0) + std::abs(g1) <= 1e-15 * scale)
        break;
      g(x + step, y, a0, a1);
      g(x, y + step, b0, b1);
      const double j00 = (a0 - g0) / step, j10 = (a1 - g1) / step, j01 = (b0 - g0) / step, j11 = (b1 - g1) / step;
      const double det = j00 * j11 - j01 * j10;
      if(!(std::abs(det) > 0.) || !std::isfinite(det))
        break;
      const double nx = x - (j11 * g0 - j01 * g1) / det, ny = y - (-j10 * g0 + j00 * g1) / det;
      // keep the point in the face
      const Curve_point p = point_in_face(f, fr, nx, ny);
      if(!(p.b[0] >= -1e-9 && p.b[1] >= -1e-9 && p.b[2] >= -1e-9))
      {
        ++junction_fallbacks;
        break;
      }
      x = nx;
      y = ny;
    }
  }

  // The changes of the label of the least candidate along the lower half-edge c (abscissae from source(c), in
  // order), from the candidates of its two faces (Label_envelope: exact), where its vertices have labels la and
  // lb: a change is added at an end where the least has another label (a tie at the vertex). False if the
  // sweep gave up (rounding: `out` holds what it found, with the ends' changes).
  bool border_changes(Index c, Index la, Index lb, std::vector<Label_change>& out)
  {
    const Index o = m_mesh.opposite[c];
    double line[2][4];
    edge_candidates(c, line);
    const double length = m_mesh.geometry[c].length;
    const double scale = (std::max)(m_field.distance(m_mesh.source[c]),
                                    m_field.distance(m_mesh.source[Mesh_arrays::next(c)])) + length;
    m_envelope.reset(0., 1., length * length, scale);
    m_envelope.add(m_cf, line[0][0], line[0][1], line[0][2], line[0][3]);
    if(o != NO_INDEX)
      m_envelope.add(m_cg, line[1][0], line[1][1], line[1][2], line[1][3]);
    Index first, last;
    const bool done = m_envelope.changes(la, out, first, last);
    if(first == NO_INDEX)  // (no candidate: cannot happen with reached corners)
    {
      if(la != lb)
        out.push_back(Label_change{ 0.5, la, lb });
      return false;
    }
    if(first != la)
      out.insert(out.begin(), Label_change{ 0., la, first });
    if(last != lb)
      out.push_back(Label_change{ 1., last, lb });
    return done;
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
  double value_tolerance() const { return m_tolerance_g; }

private:
  const Curve_field& m_field;
  const Mesh_arrays& m_mesh;
  double m_tolerance;
  double m_tolerance_g = 0.;
  std::vector<Curve_candidate> m_cf, m_cg;
  std::vector<std::pair<double, double> > m_intervals;
  Label_envelope m_envelope;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_PIECES_H
