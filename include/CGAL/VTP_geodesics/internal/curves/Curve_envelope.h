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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_ENVELOPE_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_ENVELOPE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/curves/Curve_roots.h>
#include <CGAL/VTP_geodesics/internal/field/Curve_candidate.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A piece of a candidate's distance along a line: b + sqrt(l2 (u - m)^2 + h2) for u in [lo, hi], the distance
// from a circle whose centre projects on the line at abscissa m, at squared height h2 (l2: the squared length of
// the line's vector, the same for all the pieces of a line).
struct Line_circle
{
  double m, h2, b, lo, hi;
  Index label;
};

// where the label of the least candidate changes along a line: at abscissa u, from label `from` to `to`
struct Label_change
{
  double u;
  Index from, to;
};

// The least of the candidates (Curve_candidate.h) along a segment (px, py) + u (dx, dy), u in [u0, u1], of a face
// (or of an edge, from the candidates of its two faces): each candidate is one circle along the line (a corner, a
// source), or a window: its image where the window sees the line, else the nearer of its two ends (bent). The
// label of the least is settled on parts of the segment by bounds: on a part, a candidate's distance is at most the
// larger of its values at the ends (convex), a piece's at least its least there; where one label's bound from
// above is below every other label's from below, that label holds all over the part. Other parts are halved
// (keeping only the pieces that can be the least there) until few pieces are left, then swept from their start:
// the piece that holds, up to the first place where another piece gets below it (the roots of the difference of
// two circles' distances along a line: at most two, those of a quadratic, each polished by a bracketing root
// finder on the difference), or where its own part of the line ends. The changes of the label are exact up to
// the rounding of the distances.
class Label_envelope
{
public:
  // starts a segment u in [u0, u1] of a line whose vector has squared length l2; `scale`: the size of the
  // distances there (their rounding is a few units of it)
  void reset(double u0, double u1, double l2, double scale)
  {
    m_pieces.clear();
    m_candidate.clear();
    m_groups.clear();
    m_u0 = u0;
    m_u1 = u1;
    m_l2 = l2;
    m_tolerance = 4e-15 * scale;
  }

  // adds the candidates `c`, the line being (px, py) + u (dx, dy) in their frame
  void add(const std::vector<Curve_candidate>& c, double px, double py, double dx, double dy)
  {
    const double l2 = dx * dx + dy * dy;
    if(!(l2 > 0.))
      return;
    for(const Curve_candidate& q : c)
    {
      const std::size_t begin = m_pieces.size();
      if(!q.window)
        add_circle(px, py, dx, dy, l2, q.x, q.y, q.base, m_u0, m_u1, q.label);
      else
      {
        double v_lo, v_hi;
        q.seen_on_line(px, py, dx, dy, v_lo, v_hi);
        v_lo = (std::max)(v_lo, m_u0);
        v_hi = (std::min)(v_hi, m_u1);
        // (where the window does not see the line, the path bends at the end on that side of its wedge: the
        // one the line from the image to the point passes; the parts of the segment outside the wedge are each
        // on one side)
        if(!(v_lo < v_hi))
          add_bent(q, px, py, dx, dy, l2, m_u0, m_u1);
        else
        {
          add_circle(px, py, dx, dy, l2, q.x, q.y, q.base, v_lo, v_hi, q.label);
          if(m_u0 < v_lo)
            add_bent(q, px, py, dx, dy, l2, m_u0, v_lo);
          if(v_hi < m_u1)
            add_bent(q, px, py, dx, dy, l2, v_hi, m_u1);
        }
      }
      for(std::size_t i = begin; i < m_pieces.size(); ++i)
        m_candidate.push_back(m_groups.size());
      if(m_pieces.size() > begin)
        m_groups.push_back(Group{ begin, m_pieces.size(), q.label });
    }
  }

  // The changes of the label of the least along the segment, in order of u (`out`), and the labels at its ends
  // (`first`, `last`). At u0 the label `prefer` is taken where it is the least to rounding (NO_INDEX: none).
  // Returns false if a sweep took more steps than its pieces can give (rounding; then `out` holds what was
  // found).
  bool changes(Index prefer, std::vector<Label_change>& out, Index& first, Index& last)
  {
    out.clear();
    first = last = NO_INDEX;
    if(m_pieces.empty())
      return true;
    m_done = true;
    m_survivors.resize(26);  // (the deepest settle() goes; no reallocation while it runs)
    m_survivors[0].resize(m_pieces.size());
    for(std::size_t i = 0; i < m_pieces.size(); ++i)
      m_survivors[0][i] = i;
    Index current = NO_INDEX;
    settle(m_u0, m_u1, 0, prefer, out, current);
    first = out.empty() ? current : out.front().from;
    last = current;
    return m_done;
  }

