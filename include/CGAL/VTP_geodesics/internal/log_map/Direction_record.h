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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_DIRECTION_RECORD_H
#define CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_DIRECTION_RECORD_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/log_map/Tangent_frame.h>

#include <CGAL/assertions.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The log map (geodesic polar coordinates), a hook of the propagation like the path record: per vertex the
// angle theta of the offer that gave its distance, with no trace-back.
//
// Every window carries `angle`: the direction of the x-axis of its edge's frame in the *turning frame* of its
// origin, so that the ray from the origin's image (sx, sy) to a point (px, py) leaves the origin at
// gamma = angle + atan2(py - sy, px - sx) (children add the change of frame, Triangle_propagation.h).
// - A source vertex c: the turning frame is its unscaled frame (Tangent_frame.h, minus the user's reference
//   divided by the scale): theta = scale(c) * gamma.
// - A source point (inside a face or an edge): the frame of the user's face: theta = gamma.
// - A pseudo-source s (a saddle or border vertex the geodesic passes through): the turning frame is the
//   tangent plane of the source, s's directions turned so that the line that reaches s goes on straight
//   (straightest geodesics: equal angles on both sides, S(s) / 2 each at an interior vertex; at a border
//   vertex the continued line makes the angle pi with the incoming one). A vertex v behind s gets the point
//   P(s) + |s v| (cos gamma, sin gamma) of the tangent plane, P(s) = rho(s) (cos theta(s), sin theta(s)),
//   and theta(v) its angle (rho stays the distance). With `strict`, theta(v) = theta(s) (polyhedral).
//
// Cost: an offer (a distance lowered) costs one atan2; behind a pseudo-source, theta(v) is found once per
// vertex after the run (finish()): until then theta[v] holds gamma and the sign bit of turn[v] says so, and
// |s v| is D(v) - D(s) (the offer's distance is D(s) plus it). The turning angle of a pseudo-source needs the
// angle of the incoming ray in its fan: products of unit vectors around the fan, two atan2, no atan2 per
// corner.
//
// The fan of an interior vertex is a circle of length S (the sum of its corner angles), not 2 pi: the turn
// of a half-edge at fan angle phi from the continued line at fan angle `straight` is phi - straight taken in
// [-S/2, S/2) (emission_angles()). (Taken modulo 2 pi, as it was until December 2026, it was off by the
// excess S - 2 pi for every half-edge on the far side of the fan's first half-edge: behind 553 of the 773
// vertices of the elephant that lie behind one saddle reached straight from vertex 0.)
//
// Memory: 17 bytes per vertex (theta, turn, cut, via), allocated only when the log map is asked for; 8
// bytes per window (Window::angle).
struct Ray_arrival
{
  double angle;   // the direction of the x-axis of the frame F below, in the turning frame of the origin
  double dx, dy;  // the vector from the origin's image to the vertex, in F
  Index g;        // a half-edge leaving the vertex, in a face of the ray's last stretch
  double gx, gy;  // its direction in F (a vector of any length)
  Index origin = NO_INDEX;  // if not NO_INDEX, the origin of the ray (a path bent at a vertex: that vertex)
};

// A vertex source of the log map: its reference half-edge (NO_INDEX: the border rule) and the theta of the
// user's reference direction (subtracted).
struct Log_map_source
{
  Index vertex = NO_INDEX;
  Index reference = NO_INDEX;
  double offset = 0.;
};

class Direction_record
{
public:
  std::vector<double> theta;  // per vertex
  // per vertex, a pseudo-source: the turning angle of its fan, in [0, 2 pi) (a float: 1e-7 rad behind
  // pseudo-sources is far below the mesh's own error there, and keeps the record small; a value near 0, as
  // on flat domains, is kept to 1e-7 of itself); its sign bit set while theta[v] holds gamma (to be resolved
  // by finish())
  std::vector<float> turn;
  // per vertex, a pseudo-source in a closed fan: the fan angle of the continued line is
  // angle_in_0_2pi(theta[v] - turn[v]) + 2 pi cut[v] (on_offer(), emission_angles())
  std::vector<signed char> cut;
  // per vertex: the last vertex its geodesic passes through, NO_INDEX, or -2 - k for the vertex source k
  std::vector<Index> via;
  // Set by the caller before a run: the vertex sources, and per seed the direction of the x-axis of its
  // half-edge's frame (edge seeds: the seed's half-edge; face seeds: 3f) in the user's face frame, minus the
  // user's reference (point seeds only).
  std::vector<Log_map_source> vertex_sources;
  std::vector<double> seed_angle;

