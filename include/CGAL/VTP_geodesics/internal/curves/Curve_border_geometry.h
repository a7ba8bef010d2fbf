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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_GEOMETRY_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_GEOMETRY_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/curves/Curve_pieces.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// What the field says inside one face about its cell borders (Curve_border_face.h, Curve_borders.h), from the
// changes of label on its edges (`nodes`, `crossings`: counterclockwise, each from a label to the next) and the
// candidates of the face: the points of a piece of border between two of its points (along lines across its
// chord, exact, refined where it bends away from its chords: kinks), a junction of three labels (exact).
class Border_geometry
{
public:
  struct Node  // a crossing, or a junction (key -1 until the plan is kept)
  {
    double x, y;  // in the frame of the face
    Curve_point point;
    std::int64_t key;
  };
  struct Crossing  // a change on the face's border, counterclockwise: from label `from` to `to`
  {
    Index from, to;
    int edge;  // edge k of the face (half-edge 3f + k), abscissa s along it
    double s;
  };
  struct Link  // a piece from node a to node b, label `left` on its left
  {
    std::size_t a, b;
    Index left, right;
  };
  struct Plan
  {
    std::vector<Node> nodes;
    std::vector<Link> links;
    std::vector<std::vector<Curve_point> > points;  // per link, from a to b
    int bad_junctions = 0;
    std::size_t undecided = 0;
    std::vector<int> region;  // per arc of the face's border, its region (the least arc in it)
  };



  Border_geometry(Curve_pieces& pieces, double tolerance) : m_pieces(pieces), m_tolerance(tolerance) {}

  // the changes on the border of the face, counterclockwise (set before use): where, and from which label to
  // which
  std::vector<Node> nodes;
  std::vector<Crossing> crossings;

  void arc(const Face_frame& fr, std::size_t i, std::vector<std::pair<double, double> >& points) const
  {
    const std::size_t n = crossings.size(), j = (i + 1) % n;
    points.emplace_back(nodes[i].x, nodes[i].y);
    const int a = crossings[i].edge, b = crossings[j].edge;
    if(!(j > i && a == b))
    {
      int k = a;
      do
      {
        k = (k + 1) % 3;
        points.emplace_back(fr.x[k], fr.y[k]);
      } while(k != b);
    }
    points.emplace_back(nodes[j].x, nodes[j].y);
  }

protected:
  // The junction of labels l (x, y, z) in face f from the guess (gx, gy), else from points between the nodes of
  // its ends a, b, c (a junction near an edge, between two of its crossings, is found from there); false if
  // not found in the face (then at the guess).
  // A point found where another junction of the way is (`made`: the nodes so far, the junctions after the
  // crossings) does not count: two junctions of one way are apart (the point is that of the other, from the
  // same circles; this one is where other circles of the labels hold).
  bool junction_node(Index f, const Face_frame& fr, const Index l[3], double gx, double gy, const Node& a,
                     const Node& b, const Node& c, const std::vector<Node>& made, Node& node)
  {
    const double cx = (fr.x[0] + fr.x[1] + fr.x[2]) / 3., cy = (fr.y[0] + fr.y[1] + fr.y[2]) / 3.;
    const double size = std::abs(fr.x[1]) + std::abs(fr.x[2]) + std::abs(fr.y[2]);
    auto solved = [&]() {
      if(!memo_junction(f, l, node.x, node.y))
        return false;
      for(std::size_t i = crossings.size(); i < made.size(); ++i)
        if(std::hypot(made[i].x - node.x, made[i].y - node.y) <= 1e-9 * size)
          return false;
      return true;
    };
    node.x = gx;
    node.y = gy;
    node.key = -1;
    bool found = solved();
    const Node* around[3] = { &a, &b, &c };
    for(int i = 0; i < 3 && !found; ++i)
      for(int j = i + 1; j < 3 && !found; ++j)
        for(double pull : { 0.01, 0.1 })
        {
          const Node &ni = *around[i], &nj = *around[j];
          if(found || (ni.x == nj.x && ni.y == nj.y))
            continue;
          node.x = (1. - pull) * 0.5 * (ni.x + nj.x) + pull * cx;
          node.y = (1. - pull) * 0.5 * (ni.y + nj.y) + pull * cy;
          found = solved();
        }
    if(!found)
    {
      node.x = gx;
      node.y = gy;
    }
    node.point = Curve_pieces::point_in_face(f, fr, node.x, node.y);
    return found;
  }

