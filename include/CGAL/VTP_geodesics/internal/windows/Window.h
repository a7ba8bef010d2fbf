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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_WINDOW_H
#define CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_WINDOW_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The window and its geometry, written once: the propagation (Triangle_propagation.h), the stop rule
// (propagation/Stop_rule.h), the path record and the trace-back (paths/Path_record.h, paths/Path_trace.h)
// all evaluate windows and cross rays with edges through the functions of this file.

// A window on a half-edge h = (A -> B), in the frame of h (A = (0,0), B = (length,0), the face
// of h above the x-axis). It covers [b0, b1] on the edge and carries the geodesics that come,
// straight in the unfolding, from the (pseudo-)source image (sx, sy), sy <= 0, whose own
// distance to the source is sigma. The distance of a point (x, 0) of the window is
// sigma + sqrt((x - sx)^2 + sy^2). The window is waiting to be propagated into face(h).
// `origin` says which (pseudo-)source the image stands for: a vertex index, or the number of
// vertices plus the index of a point source (see Seeding.h); children keep the origin of their parent.
// `angle` is the direction of the x-axis of the frame of h in the turning frame of the origin (the log map,
// log_map/Direction_record.h; 0 when the log map is not asked for).
//
// A window whose source is a line (a piece of a source curve, propagation/Seeding.h) is told by sy > 0: its
// geodesics are parallel in the unfolding, (sx, sy) is their unit direction (sy > 0: into face(h)) and the
// distance of a point (x, y) of the unfolding is sigma + sx x + sy y (sigma: the distance at A). It is
// propagated, trimmed and pruned by the same rules; the functions below evaluate both kinds.
struct Window
{
  double b0, b1;
  double sx, sy;
  double sigma;
  double angle;
  Index origin;
};
// 56 bytes (48 without `angle`: what the log map costs per window; the manual's claims page cites this line).
static_assert(sizeof(Window) == 56, "a window is six doubles and a 32-bit index, padded to 56 bytes");

// Whether w is a line window (see above).
inline bool is_line(const Window& w) { return w.sy > 0.; }

// The change of frame, written once: the vector (rx, ry) in the frame of an edge of unit direction (ux, uy)
// (both given in the same frame): (qx, qy) = (r . u, u x r). The children of a window (their source image
// and the ends of their rays), the points of faces and the walk of the trace-back all use it.
inline void rotate_into(double rx, double ry, double ux, double uy, double& qx, double& qy)
{
  qx = rx * ux + ry * uy;
  qy = ux * ry - uy * rx;
}

// The abscissa where the ray from the image (sx, sy), sy <= 0, to the point (px, py) crosses the x-axis,
// or `fallback` when the point is not above the image (py <= sy: the ray does not cross properly).
inline double ray_crossing(double sx, double sy, double px, double py, double fallback)
{
  const double den = py - sy;
  return den > 0. ? sx + (px - sx) * (-sy / den) : fallback;
}

// The same for window w: where the segment from its image to (px, py) crosses its edge (px itself when the
// point is not above the image); for a line window, where the parallel through (px, py) does.
inline double ray_crossing(const Window& w, double px, double py)
{
  if(is_line(w))
    return px - w.sx * (py / w.sy);
  return ray_crossing(w.sx, w.sy, px, py, px);
}

// The distance window w offers at the point (x, 0) of its edge; distance_of<true> for a line window,
// distance_of<false> for a point window (the hot loops of the lists test the kind once per window).
template <bool line>
inline double distance_of(const Window& w, double x)
{
  if constexpr(line)
    return w.sigma + w.sx * x;
  else
  {
    const double dx = x - w.sx;
    return w.sigma + std::sqrt(dx * dx + w.sy * w.sy);
  }
}

inline double window_distance(const Window& w, double x)
{
  return is_line(w) ? distance_of<true>(w, x) : distance_of<false>(w, x);
}

// The smallest distance that window w offers at a point (px, py), py >= 0, of the face it is about to
// cross: the straight segment from its source image when the point is seen through the window, else
// the path bent at the nearer end of the window (a real path, longer than the straight one).
inline double window_distance_at(const Window& w, double px, double py)
{
  const double xc = ray_crossing(w, px, py);
  const double e = (std::min)((std::max)(xc, w.b0), w.b1);
  const double bx = px - e;
  if(is_line(w))
    return e == xc ? (std::max)(0., w.sigma + w.sx * px + w.sy * py) : w.sigma + w.sx * e + std::sqrt(bx * bx + py * py);
  const double ax = e - w.sx;
  if(e == xc)
  {
    const double dx = px - w.sx, dy = py - w.sy;
    return w.sigma + std::sqrt(dx * dx + dy * dy);
  }
  return w.sigma + std::sqrt(ax * ax + w.sy * w.sy) + std::sqrt(bx * bx + py * py);
}

// Whether the path of w to the point (px, py) is bent (the point is not seen through the window); if so,
// `bend` is the end of the window where it bends (the end nearer to the ray).
inline bool window_bend(const Window& w, double px, double py, double& bend)
{
  const double xc = ray_crossing(w, px, py);
  if(xc >= w.b0 && xc <= w.b1)
    return false;
  bend = (std::min)((std::max)(xc, w.b0), w.b1);
  return true;
}

// Distances a window offers at its two ends, kept next to the window while its list is filtered
// (each is needed by several tests).
struct Window_ends
{
  double f0, f1;  // window_distance(w, w.b0), window_distance(w, w.b1)
};

// The smallest distance a window offers on its own edge: every path it carries beyond is longer.
inline double window_lower_bound(const Window& w)
{
  if(is_line(w))
    return w.sigma + w.sx * (w.sx > 0. ? w.b0 : w.b1);
  const double e = (std::min)((std::max)(w.sx, w.b0), w.b1) - w.sx;
  return w.sigma + std::sqrt(e * e + w.sy * w.sy);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_WINDOW_H
