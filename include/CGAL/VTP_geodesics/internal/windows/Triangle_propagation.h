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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_TRIANGLE_PROPAGATION_H
#define CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_TRIANGLE_PROPAGATION_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/windows/List_filter.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The geometry of one window list crossing one triangle. Everything here is a pure function of
// its arguments (no shared state), so that the parallel scheduling can call it from many threads.
//
// Notation: the list lies on h = (A -> B) and crosses face(h) = (A, B, C). In the frame of h,
// A = (0,0), B = (L,0), C = (cx,cy). Children go to the edge A-C (stored on the half-edge
// A -> C of the neighbouring face) and to the edge C-B (stored on C -> B of the neighbour).

// Output of the propagation of one list across one triangle.
struct Propagation_result
{
  double distance_to_C = std::numeric_limits<double>::infinity();
  std::size_t best = 0;        // the window that gives distance_to_C (when finite)
  std::size_t propagated = 0;
};

// Maps the part [p0, p1] of window w (frame of h) onto the edge X -> Y whose frame is given by
// its origin (ox, oy), unit direction (ux, uy) (both in the frame of h) and length lc; appends
// the child to `out` unless it is shorter than `min_length`. `c_pos` is the position of C on the
// child edge: a ray that does not meet the line of the child edge properly (only by rounding,
// for the ray through C) is sent to C. `turn` is the direction of the child edge in the frame of h (its
// atan2, for the log map; 0 without it).
template <bool mixed>
inline void emit_child(const Window& w, double p0, double p1,
                       double ox, double oy, double ux, double uy, double lc, double c_pos,
                       double min_length, double turn, std::vector<Window>& out)
{
  Window c;
  c.angle = w.angle + turn;
  c.origin = w.origin;
  double px0, py0, px1, py1;
  rotate_into(p0 - ox, -oy, ux, uy, px0, py0);
  rotate_into(p1 - ox, -oy, ux, uy, px1, py1);
  double x0, x1;
  if(mixed && is_line(w))
  {
    // the direction turns with the frame; sigma becomes the distance at the origin of the child edge
    rotate_into(w.sx, w.sy, ux, uy, c.sx, c.sy);
    c.sigma = w.sigma + w.sx * ox + w.sy * oy;
    if(!(c.sy > 0.))
      return; // the front runs along the child edge (degenerate face): nothing crosses
    x0 = px0 - c.sx * (py0 / c.sy);
    x1 = px1 - c.sx * (py1 / c.sy);
  }
  else
  {
    rotate_into(w.sx - ox, w.sy - oy, ux, uy, c.sx, c.sy);
    c.sigma = w.sigma;
    if(!(c.sy < 0.))
      return; // source on the line of the edge (degenerate face): nothing crosses
    // intersection of the ray from the source through (p, 0) with the line of the child edge
    x0 = ray_crossing(c.sx, c.sy, px0, py0, c_pos);
    x1 = ray_crossing(c.sx, c.sy, px1, py1, c_pos);
  }
  if(x0 > x1) std::swap(x0, x1);
  if(x0 < 0.) x0 = 0.;
  if(x1 > lc) x1 = lc;
  if(!(x1 - x0 > min_length))
    return;
  c.b0 = x0;
  c.b1 = x1;
  out.push_back(c);
}

