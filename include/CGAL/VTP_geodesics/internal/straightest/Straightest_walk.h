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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_STRAIGHTEST_WALK_H
#define CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_STRAIGHTEST_WALK_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/log_map/Tangent_frame.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// Straightest geodesics (the exponential map) on the mesh arrays: from a point of a face and a direction in
// the frame of that face (the frame of its half-edge 3f, Face_frame), walk straight for a given length.
// Inside a face the walk is a segment; across an edge the next face is unfolded into the plane of the face
// before (the direction keeps its angle with the edge); at a vertex the walk leaves so that the angles on its
// two sides are equal, half of the vertex's angle sum each (Polthier and Schmies' straightest geodesics; on
// a flat vertex that is the straight line). A walk that reaches the border ends exactly on it; a walk that
// reaches a border vertex ends there; a walk that enters a face of (almost) zero area ends on its edge.
//
// Passing through a vertex: a vertex is taken as hit when it lies ahead of the walk, within the face being
// crossed, at a distance of at most `vertex_tolerance` times the face's longest edge from the line of the
// walk (decided per face, in the face's own frame: deterministic). The walk then goes on from the vertex
// exactly, so rounding does not accumulate through vertices. A walk along an edge is a walk through its
// vertices.

// A point of a walk: a face and its barycentric coordinates, in the order of the face's corners
// (source(3f), source(3f+1), source(3f+2)).
struct Walk_point
{
  Index face = NO_INDEX;
  double b[3] = { 0., 0., 0. };
};

struct Walk_result
{
  enum Stop { LENGTH, BORDER, DEGENERATE_FACE, NUMERICAL_FAILURE };
  std::vector<Walk_point> points;  // the start, every crossing of an edge, every vertex, the end
  Index end_face = NO_INDEX;       // the face of the end point (points.back().face)
  double dx = 1., dy = 0.;         // the unit direction at the end, in the frame of 3 * end_face
  double length = 0.;              // the length walked (in the unit of the arrays)
  Stop stop = LENGTH;
  Index end_vertex = NO_INDEX;     // the vertex the walk ends at, if it ends at one
};

class Straightest_walk
{
public:
  // where a point lies in its face: inside, on edge k (from corner k to corner k+1), at corner k
  enum Place { INSIDE, ON_EDGE, AT_CORNER };

  struct State
  {
    Index face = NO_INDEX;
    Place place = INSIDE;
    int k = 0;
    double px = 0., py = 0.;  // the point, in the frame of 3 * face
    double dx = 1., dy = 0.;  // the unit direction, in the same frame
  };

  static constexpr double vertex_tolerance = 1e-10;

  explicit Straightest_walk(const Mesh_arrays& m) : m_m(m) {}

  // The sum of the corner angles of the fan around the source of half-edge h (turning counter-clockwise from
  // h), and whether the fan reaches the border.
  double fan_angle_sum(Index h, bool& border) const
  {
    border = false;
    double sum = 0.;
    const Index v = m_m.source[h];
    const Index limit = m_m.corner_begin[v + 1] - m_m.corner_begin[v];
    Index g = h;
    for(Index i = 0; i < limit; ++i)
    {
      sum += corner_angle(g);
      const Index o = ccw_outgoing(m_m, g);
      if(o == NO_INDEX)
      {
        border = true;
        break;
      }
      g = o;
      if(g == h)
        break;
    }
    // a border vertex: its fan counter-clockwise from h may not be the whole of it
    if(!border)
      for(Index i = m_m.corner_begin[v]; i < m_m.corner_begin[v + 1]; ++i)
        if(m_m.opposite[m_m.corners[i]] == NO_INDEX)
          border = true;
    return sum;
  }

  // the corner angle at the source of h in face(h) (that of the tangent frame)
  double corner_angle(Index h) const { return corner_angle_of(m_m, h); }

