// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_COLOUR_MAP_H
#define VTP_GEODESICS_APP_COLOUR_MAP_H

// The colour map of distances: matplotlib's perceptually uniform "viridis" (dark blue at 0, yellow at the
// largest distance), sampled at 256 points into a header generated at configure time (see
// make_colour_map.py); unreachable vertices are grey.

#include "generated_colour_map.h"

#include <cmath>

namespace vtp_geodesics_app {

struct Rgb
{
  unsigned char r, g, b;
};

// Grey, for unreachable vertices (and NaN).
inline Rgb unreachable_colour() { return Rgb{ 150, 150, 150 }; }

// The colour of `t` in [0, 1] (clamped), interpolated between the 256 samples.
inline Rgb colour_of_fraction(double t)
{
  if(std::isnan(t))
    return unreachable_colour();
  t = t < 0. ? 0. : (t > 1. ? 1. : t);
  const double x = t * 255.;
  const int i = x >= 255. ? 254 : static_cast<int>(x);
  const double w = x - i;
  const unsigned char* a = generated::colour_map[i];
  const unsigned char* b = generated::colour_map[i + 1];
  auto mix = [w](unsigned char u, unsigned char v) {
    return static_cast<unsigned char>((1. - w) * u + w * v + 0.5);
  };
  return Rgb{ mix(a[0], b[0]), mix(a[1], b[1]), mix(a[2], b[2]) };
}

// The colour of a distance `d` on a scale from 0 to `max_distance`; grey if `d` is not finite.
inline Rgb colour_of_distance(double d, double max_distance)
{
  if(!std::isfinite(d))
    return unreachable_colour();
  return colour_of_fraction(max_distance > 0. ? d / max_distance : 0.);
}

inline const char* colour_map_name() { return generated::colour_map_name; }
inline const char* colour_map_source() { return generated::colour_map_source; }

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_COLOUR_MAP_H
