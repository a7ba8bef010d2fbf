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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_PAIR_PRUNING_H
#define CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_PAIR_PRUNING_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/windows/Window.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The pairwise pruning of the windows of one list (Rule 2), used by filter_list() (List_filter.h).

// Sign of fa - fb: 1, -1, or 0 for a near-tie.
inline int compare_distances(double fa, double fb)
{
  const double tol = 1e-13 * (std::max)(fa, fb);
  return (fa > fb + tol) ? 1 : ((fb > fa + tol) ? -1 : 0);
}

// Sign of window_distance(w, x) - F, as compare_distances() gives it (with the tolerance taken
// from F), without the square root.
template <bool points>
inline int compare_distance_to(const Window& w, double x, double F)
{
  if constexpr(!points)
    if(is_line(w))
      return compare_distances(window_distance(w, x), F);
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
template <bool points>
inline int compare_at(const Window& a, bool known_a, double fa, const Window& b, bool known_b, double fb, double x)
{
  if(known_a && known_b)
    return compare_distances(fa, fb);
  if(known_b)
    return compare_distance_to<points>(a, x, fb);
  CGAL_assertion(known_a);
  return -compare_distance_to<points>(b, x, fa);
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

// A polynomial q(x) = (qa x + qb) x + qc that vanishes wherever windows a and b offer the same distance at
// (x, 0) (it may vanish elsewhere too: its roots are candidates only).
template <bool points>
inline void difference_polynomial(const Window& a, const Window& b, double& qa, double& qb, double& qc)
{
  if constexpr(!points)  // (points: both are point windows)
  {
    if(is_line(a) && is_line(b))
    {
      // (sigma_a - sigma_b) + (sx_a - sx_b) x
      qa = 0.;
      qb = a.sx - b.sx;
      qc = a.sigma - b.sigma;
      return;
    }
    if(is_line(a) || is_line(b))
    {
      // beta + n x = sqrt((x - px)^2 + py^2), beta = sigma_line - sigma_point, squared once
      const Window& l = is_line(a) ? a : b;
      const Window& p = is_line(a) ? b : a;
      const double beta = l.sigma - p.sigma, n = l.sx;
      qa = n * n - 1.;
      qb = 2. * (beta * n + p.sx);
      qc = beta * beta - p.sx * p.sx - p.sy * p.sy;
      return;
    }
  }
  // sqrt(Qa) = beta + sqrt(Qb), beta = sigma_b - sigma_a, squared twice
  const double beta = b.sigma - a.sigma;
  const double lin = 2. * (b.sx - a.sx);
  const double c = a.sx * a.sx + a.sy * a.sy - b.sx * b.sx - b.sy * b.sy - beta * beta;
  const double b2 = beta * beta;
  qa = lin * lin - 4. * b2;
  qb = 2. * lin * c + 8. * b2 * b.sx;
  qc = c * c - 4. * b2 * (b.sx * b.sx + b.sy * b.sy);
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
template <bool points>
inline void settle_pair(Window& a, Window_ends& ea, Window& b, Window_ends& eb, double l, double r, int sl, int sr,
                        std::vector<Window_piece>& pieces)
{
  // (points: both are point windows, tested once by prune_pair())
  auto distance = [](const Window& w, double x) { return points ? distance_of<false>(w, x) : window_distance(w, x); };
  const bool al = (l == a.b0), bl = (l == b.b0), ar = (r == a.b1), br = (r == b.b1);
  double qa, qb, qc;
  difference_polynomial<points>(a, b, qa, qb, qc);

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
      piece.e.f0 = distance(w, r);
      piece.e.f1 = e.f1;
      pieces.push_back(piece);
      std::push_heap(pieces.begin(), pieces.end(), starts_later);
      e.f1 = distance(w, l);
      w.b1 = l;
      return;
    }
    if(starts && ends)
      w.b1 = w.b0 - 1.;
    else if(starts)
    {
      e.f0 = distance(w, r);
      w.b0 = r;
    }
    else
    {
      e.f1 = distance(w, l);
      w.b1 = l;
    }
    return;
  }
  const double fal = al ? ea.f0 : distance(a, l);
  const double fbl = bl ? eb.f0 : distance(b, l);
  const double far = ar ? ea.f1 : distance(a, r);
  const double fbr = br ? eb.f1 : distance(b, r);
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
    fa[i] = distance(a, cuts[i]);
    fb[i] = distance(b, cuts[i]);
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

// `mixed`: the list may hold line windows (else both are point windows, untested).
template <bool mixed>
inline void prune_pair(Window& a, Window_ends& ea, Window& b, Window_ends& eb, std::vector<Window_piece>& pieces)
{
  const double l = (std::max)(a.b0, b.b0);
  const double r = (std::min)(a.b1, b.b1);
  if(!(r > l))
    return;
  // l is the start of a or b, r the end of a or b: there the distance is known
  if(!mixed || (!is_line(a) && !is_line(b)))
  {
    const int sl = compare_at<true>(a, l == a.b0, ea.f0, b, l == b.b0, eb.f0, l);
    const int sr = compare_at<true>(a, r == a.b1, ea.f1, b, r == b.b1, eb.f1, r);
    if(sl != 0 || sr != 0)
      settle_pair<true>(a, ea, b, eb, l, r, sl, sr, pieces);
    return;
  }
  const int sl = compare_at<false>(a, l == a.b0, ea.f0, b, l == b.b0, eb.f0, l);
  const int sr = compare_at<false>(a, r == a.b1, ea.f1, b, r == b.b1, eb.f1, r);
  if(sl == 0 && sr == 0)
    return;
  settle_pair<false>(a, ea, b, eb, l, r, sl, sr, pieces);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_PAIR_PRUNING_H
