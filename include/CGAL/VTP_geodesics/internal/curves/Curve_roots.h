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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_ROOTS_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_ROOTS_H

#include <CGAL/license/VTP_geodesics.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The zeros of the field of a face along a line (Curve_pieces.h), and the point where three circles' distances
// are equal (junctions of cell borders: Curve_border_geometry.h).

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

// The points (x[i], y[i]) where b_i + |(x, y) - c_i| is the same for the three circles (c_i, b_i), i = 0, 1, 2
// (at most two, the nearer to (gx, gy) first): with r = b_0 + rho, |p - c_i| = rho - (b_i - b_0); the
// differences of the squared equations are linear in (p, rho), so p = p0 + rho q, and the first equation is a
// quadratic in rho. Returns how many (none if the centres are on a line).
inline int three_circle_points(const double c[3][2], const double b[3], double gx, double gy, double x[2], double y[2])
{
  // (relative to the guess)
  double cx[3], cy[3], d[3];
  for(int i = 0; i < 3; ++i)
  {
    cx[i] = c[i][0] - gx;
    cy[i] = c[i][1] - gy;
    d[i] = b[i] - b[0];
  }
  // 2 (c_i - c_0) . p - 2 d_i rho = |c_i|^2 - |c_0|^2 - d_i^2, i = 1, 2
  const double a00 = 2. * (cx[1] - cx[0]), a01 = 2. * (cy[1] - cy[0]);
  const double a10 = 2. * (cx[2] - cx[0]), a11 = 2. * (cy[2] - cy[0]);
  const double det = a00 * a11 - a01 * a10;
  const double size = (std::abs(a00) + std::abs(a01)) * (std::abs(a10) + std::abs(a11));
  if(!(std::abs(det) > 1e-12 * size))
    return 0;
  const double k1 = (cx[1] - cx[0]) * (cx[1] + cx[0]) + (cy[1] - cy[0]) * (cy[1] + cy[0]) - d[1] * d[1];
  const double k2 = (cx[2] - cx[0]) * (cx[2] + cx[0]) + (cy[2] - cy[0]) * (cy[2] + cy[0]) - d[2] * d[2];
  const double p0x = (a11 * k1 - a01 * k2) / det, p0y = (-a10 * k1 + a00 * k2) / det;
  const double qx = (a11 * 2. * d[1] - a01 * 2. * d[2]) / det, qy = (-a10 * 2. * d[1] + a00 * 2. * d[2]) / det;
  // |p0 + rho q - c_0|^2 = rho^2
  const double wx = p0x - cx[0], wy = p0y - cy[0];
  const double qa = qx * qx + qy * qy - 1., qb = wx * qx + wy * qy, qc = wx * wx + wy * wy;
  double rho[2];
  int n = 0;
  if(std::abs(qa) <= 1e-14)
  {
    if(qb != 0.)
      rho[n++] = -qc / (2. * qb);
  }
  else
  {
    const double disc = qb * qb - qa * qc;
    if(!(disc >= 0.))
      return 0;
    const double q = -(qb + (qb < 0. ? -1. : 1.) * std::sqrt(disc));
    rho[n++] = q / qa;
    if(q != 0.)
      rho[n++] = qc / q;
  }
  const double least = (std::max)({ 0., d[1], d[2] });
  int found = 0;
  double r2[2];
  for(int i = 0; i < n; ++i)
  {
    const double scale = std::abs(rho[i]) + std::abs(least);
    if(!(rho[i] >= least - 1e-12 * scale))
      continue;
    const double px = p0x + rho[i] * qx, py = p0y + rho[i] * qy;
    x[found] = px + gx;
    y[found] = py + gy;
    r2[found++] = px * px + py * py;
  }
  if(found == 2 && r2[1] < r2[0])
  {
    std::swap(x[0], x[1]);
    std::swap(y[0], y[1]);
  }
  return found;
}

// the point of three_circle_points() nearest to (gx, gy); false if none
inline bool three_circle_point(const double c[3][2], const double b[3], double gx, double gy, double& x, double& y)
{
  double xs[2], ys[2];
  if(three_circle_points(c, b, gx, gy, xs, ys) == 0)
    return false;
  x = xs[0];
  y = ys[0];
  return true;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_ROOTS_H
