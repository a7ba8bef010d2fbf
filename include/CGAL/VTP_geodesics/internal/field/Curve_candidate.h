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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_FIELD_CURVE_CANDIDATE_H
#define CGAL_VTP_GEODESICS_INTERNAL_FIELD_CURVE_CANDIDATE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/field/Kept_field.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A candidate of the field inside a face (Curve_field.h): a point (x, y) of the plane of the face (its frame,
// that of half-edge 3f) with a distance `base`: the candidate's distance at a point p of the face is base +
// |p - (x, y)| (or, for a window, bent at an end of its interval where p is not seen through it).
struct Curve_candidate
{
  double x, y, base;
  Index label;
  // an image seen through a window: the window (gx0, gy0) - (gx1, gy1), which the segment from the image to
  // the point must cross for the candidate to be a path
  bool gated = false;
  double gx0 = 0., gy0 = 0., gx1 = 0., gy1 = 0.;
  // a window that crossed the face (field/Kept_field.h): straight where the segment from the image to the point
  // crosses its interval (gx0, gy0) - (gx1, gy1), else bent at the nearer end (e0, e1: the image to the ends)
  bool window = false;
  double e0 = 0., e1 = 0., low = 0.;  // (low: base plus the image's distance to the interval)
  // a line window (a piece of a source curve, windows/Window.h), or a side of a piece lying in the face: no image;
  // where the parallel through the point crosses the interval in front of it, the distance is base + n . p
  // (n = (nx, ny), the unit direction of the front), else it bends at an end (base + e0 or e1 there)
  bool line = false;
  double nx = 0., ny = 0.;

  // whether a line candidate's front reaches (px, py) straight: the parallel through it crosses the interval,
  // which lies behind it
  bool line_sees(double px, double py) const
  {
    // p - g0 = t (g1 - g0) + s n: seen where 0 <= t <= 1 and s >= 0
    const double ex = gx1 - gx0, ey = gy1 - gy0, rx = px - gx0, ry = py - gy0;
    const double den = ex * ny - ey * nx;
    if(den == 0. || (ex * ry - ey * rx) / den < 0.)
      return false;
    const double t = (rx * ny - ry * nx) / den;
    return t >= 0. && t <= 1.;
  }

  // the candidate's distance at (px, py)
  double distance_at(double px, double py) const
  {
    const double dx = px - x, dy = py - y;
    if(line && line_sees(px, py))
      return (std::max)(0., base + nx * px + ny * py);  // (0 on the curve, to rounding)
    if(window && !line)
    {
      const double ex = gx1 - gx0, ey = gy1 - gy0, rx = gx0 - x, ry = gy0 - y;
      const double den = dx * ey - dy * ex;
      const double t = den != 0. ? (rx * dy - ry * dx) / den : -1.;
      if(!(t >= 0. && t <= 1.))  // (the nearer end gives the lesser of the two)
        return bent_distance(px, py);
    }
    if(line)
      return bent_distance(px, py);
    return base + std::sqrt(dx * dx + dy * dy);
  }

  // the distance of a window's path to (px, py) bent at the nearer end of its interval
  double bent_distance(double px, double py) const
  {
    const double ax = px - gx0, ay = py - gy0, bx = px - gx1, by = py - gy1;
    return base + (std::min)(e0 + std::sqrt(ax * ax + ay * ay), e1 + std::sqrt(bx * bx + by * by));
  }

  // whether the piece of the candidate's distance that holds at (px, py) is its straight front (a line
  // candidate that sees the point: no circle, see active_circle())
  bool front_at(double px, double py) const { return line && line_sees(px, py); }

  // the abscissa u of the line (px, py) + u (dx, dy) where a line candidate's front reaches `level`, from u
  // (the front's value is linear along the line); u itself if the line runs along the front
  double front_on_line(double px, double py, double dx, double dy, double level, double u) const
  {
    const double slope = nx * dx + ny * dy;
    return slope != 0. ? (level - base - nx * px - ny * py) / slope : u;
  }