  // exact_junction() from (x, y), the answers kept for the face (the search of the ways and the way kept solve
  // the same junctions from the same points; clear_junctions() when the face changes)
  bool memo_junction(Index f, const Index l[3], double& x, double& y)
  {
    for(const Junction_memo& j : m_junctions)
      if(j.l[0] == l[0] && j.l[1] == l[1] && j.l[2] == l[2] && j.from[0] == x && j.from[1] == y)
      {
        x = j.at[0];
        y = j.at[1];
        return j.found;
      }
    Junction_memo j{ { l[0], l[1], l[2] }, { x, y }, { x, y }, false };
    j.found = exact_junction(f, m_c, l, j.at[0], j.at[1]);
    m_junctions.push_back(j);
    x = j.at[0];
    y = j.at[1];
    return j.found;
  }
  void clear_junctions() { m_junctions.clear(); }

  // The points of a link: its ends, and between them, on lines across its chord, where the label changes from
  // its right one to its left one (the nearest to the chord); then, between two points, the point found so on
  // the line across their chord at its middle is added where it is farther from that chord than the chord
  // tolerance (a kink: the border crosses the cut locus of one of its labels), and the two halves done again
  // (at most 6 times deep). (From the field's values only: two runs whose windows differ to rounding give the
  // same points.)
  void link_points(Index f, const Face_frame& fr, Plan& plan, const Link& k, std::vector<Curve_point>& points)
  {
    const Node &a = plan.nodes[k.a], &b = plan.nodes[k.b];
    points.clear();
    points.push_back(a.point);
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    const double r = (std::min)(Curve_field::value(m_c, a.x, a.y), Curve_field::value(m_c, b.x, b.y));
    const int chords = len > 0. ? m_pieces.number_of_chords(len, r) : 1;
    double x0 = a.x, y0 = a.y;
    bool found0 = true;
    for(int i = 1; i <= chords; ++i)
    {
      double x = b.x, y = b.y;
      bool found = true;
      if(i < chords)
      {
        const double s = static_cast<double>(i) / chords;
        found = border_across(f, fr, k.left, k.right, a.x, a.y, b.x, b.y, a.x + s * dx, a.y + s * dy, r, x, y);
        plan.undecided += found ? 0 : 1;
      }
      if(found0 && found)
        refine(f, fr, k.left, k.right, x0, y0, x, y, r, 0, points);
      if(i < chords)
        points.push_back(Curve_pieces::point_in_face(f, fr, x, y));
      x0 = x;
      y0 = y;
      found0 = found;
    }
    points.push_back(b.point);
  }

  // The point of the border of `left` | `right` on the line across the chord (ax, ay) - (bx, by) through its
  // point (qx, qy), inside the face (border_on_segment(): the change from the right label to the
  // left one nearest to the chord); else (qx, qy) if it is on the border (the border along the chord: along an
  // edge, where the line starts); false if neither (then (qx, qy)). `r`: the distances there.
  bool border_across(Index f, const Face_frame& fr, Index left, Index right, double ax, double ay, double bx,
                     double by, double qx, double qy, double r, double& x, double& y)
  {
    CGAL_USE(f);
    const double dx = bx - ax, dy = by - ay, len = std::sqrt(dx * dx + dy * dy);
    const double size = std::abs(fr.x[1]) + std::abs(fr.x[2]) + std::abs(fr.y[2]);
    x = qx;
    y = qy;
    if(!(len > 0.))
      return false;
    const double nx = -dy / len, ny = dx / len;  // (towards the left label)
    // the line q + u (nx, ny) inside the face
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    fr.clip_line(qx, qy, nx, ny, lo, hi);
    if(lo < hi && std::isfinite(lo) && std::isfinite(hi))
    {
      // first within w of the chord (a change found there at d <= w from it is the nearest), then all across
      const double w = 0.1 * len + m_tolerance;
      for(int pass = 0; pass < 2; ++pass)
      {
        const double a = pass == 0 ? (std::max)(lo, -w) : lo, b = pass == 0 ? (std::min)(hi, w) : hi;
        double u = 0.;
        if(a < b && border_on_segment(m_c, qx + a * nx, qy + a * ny, (b - a) * nx, (b - a) * ny, left, right,
                                               -a / (b - a), r + size, u)
           && (pass == 1 || std::abs(a + u * (b - a)) <= w))
        {
          x = qx + (a + u * (b - a)) * nx;
          y = qy + (a + u * (b - a)) * ny;
          return true;
        }
        if(pass == 0 && a == lo && b == hi)
          break;  // (the window was the whole line)
      }
    }
    return on_border(left, right, qx, qy, size);
  }