  // the least of the pieces at u (+infinity if none holds there)
  double least(double u) const
  {
    double best = std::numeric_limits<double>::infinity();
    for(const Line_circle& p : m_pieces)
      if(p.lo <= u && u <= p.hi)
        best = (std::min)(best, at(p, u));
    return best;
  }

  double tolerance() const { return m_tolerance; }

private:
  double at(const Line_circle& p, double u) const
  {
    const double d = u - p.m;
    return p.b + std::sqrt(m_l2 * d * d + p.h2);
  }

  // the least of p over [a, e]
  double lowest(const Line_circle& p, double a, double e) const { return at(p, (std::min)((std::max)(p.m, a), e)); }

  void add_circle(double px, double py, double dx, double dy, double l2, double cx, double cy, double b, double lo,
                  double hi, Index label)
  {
    if(!(lo < hi))
      return;
    const double qx = px - cx, qy = py - cy;
    const double cross = qx * dy - qy * dx;
    m_pieces.push_back(Line_circle{ -(qx * dx + qy * dy) / l2, cross * cross / l2, b, lo, hi, label });
  }

  // the window q bent at one end on [lo, hi] (a part of the line outside its wedge): at the end on that side
  void add_bent(const Curve_candidate& q, double px, double py, double dx, double dy, double l2, double lo, double hi)
  {
    const double u = 0.5 * (lo + hi), x = px + u * dx - q.x, y = py + u * dy - q.y;
    const double ex = q.gx1 - q.gx0, ey = q.gy1 - q.gy0, rx = q.gx0 - q.x, ry = q.gy0 - q.y;
    const double den = x * ey - y * ex;
    const double t = den != 0. ? (rx * y - ry * x) / den : 0.;  // (where the line from the image crosses the window's)
    if(t < 0.5)
      add_circle(px, py, dx, dy, l2, q.gx0, q.gy0, q.base + q.e0, lo, hi, q.label);
    else
      add_circle(px, py, dx, dy, l2, q.gx1, q.gy1, q.base + q.e1, lo, hi, q.label);
  }

  struct Group  // the pieces of one candidate: [begin, end)
  {
    std::size_t begin, end;
    Index label;
  };
  struct Label_bounds  // on a part of the segment, the least of a label is in [lower, upper]
  {
    Index label;
    double upper, lower;
  };

  // the value of the candidate of group g at u (the least of its pieces there)
  double group_value(const Group& g, double u) const
  {
    double v = std::numeric_limits<double>::infinity();
    for(std::size_t i = g.begin; i < g.end; ++i)
      if(m_pieces[i].lo <= u && u <= m_pieces[i].hi)
        v = (std::min)(v, at(m_pieces[i], u));
    return v;
  }

  // The changes on [lo, hi] (m_survivors[depth]: the pieces that can be the least there), after the label
  // `current` (NO_INDEX at the start): settled by bounds, or halved, or swept.
  void settle(double lo, double hi, std::size_t depth, Index prefer, std::vector<Label_change>& out, Index& current)
  {
    const std::vector<std::size_t>& alive = m_survivors[depth];
    // per label, from above: the least over its candidates of their larger end value (convex); from below: the
    // least of its pieces over the part
    m_bounds.clear();
    auto bounds_of = [&](Index label) -> Label_bounds& {
      for(Label_bounds& b : m_bounds)
        if(b.label == label)
          return b;
      m_bounds.push_back(Label_bounds{ label, std::numeric_limits<double>::infinity(),
                                       std::numeric_limits<double>::infinity() });
      return m_bounds.back();
    };
    std::size_t last_group = m_groups.size();
    double upper = std::numeric_limits<double>::infinity();
    m_lowest.resize(alive.size());
    for(std::size_t j = 0; j < alive.size(); ++j)
    {
      const std::size_t i = alive[j];
      const Line_circle& p = m_pieces[i];
      Label_bounds& b = bounds_of(p.label);
      m_lowest[j] = p.hi >= lo && p.lo <= hi ? lowest(p, (std::max)(lo, p.lo), (std::min)(hi, p.hi))
                                              : std::numeric_limits<double>::infinity();
      b.lower = (std::min)(b.lower, m_lowest[j]);
      const std::size_t g = m_candidate[i];
      if(g != last_group)  // (the pieces of a candidate are listed together)
      {
        last_group = g;
        const double high = (std::max)(group_value(m_groups[g], lo), group_value(m_groups[g], hi));
        b.upper = (std::min)(b.upper, high);
        upper = (std::min)(upper, high);
      }
    }
    const Label_bounds* least = nullptr;
    for(const Label_bounds& b : m_bounds)
      if(least == nullptr || b.upper < least->upper)
        least = &b;
    bool settled = least != nullptr;
    for(const Label_bounds& b : m_bounds)
      if(settled && &b != least && !(b.lower > least->upper + m_tolerance))
        settled = false;
    if(settled)
    {
      if(current != NO_INDEX && current != least->label)
        out.push_back(Label_change{ lo, current, least->label });
      current = least->label;
      return;
    }
    // the pieces that can be the least on [lo, hi]
    std::vector<std::size_t>& kept = m_survivors[depth + 1];
    kept.clear();
    for(std::size_t j = 0; j < alive.size(); ++j)
      if(m_lowest[j] <= upper + m_tolerance)
        kept.push_back(alive[j]);
    if(kept.size() > 24 && depth < 24 && hi - lo > 1e-6 * (m_u1 - m_u0))
    {
      const double mid = 0.5 * (lo + hi);
      settle(lo, mid, depth + 1, prefer, out, current);
      settle(mid, hi, depth + 1, prefer, out, current);
      return;
    }
    sweep(lo, hi, kept, current != NO_INDEX ? current : prefer, out, current);
  }