  // The state at the source of half-edge h going at the angle phi (counter-clockwise, not scaled) from h,
  // turning around the vertex through the faces after face(h) when phi is larger than the corner's angle.
  // Returns false if the turn reaches the border (the direction is not in the surface) or a face of zero area.
  bool state_at_corner(Index h, double phi, State& s) const
  {
    const Index v = m_m.source[h];
    const Index limit = m_m.corner_begin[v + 1] - m_m.corner_begin[v];
    for(Index i = 0; i <= limit; ++i)
    {
      const double alpha = corner_angle(h);
      if(phi <= alpha || i == limit)
      {
        phi = (std::min)((std::max)(phi, 0.), alpha);
        return corner_state(h, phi, s);
      }
      phi -= alpha;
      const Index o = ccw_outgoing(m_m, h);
      if(o == NO_INDEX)
        return false;
      h = o;
    }
    return false;
  }

  // The state at the point of face f of barycentric coordinates b (non-negative, of sum 1) going in the
  // direction (dx, dy) of the frame of 3f (unit). A point on an edge whose direction points out of the face
  // starts in the face beyond (false on the border: the walk cannot start). A corner (one coordinate 1) is the
  // vertex: the angle of the direction from the corner's edge, counter-clockwise in the face, is continued
  // around the vertex (not scaled; a negative angle goes clockwise). False if that leaves the surface.
  bool state_at_point(Index f, const double b[3], double dx, double dy, State& s) const
  {
    for(int j = 0; j < 3; ++j)
      if(b[j] == 1.)
      {
        const Face_frame fr(m_m, f);
        double ux, uy, along, left;
        fr.direction(j, ux, uy);
        rotate_into(dx, dy, ux, uy, along, left);
        double phi = std::atan2(left, along);
        const Index h = 3 * f + j;
        if(phi < 0.)
        {
          bool border = false;
          const double sum = fan_angle_sum(h, border);
          if(border)
            return false;
          phi += sum;
        }
        return state_at_corner(h, phi, s);
      }
    s.face = f;
    s.place = INSIDE;
    s.k = 0;
    s.dx = dx;
    s.dy = dy;
    const Halfedge_geometry g = m_m.geometry[3 * f];
    s.px = b[1] * g.length + b[2] * g.cx;
    s.py = b[2] * g.cy;
    for(int j = 0; j < 3; ++j)
      if(b[(j + 2) % 3] == 0.)
      {
        s.place = ON_EDGE;
        s.k = j;
        const Face_frame fr(m_m, f);
        double ux, uy, along, left;
        fr.direction(j, ux, uy);
        rotate_into(dx, dy, ux, uy, along, left);
        if(left < 0.)
          return cross_edge(s, fr, b[(j + 1) % 3]);
      }
    return true;
  }

  // The state at the source of h going at the angle phi (0 <= phi <= the corner's angle) from h in face(h);
  // false if face(h) has (almost) zero area.
  bool corner_state(Index h, double phi, State& s) const
  {
    s.face = Mesh_arrays::face(h);
    s.place = AT_CORNER;
    s.k = static_cast<int>(h - 3 * s.face);
    const Face_frame fr(m_m, s.face);
    s.px = fr.x[s.k];
    s.py = fr.y[s.k];
    double ux, uy;
    fr.direction(s.k, ux, uy);
    const double cs = std::cos(phi), sn = std::sin(phi);
    s.dx = ux * cs - uy * sn;
    s.dy = ux * sn + uy * cs;
    return !m_m.is_degenerate_face[static_cast<std::size_t>(s.face)];
  }

