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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_FAST_ATAN2_H
#define CGAL_VTP_GEODESICS_INTERNAL_FAST_ATAN2_H

#include <CGAL/license/VTP_geodesics.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// atan2 for the log map's inner loops (the angles of the corners a window list crosses, of the rays that
// reach a vertex, of the fans of pseudo-sources), within a few units in the last place of the correctly
// rounded value (test: FastAtan2.*): the libm function is correctly rounded at about three times the cost,
// and the log map calls it several times per vertex.
//
// The vector is folded into the first octant (0 <= r = min / max <= 1); r is split as the nearest
// c = k / 16 plus the rest, atan r = atan c + atan t with t = (r - c) / (1 + c r), |t| <= 1 / 32: atan c from
// a table (the values rounded to nearest from 21 significant digits), atan t from its odd series up to t^11
// (the first term left out, t^13 / 13, is below 1e-19 times t). Zeros, infinities and NaNs go to std::atan2
// (so the signs of zeros give the same angles as there).
inline double fast_atan2(double y, double x)
{
  static const double atan_k16[17] = {
    0.0,
    0.062418809995957348474,
    0.124354994546761435031,
    0.185347949995694764886,
    0.244978663126864154172,
    0.302884868374971405561,
    0.358770670270572220396,
    0.4124104415973873069,
    0.463647609000806116214,
    0.512389460310737706667,
    0.558599315343562435972,
    0.602287346134964181682,
    0.643501108793284386803,
    0.682316554874748078256,
    0.718829999621624505417,
    0.753151280962194389525,
    0.785398163397448309616};
  const double ax = std::fabs(x), ay = std::fabs(y);
  const bool steep = ay > ax;
  const double num = (std::min)(ax, ay), den = (std::max)(ax, ay);
  if(!(num > 0.) || !(ax + ay < HUGE_VAL))  // a zero, an infinity or a NaN (or a sum that overflows)
    return std::atan2(y, x);
  const double r = num / den;
  const int k = static_cast<int>(r * 16. + 0.5);
  const double c = k * (1. / 16.);
  const double t = (r - c) / (1. + c * r);
  const double s = t * t;
  const double a = atan_k16[k] +
                   (t + t * s * (-1. / 3. + s * (1. / 5. + s * (-1. / 7. + s * (1. / 9. + s * (-1. / 11.))))));
  // the octant, without branches: pi / 2 - a when steep, then pi - that when x < 0, then the sign of y
  const double b = (steep ? 1.57079632679489661923 : 0.) + (steep ? -a : a);
  const double q = (x < 0. ? 3.14159265358979323846 : 0.) + (x < 0. ? -b : b);
  return std::copysign(q, y);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_FAST_ATAN2_H