  // The sweep of [lo, hi] over the pieces `kept`, after the label `current` (NO_INDEX at the start).
  void sweep(double lo, double hi, const std::vector<std::size_t>& kept, Index prefer, std::vector<Label_change>& out,
             Index& current)
  {
    if(kept.empty())
      return;
    double u = lo;
    std::size_t w = least_right_of(kept, u, hi, prefer);
    if(current != NO_INDEX && current != m_pieces[w].label)
      out.push_back(Label_change{ lo, current, m_pieces[w].label });
    current = m_pieces[w].label;
    const std::size_t steps = 4 * kept.size() + 64;
    for(std::size_t step = 0; step < steps; ++step)
    {
      const Line_circle& pw = m_pieces[w];
      double event = (std::min)(pw.hi, hi);
      std::size_t next = m_pieces.size();
      // (w is at most this on [u, event]: convex)
      const double upper = (std::max)(at(pw, u), at(pw, event)) + m_tolerance;
      for(std::size_t r : kept)
      {
        const Line_circle& pr = m_pieces[r];
        if(r == w || pr.hi <= u || pr.lo >= event)
          continue;
        const double a = (std::max)(u, pr.lo), e = (std::min)(event, pr.hi);
        if(!(a < e) || lowest(pr, a, e) > upper)
          continue;
        double x;
        if(first_below(pr, pw, a, e, x) && x < event)
        {
          event = x;
          next = r;
        }
      }
      if(next == m_pieces.size())
      {
        // w's part of the line ends (or the part swept does): the least just after
        if(!(event < hi))
          return;
        next = least_right_of(kept, event, hi, pw.label);
      }
      if(m_pieces[next].label != pw.label)
        out.push_back(Label_change{ event, pw.label, m_pieces[next].label });
      current = m_pieces[next].label;
      w = next;
      u = event;
    }
    m_done = false;
  }