  // Walks `length` from `s` (length >= 0) and writes the walk to `r`.
  void walk(State s, double length, Walk_result& r) const
  {
    r.points.clear();
    r.length = 0.;
    r.stop = Walk_result::LENGTH;
    r.end_vertex = NO_INDEX;
    r.points.push_back(point_of(s));
    double left = length;
    // each step crosses a face or turns at a vertex, and moves on: a walk that stops moving (crossings of
    // zero length one after the other) is a numerical failure
    int stalled = 0;
    while(true)
    {
      if(stalled > 8)
        return finish(s, r, Walk_result::NUMERICAL_FAILURE);
      if(m_m.is_degenerate_face[static_cast<std::size_t>(s.face)])
        return finish(s, r, Walk_result::DEGENERATE_FACE);
      const Face_frame fr(m_m, s.face);
      double c[3], ahead[3];
      for(int j = 0; j < 3; ++j)
      {
        const double rx = fr.x[j] - s.px, ry = fr.y[j] - s.py;
        c[j] = s.dx * ry - s.dy * rx;  // > 0: corner j on the left of the line of the walk
        ahead[j] = s.dx * rx + s.dy * ry;
      }
      if(s.place == AT_CORNER)
        c[s.k] = 0., ahead[s.k] = 0.;
      // a vertex hit: the nearest corner ahead within the tolerance of the line
      const double tolerance = vertex_tolerance * longest(fr);
      int hit = -1;
      for(int j = 0; j < 3; ++j)
        if(ahead[j] > 0. && std::abs(c[j]) <= tolerance && (hit < 0 || ahead[j] < ahead[hit]))
          hit = j;
      if(hit >= 0)
      {
        if(ahead[hit] >= left)
          return end_inside(s, left, r);
        left -= ahead[hit];
        r.length += ahead[hit];
        s.place = AT_CORNER;
        s.k = hit;
        s.px = fr.x[hit];
        s.py = fr.y[hit];
        r.points.push_back(point_of(s));
        if(!turn_at_vertex(s, r))
          return;
        continue;
      }
      // the edge where the walk leaves: from a corner on the right to a corner on the left
      int exit = -1;
      for(int j = 0; j < 3; ++j)
        if(c[j] < 0. && c[(j + 1) % 3] > 0. && !(s.place == ON_EDGE && s.k == j))
          exit = j;
      if(exit < 0)
        return finish(s, r, Walk_result::NUMERICAL_FAILURE);
      const int j1 = (exit + 1) % 3;
      const double w = c[exit] / (c[exit] - c[j1]);  // in (0, 1)
      const double qx = fr.x[exit] + w * (fr.x[j1] - fr.x[exit]), qy = fr.y[exit] + w * (fr.y[j1] - fr.y[exit]);
      const double t = (std::max)(0., s.dx * (qx - s.px) + s.dy * (qy - s.py));
      if(t >= left)
        return end_inside(s, left, r);
      stalled = t > 0. ? 0 : stalled + 1;
      left -= t;
      r.length += t;
      s.place = ON_EDGE;
      s.k = exit;
      s.px = qx;
      s.py = qy;
      Walk_point q;
      q.face = s.face;
      q.b[exit] = 1. - w;
      q.b[j1] = w;
      r.points.push_back(q);
      const Index beyond = m_m.opposite[3 * s.face + exit];
      if(beyond != NO_INDEX && m_m.is_degenerate_face[static_cast<std::size_t>(Mesh_arrays::face(beyond))])
        return finish(s, r, Walk_result::DEGENERATE_FACE);  // on the edge, in the face before
      if(!cross_edge(s, fr, w))
        return finish(s, r, Walk_result::BORDER);
    }
  }

  // the barycentric coordinates of the point of s in its face (exact on edges and at corners)
  Walk_point point_of(const State& s) const
  {
    Walk_point q;
    q.face = s.face;
    if(s.place == AT_CORNER)
    {
      q.b[s.k] = 1.;
      return q;
    }
    const Halfedge_geometry g = m_m.geometry[3 * s.face];
    double b2 = g.cy > 0. ? s.py / g.cy : 0.;
    double b1 = g.length > 0. ? (s.px - b2 * g.cx) / g.length : 0.;
    double b0 = 1. - b1 - b2;
    b0 = (std::max)(0., b0), b1 = (std::max)(0., b1), b2 = (std::max)(0., b2);
    const double sum = b0 + b1 + b2;
    q.b[0] = b0 / sum, q.b[1] = b1 / sum, q.b[2] = b2 / sum;
    if(s.place == ON_EDGE)  // on the edge exactly
    {
      const int j1 = (s.k + 1) % 3, j2 = (s.k + 2) % 3;
      const double e = q.b[s.k] + q.b[j1];
      q.b[s.k] = e > 0. ? q.b[s.k] / e : 1.;
      q.b[j1] = 1. - q.b[s.k];
      q.b[j2] = 0.;
    }
    return q;
  }

private:
  static double longest(const Face_frame& fr)
  {
    double l = 0.;
    for(int j = 0; j < 3; ++j)
      l = (std::max)(l, std::sqrt(fr.ex(j) * fr.ex(j) + fr.ey(j) * fr.ey(j)));
    return l;
  }

