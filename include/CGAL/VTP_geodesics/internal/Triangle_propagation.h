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

// Distances a window offers at its two ends, kept next to the window while its list is filtered
// (each is needed by several tests).
struct Window_ends
{
  double f0, f1;  // window_distance(w, w.b0), window_distance(w, w.b1)
};

// Pointwise domination by the endpoint vertices (the ICH filter, applied as trimming): on an edge
// X -> Y of length L, the part of the window where sigma + |S q| > d(X) + |X q| (a prefix, since
// |S q| - |X q| does not increase away from X) or sigma + |S q| > d(Y) + |Y q| (a suffix) carries
// no shortest path: every point beyond is reached at least as fast through X or Y.
// Returns false when nothing is left; otherwise `e` holds the distances at the new ends.
inline bool trim_by_vertices(Window& w, Window_ends& e, double L, double dX, double dY)
{
  e.f0 = window_distance(w, w.b0);
  e.f1 = window_distance(w, w.b1);
  // prefix dominated by X
  if(e.f1 > dX + w.b1)
    return false;
  if(e.f0 > dX + w.b0)
  {
    const double D = dX - w.sigma;
    const double den = 2. * (w.sx + D);
    double t = (den > 0.) ? (w.sx * w.sx + w.sy * w.sy - D * D) / den : w.b0;
    if(!(t > w.b0)) t = w.b0;
    if(t > w.b1) t = w.b1;
    if(t != w.b0)
    {
      w.b0 = t;
      e.f0 = window_distance(w, t);
    }
  }
  // suffix dominated by Y
  if(e.f0 > dY + (L - w.b0))
    return false;
  if(e.f1 > dY + (L - w.b1))
  {
    const double rx = L - w.sx;
    const double D = dY - w.sigma;
    const double den = 2. * (rx + D);
    double t = (den > 0.) ? (rx * rx + w.sy * w.sy - D * D) / den : (L - w.b1);
    double nb1 = L - t;
    if(!(nb1 < w.b1)) nb1 = w.b1;
    if(nb1 < w.b0) nb1 = w.b0;
    if(nb1 != w.b1)
    {
      w.b1 = nb1;
      e.f1 = window_distance(w, nb1);
    }
  }
  return w.b1 > w.b0;
}

inline bool trim_by_vertices(Window& w, double L, double dX, double dY)
{
  Window_ends e;
  return trim_by_vertices(w, e, L, dX, dY);
}

// Sign of fa - fb: 1, -1, or 0 for a near-tie.
inline int compare_distances(double fa, double fb)
{
  const double tol = 1e-13 * (std::max)(fa, fb);
  return (fa > fb + tol) ? 1 : ((fb > fa + tol) ? -1 : 0);
}

// Sign of window_distance(w, x) - F, as compare_distances() gives it (with the tolerance taken
// from F), without the square root.
inline int compare_distance_to(const Window& w, double x, double F)
{
  const double dx = x - w.sx;
  const double q = dx * dx + w.sy * w.sy;
  const double tol = 1e-13 * F;
  const double above = F + tol - w.sigma;   // w is longer where sqrt(q) > above
  if(above < 0. || q > above * above)
    return 1;
  const double below = F - tol - w.sigma;   // w is shorter where sqrt(q) < below
  if(below > 0. && q < below * below)
    return -1;
  return 0;
}

// Sign of window_distance(a, x) - window_distance(b, x), where at least one of them is known
// (fa, fb; `known_a`, `known_b`): one square root at most.
inline int compare_at(const Window& a, bool known_a, double fa, const Window& b, bool known_b, double fb, double x)
{
  if(known_a && known_b)
    return compare_distances(fa, fb);
  if(known_b)
    return compare_distance_to(a, x, fb);
  CGAL_assertion(known_a);
  return -compare_distance_to(b, x, fa);
}

// Whether the quadratic q(x) = (qa x + qb) x + qc may vanish inside (l, r); false only if it has
// the same nonzero sign at l, r and (when it lies inside) at its apex. No square root.
inline bool may_vanish_inside(double qa, double qb, double qc, double l, double r)
{
  const double ql = (qa * l + qb) * l + qc;
  const double qr = (qa * r + qb) * r + qc;
  if(!(ql * qr > 0.))
    return true;
  if(qa != 0.)
  {
    const double xm = -qb / (2. * qa);
    if(xm > l && xm < r)
    {
      const double qm = (qa * xm + qb) * xm + qc;
      if(!(qm * ql > 0.))
        return true;
    }
  }
  return false;
}