  // the piece of the candidate's distance that holds at (px, py), as in distance_at(): there the distance is
  // b + |p - (cx, cy)| (the image, or the end of the interval the path bends at)
  void active_circle(double px, double py, double& cx, double& cy, double& b) const
  {
    cx = x;
    cy = y;
    b = base;
    if(!window)
      return;
    if(line)
    {
      // (a front that sees the point has no circle: callers that solve on it ask front_at() first; this one,
      // far behind the point, is tangent to the front there, for a first guess)
      if(line_sees(px, py))
      {
        const double far = 1e4 * (std::abs(px) + std::abs(py) + std::abs(gx1 - gx0) + std::abs(gy1 - gy0) + 1.);
        cx = px - far * nx;
        cy = py - far * ny;
        b = base + nx * px + ny * py - far;
        return;
      }
    }
    else
    {
      const double dx = px - x, dy = py - y;
      const double ex = gx1 - gx0, ey = gy1 - gy0, rx = gx0 - x, ry = gy0 - y;
      const double den = dx * ey - dy * ex;
      const double t = den != 0. ? (rx * dy - ry * dx) / den : -1.;
      if(t >= 0. && t <= 1.)
        return;
    }
    const double ax = px - gx0, ay = py - gy0, bx = px - gx1, by = py - gy1;
    if(e0 + std::sqrt(ax * ax + ay * ay) <= e1 + std::sqrt(bx * bx + by * by))
    {
      cx = gx0;
      cy = gy0;
      b = base + e0;
    }
    else
    {
      cx = gx1;
      cy = gy1;
      b = base + e1;
    }
  }

  // The abscissae u of the line (px, py) + u (dx, dy) (a line through the face) where the candidate's distance
  // is below `level`: one interval (its distance is convex along a line), (lo, hi); false if none.
  bool below_on_line(double px, double py, double dx, double dy, double level, double& lo, double& hi) const
  {
    if(!window)
      return circle_interval(px, py, dx, dy, x, y, level - base, lo, hi);
    double v_lo, v_hi;
    if(line)
      front_seen_on_line(px, py, dx, dy, v_lo, v_hi);
    else
      seen_on_line(px, py, dx, dy, v_lo, v_hi);
    lo = std::numeric_limits<double>::infinity();
    hi = -std::numeric_limits<double>::infinity();
    auto hull = [&](double a0, double a1) {
      if(a0 < a1)
      {
        lo = (std::min)(lo, a0);
        hi = (std::max)(hi, a1);
      }
    };
    double s0, s1;
    if(line)
    {
      // straight, where seen: base + n . (p + u d) < level, a half-line
      const double slope = nx * dx + ny * dy, at = level - base - nx * px - ny * py;
      s0 = -std::numeric_limits<double>::infinity();
      s1 = std::numeric_limits<double>::infinity();
      if(slope > 0.)
        s1 = at / slope;
      else if(slope < 0.)
        s0 = at / slope;
      else if(!(at > 0.))
        s1 = s0;
      hull((std::max)(s0, v_lo), (std::min)(s1, v_hi));
    }
    else if(circle_interval(px, py, dx, dy, x, y, level - base, s0, s1))
      hull((std::max)(s0, v_lo), (std::min)(s1, v_hi));  // straight, where seen
    const double ends[2][3] = { { gx0, gy0, e0 }, { gx1, gy1, e1 } };
    for(const auto& e : ends)  // bent at an end, where not seen
      if(circle_interval(px, py, dx, dy, e[0], e[1], level - base - e[2], s0, s1))
      {
        if(!(v_lo < v_hi))
          hull(s0, s1);
        else
        {
          hull(s0, (std::min)(s1, v_lo));
          hull((std::max)(s0, v_hi), s1);
        }
      }
    return lo < hi;
  }