  // The points strictly between two points of the border (x0, y0) and (x1, y1), appended: the border on the
  // line across their chord at its middle, if farther from it than the chord tolerance, and again on either
  // side (see link_points()).
  void refine(Index f, const Face_frame& fr, Index left, Index right, double x0, double y0, double x1, double y1,
              double r, int depth, std::vector<Curve_point>& points)
  {
    if(depth >= 6)
      return;
    const double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
    double x, y;
    if(!border_across(f, fr, left, right, x0, y0, x1, y1, mx, my, r, x, y)
       || !(std::hypot(x - mx, y - my) > m_tolerance))
      return;
    refine(f, fr, left, right, x0, y0, x, y, r, depth + 1, points);
    points.push_back(Curve_pieces::point_in_face(f, fr, x, y));
    refine(f, fr, left, right, x, y, x1, y1, r, depth + 1, points);
  }

  // whether (x, y) is on the border of `left` | `right`: the two labels' least equal and least of all, to 1e-10 of
  // the distances (`size`: of the face)
  bool on_border(Index left, Index right, double x, double y, double size) const
  {
    const double vl = Curve_field::value(m_c, x, y, left), vr = Curve_field::value(m_c, x, y, right);
    const double tolerance = 1e-10 * ((std::max)(vl, vr) + size);
    return std::abs(vl - vr) <= tolerance && Curve_field::value(m_c, x, y) >= (std::max)(vl, vr) - tolerance;
  }

  // The place where the segment (px, py) + u (dx, dy), u in [0, 1], of a face (candidates c) crosses the border
  // of cells y and x, from y to x, the nearest to abscissa `near` (Label_envelope: exact); `scale`: the size of the
  // distances there. False if it does not.
  bool border_on_segment(const std::vector<Curve_candidate>& c, double px, double py, double dx, double dy, Index x,
                         Index y, double near, double scale, double& u)
  {
    m_envelope.reset(0., 1., dx * dx + dy * dy, scale);
    m_envelope.add(c, px, py, dx, dy);
    Index first, last;
    m_envelope.changes(NO_INDEX, m_changes, first, last);
    bool found = false;
    for(const Label_change& ch : m_changes)
      if(ch.from == y && ch.to == x && (!found || std::abs(ch.u - near) < std::abs(u - near)))
      {
        u = ch.u;
        found = true;
      }
    return found;
  }

  // whether the least candidate of `c` has label `label` all along the segment (px, py) + u (dx, dy), u in
  // [0, 1] (Label_envelope: exact); `scale`: the size of the distances there
  bool has_one_label(const std::vector<Curve_candidate>& c, double px, double py, double dx, double dy, Index label,
                     double scale)
  {
    m_envelope.reset(0., 1., dx * dx + dy * dy, scale);
    m_envelope.add(c, px, py, dx, dy);
    Index first, last;
    m_envelope.changes(NO_INDEX, m_changes, first, last);
    return m_changes.empty() && first == label;
  }