// Window w (with the distances e at its ends) is dominated on [l, r], its overlap with another
// window, where it offers f_l at l and f_r at r: cut that part off when it is at an end of w
// (marking w dead, b1 < b0, when it is all of w).
inline void lose_overlap(Window& w, Window_ends& e, double l, double r, double f_l, double f_r)
{
  const bool starts = (w.b0 == l), ends = (w.b1 == r);
  if(starts && ends)
    w.b1 = w.b0 - 1.;
  else if(starts)
  {
    w.b0 = r;
    e.f0 = f_r;
  }
  else if(ends)
  {
    w.b1 = l;
    e.f1 = f_l;
  }
}

// The right part of a window that the pruning cuts in two, with the distances at its ends: it goes
// back into the sweep of filter_list() at its start.
struct Window_piece
{
  Window w;
  Window_ends e;
};

// Order of the pending pieces (a heap whose top is the piece that starts first).
inline bool starts_later(const Window_piece& x, const Window_piece& y) { return x.w.b0 > y.w.b0; }

// Pairwise pruning of two windows of the same list (Rule 2), by pointwise comparison on their
// overlap: the part of a window where the other one is strictly shorter carries no shortest
// path and is cut off when it is at an end of the window. A window that loses the whole overlap
// with a window lying inside it is cut in two: it keeps its left part and its right part is
// pushed onto `pieces` (a heap, see starts_later()). Otherwise a window that loses only a middle
// piece is kept whole. Near-ties are left alone, and so may be any pair: skipping a pair only
// leaves redundant coverage. Marks a window dead by setting b1 < b0. `ea` and `eb` are the
// distances at the ends of a and b, updated with the cuts.
//
// fa(x) = fb(x) is a quadratic equation q(x) = 0 once its square roots are squared away; its
// roots (and its apex: a double root can be lost to rounding) cut the overlap into pieces on
// which fa - fb has one sign, found by evaluating the distances themselves. The common cases
// are settled first from the signs at the ends of the overlap alone: a near-tie at both ends (two
// windows that meet at a point they reach at the same distance), or the same window shorter at
// both ends (the other loses the whole overlap, provided q keeps its sign).
//
// prune_pair() settles the ties and leaves the others to settle_pair().
inline void settle_pair(Window& a, Window_ends& ea, Window& b, Window_ends& eb, double l, double r, int sl, int sr,
                        std::vector<Window_piece>& pieces)
{
  const bool al = (l == a.b0), bl = (l == b.b0), ar = (r == a.b1), br = (r == b.b1);
  // q(x): sqrt(Qa) = beta + sqrt(Qb), beta = sigma_b - sigma_a, squared twice
  const double beta = b.sigma - a.sigma;
  const double lin = 2. * (b.sx - a.sx);
  const double c = a.sx * a.sx + a.sy * a.sy - b.sx * b.sx - b.sy * b.sy - beta * beta;
  const double b2 = beta * beta;
  const double qa = lin * lin - 4. * b2;
  const double qb = 2. * lin * c + 8. * b2 * b.sx;
  const double qc = c * c - 4. * b2 * (b.sx * b.sx + b.sy * b.sy);

  // The same window shorter at both ends, or at one end with a near-tie at the other: if q keeps
  // its sign inside, so does fa - fb, and the other window loses the whole overlap.
  const int s = (sl != 0) ? sl : sr;
  if((sl == sr || sl == 0 || sr == 0) && !may_vanish_inside(qa, qb, qc, l, r))
  {
    // the distance at the new end of the loser is needed
    Window& w = s > 0 ? a : b;
    Window_ends& e = s > 0 ? ea : eb;
    const bool starts = (w.b0 == l), ends = (w.b1 == r);
    if(!starts && !ends)
    {
      // the overlap lies inside w: cut w in two (the parts keep their own lists of children,
      // which no longer overlap those of the other window, and are pruned no more against them)
      Window_piece piece;
      piece.w = w;
      piece.w.b0 = r;
      piece.e.f0 = window_distance(w, r);
      piece.e.f1 = e.f1;
      pieces.push_back(piece);
      std::push_heap(pieces.begin(), pieces.end(), starts_later);
      e.f1 = window_distance(w, l);
      w.b1 = l;
      return;
    }
    if(starts && ends)
      w.b1 = w.b0 - 1.;
    else if(starts)
    {
      e.f0 = window_distance(w, r);
      w.b0 = r;
    }
    else
    {
      e.f1 = window_distance(w, l);
      w.b1 = l;
    }
    return;
  }
  const double fal = al ? ea.f0 : window_distance(a, l);
  const double fbl = bl ? eb.f0 : window_distance(b, l);
  const double far = ar ? ea.f1 : window_distance(a, r);
  const double fbr = br ? eb.f1 : window_distance(b, r);
  CGAL_assertion(compare_distances(fal, fbl) == sl || sl == 0 || compare_distances(fal, fbl) == 0);

  // Candidate break points: the roots and the apex of the quadratic. Extra candidates are
  // harmless: the pieces are classified below by evaluating the distances themselves.
  double cuts[5];
  int nc = 0;
  cuts[nc++] = l;
  {
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
    // sort the (at most 3) candidates
    if(nr > 1 && roots[1] < roots[0]) std::swap(roots[0], roots[1]);
    if(nr > 2 && roots[2] < roots[1]) std::swap(roots[1], roots[2]);
    if(nr > 1 && roots[1] < roots[0]) std::swap(roots[0], roots[1]);
    for(int i = 0; i < nr; ++i)
      if(roots[i] > l && roots[i] < r && roots[i] > cuts[nc - 1])
        cuts[nc++] = roots[i];
  }
  cuts[nc++] = r;

  // Distances and sign of fa - fb at the break points. All the roots are break points, so the
  // sign is constant inside each piece: it is the sign at a nonzero end. A piece whose ends
  // disagree (a root lost to rounding) or are both ties is left alone (sign 0).
  double fa[5], fb[5];
  int end_sign[5];
  fa[0] = fal;
  fb[0] = fbl;
  end_sign[0] = compare_distances(fal, fbl);
  for(int i = 1; i < nc - 1; ++i)
  {
    fa[i] = window_distance(a, cuts[i]);
    fb[i] = window_distance(b, cuts[i]);
    end_sign[i] = compare_distances(fa[i], fb[i]);
  }
  fa[nc - 1] = far;
  fb[nc - 1] = fbr;
  end_sign[nc - 1] = compare_distances(far, fbr);
  int sign[4];
  const int np = nc - 1;
  for(int i = 0; i < np; ++i)
  {
    const int s0 = end_sign[i], s1 = end_sign[i + 1];
    sign[i] = (s0 == s1 || s1 == 0) ? s0 : (s0 == 0 ? s1 : 0);
  }

  // a loses where sign > 0, b loses where sign < 0
  for(int who = 0; who < 2; ++who)
  {
    Window& w = who == 0 ? a : b;
    Window_ends& e = who == 0 ? ea : eb;
    const double* f = who == 0 ? fa : fb;
    const int lose = who == 0 ? 1 : -1;
    const bool starts = (w.b0 == l);
    const bool ends = (w.b1 == r);
    int first = 0;
    while(first < np && sign[first] == lose) ++first;        // losing pieces from the left
    int last = np;
    while(last > 0 && sign[last - 1] == lose) --last;        // losing pieces from the right
    if(first == np)
    {
      lose_overlap(w, e, l, r, f[0], f[np]);
      continue;
    }
    if(starts && first > 0)
    {
      w.b0 = cuts[first];
      e.f0 = f[first];
    }
    if(ends && last < np)
    {
      w.b1 = cuts[last];
      e.f1 = f[last];
    }
  }
}