  // The abscissae u of the line (px, py) + u (dx, dy) (a line through the face, beyond the window) where a
  // window sees it, the path from the image straight (v_lo, v_hi): empty (v_lo >= v_hi) if nowhere.
  void seen_on_line(double px, double py, double dx, double dy, double& v_lo, double& v_hi) const
  {
    // the ray from the image through p(u) crosses the window at num(u) / den(u) of it (den has one sign over
    // the face, which is beyond the window)
    const double ex = gx1 - gx0, ey = gy1 - gy0, rx = gx0 - x, ry = gy0 - y, qx = px - x, qy = py - y;
    const double den0 = qx * ey - qy * ex, den1 = dx * ey - dy * ex;
    const double num0 = rx * qy - ry * qx, num1 = rx * dy - ry * dx;
    const double sign = den0 + 0.5 * den1 < 0. ? -1. : 1.;
    // visible: sign num >= 0 and sign (den - num) >= 0, each linear in u
    v_lo = -std::numeric_limits<double>::infinity();
    v_hi = std::numeric_limits<double>::infinity();
    const double a[2][2] = { { sign * num0, sign * num1 }, { sign * (den0 - num0), sign * (den1 - num1) } };
    for(const auto& l : a)  // l[0] + u l[1] >= 0
    {
      if(l[1] > 0.)
        v_lo = (std::max)(v_lo, -l[0] / l[1]);
      else if(l[1] < 0.)
        v_hi = (std::min)(v_hi, -l[0] / l[1]);
      else if(l[0] < 0.)
        v_lo = std::numeric_limits<double>::infinity();
    }
  }

  // The same for a line candidate: where the parallel through p(u) crosses the interval behind p(u).
  void front_seen_on_line(double px, double py, double dx, double dy, double& v_lo, double& v_hi) const
  {
    // t(u) = cross(p(u) - g0, n) / cross(g1 - g0, n) in [0, 1], s(u) = cross(g1 - g0, p(u) - g0) / cross(g1 - g0, n)
    // >= 0: linear in u
    const double ex = gx1 - gx0, ey = gy1 - gy0, rx = px - gx0, ry = py - gy0;
    const double den = ex * ny - ey * nx;
    v_lo = -std::numeric_limits<double>::infinity();
    v_hi = std::numeric_limits<double>::infinity();
    if(den == 0.)
    {
      v_lo = v_hi;
      return;
    }
    const double t0 = (rx * ny - ry * nx) / den, t1 = (dx * ny - dy * nx) / den;
    const double a[3][2] = { { t0, t1 }, { 1. - t0, -t1 }, { (ex * ry - ey * rx) / den, (ex * dy - ey * dx) / den } };
    for(const auto& l : a)  // l[0] + u l[1] >= 0
    {
      if(l[1] > 0.)
        v_lo = (std::max)(v_lo, -l[0] / l[1]);
      else if(l[1] < 0.)
        v_hi = (std::min)(v_hi, -l[0] / l[1]);
      else if(l[0] < 0.)
        v_lo = std::numeric_limits<double>::infinity();
    }
  }

  // the abscissae u of the line (px, py) + u (dx, dy) at distance less than r from (cx, cy): (lo, hi)
  static bool circle_interval(double px, double py, double dx, double dy, double cx, double cy, double r, double& lo,
                              double& hi)
  {
    const double qx = px - cx, qy = py - cy;
    const double a2 = dx * dx + dy * dy, b = qx * dx + qy * dy, c = qx * qx + qy * qy - r * r;
    const double disc = b * b - a2 * c;
    if(!(r > 0.) || !(disc > 0.) || !(a2 > 0.))
      return false;
    const double q = -(b + (b < 0. ? -1. : 1.) * std::sqrt(disc));  // (the two roots without cancellation)
    const double u1 = q / a2, u2 = c / q;
    lo = (std::min)(u1, u2);
    hi = (std::max)(u1, u2);
    return true;
  }

  // whether the candidate is a path to (px, py)
  bool sees(double px, double py) const
  {
    if(!gated)
      return true;
    const double dx = px - x, dy = py - y, ex = gx1 - gx0, ey = gy1 - gy0;
    const double den = dx * ey - dy * ex;
    if(den == 0.)
      return false;
    const double rx = gx0 - x, ry = gy0 - y;
    const double s = (rx * ey - ry * ex) / den, u = (rx * dy - ry * dx) / den;
    const double eps = 1e-9;
    return s >= -eps && s <= 1. + eps && u >= -eps && u <= 1. + eps;
  }
};