  // Prepares a run (throws Invalid_input_error for a source vertex whose faces are not one fan).
  void start(const Mesh_arrays& m, bool active, bool strict)
  {
    m_active = active;
    m_strict = strict;
    m_mesh = &m;
    if(!active)
    {
      theta.clear();
      turn.clear();
      cut.clear();
      via.clear();
      return;
    }
    const std::size_t nv = static_cast<std::size_t>(m.nv);
    theta.assign(nv, 0.);
    turn.assign(nv, 0.);
    cut.assign(nv, 0);
    via.assign(nv, NO_INDEX);
    start_sources(m);
  }

  // The same, when the previous run on `m` was active too: only the vertices of `previous` (all those it
  // reached) are cleared (Local_propagation.h).
  void restart(const Mesh_arrays& m, bool active, bool strict, const std::vector<Index>& previous)
  {
    if(!active || !m_active || m_mesh != &m || theta.size() != static_cast<std::size_t>(m.nv))
      return start(m, active, strict);
    m_strict = strict;
    for(Index v : previous)
    {
      theta[v] = 0.;
      turn[v] = 0.f;
      cut[v] = 0;
      via[v] = NO_INDEX;
    }
    start_sources(m);
  }

private:
  void start_sources(const Mesh_arrays& m)
  {
    m_frames.clear();
    for(const Log_map_source& s : vertex_sources)
    {
      Vertex_frame frame;
      if(!make_vertex_frame(m, s.vertex, s.reference, frame))
        throw Invalid_input_error("the log map needs a source vertex whose faces form one fan around it");
      via[s.vertex] = -2 - static_cast<Index>(m_frames.size());
      m_frames.push_back(std::make_pair(frame, s.offset));
    }
  }

public:
  bool is_active() const { return m_active; }
  bool is_source(Index v) const { return via[v] < NO_INDEX; }

  // An offer of `distance` from `origin` to v, whose distance was `old`. It gives v its
  // direction if it is shorter by more than rounding (Path_record::tie); on a tie, if its key is smaller: the
  // last vertex it passes through (none first, then the least index), then theta (or, behind a vertex in the
  // default mode, gamma) in [0, 2 pi). So the choice does not depend on the order of the offers (VTP and
  // PVTP), and a path that grazes a pseudo-source goes on straight.
  template <class Arrival>
  void on_offer(Index v, Index origin, double distance, double old, const Arrival& arrival)
  {
    const bool lower = !(old < std::numeric_limits<double>::infinity()) || distance < old * (1. - 1e-12);
    if(!lower && is_source(v))
      return;
    const Ray_arrival r = arrival();
    double t, a;
    Index last;
    direction_of(origin, r, t, a, last);
    if(!lower && !(last < via[v] || (last == via[v] && angle_in_0_2pi(t) < angle_in_0_2pi(theta[v]))))
      return;
    theta[v] = t;
    via[v] = last;
    const bool lazy = !m_strict && last >= 0;  // theta[v] holds gamma
    const Mesh_arrays& m = *m_mesh;
    CGAL_assertion(m_strict || theta[v] == a || std::isnan(a));  // (emission_angles() reads `a` there)
    float turning = 0.f;
    signed char turns = 0;
    if(!m_strict && m.is_pseudo_source[v] && r.g != NO_INDEX)
    {
      // the turning angle: the continued line (beta_in + S/2, or + pi at the border) goes on at `a`; beta_in,
      // the direction of the reversed ray from the fan's first half-edge
      bool border = false;
      double sum = 0., phi = 0.;
      fan_angles(r.g, border, sum, phi);
      const double beta_in = phi + std::atan2(r.gy * r.dx - r.gx * r.dy, -(r.gx * r.dx + r.gy * r.dy));
      // in a closed fan, the continued line's angle in [0, S) (the fan is a circle of length S, not 2 pi):
      // emission_angles() finds it again as a - turning + 2 pi turns
      const double straight = border ? beta_in + TANGENT_FRAME_PI : wrap_in_fan(beta_in + 0.5 * sum, sum, 0.);
      turning = std::fabs(static_cast<float>(angle_in_0_2pi(a - straight)));  // (+0 for -0: the flag below)
      if(!border)
        turns = static_cast<signed char>((std::max)(-100., (std::min)(100., std::nearbyint((straight - angle_in_0_2pi(
                                           a - static_cast<double>(turning))) / (2. * TANGENT_FRAME_PI)))));
    }
    turn[v] = lazy ? -turning : turning;
    cut[v] = turns;
  }