inline void prune_pair(Window& a, Window_ends& ea, Window& b, Window_ends& eb, std::vector<Window_piece>& pieces)
{
  const double l = (std::max)(a.b0, b.b0);
  const double r = (std::min)(a.b1, b.b1);
  if(!(r > l))
    return;
  // l is the start of a or b, r the end of a or b: there the distance is known
  const int sl = compare_at(a, l == a.b0, ea.f0, b, l == b.b0, eb.f0, l);
  const int sr = compare_at(a, r == a.b1, ea.f1, b, r == b.b1, eb.f1, r);
  if(sl == 0 && sr == 0)
    return;
  settle_pair(a, ea, b, eb, l, r, sl, sr, pieces);
}

// Whether a window of a list being filtered is still alive (filter_list() marks the windows
// it cuts away by making them shorter than `min_length`).
inline bool is_alive(const Window& w, double min_length) { return w.b1 - w.b0 > min_length; }

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
// `ends` holds the distances at the ends of the windows (as left by filter_list()).
// The distance the list offers to C (through the best window) is returned. Children are trimmed
// by the vertices later, when their own list is propagated (with the distances of that time).
// The children are appended to out_ac (frame of A -> C) and out_cb (frame of C -> B); when
// `want_ac` / `want_cb` is false (border edge) the corresponding children are not computed.
inline Propagation_result
propagate_list(const Halfedge_geometry& g, const std::vector<Window>& ws,
               const std::vector<Window_ends>& ends,
               double min_ratio,
               bool want_ac, bool want_cb,
               std::vector<Window>& out_ac, std::vector<Window>& out_cb,
               std::vector<double>& scratch_xc)
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
    const double den = cy - w.sy;
    const double xc = den > 0. ? w.sx + (cx - w.sx) * (-w.sy / den) : cx;
    scratch_xc[i] = xc;
    double base, sp, ex, ey;
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

