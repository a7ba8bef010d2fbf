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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_TRIANGLE_PROPAGATION_H
#define CGAL_VTP_GEODESICS_INTERNAL_TRIANGLE_PROPAGATION_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/Window_storage.h>

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

inline double window_distance(const Window& w, double x)
{
  const double dx = x - w.sx;
  return w.sigma + std::sqrt(dx * dx + w.sy * w.sy);
}

// Pointwise domination by the endpoint vertices (the ICH filter, applied as trimming): on an edge
// X -> Y of length L, the part of the window where sigma + |S q| > d(X) + |X q| (a prefix, since
// |S q| - |X q| does not increase away from X) or sigma + |S q| > d(Y) + |Y q| (a suffix) carries
// no shortest path: every point beyond is reached at least as fast through X or Y.
// Returns false when nothing is left.
inline bool trim_by_vertices(Window& w, double L, double dX, double dY)
{
  // prefix dominated by X
  if(window_distance(w, w.b1) > dX + w.b1)
    return false;
  if(window_distance(w, w.b0) > dX + w.b0)
  {
    const double D = dX - w.sigma;
    const double den = 2. * (w.sx + D);
    double t = (den > 0.) ? (w.sx * w.sx + w.sy * w.sy - D * D) / den : w.b0;
    if(!(t > w.b0)) t = w.b0;
    if(t > w.b1) t = w.b1;
    w.b0 = t;
  }
  // suffix dominated by Y
  if(window_distance(w, w.b0) > dY + (L - w.b0))
    return false;
  if(window_distance(w, w.b1) > dY + (L - w.b1))
  {
    const double rx = L - w.sx;
    const double D = dY - w.sigma;
    const double den = 2. * (rx + D);
    double t = (den > 0.) ? (rx * rx + w.sy * w.sy - D * D) / den : (L - w.b1);
    double nb1 = L - t;
    if(!(nb1 < w.b1)) nb1 = w.b1;
    if(nb1 < w.b0) nb1 = w.b0;
    w.b1 = nb1;
  }
  return w.b1 > w.b0;
}

// Window w is dominated on [l, r], its overlap with another window: cut that part off when it is
// at an end of w (marking w dead, b1 < b0, when it is all of w).
inline void lose_overlap(Window& w, double l, double r)
{
  const bool starts = (w.b0 == l), ends = (w.b1 == r);
  if(starts && ends)
    w.b1 = w.b0 - 1.;
  else if(starts)
    w.b0 = r;
  else if(ends)
    w.b1 = l;
}