  // The direction of the ray r from `origin` at its end: theta (gamma behind a vertex in the default mode),
  // the direction of its last stretch in the tangent plane of the source (a), the last vertex it passes
  // through (last).
  void direction_of(Index origin, const Ray_arrival& r, double& t, double& a, Index& last) const
  {
    const Mesh_arrays& m = *m_mesh;
    if(r.origin != NO_INDEX)
      origin = r.origin;
    const double gamma = r.angle + std::atan2(r.dy, r.dx);
    t = a = gamma;
    last = NO_INDEX;
    if(origin >= m.nv)
      return;
    if(is_source(origin))
    {
      a = t = m_frames[static_cast<std::size_t>(-2 - via[origin])].first.scale * gamma;
      return;
    }
    last = origin;
    if(m_strict)
      t = theta[origin];
  }

  // After the run: theta of every vertex behind a vertex (default mode), from the coordinates of that vertex,
  // nearer to the source first: P(s) + (D(v) - D(s)) (cos gamma, sin gamma). `reached`: if given, the only
  // vertices the run reached (a local run, Local_propagation.h: the cost of its patch, not of the mesh).
  void finish(const std::vector<double>& dist, const std::vector<Index>* reached = nullptr)
  {
    if(!m_active || m_strict)
      return;
    std::vector<Index> chain;
    const std::size_t nv = theta.size(), n = reached ? reached->size() : nv;
    for(std::size_t i = 0; i < n; ++i)
    {
      Index x = reached ? (*reached)[i] : static_cast<Index>(i);
      chain.clear();
      while(std::signbit(turn[x]) && chain.size() <= nv)  // (a cycle of equal distances is cut)
      {
        chain.push_back(x);
        if(via[x] < 0)
          break;
        x = via[x];
      }
      for(std::size_t k = chain.size(); k-- > 0;)
      {
        const Index u = chain[k], s = via[u];
        turn[u] = std::fabs(turn[u]);
        if(s < 0)
          continue;
        const double rho = dist[s], run = dist[u] - rho, t = theta[s], gamma = theta[u];
        if(rho < std::numeric_limits<double>::infinity() && run < std::numeric_limits<double>::infinity())
          theta[u] = std::atan2(rho * std::sin(t) + run * std::sin(gamma), rho * std::cos(t) + run * std::cos(gamma));
      }
    }
  }

  // The direction of h (leaving v) in the turning frame of v, for the windows and the rays v starts (v a
  // source or a pseudo-source); false when they need none (strict, v a pseudo-source).
  bool emission_angles(Index v, std::vector<std::pair<Index, double> >& out)
  {
    const Mesh_arrays& m = *m_mesh;
    out.clear();
    if(is_source(v))
    {
      const auto& f = m_frames[static_cast<std::size_t>(-2 - via[v])];
      for(std::size_t i = 0; i < f.first.halfedges.size(); ++i)
        out.push_back(std::make_pair(f.first.halfedges[i], f.first.phi[i] - f.second / f.first.scale));
      return true;
    }
    if(m_strict)
      return false;
    // one walk per fan (a vertex of a manifold mesh has one; others are found from their corners): a
    // half-edge at fan angle phi leaves at turning + phi; in a closed fan, phi is first moved by a multiple of
    // S into [straight - S/2, straight + S/2) (the fan is a circle of length S, not 2 pi), straight the angle of
    // the continued line (on_offer())
    const double t = std::fabs(turn[v]);
    const double straight = angle_in_0_2pi(theta[v] - t) + 2. * TANGENT_FRAME_PI * cut[v];
    const Index begin = m.corner_begin[v], degree = m.corner_begin[v + 1] - begin;
    for(Index c = begin; c < begin + degree && static_cast<Index>(out.size()) < degree; ++c)
    {
      const Index h = m.corners[c];
      bool seen = false;
      for(std::size_t i = 0; i < out.size() && !seen; ++i)
        seen = out[i].first == h;
      if(seen)
        continue;
      bool border = false;
      const std::size_t fan = out.size();
      const double sum = walk_fan(fan_first(h, border), [&](Index g, double phi) { out.push_back(std::make_pair(g, t + phi)); });
      if(border)
        continue;
      // phi in [0, S), growing along the walk, and straight - S/2 in [-S/2, S/2): a first stretch moves up
      // by S, or a last one down
      const double low = t + straight - 0.5 * sum;
      if(low >= t)
        for(std::size_t i = fan; i < out.size() && out[i].second < low; ++i)
          out[i].second += sum;
      else
        for(std::size_t i = out.size(); i-- > fan && out[i].second >= low + sum;)
          out[i].second -= sum;
    }
    return true;
  }