// The windows that crossed face f (field/Kept_field.h), as candidates in the frame of f; `label_of(origin)`: the
// label of an origin.
template <class LabelOf>
void add_crossing_candidates(const Kept_field& field, Index f, const Face_frame& frame,
                             const LabelOf& label_of, std::vector<Curve_candidate>& out)
{
  for(std::size_t i = field.first(f); i < field.last(f); ++i)
  {
    const Field_piece* c = &field.piece_of_face(i);
    const int k = static_cast<int>(c->halfedge % 3);
    Curve_candidate q{0., 0., c->sigma, label_of(c->origin)};
    q.window = true;
    frame.from_edge_frame(k, c->b0, 0., q.gx0, q.gy0);
    frame.from_edge_frame(k, c->b1, 0., q.gx1, q.gy1);
    if(c->sy > 0.)
    {
      // a line window: sigma + n . (p - corner k) in the frame of f
      double ox, oy, tx, ty;
      frame.from_edge_frame(k, 0., 0., ox, oy);
      frame.from_edge_frame(k, c->sx, c->sy, tx, ty);
      q.line = true;
      q.nx = tx - ox;
      q.ny = ty - oy;
      q.base = c->sigma - (q.nx * ox + q.ny * oy);
      q.e0 = c->sigma + c->sx * c->b0 - q.base;
      q.e1 = c->sigma + c->sx * c->b1 - q.base;
      q.low = c->sigma + c->sx * (c->sx > 0. ? c->b0 : c->b1);
      out.push_back(q);
      continue;
    }
    frame.from_edge_frame(k, c->sx, c->sy, q.x, q.y);
    const double a = c->b0 - c->sx, b = c->b1 - c->sx, s2 = c->sy * c->sy;
    q.e0 = std::sqrt(a * a + s2);
    q.e1 = std::sqrt(b * b + s2);
    q.low = c->sigma + (c->sx >= c->b0 && c->sx <= c->b1 ? -c->sy : (std::min)(q.e0, q.e1));
    out.push_back(q);
  }
}

// The side `side` of the piece of a source curve from (x0, y0) to (x1, y1) (frame of its face), as a line
// candidate of that face: the distance to the piece's line where the foot lies on the piece, on that side.
inline Curve_candidate piece_candidate(double x0, double y0, double x1, double y1, int side, Index label)
{
  Curve_candidate q{0., 0., 0., label};
  const double dx = x1 - x0, dy = y1 - y0, len = std::sqrt(dx * dx + dy * dy);
  q.window = true;
  q.line = true;
  q.nx = len > 0. ? -side * dy / len : 0.;
  q.ny = len > 0. ? side * dx / len : 0.;
  q.base = -(q.nx * x0 + q.ny * y0);
  q.gx0 = x0;
  q.gy0 = y0;
  q.gx1 = x1;
  q.gy1 = y1;
  q.e0 = -q.base;  // (base + e0 = 0 at the ends)
  q.e1 = -q.base;
  q.low = 0.;
  return q;
}

// Drops the windows that are nowhere the least of their label in the face: a candidate's distance is convex
// over the face (largest at a corner), so the least over the candidates of a label of their largest corner
// value bounds that label's field everywhere in the face; a window whose lower bound is above it never counts.
// `bound`: scratch.
inline void prune_candidates(const Face_frame& frame, std::vector<Curve_candidate>& out,
                             std::vector<std::pair<Index, double> >& bound)
{
  bound.clear();
  for(const Curve_candidate& c : out)
  {
    double high = 0.;
    for(int k = 0; k < 3; ++k)
      high = (std::max)(high, c.distance_at(frame.x[k], frame.y[k]));
    auto it = std::find_if(bound.begin(), bound.end(), [&](const std::pair<Index, double>& b) { return b.first == c.label; });
    if(it == bound.end())
      bound.emplace_back(c.label, high);
    else
      it->second = (std::min)(it->second, high);
  }
  out.erase(std::remove_if(out.begin(), out.end(), [&](const Curve_candidate& c) {
              if(!c.window)
                return false;
              for(const auto& b : bound)
                if(b.first == c.label)
                  return c.low > b.second * (1. + 1e-12);
              return false;
            }), out.end());
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_FIELD_CURVE_CANDIDATE_H