// Pairwise pruning of two windows of the same list (Rule 2), by pointwise comparison on their
// overlap: the part of a window where the other one is strictly shorter carries no shortest
// path and is cut off, when it is at an end of the window (a window is never split in two).
// Near-ties are left alone. Marks a window dead by setting b1 < b0.
inline void prune_pair(Window& a, Window& b)
{
  const double l = (std::max)(a.b0, b.b0);
  const double r = (std::min)(a.b1, b.b1);
  if(!(r > l))
    return;

  const double fal = window_distance(a, l), far = window_distance(a, r);
  const double fbl = window_distance(b, l), fbr = window_distance(b, r);

  // roots of fa(x) = fb(x): sqrt(qa) = beta + sqrt(qb), beta = sigma_b - sigma_a
  double cuts[5];
  int nc = 0;
  cuts[nc++] = l;
  {
    const double beta = b.sigma - a.sigma;
    const double al = 2. * (b.sx - a.sx);
    const double c = a.sx * a.sx + a.sy * a.sy - b.sx * b.sx - b.sy * b.sy - beta * beta;
    const double b2 = beta * beta;
    const double qa = al * al - 4. * b2;
    const double qb = 2. * al * c + 8. * b2 * b.sx;
    const double qc = c * c - 4. * b2 * (b.sx * b.sx + b.sy * b.sy);
    // Candidate break points: the roots and the apex of the quadratic (a double root can be
    // lost to rounding). Extra candidates are harmless: the pieces are classified below by
    // evaluating the distances themselves.
    double roots[3];
    int nr = 0;
    if(qa != 0.)
    {
      roots[nr++] = -qb / (2. * qa);
      const double disc = qb * qb - 4. * qa * qc;
      if(disc > 0.)
      {
        const double sq = std::sqrt(disc);
        const double q = -0.5 * (qb + (qb >= 0. ? sq : -sq));
        if(q != 0.)
        {
          roots[nr++] = q / qa;
          roots[nr++] = qc / q;
        }
      }
    }
    else if(qb != 0.)
      roots[nr++] = -qc / qb;
    std::sort(roots, roots + nr);
    for(int i = 0; i < nr; ++i)
      if(roots[i] > l && roots[i] < r && roots[i] > cuts[nc - 1])
        cuts[nc++] = roots[i];
  }
  cuts[nc++] = r;

  // Sign of fa - fb at the break points (0 for a near-tie). All the roots are break points, so
  // the sign is constant inside each piece: it is the sign at a nonzero end. A piece whose ends
  // disagree (a root lost to rounding) or are both ties is left alone (sign 0).
  int sign[4];
  int end_sign[5];
  const int np = nc - 1;
  for(int i = 0; i < nc; ++i)
  {
    const double fa = (i == 0) ? fal : (i == nc - 1 ? far : window_distance(a, cuts[i]));
    const double fb = (i == 0) ? fbl : (i == nc - 1 ? fbr : window_distance(b, cuts[i]));
    const double tol = 1e-13 * (std::max)(fa, fb);
    end_sign[i] = (fa > fb + tol) ? 1 : ((fb > fa + tol) ? -1 : 0);
  }
  for(int i = 0; i < np; ++i)
  {
    const int s0 = end_sign[i], s1 = end_sign[i + 1];
    sign[i] = (s0 == s1 || s1 == 0) ? s0 : (s0 == 0 ? s1 : 0);
  }

  // a loses where sign > 0, b loses where sign < 0
  for(int who = 0; who < 2; ++who)
  {
    Window& w = who == 0 ? a : b;
    const int lose = who == 0 ? 1 : -1;
    const bool starts = (w.b0 == l);
    const bool ends = (w.b1 == r);
    int first = 0;
    while(first < np && sign[first] == lose) ++first;        // losing pieces from the left
    int last = np;
    while(last > 0 && sign[last - 1] == lose) --last;        // losing pieces from the right
    if(first == np)
    {
      lose_overlap(w, l, r);
      continue;
    }
    if(starts && first > 0)
      w.b0 = cuts[first];
    if(ends && last < np)
      w.b1 = cuts[last];
  }
}

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
// for the ray through C) is sent to C.
inline void emit_child(const Window& w, double p0, double p1,
                       double ox, double oy, double ux, double uy, double lc, double c_pos,
                       double min_length, std::vector<Window>& out)
{
  const double rx = w.sx - ox, ry = w.sy - oy;
  Window c;
  c.sx = rx * ux + ry * uy;
  c.sy = ux * ry - uy * rx;
  c.sigma = w.sigma;
  c.origin = w.origin;
  if(!(c.sy < 0.))
    return; // source on the line of the edge (degenerate face): nothing crosses
  // intersection of the ray from the source through (p, 0) with the line of the child edge
  const double ax0 = p0 - ox, ay0 = -oy;
  const double px0 = ax0 * ux + ay0 * uy, py0 = ux * ay0 - uy * ax0;
  const double ax1 = p1 - ox, ay1 = -oy;
  const double px1 = ax1 * ux + ay1 * uy, py1 = ux * ay1 - uy * ax1;
  double x0, x1;
  {
    const double den = c.sy - py0;
    x0 = (den < 0.) ? c.sx + (px0 - c.sx) * (c.sy / den) : c_pos;
  }
  {
    const double den = c.sy - py1;
    x1 = (den < 0.) ? c.sx + (px1 - c.sx) * (c.sy / den) : c_pos;
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
// The distance the list offers to C (through the best window) is returned. Children are trimmed
// by the vertices later, when their own list is propagated (with the distances of that time).
// The children are appended to out_ac (frame of A -> C) and out_cb (frame of C -> B); when
// `want_ac` / `want_cb` is false (border edge) the corresponding children are not computed.
inline Propagation_result
propagate_list(const Halfedge_geometry& g, const std::vector<Window>& ws,
               double min_ratio,
               bool want_ac, bool want_cb,
               std::vector<Window>& out_ac, std::vector<Window>& out_cb,
               std::vector<double>& scratch_xc)
{
  Propagation_result res;
  const double L = g.length, cx = g.cx, cy = g.cy;
  const std::size_t n = ws.size();
  scratch_xc.resize(n);

  // Rule 1: the window giving the shortest distance to C, and its separating point sp_s.
  double best = std::numeric_limits<double>::infinity();
  std::size_t best_index = 0;
  double sp_s = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Window& w = ws[i];
    const double den = cy - w.sy;
    const double xc = den > 0. ? w.sx + (cx - w.sx) * (-w.sy / den) : cx;
    scratch_xc[i] = xc;
    // straight to C when C is seen through the window; otherwise bent at the end point, which
    // is longer than the straight line (a lower bound that often spares the two square roots)
    const double ex = cx - w.sx, ey = cy - w.sy;
    double dist = w.sigma + std::sqrt(ex * ex + ey * ey);
    double sp = xc;
    if(!(xc >= w.b0 && xc <= w.b1))
    {
      if(!(dist < best))
        continue;
      sp = (std::min)((std::max)(xc, w.b0), w.b1);
      const double d1x = sp - w.sx, d2x = cx - sp;
      dist = w.sigma + std::sqrt(d1x * d1x + w.sy * w.sy) + std::sqrt(d2x * d2x + cy * cy);
    }
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

  for(std::size_t i = 0; i < n; ++i)
  {
    const Window& w = ws[i];
    const double xc = scratch_xc[i];
    if(want_ac && lac > 0.)
    {
      const double p1 = (std::min)(w.b1, (std::min)(xc, sp_s));
      if(p1 > w.b0)
        emit_child(w, w.b0, p1, 0., 0., uax, uay, lac, lac, min_ac, out_ac);
    }
    if(want_cb && lcb > 0.)
    {
      const double p0 = (std::max)(w.b0, (std::max)(xc, sp_s));
      if(w.b1 > p0)
        emit_child(w, p0, w.b1, cx, cy, ubx, uby, lcb, 0., min_cb, out_cb);
    }
  }
  return res;
}

// A point source lying on the edge h itself, at (t, 0) with 0 < t < L, at distance sigma: this is
// how a vertex reaches the face beyond a zero-area face in which it lies inside the opposite edge
// (a window cannot carry it: its source would be on the line of the edge). The whole triangle is
// seen from the point, so each child covers its whole edge. Children are appended as in
// propagate_list(), with the origin `origin`; the distance to C is returned.
inline double propagate_edge_point(const Halfedge_geometry& g, double t, double sigma, Index origin,
                                   bool want_ac, bool want_cb,
                                   std::vector<Window>& out_ac, std::vector<Window>& out_cb)
{
  const double L = g.length, cx = g.cx, cy = g.cy;
  const double lac = g.l_prev, lcb = g.l_next;
  if(want_ac && lac > 0.)
  {
    // frame of A -> C: origin A, direction (cx, cy) / lac
    const double ux = cx / lac, uy = cy / lac;
    Window c;
    c.sx = t * ux;
    c.sy = -uy * t;
    c.sigma = sigma;
    c.origin = origin;
    c.b0 = 0.;
    c.b1 = lac;
    if(c.sy < 0.)
      out_ac.push_back(c);
  }
  if(want_cb && lcb > 0.)
  {
    // frame of C -> B: origin C, direction (L - cx, -cy) / lcb
    const double ux = (L - cx) / lcb, uy = -cy / lcb;
    const double rx = t - cx, ry = -cy;
    Window c;
    c.sx = rx * ux + ry * uy;
    c.sy = ux * ry - uy * rx;
    c.sigma = sigma;
    c.origin = origin;
    c.b0 = 0.;
    c.b1 = lcb;
    if(c.sy < 0.)
      out_cb.push_back(c);
  }
  const double dx = cx - t;
  return sigma + std::sqrt(dx * dx + cy * cy);
}

// Filters a list before propagation: vertex trimming (ICH), tiny windows, pairwise pruning.
inline void filter_list(std::vector<Window>& ws, double L, double dA, double dB, double min_length,
                        std::vector<double>& reach)
{
  std::size_t k = 0;
  for(std::size_t i = 0; i < ws.size(); ++i)
  {
    Window w = ws[i];
    if(trim_by_vertices(w, L, dA, dB) && w.b1 - w.b0 > min_length)
      ws[k++] = w;
  }
  ws.resize(k);
  if(k < 2)
    return;
  // Sorted by start, a window can only overlap earlier windows while the running maximum of
  // their ends exceeds its start: most lists are nearly disjoint, so few pairs are examined.
  // (Skipping a pair is always safe: pruning only removes redundant coverage.)
  std::sort(ws.begin(), ws.end(), [](const Window& x, const Window& y) { return x.b0 < y.b0; });
  reach.resize(k);
  reach[0] = ws[0].b1;
  for(std::size_t i = 1; i < k; ++i)
  {
    for(std::size_t j = i; j-- > 0;)
    {
      if(!(reach[j] > ws[i].b0) || !(ws[i].b1 > ws[i].b0))
        break;
      if(ws[j].b1 > ws[j].b0)
        prune_pair(ws[j], ws[i]);
    }
    reach[i] = (std::max)(reach[i - 1], ws[i].b1);
  }
  k = 0;
  for(std::size_t i = 0; i < ws.size(); ++i)
    if(ws[i].b1 - ws[i].b0 > min_length)
      ws[k++] = ws[i];
  ws.resize(k);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_TRIANGLE_PROPAGATION_H