  // The junction of the cells of labels l[0..2] in face f (candidates c): where their least candidates are
  // equal, from (x, y): each step takes the circles that hold at the point for the three labels and solves
  // three_circle_point() (exact once these circles hold at the point found); where these have no common point
  // near (the circles that hold at the junction are others), a Newton step on them (at most half the face's
  // size); each step is kept in the face (false if held back three times in a row). True if found inside the
  // face (to 1e-9 of its barycentric coordinates), the three equal and no label less there (to 1e-10 of the
  // distances).
  bool exact_junction(Index f, const std::vector<Curve_candidate>& c, const Index l[3], double& x, double& y)
  {
    const Face_frame fr(m_pieces.field().mesh(), f);
    const double size = std::abs(fr.x[1]) + std::abs(fr.x[2]) + std::abs(fr.y[2]);
    double px = x, py = y, last[3][3] = { { 0., 0., 0. }, { 0., 0., 0. }, { 0., 0., 0. } };
    bool stable = false, solved = false;
    int outside = 0;
    for(int step = 0; step < 32; ++step)
    {
      double cc[3][2], b[3], v[3], gx[3], gy[3];
      stable = step > 0;
      for(int i = 0; i < 3; ++i)
      {
        int which;
        Curve_field::value(c, px, py, l[i], which);
        if(which < 0)
          return false;
        c[static_cast<std::size_t>(which)].active_circle(px, py, cc[i][0], cc[i][1], b[i]);
        stable = stable && cc[i][0] == last[i][0] && cc[i][1] == last[i][1] && b[i] == last[i][2];
        last[i][0] = cc[i][0];
        last[i][1] = cc[i][1];
        last[i][2] = b[i];
        const double dx = px - cc[i][0], dy = py - cc[i][1], r = std::sqrt(dx * dx + dy * dy);
        v[i] = b[i] + r;
        gx[i] = r > 0. ? dx / r : 0.;
        gy[i] = r > 0. ? dy / r : 0.;
      }
      if(stable && solved)
        break;
      double nx, ny;
      solved = three_circle_point(cc, b, px, py, nx, ny) && std::hypot(nx - px, ny - py) <= size;
      if(!solved)
      {
        // Newton on (v1 - v0, v2 - v0) = 0 with the gradients of these circles
        const double a00 = gx[1] - gx[0], a01 = gy[1] - gy[0], a10 = gx[2] - gx[0], a11 = gy[2] - gy[0];
        const double det = a00 * a11 - a01 * a10, r0 = v[0] - v[1], r1 = v[0] - v[2];
        if(!(std::abs(det) > 0.) || !std::isfinite(det))
          return false;
        double sx = (a11 * r0 - a01 * r1) / det, sy = (-a10 * r0 + a00 * r1) / det;
        const double length = std::hypot(sx, sy);
        if(length > 0.5 * size)
        {
          sx *= 0.5 * size / length;
          sy *= 0.5 * size / length;
        }
        nx = px + sx;
        ny = py + sy;
      }
      // (kept in the face: the junction is in it, maybe within rounding of an edge, and beyond the edge the
      // candidates are not those of the face)
      Curve_point q = Curve_pieces::point_in_face(f, fr, nx, ny);
      if(!(q.b[0] >= 0. && q.b[1] >= 0. && q.b[2] >= 0.))
      {
        if(++outside == 3)
          return false;  // (held back three times in a row: the point is beyond the face)
        double sum = 0.;
        for(double& w : q.b)
          sum += (w = (std::max)(w, 0.));
        nx = (q.b[1] * fr.x[1] + q.b[2] * fr.x[2]) / sum;
        ny = q.b[2] * fr.y[2] / sum;
      }
      else
        outside = 0;
      px = nx;
      py = ny;
    }
    if(!solved)
      return false;
    const Curve_point p = Curve_pieces::point_in_face(f, fr, px, py);
    if(!(p.b[0] >= -1e-9 && p.b[1] >= -1e-9 && p.b[2] >= -1e-9))
      return false;
    double v[3];
    for(int i = 0; i < 3; ++i)
      v[i] = Curve_field::value(c, px, py, l[i]);
    const double high = (std::max)({ v[0], v[1], v[2] }), low = (std::min)({ v[0], v[1], v[2] });
    const double tolerance = 1e-10 * (high + size);
    if(!(high - low <= tolerance) || !(Curve_field::value(c, px, py) >= high - tolerance))
      return false;
    x = px;
    y = py;
    return true;
  }

  Curve_pieces& m_pieces;
  double m_tolerance;
  Label_envelope m_envelope;
  std::vector<Label_change> m_changes;
  struct Junction_memo
  {
    Index l[3];
    double from[2], at[2];
    bool found;
  };
  std::vector<Junction_memo> m_junctions;  // (memo_junction())
  std::vector<Curve_candidate> m_c;  // (the candidates of the face)
  std::vector<std::pair<double, double> > m_arc;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_GEOMETRY_H