  // The piece of `kept` that is the least just right of u (the least at u, then the one that rises slowest;
  // `prefer`'s label among those least at u to rounding); at the end `hi`, just left of it.
  std::size_t least_right_of(const std::vector<std::size_t>& kept, double u, double hi, Index prefer) const
  {
    const bool end = !(u < hi);
    auto holds = [&](const Line_circle& p) { return p.lo <= u && (end ? u <= p.hi : u < p.hi); };
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t i : kept)
      if(holds(m_pieces[i]))
        best = (std::min)(best, at(m_pieces[i], u));
    std::size_t which = m_pieces.size();
    double slope = std::numeric_limits<double>::infinity();
    bool preferred = false;
    for(std::size_t i : kept)
    {
      const Line_circle& p = m_pieces[i];
      if(!holds(p) || !(at(p, u) <= best + m_tolerance))
        continue;
      const double d = u - p.m, s = std::sqrt(m_l2 * d * d + p.h2);
      const double ds = s > 0. ? m_l2 * d / s : 0.;
      const bool is_preferred = prefer != NO_INDEX && p.label == prefer;
      if(which == m_pieces.size() || (is_preferred && !preferred) || (is_preferred == preferred && ds < slope))
      {
        which = i;
        slope = ds;
        preferred = is_preferred;
      }
    }
    if(which == m_pieces.size())  // (no piece holds at u: the nearest one after it)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for(std::size_t i : kept)
        if(m_pieces[i].hi > u && m_pieces[i].lo < nearest)
        {
          nearest = m_pieces[i].lo;
          which = i;
        }
      if(which == m_pieces.size())
        which = kept.front();
    }
    return which;
  }

  // The first abscissa x in [a, e) from which piece r is below piece w (w the least at a, to rounding): the
  // roots of r - w split [a, e] into parts of one sign each, tested at their middles; x is polished by a
  // bracketing root finder on r - w. False if r stays above w on [a, e].
  bool first_below(const Line_circle& r, const Line_circle& w, double a, double e, double& x) const
  {
    auto g = [&](double t) { return at(r, t) - at(w, t); };
    double cut[4];
    int n = 0;
    cut[n++] = a;
    double roots[2];
    const int k = difference_roots(r, w, roots);
    for(int i = 0; i < k; ++i)
      if(roots[i] > a && roots[i] < e)
        cut[n++] = roots[i];
    if(n == 3 && cut[2] < cut[1])
      std::swap(cut[1], cut[2]);
    cut[n++] = e;
    double left = a, g_left = g(a);
    for(int i = 0; i + 1 < n; ++i)
    {
      const double mid = 0.5 * (cut[i] + cut[i + 1]), g_mid = g(mid);
      if(g_mid < -m_tolerance)
      {
        if(!(g_left > 0.))
        {
          x = left;  // (below from `left` on: a tie there)
          return true;
        }
        // (Newton steps on the difference, kept in the bracket, else Illinois steps)
        x = circle_zero(
          [&](double t, double& next) {
            const double v = g(t), dr = t - r.m, dw = t - w.m;
            const double sr = std::sqrt(m_l2 * dr * dr + r.h2), sw = std::sqrt(m_l2 * dw * dw + w.h2);
            const double slope = (sr > 0. ? m_l2 * dr / sr : 0.) - (sw > 0. ? m_l2 * dw / sw : 0.);
            next = slope != 0. ? t - v / slope : std::numeric_limits<double>::quiet_NaN();
            return v;
          },
          left, mid, g_left, g_mid, 1e-16 * (std::abs(left) + std::abs(mid)) + 1e-300, 0.);
        return true;
      }
      left = mid;
      g_left = g_mid;
    }
    return false;
  }

  // The roots of at(r, .) = at(w, .) (with spurious ones of the squared equation): b_r + s_r = b_w + s_w, with
  // s^2 = l2 (x - m)^2 + h2; k = b_w - b_r: s_r^2 - s_w^2 is linear in x, = k (s_r + s_w), so that
  // 4 k^2 s_r^2 = (s_r^2 - s_w^2 + k^2)^2, a quadratic in x. Returns how many (0 to 2).
  int difference_roots(const Line_circle& r, const Line_circle& w, double roots[2]) const
  {
    const double k = w.b - r.b;
    // in y = x - r.m: s_r^2 - s_w^2 = alpha y + beta
    const double dm = r.m - w.m;  // (x - w.m = y + dm)
    const double alpha = -2. * m_l2 * dm, beta = r.h2 - w.h2 - m_l2 * dm * dm;
    if(k == 0.)
    {
      if(alpha == 0.)
        return 0;
      roots[0] = r.m - beta / alpha;
      return 1;
    }
    const double k2 = k * k, c0 = beta + k2;
    // 4 k^2 (l2 y^2 + h_r) = (alpha y + c0)^2
    const double qa = 4. * k2 * m_l2 - alpha * alpha, qb = -2. * alpha * c0, qc = 4. * k2 * r.h2 - c0 * c0;
    int n = 0;
    if(std::abs(qa) <= 1e-14 * (4. * k2 * m_l2 + alpha * alpha))
    {
      if(qb != 0.)
        roots[n++] = r.m - qc / qb;
      return n;
    }
    const double disc = qb * qb - 4. * qa * qc;
    if(!(disc >= 0.))
    {
      roots[n++] = r.m - qb / (2. * qa);  // (a near tangency: the vertex, one more place to test)
      return n;
    }
    const double q = -0.5 * (qb + (qb < 0. ? -1. : 1.) * std::sqrt(disc));
    roots[n++] = r.m + q / qa;
    if(q != 0.)
      roots[n++] = r.m + qc / q;
    return n;
  }

  std::vector<Line_circle> m_pieces;
  std::vector<std::size_t> m_candidate;  // per piece, its group
  std::vector<Group> m_groups;
  std::vector<std::vector<std::size_t> > m_survivors;  // per depth of settle()
  std::vector<Label_bounds> m_bounds;
  std::vector<double> m_lowest;  // (settle(): per piece alive, its least on the part)
  double m_u0 = 0., m_u1 = 1., m_l2 = 1., m_tolerance = 0.;
  bool m_done = true;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_ENVELOPE_H
