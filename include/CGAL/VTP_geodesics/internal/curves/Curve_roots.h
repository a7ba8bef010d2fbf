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

#include <cmath>
#include <limits>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The zeros of the field of a face along a line (Curve_pieces.h).

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

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_ROOTS_H