// Scratch memory of filter_list() and propagate_list(), kept from list to list (one per thread).
struct List_scratch
{
  std::vector<Window_ends> ends;
  std::vector<Index> active;
  std::vector<double> xc;
  std::vector<Window> buffer;
  std::vector<Window_piece> pieces;
};

// Sorts a list by the starts of its windows. A list is made of a few batches of children, each
// in the order of the starts already (geodesics do not cross): a list of one or two such runs is
// merged in linear time.
inline void sort_by_start(std::vector<Window>& ws, std::vector<Window>& buffer)
{
  const std::size_t n = ws.size();
  std::size_t m = 1;
  while(m < n && !(ws[m].b0 < ws[m - 1].b0))
    ++m;
  if(m >= n)
    return;
  std::size_t e = m + 1;
  while(e < n && !(ws[e].b0 < ws[e - 1].b0))
    ++e;
  const auto by_start = [](const Window& x, const Window& y) { return x.b0 < y.b0; };
  if(e < n)
  {
    std::sort(ws.begin(), ws.end(), by_start);
    return;
  }
  buffer.resize(n);
  std::merge(ws.begin(), ws.begin() + static_cast<std::ptrdiff_t>(m),
             ws.begin() + static_cast<std::ptrdiff_t>(m), ws.end(), buffer.begin(), by_start);
  ws.swap(buffer);
}

// Filters a list before propagation: vertex trimming (ICH), tiny windows, pairwise pruning. The
// list is left sorted by the starts (up to the few starts that trimming moves), followed by the
// right parts of the windows cut in two (sorted too), with the distances at the ends of its
// windows in scratch.ends. During the filtering, a window that is cut away
// stays in place, shorter than `min_length` (see is_alive()); it is dropped at the end.
inline void filter_list(std::vector<Window>& ws, double L, double dA, double dB, double min_length,
                        List_scratch& scratch)
{
  const std::size_t n = ws.size();
  sort_by_start(ws, scratch.buffer);
  std::vector<Window_ends>& ends = scratch.ends;
  ends.resize(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    Window& w = ws[i];
    if(!trim_by_vertices(w, ends[i], L, dA, dB) || !is_alive(w, min_length))
      w.b1 = w.b0 - 1.;
  }
  // Sweep in the order of the starts (trimming may have moved a few of them: skipping a pair is
  // always safe, pruning only removes redundant coverage), with the windows that still reach
  // beyond the current start: most lists are nearly disjoint, so few pairs are examined.
  // The right parts of windows cut in two are appended to the list when the sweep reaches their
  // start.
  std::vector<Index>& active = scratch.active;
  std::vector<Window_piece>& pieces = scratch.pieces;
  active.clear();
  pieces.clear();
  for(std::size_t next = 0;;)
  {
    std::size_t i;
    if(!pieces.empty() && (next == n || !(ws[next].b0 < pieces.front().w.b0)))
    {
      std::pop_heap(pieces.begin(), pieces.end(), starts_later);
      ws.push_back(pieces.back().w);
      ends.push_back(pieces.back().e);
      pieces.pop_back();
      i = ws.size() - 1;
    }
    else if(next < n)
      i = next++;
    else
      break;
    Window& w = ws[i];
    if(!(w.b1 > w.b0))
      continue;
    Window_ends& ew = ends[i];
    std::size_t kept = 0;
    for(std::size_t j = 0; j < active.size(); ++j)
    {
      const Index a = active[j];
      Window& v = ws[static_cast<std::size_t>(a)];
      if(w.b1 > w.b0 && v.b1 > w.b0)
        prune_pair(v, ends[static_cast<std::size_t>(a)], w, ew, pieces);
      if(v.b1 > v.b0 && v.b1 > w.b0)
        active[kept++] = a;
    }
    active.resize(kept);
    if(w.b1 > w.b0)
      active.push_back(static_cast<Index>(i));
  }
  // drop the windows cut away (most lists lose none)
  std::size_t k = 0;
  const std::size_t total = ws.size();
  while(k < total && is_alive(ws[k], min_length))
    ++k;
  for(std::size_t i = k; i < total; ++i)
    if(is_alive(ws[i], min_length))
    {
      ws[k] = ws[i];
      ends[k] = ends[i];
      ++k;
    }
  ws.resize(k);
  ends.resize(k);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_TRIANGLE_PROPAGATION_H
