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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_MARCH_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_MARCH_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/curves/Curve_roots.h>
#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// An isoline followed inside a face, step by step, where the points on lines across its chord fail (the field of
// the face has a ridge, the cut locus, and the curve is not a graph over its chord: Curve_extraction.h tries this
// when both ways of joining the crossings leave points undecided). The field is the least of circles' distances
// (each candidate's is convex), so near a point of the isoline the curve is nearly the circle that holds there:
// each step goes `step` along its tangent, then back onto the level along the gradient at the point it left
// (a bracket of the level on that line, the zero by circle_zero()); a step without a bracket is halved.
//
// `phi(x, y, gx, gy, cx, cy, b)`: the field minus the level at (x, y) of the face's frame, the unit gradient (gx, gy)
// there and the circle that holds (centre (cx, cy), base b; the field is b + |(x, y) - (cx, cy)| there); NaN
// where no candidate holds. From (x0, y0), a crossing of the face's boundary, into the face: the points inside go
// to `points`, the point where the march leaves the face to (x1, y1). Returns false if a step finds no bracket
// even when short, or after `max_steps` steps.
template <class Phi>
bool march_isoline(const Face_frame& fr, Phi phi, double level, double x0, double y0, double step, double tolerance_g,
                   std::vector<std::pair<double, double> >& points, double& x1, double& y1, int max_steps = 4096)
{
  // the signed distances of (x, y) to the lines of the edges, positive inside (the corners are counterclockwise)
  auto side = [&fr](int k, double x, double y) {
    const int j = (k + 1) % 3;
    const double ex = fr.x[j] - fr.x[k], ey = fr.y[j] - fr.y[k];
    const double e = std::sqrt(ex * ex + ey * ey);
    return e > 0. ? (ex * (y - fr.y[k]) - ey * (x - fr.x[k])) / e : 0.;
  };
  auto inside = [&](double x, double y) { return side(0, x, y) >= 0. && side(1, x, y) >= 0. && side(2, x, y) >= 0.; };
  if(!(step > 0.) || !(fr.y[2] > 0.))
    return false;
  double px = x0, py = y0;
  // into the face first: along the inward normal of the edge the start lies on (the nearest)
  int start_edge = 0;
  for(int k = 1; k < 3; ++k)
    if(std::abs(side(k, px, py)) < std::abs(side(start_edge, px, py)))
      start_edge = k;
  const int start_next = (start_edge + 1) % 3;
  double dir_x = -(fr.y[start_next] - fr.y[start_edge]), dir_y = fr.x[start_next] - fr.x[start_edge];
  for(int n = 0; n < max_steps; ++n)
  {
    double gx = 0., gy = 0., cx = 0., cy = 0., b = 0.;
    const double f0 = phi(px, py, gx, gy, cx, cy, b);
    if(!(f0 == f0))
      return false;
    // the tangent that goes on in the direction of the march
    double tx = -gy, ty = gx;
    if(tx * dir_x + ty * dir_y < 0.)
    {
      tx = -tx;
      ty = -ty;
    }
    bool moved = false;
    for(double h = step; h > 1e-9 * step && !moved; h *= 0.5)
    {
      const double qx = px + h * tx, qy = py + h * ty;
      if(!inside(qx, qy))
      {
        // leaving: where the step meets the boundary (the caller joins it to the crossing there)
        double s = 1.;
        for(int k = 0; k < 3; ++k)
        {
          const double sp = side(k, px, py), sq = side(k, qx, qy);
          if(sq < 0. && sp >= 0.)
            s = (std::min)(s, sp / (sp - sq));
        }
        if(s * h <= 0.25 * step || h <= 0.25 * step)
        {
          x1 = px + s * h * tx;
          y1 = py + s * h * ty;
          return true;
        }
        continue;  // a shorter step, to come closer to the boundary on the curve first
      }
      // back onto the level along the gradient at (px, py): the line (qx, qy) + u (gx, gy), u in [-h, h] in the face
      double lo = -h, hi = h;
      fr.clip_line(qx, qy, gx, gy, lo, hi);
      if(!(lo < hi))
        continue;
      auto g = [&](double u, double& next) {
        double ggx = 0., ggy = 0., ccx = 0., ccy = 0., bb = 0.;
        const double v = phi(qx + u * gx, qy + u * gy, ggx, ggy, ccx, ccy, bb);
        next = v == v ? circle_on_line(qx, qy, gx, gy, ccx, ccy, bb, level, u)
                      : std::numeric_limits<double>::quiet_NaN();
        return v;
      };
      double next;
      const double glo = g(lo, next), ghi = g(hi, next);
      if(!(glo < 0. && ghi > 0.) && !(glo > 0. && ghi < 0.))
        continue;
      const double u = circle_zero(g, lo, hi, glo, ghi, 1e-15 * (hi - lo + step), tolerance_g);
      const double nx = qx + u * gx, ny = qy + u * gy;
      if(!(nx != px || ny != py))
        continue;
      dir_x = nx - px;
      dir_y = ny - py;
      px = nx;
      py = ny;
      points.emplace_back(px, py);
      moved = true;
    }
    if(!moved)
      return false;
  }
  return false;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_MARCH_H