  // The angle of h in `angles` (as left by emission_angles()).
  static double angle_of(const std::vector<std::pair<Index, double> >& angles, Index h)
  {
    for(const auto& a : angles)
      if(a.first == h)
        return a.second;
    CGAL_assertion(false);
    return 0.;
  }

private:
  // The fan of faces around source(h) that holds h: its first half-edge, counter-clockwise (the border
  // half-edge leaving the vertex, or the least half-edge of a closed fan).
  Index fan_first(Index h, bool& border) const
  {
    const Mesh_arrays& m = *m_mesh;
    const Index v = m.source[h];
    const Index degree = m.corner_begin[v + 1] - m.corner_begin[v];
    Index first = h, g = h;
    border = false;
    for(Index k = 0; k < degree; ++k)
    {
      const Index p = cw_outgoing(m, g);
      if(p == NO_INDEX)
      {
        border = true;
        return g;
      }
      if(p == h)
        break;
      g = p;
      first = (std::min)(first, g);
    }
    return first;
  }

  // Walks the fan from its first half-edge: f(g, phi) for each half-edge g of the fan, phi its unscaled
  // angle; returns the sum of the corner angles.
  template <class F>
  double walk_fan(Index first, const F& f) const
  {
    const Mesh_arrays& m = *m_mesh;
    const Index v = m.source[first];
    const Index degree = m.corner_begin[v + 1] - m.corner_begin[v];
    double sum = 0.;
    Index g = first;
    for(Index k = 0; k < degree && g != NO_INDEX; ++k)
    {
      f(g, sum);
      sum += corner_angle_of(m, g);
      g = ccw_outgoing(m, g);
      if(g == first)
        break;
    }
    return sum;
  }

  // The sum of the corner angles of the fan of h and the unscaled angle of h in it: the unit vectors of the
  // corners multiplied around the fan (each corner below pi: a turn is counted when the product crosses the
  // positive x-axis), one atan2 at the first half-edge and one at the end. A closed fan is walked once from h
  // (its first half-edge, the least, is met on the way); a border fan from its border half-edge.
  void fan_angles(Index h, bool& border, double& sum, double& phi_of_h) const
  {
    const Mesh_arrays& m = *m_mesh;
    const Index degree = m.corner_begin[m.source[h] + 1] - m.corner_begin[m.source[h]];
    double z[2] = {1., 0.}, at_least[2] = {1., 0.};
    int turns = 0, turns_at_least = 0;
    Index least = h, g = h;
    for(Index k = 0; k < degree; ++k)
    {
      if(g < least)
      {
        least = g;
        at_least[0] = z[0];
        at_least[1] = z[1];
        turns_at_least = turns;
      }
      turn_by_corner(g, z, turns);
      g = ccw_outgoing(m, g);
      if(g == NO_INDEX)
        break;
      if(g == h)
      {
        border = false;
        sum = product_angle(z[0], z[1], turns);
        phi_of_h = least == h ? 0. : sum - product_angle(at_least[0], at_least[1], turns_at_least);
        return;
      }
    }
    const Index first = fan_first(h, border);
    z[0] = 1.;
    z[1] = 0.;
    turns = 0;
    phi_of_h = 0.;
    g = first;
    for(Index k = 0; k < degree && g != NO_INDEX; ++k)
    {
      if(g == h)
        phi_of_h = product_angle(z[0], z[1], turns);
      turn_by_corner(g, z, turns);
      g = ccw_outgoing(m, g);
      if(g == first)
        break;
    }
    sum = product_angle(z[0], z[1], turns);
  }

  // z (a unit vector, `turns` whole turns) turned by the corner angle at source(g) in face(g)
  void turn_by_corner(Index g, double z[2], int& turns) const
  {
    const Halfedge_geometry q = m_mesh->geometry[g];
    const double ux = q.l_prev > 0. ? q.cx / q.l_prev : 1., uy = q.l_prev > 0. ? q.cy / q.l_prev : 0.;
    const double x = z[0] * ux - z[1] * uy, y = z[0] * uy + z[1] * ux;
    if(z[1] < 0. && !(y < 0.))
      ++turns;
    z[0] = x;  // (products of unit vectors: no renormalisation for the few corners of a fan)
    z[1] = y;
  }

  static double product_angle(double zx, double zy, int turns)
  {
    double a = std::atan2(zy, zx);
    if(a < 0.)
      a += 2. * TANGENT_FRAME_PI;
    return 2. * TANGENT_FRAME_PI * turns + a;
  }

  const Mesh_arrays* m_mesh = nullptr;
  bool m_active = false, m_strict = false;
  std::vector<std::pair<Vertex_frame, double> > m_frames;  // of the vertex sources, with their offsets
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_DIRECTION_RECORD_H
