// The lower envelope of the kept field in a face, for the test that measures how much of the field it is
// (test_kept_field.cpp, KeptField.NearlyEveryPieceIsTheLeastSomewhere; doc/VTP_geodesics/curves.txt).

#ifndef VTP_TEST_FIELD_ENVELOPE_H
#define VTP_TEST_FIELD_ENVELOPE_H

#include <CGAL/VTP_geodesics/internal/field/Curve_candidate.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace vtp_test {

using CGAL::VTP_geodesics::internal::Curve_candidate;
using CGAL::VTP_geodesics::internal::NO_INDEX;

// The lower envelope of the candidates of a face (Curve_candidate.h): which windows are the least candidate
// somewhere in the face, decided on their own interval.
//
// Why the interval is enough: if window w is the least candidate at a point p of the face, the path it offers
// to p (straight from its image through its interval, or bent at an end of it) crosses its interval at a point
// x, and the part of a shortest path up to x is a shortest path: w is the least candidate at x too. So a window
// that is above the least of the others at every point of its interval is above it everywhere in the face, and
// dropping it leaves the least candidate, hence the field, the same at every point of the face.
//
// How it is decided: every candidate's distance is convex along a line (Curve_candidate.h), so on a piece
// [ua, ub] of the interval, w is above its tangent at the middle and another candidate q is below its chord; if
// the tangent is above q at both ends, w is above q on the whole piece. A piece where w is below every other
// candidate at a point keeps w; a piece not decided after `depth` halvings keeps it too (the envelope kept is
// then a superset of the true one, never a subset). `slack`: a window above the others by less than this
// somewhere may be dropped (an error of at most `slack` in the field).
class Field_envelope
{
public:
  explicit Field_envelope(int depth = 12) : m_depth(depth) {}

  // Removes from `c` the windows that are nowhere the least candidate, considering them from the highest least
  // value (`low`) down (each is compared with those still kept). Corners and sources are kept.
  void keep_least(std::vector<Curve_candidate>& c, double slack)
  {
    const std::size_t n = c.size();
    m_order.clear();
    for(std::size_t i = 0; i < n; ++i)
      if(c[i].window)
        m_order.push_back(i);
    if(m_order.empty())
      return;
    m_removed.assign(n, 0);
    std::sort(m_order.begin(), m_order.end(), [&](std::size_t a, std::size_t b) { return c[a].low > c[b].low; });
    for(std::size_t i : m_order)
      if(is_dominated(c, i, slack))
        m_removed[i] = 1;
    std::size_t k = 0;
    for(std::size_t i = 0; i < n; ++i)
      if(!m_removed[i])
        c[k++] = c[i];
    c.resize(k);
  }

  // whether window c[w] is above the least of the other kept candidates (or equal to it, up to `slack`) at every
  // point of its interval
  bool is_dominated(const std::vector<Curve_candidate>& c, std::size_t w, double slack)
  {
    const Curve_candidate& W = c[w];
    // the same circle as another candidate that sees all of w's interval: w is that candidate there
    for(std::size_t q = 0; q < c.size(); ++q)
      if(q != w && !m_removed[q] && same_circle(W, c[q], slack) && covers(c[q], W))
        return true;
    Sample a = sample(c, w, 0.), b = sample(c, w, 1.);
    if(a.w < a.least - slack || b.w < b.least - slack)
      return false;
    m_stack.clear();
    m_stack.push_back(Piece{ a, b, 0 });
    while(!m_stack.empty())
    {
      const Piece p = m_stack.back();
      m_stack.pop_back();
      const double um = 0.5 * (p.a.u + p.b.u);
      const Sample m = sample(c, w, um);
      if(m.w < m.least - slack)
        return false;
      // w's tangent at the middle, at the two ends
      const double slope = slope_at(W, um);
      const double ta = m.w + slope * (p.a.u - um), tb = m.w + slope * (p.b.u - um);
      bool certified = false;
      const std::size_t tries[3] = { m.which, p.a.which, p.b.which };
      for(std::size_t q : tries)
        if(q != NO_CANDIDATE && ta >= value(c[q], W, p.a.u) - slack && tb >= value(c[q], W, p.b.u) - slack)
        {
          certified = true;
          break;
        }
      if(certified)
        continue;
      if(p.depth >= m_depth)
        return false;  // (undecided: kept)
      m_stack.push_back(Piece{ p.a, m, p.depth + 1 });
      m_stack.push_back(Piece{ m, p.b, p.depth + 1 });
    }
    return true;
  }

private:
  static constexpr std::size_t NO_CANDIDATE = static_cast<std::size_t>(-1);
  struct Sample
  {
    double u, w, least;   // the place on w's interval, w's distance, the least of the others
    std::size_t which;    // the least other candidate
  };
  struct Piece
  {
    Sample a, b;
    int depth;
  };

  static void point_at(const Curve_candidate& W, double u, double& px, double& py)
  {
    px = W.gx0 + u * (W.gx1 - W.gx0);
    py = W.gy0 + u * (W.gy1 - W.gy0);
  }
  // candidate q's distance at the point u of w's interval
  static double value(const Curve_candidate& q, const Curve_candidate& W, double u)
  {
    double px, py;
    point_at(W, u, px, py);
    return q.distance_at(px, py);
  }
  // w's distance on its interval (straight from its image) and its derivative in u
  static double straight(const Curve_candidate& W, double u)
  {
    double px, py;
    point_at(W, u, px, py);
    return W.base + std::hypot(px - W.x, py - W.y);
  }
  static double slope_at(const Curve_candidate& W, double u)
  {
    double px, py;
    point_at(W, u, px, py);
    const double dx = px - W.x, dy = py - W.y, r = std::hypot(dx, dy);
    return r > 0. ? (dx * (W.gx1 - W.gx0) + dy * (W.gy1 - W.gy0)) / r : 0.;
  }
  Sample sample(const std::vector<Curve_candidate>& c, std::size_t w, double u) const
  {
    const Curve_candidate& W = c[w];
    double px, py;
    point_at(W, u, px, py);
    Sample s{ u, straight(W, u), std::numeric_limits<double>::infinity(), NO_CANDIDATE };
    for(std::size_t q = 0; q < c.size(); ++q)
      if(q != w && !m_removed[q])
      {
        const double d = c[q].distance_at(px, py);
        if(d < s.least)
        {
          s.least = d;
          s.which = q;
        }
      }
    return s;
  }
  static bool same_circle(const Curve_candidate& a, const Curve_candidate& b, double slack)
  {
    return std::abs(a.base - b.base) <= slack && std::abs(a.x - b.x) <= slack && std::abs(a.y - b.y) <= slack;
  }
  // whether q is straight (not bent) at both ends of w's interval, hence on all of it
  static bool covers(const Curve_candidate& q, const Curve_candidate& W)
  {
    if(!q.window)
      return true;
    for(double u : { 0., 1. })
    {
      double px, py;
      point_at(W, u, px, py);
      if(q.distance_at(px, py) > q.base + std::hypot(px - q.x, py - q.y) * (1. + 1e-15))
        return false;
    }
    return true;
  }

  int m_depth;
  std::vector<std::size_t> m_order;
  std::vector<char> m_removed;
  std::vector<Piece> m_stack;
};

} // namespace vtp_test

#endif // VTP_TEST_FIELD_ENVELOPE_H
