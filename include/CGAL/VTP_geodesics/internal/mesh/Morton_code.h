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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_MESH_MORTON_CODE_H
#define CGAL_VTP_GEODESICS_INTERNAL_MESH_MORTON_CODE_H

#include <CGAL/license/VTP_geodesics.h>

#include <algorithm>
#include <cstdint>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// Morton (Z-order) codes of points in a box: 21 bits per axis, interleaved. The solver numbers the vertices
// by them (mesh/Mesh_import.h; Geodesic_distance_solver::vertices_in_storage_order(), which the benchmark's
// --morton follows).
struct Morton_code
{
  static constexpr double cells = double((1 << 21) - 1);

  // Spreads the 21 low bits of x to every third bit.
  static std::uint64_t spread_bits(std::uint64_t x)
  {
    x &= 0x1fffff;
    x = (x | (x << 32)) & 0x1f00000000ffffULL;
    x = (x | (x << 16)) & 0x1f0000ff0000ffULL;
    x = (x | (x << 8)) & 0x100f00f00f00f00fULL;
    x = (x | (x << 4)) & 0x10c30c30c30c30c3ULL;
    x = (x | (x << 2)) & 0x1249249249249249ULL;
    return x;
  }

  // The code of p in the box of lower corner `lo` whose cells are 1 / `scale` wide (scale: cells over the
  // largest extent of the box). A coordinate below the box, or NaN, counts as the first cell.
  static std::uint64_t of(const double p[3], const double lo[3], double scale)
  {
    std::uint64_t code = 0;
    for(int j = 0; j < 3; ++j)
    {
      const double c = (p[j] - lo[j]) * scale;
      const std::uint64_t cell = c >= 0. ? static_cast<std::uint64_t>((std::min)(c, cells)) : 0;
      code |= spread_bits(cell) << j;
    }
    return code;
  }
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_MESH_MORTON_CODE_H