// Propagates the windows `ws` (already trimmed by the vertices and pruned pairwise) of a list on
// h across face(h): Rule 1 ("one angle, two sides") then the children on A-C and C-B.
// `ends` holds the distances at the ends of the windows (as left by filter_list()).
// The distance the list offers to C (through the best window) is returned. Children are trimmed
// by the vertices later, when their own list is propagated (with the distances of that time).
// The children are appended to out_ac (frame of A -> C) and out_cb (frame of C -> B); when
// `want_ac` / `want_cb` is false (border edge) the corresponding children are not computed. With
// `want_angles` (the log map), the children's angles get the change of frame.
template <bool mixed>
inline Propagation_result
propagate_list_of(const Halfedge_geometry& g, const std::vector<Window>& ws,
                  const std::vector<Window_ends>& ends,
                  double min_ratio,
                  bool want_ac, bool want_cb,
                  std::vector<Window>& out_ac, std::vector<Window>& out_cb,
                  std::vector<double>& scratch_xc, bool want_angles)
{
  CGAL_precondition(ends.size() == ws.size());
  Propagation_result res;
  const double L = g.length, cx = g.cx, cy = g.cy;
  const std::size_t n = ws.size();
  scratch_xc.resize(n);

  // Rule 1: the window giving the shortest distance to C, and its separating point sp_s.
  // A window is measured (a square root) only if the square of its distance beyond the part
  // already known (sigma, or the distance at an end) shows that it may beat the best so far.
  double best = std::numeric_limits<double>::infinity();
  std::size_t best_index = 0;
  double sp_s = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Window& w = ws[i];
    const bool line = mixed && is_line(w);  // (tested once per window, in lists that hold line windows)
    const double xc = line ? cx - w.sx * (cy / w.sy) : ray_crossing(w.sx, w.sy, cx, cy, cx);
    scratch_xc[i] = xc;
    double base, sp, ex, ey;
    if(line && xc >= w.b0 && xc <= w.b1)
    {
      // straight to C along the parallel front (never below 0: C on the curve, to rounding)
      const double dist = (std::max)(0., w.sigma + w.sx * cx + w.sy * cy);
      if(dist < best)
      {
        best = dist;
        best_index = i;
        sp_s = xc;
      }
      continue;
    }
    if(xc >= w.b0 && xc <= w.b1)
    {
      // straight to C, seen through the window
      base = w.sigma;
      sp = xc;
      ex = cx - w.sx;
      ey = cy - w.sy;
    }
    else
    {
      // bent at the end of the window closer to the ray through C
      const bool left = !(xc > w.b0);
      base = left ? ends[i].f0 : ends[i].f1;
      sp = left ? w.b0 : w.b1;
      ex = cx - sp;
      ey = cy;
    }
    const double margin = best - base;
    if(!(margin > 0.))
      continue;
    const double e2 = ex * ex + ey * ey;
    if(!(e2 <= margin * margin * (1. + 1e-12)))
      continue;
    const double dist = base + std::sqrt(e2);
    if(dist < best)
    {
      best = dist;
      best_index = i;
      sp_s = sp;
    }
  }
  res.distance_to_C = best;
  res.best = best_index;
  res.propagated = n;

  const double lac = g.l_prev, lcb = g.l_next;
  // frames of the child edges, expressed in the frame of h
  const double uax = lac > 0. ? cx / lac : 0., uay = lac > 0. ? cy / lac : 0.;
  const double ubx = lcb > 0. ? (L - cx) / lcb : 0., uby = lcb > 0. ? -cy / lcb : 0.;
  const double min_ac = min_ratio * lac, min_cb = min_ratio * lcb;
  const double turn_ac = want_angles ? std::atan2(uay, uax) : 0., turn_cb = want_angles ? std::atan2(uby, ubx) : 0.;

  for(std::size_t i = 0; i < n; ++i)
  {
    const Window& w = ws[i];
    const double xc = scratch_xc[i];
    if(want_ac && lac > 0.)
    {
      const double p1 = (std::min)(w.b1, (std::min)(xc, sp_s));
      if(p1 > w.b0)
        emit_child<mixed>(w, w.b0, p1, 0., 0., uax, uay, lac, lac, min_ac, turn_ac, out_ac);
    }
    if(want_cb && lcb > 0.)
    {
      const double p0 = (std::max)(w.b0, (std::max)(xc, sp_s));
      if(w.b1 > p0)
        emit_child<mixed>(w, p0, w.b1, cx, cy, ubx, uby, lcb, 0., min_cb, turn_cb, out_cb);
    }
  }
  return res;
}

// (`lines`: the list may hold line windows, i.e. a source of the run is a curve; without, the list is propagated
// without testing the kind of each window)
inline Propagation_result
propagate_list(const Halfedge_geometry& g, const std::vector<Window>& ws,
               const std::vector<Window_ends>& ends,
               double min_ratio,
               bool want_ac, bool want_cb,
               std::vector<Window>& out_ac, std::vector<Window>& out_cb,
               std::vector<double>& scratch_xc, bool want_angles = false, bool lines = true)
{
  if(lines)
    return propagate_list_of<true>(g, ws, ends, min_ratio, want_ac, want_cb, out_ac, out_cb, scratch_xc, want_angles);
  return propagate_list_of<false>(g, ws, ends, min_ratio, want_ac, want_cb, out_ac, out_cb, scratch_xc, want_angles);
}

// The window from a point source at (t, 0) of h, at distance sigma, that covers the whole edge X -> Y of
// face(h) whose frame is given by its origin (ox, oy) and unit direction (ux, uy) (in the frame of h) and
// its length lc; appended to `out` unless the point lies on the line of the edge. `angle`: the direction of the
// x-axis of h in the turning frame of the origin (the log map).
inline void emit_whole_edge(double t, double sigma, Index origin, double ox, double oy, double ux, double uy,
                            double lc, double angle, std::vector<Window>& out)
{
  Window c;
  rotate_into(t - ox, -oy, ux, uy, c.sx, c.sy);
  c.sigma = sigma;
  c.angle = angle + std::atan2(uy, ux);
  c.origin = origin;
  c.b0 = 0.;
  c.b1 = lc;
  if(c.sy < 0.)
    out.push_back(c);
}

// A point source lying on the edge h itself, at (t, 0) with 0 < t < L, at distance sigma: this is
// how a vertex reaches the face beyond a zero-area face in which it lies inside the opposite edge
// (a window cannot carry it: its source would be on the line of the edge). The whole triangle is
// seen from the point, so each child covers its whole edge. Children are appended as in
// propagate_list(), with the origin `origin` (and `angle`, as emit_whole_edge()); the distance to C is returned.
inline double propagate_edge_point(const Halfedge_geometry& g, double t, double sigma, Index origin, double angle,
                                   bool want_ac, bool want_cb,
                                   std::vector<Window>& out_ac, std::vector<Window>& out_cb)
{
  const double L = g.length, cx = g.cx, cy = g.cy;
  const double lac = g.l_prev, lcb = g.l_next;
  if(want_ac && lac > 0.)  // frame of A -> C: origin A, direction (cx, cy) / lac
    emit_whole_edge(t, sigma, origin, 0., 0., cx / lac, cy / lac, lac, angle, out_ac);
  if(want_cb && lcb > 0.)  // frame of C -> B: origin C, direction (L - cx, -cy) / lcb
    emit_whole_edge(t, sigma, origin, cx, cy, (L - cx) / lcb, -cy / lcb, lcb, angle, out_cb);
  const double dx = cx - t;
  return sigma + std::sqrt(dx * dx + cy * cy);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_TRIANGLE_PROPAGATION_H