  void end_inside(State& s, double left, Walk_result& r) const
  {
    if(left > 0.)
    {
      s.px += left * s.dx;
      s.py += left * s.dy;
      s.place = INSIDE;
      r.length += left;
      r.points.push_back(point_of(s));
    }
    finish(s, r, Walk_result::LENGTH);
  }

  void finish(const State& s, Walk_result& r, Walk_result::Stop stop) const
  {
    r.stop = stop;
    r.end_face = s.face;
    r.dx = s.dx;
    r.dy = s.dy;
    r.end_vertex = s.place == AT_CORNER ? m_m.source[3 * s.face + s.k] : NO_INDEX;
    if(r.points.empty() || r.points.back().face != s.face)
      r.points.push_back(point_of(s));
  }

  // From edge s.k of s.face, at the fraction w from its corner k, into the face beyond; false on the border.
  bool cross_edge(State& s, const Face_frame& fr, double w) const
  {
    const Index h = 3 * s.face + s.k;
    const Index o = m_m.opposite[h];
    if(o == NO_INDEX)
      return false;
    double ux, uy;
    fr.direction(s.k, ux, uy);
    double along, left;  // the direction in the frame of the edge (left: into s.face, negative here)
    rotate_into(s.dx, s.dy, ux, uy, along, left);
    const Index g = Mesh_arrays::face(o);
    const int m = static_cast<int>(o - 3 * g);
    const Face_frame fg(m_m, g);
    double vx, vy;
    fg.direction(m, vx, vy);
    // the edge is reversed in g and its left side is g's interior: the direction turns by pi
    const double a = -along, b = -left;
    double dx = a * vx - b * vy, dy = a * vy + b * vx;
    const double n = std::sqrt(dx * dx + dy * dy);
    s.face = g;
    s.k = m;
    s.place = ON_EDGE;
    s.dx = dx / n;
    s.dy = dy / n;
    const int m1 = (m + 1) % 3;
    s.px = fg.x[m] + (1. - w) * (fg.x[m1] - fg.x[m]);
    s.py = fg.y[m] + (1. - w) * (fg.y[m1] - fg.y[m]);
    return true;
  }

  // At the vertex of corner s.k of s.face, reached along s.d: leaves it with half the angle sum on each side.
  // Returns false (the walk has ended, r finished) at a border vertex or a face of zero area.
  bool turn_at_vertex(State& s, Walk_result& r) const
  {
    const Index h = 3 * s.face + s.k;
    bool border = false;
    const double sum = fan_angle_sum(h, border);
    if(border)
    {
      finish(s, r, Walk_result::BORDER);
      return false;
    }
    // the angle, in the corner, of the direction back to where the walk comes from
    const Face_frame fr(m_m, s.face);
    double ux, uy;
    fr.direction(s.k, ux, uy);
    double along, left;
    rotate_into(-s.dx, -s.dy, ux, uy, along, left);
    const double beta = (std::min)((std::max)(std::atan2(left, along), 0.), corner_angle(h));
    State next;
    if(!state_at_corner(h, beta + 0.5 * sum, next))
    {
      finish(s, r, Walk_result::DEGENERATE_FACE);
      return false;
    }
    s = next;
    return true;
  }

  const Mesh_arrays& m_m;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_STRAIGHTEST_WALK_H
