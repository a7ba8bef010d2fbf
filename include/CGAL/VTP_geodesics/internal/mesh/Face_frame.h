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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_MESH_FACE_FRAME_H
#define CGAL_VTP_GEODESICS_INTERNAL_MESH_FACE_FRAME_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The corners of face f in the frame of its half-edge 3f: vertex k = source(3f + k) lies at (x[k], y[k])
// (A = (0,0), B = (L,0), C = (cx,cy)). Edge k goes from corner k to corner k+1 (half-edge 3f + k). Used
// where points of a face are placed (sources and targets inside faces), not in the propagation loops.
struct Face_frame
{
  double x[3], y[3];

  Face_frame(const Mesh_arrays& m, Index f)
  {
    const Halfedge_geometry g = m.geometry[3 * f];
    x[0] = 0.; x[1] = g.length; x[2] = g.cx;
    y[0] = 0.; y[1] = 0.;       y[2] = g.cy;
  }

  // the vector of edge k
  double ex(int k) const { return x[(k + 1) % 3] - x[k]; }
  double ey(int k) const { return y[(k + 1) % 3] - y[k]; }

  // the unit direction (ux, uy) of edge k ((1, 0) if it has zero length); returns its length
  double direction(int k, double& ux, double& uy) const
  {
    const double dx = ex(k), dy = ey(k);
    const double e = std::sqrt(dx * dx + dy * dy);
    ux = e > 0. ? dx / e : 1.;
    uy = e > 0. ? dy / e : 0.;
    return e;
  }

  // the point (px, py) of the face frame in the frame of edge k (origin at corner k, x along the edge)
  void to_edge_frame(int k, double px, double py, double& qx, double& qy) const
  {
    double ux, uy;
    direction(k, ux, uy);
    rotate_into(px - x[k], py - y[k], ux, uy, qx, qy);
  }

  // the point (qx, qy) of the frame of edge k in the face frame
  void from_edge_frame(int k, double qx, double qy, double& px, double& py) const
  {
    double ux, uy;
    direction(k, ux, uy);
    px = x[k] + qx * ux - qy * uy;
    py = y[k] + qx * uy + qy * ux;
  }

  // the abscissa along edge k of the projection of (px, py) on its line (0 if the edge has zero length)
  double projection(int k, double px, double py) const
  {
    const double dx = ex(k), dy = ey(k);
    const double e2 = dx * dx + dy * dy;
    return e2 > 0. ? ((px - x[k]) * dx + (py - y[k]) * dy) / std::sqrt(e2) : 0.;
  }

  // [lo, hi] narrowed to the abscissae u where (px, py) + u (dx, dy) is inside the face (left of each edge); the
  // line misses the face (or the range) where lo >= hi after the call
  void clip_line(double px, double py, double dx, double dy, double& lo, double& hi) const
  {
    for(int k = 0; k < 3; ++k)
    {
      const double alpha = ex(k) * (py - y[k]) - ey(k) * (px - x[k]), beta = ex(k) * dy - ey(k) * dx;
      if(beta > 0.)
        lo = (std::max)(lo, -alpha / beta);
      else if(beta < 0.)
        hi = (std::min)(hi, -alpha / beta);
    }
  }
};

// The longest edge k (half-edge 3f + k) of face f, the first one on ties: a point of a face of (almost)
// zero area is taken on it.
inline int longest_edge(const Mesh_arrays& m, Index f)
{
  int k = 0;
  for(int j = 1; j < 3; ++j)
    if(m.geometry[3 * f + j].length > m.geometry[3 * f + k].length)
      k = j;
  return k;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_MESH_FACE_FRAME_H
