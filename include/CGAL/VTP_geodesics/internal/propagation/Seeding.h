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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_SEEDING_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_SEEDING_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/mesh/Surface_point.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A source of the propagation, at distance 0: a vertex, a point inside an edge, or a point inside a face.
// `label` is the index of the source in the user's list (the nearest-source label it gives).
//
// A piece of a source curve is a seed too (`segment`): the segment from (x, y) to (x1, y1) of face `element`
// (kind IN_FACE, in the frame of 3 element), seen from one side (`side`: +1 its left, -1 its right, left =
// face normal x direction). Its windows are line windows (windows/Window.h); its ends are point seeds of
// their own (source_curves/Curve_seeds.h).
struct Seed : Surface_point
{
  Index label = 0;
  Index user_face = NO_INDEX;  // a point given as a face location: the face given (the frame of the log map)
  bool segment = false;
  int side = 0;
  double x1 = 0., y1 = 0.;
  bool curve_end = false;  // a point seed that ends an open curve
};

// Whether some seed of `seeds` is a piece of a curve.
inline bool has_segments(const std::vector<Seed>& seeds)
{
  for(const Seed& s : seeds)
    if(s.segment)
      return true;
  return false;
}

// The part of [t0, t1] where a + b t lies in [lo, hi] (t0 > t1 when it is empty).
inline void clip_linear(double a, double b, double lo, double hi, double& t0, double& t1)
{
  if(b == 0.)
  {
    if(!(a >= lo && a <= hi))
      t1 = t0 - 1.;
    return;
  }
  double u = (lo - a) / b, v = (hi - a) / b;
  if(u > v)
    std::swap(u, v);
  t0 = (std::max)(t0, u);
  t1 = (std::min)(t1, v);
}

// Starts the propagation from one side of segment seed s (origin `origin`): the vertices and the targets of
// its face seen from that side within its strip (the points whose nearest point of the segment's line lies on
// the segment) get their distance to the segment's line, and each edge of the face gets, on its other side, the
// line window of the part of it in the strip on that side. The rest of the face is reached from the ends of
// the segment (point seeds).
inline void seed_segment(Propagation_state& st, const Seed& s, Index origin)
{
  const Mesh_arrays& m = *st.mesh;
  const Index f = s.element, h0 = 3 * f;
  const Face_frame frame(m, f);
  const double ex = s.x1 - s.x, ey = s.y1 - s.y;
  const double len = std::sqrt(ex * ex + ey * ey);
  if(!(len > 0.))
    return;
  const double dx = ex / len, dy = ey / len;
  const double nx = -s.side * dy, ny = s.side * dx;
  for(int k = 0; k < 3; ++k)
  {
    const double px = frame.x[k] - s.x, py = frame.y[k] - s.y;
    const double along = px * dx + py * dy, off = px * nx + py * ny;
    if(along >= 0. && along <= len && off >= 0.)
      st.light(m.source[h0 + k], straight_offer(off, origin));
  }
  st.stop.for_each_target_in_face(f, [&](Index t) {
    const Target& target = st.stop.targets()[static_cast<std::size_t>(t)];
    const double px = target.x[0] - s.x, py = target.y[0] - s.y;
    const double along = px * dx + py * dy, off = px * nx + py * ny;
    if(along >= 0. && along <= len && off >= 0.)
      st.offer_to_target(t, off, origin);
  });
  for(int k = 0; k < 3; ++k)
  {
    const Index o = m.opposite[h0 + k];
    double ux, uy;
    if(o == NO_INDEX || !(frame.direction(k, ux, uy) > 0.))
      continue;
    const double L = m.geometry[h0 + k].length;
    // the edge is (x[k], y[k]) + t (ux, uy), 0 <= t <= L
    const double px = frame.x[k] - s.x, py = frame.y[k] - s.y;
    double t0 = 0., t1 = L;
    clip_linear(px * dx + py * dy, ux * dx + uy * dy, 0., len, t0, t1);     // in the strip
    // the segment along this edge (both ends on it, to rounding): the front leaves the edge itself
    const double tolerance = 1e-12 * (len + L);
    const double off0 = px * nx + py * ny, off1 = off0 + L * (ux * nx + uy * ny);
    const bool along = std::abs(off0) <= tolerance && std::abs(off1) <= tolerance;
    if(!along)
      clip_linear(off0, ux * nx + uy * ny, 0., HUGE_VAL, t0, t1);  // on this side
    if(!(t1 > t0))
      continue;
    // in the frame of o (from vertex k+1 to vertex k, the other face above)
    Window w;
    rotate_into(nx, ny, -ux, -uy, w.sx, w.sy);
    if(!(w.sy > 0.))
      continue;  // the front leaves the edge into the face of the segment: nothing crosses
    w.sigma = (px + L * ux) * nx + (py + L * uy) * ny;
    if(along)
    {
      // exactly: perpendicular to the edge, at distance 0 on it
      w.sx = 0.;
      w.sy = 1.;
      w.sigma = 0.;
    }
    w.b0 = L - t1;
    w.b1 = L - t0;
    w.angle = 0.;
    w.origin = origin;
    st.store_emitted(o, w);
  }
}


// The seed of the point of face f with barycentric coordinates (b0, b1, b2) with respect to the vertices
// source(3f), source(3f+1), source(3f+2) (non-negative, sum 1). A point with two zero coordinates is the
// vertex it denotes; a point with one zero coordinate is a point of an edge, given on the lower of the two
// half-edges of the edge, so that the same point gives the same seed from either face. A point of a face
// of (almost) zero area is taken on the longest edge of the face.
//
// A point closer to an edge than 1e-12 times the length of the edge is taken on the edge, and a point of an
// edge closer to one of its ends than 1e-12 times its length is that vertex: a window whose source image
// lies that close to the line of its edge cannot be propagated accurately (from 1e-15, distances would be
// wrong), while the distances change by at most that much.
inline Seed seed_from_barycentric(const Mesh_arrays& m, Index f, double b0, double b1, double b2, Index label)
{
  Seed s;
  s.label = label;
  const Index h0 = 3 * f;
  const double snap = 1e-12;
  double b[3] = { b0, b1, b2 };
  if(!m.is_degenerate_face[f])
  {
    // the height of the point above edge k (from vertex k to vertex k+1) is b[k+2] times the height of the
    // third vertex, 2 area / length
    const Halfedge_geometry& g = m.geometry[h0];
    const double twice_area = g.cy * g.length;
    for(int k = 0; k < 3; ++k)
    {
      const double length = m.geometry[h0 + k].length;
      if(length > 0. && b[(k + 2) % 3] * twice_area < snap * length * length)
      {
        const double t = b[(k + 1) % 3] / (b[k] + b[(k + 1) % 3]);
        b[(k + 2) % 3] = 0.;
        b[k] = 1. - t;
        b[(k + 1) % 3] = t;
      }
    }
  }
  // vertices
  for(int k = 0; k < 3; ++k)
    if(b[(k + 1) % 3] == 0. && b[(k + 2) % 3] == 0.)
    {
      s.kind = Seed::AT_VERTEX;
      s.element = m.source[h0 + k];
      return s;
    }
  auto on_edge = [&](Index h, double t) {
    const double length = m.geometry[h].length;
    if(!(t > snap * length))
    {
      s.kind = Seed::AT_VERTEX;
      s.element = m.source[h];
      return s;
    }
    if(!(t < length - snap * length))
    {
      s.kind = Seed::AT_VERTEX;
      s.element = m.target(h);
      return s;
    }
    const Index o = m.opposite[h];
    s.kind = Seed::ON_EDGE;
    if(o != NO_INDEX && o < h)
    {
      s.element = o;
      s.x = length - t;
    }
    else
    {
      s.element = h;
      s.x = t;
    }
    return s;
  };
  // edges: half-edge 3f+k goes from vertex k to vertex k+1; the point is on it when the third coordinate is 0
  for(int k = 0; k < 3; ++k)
    if(b[(k + 2) % 3] == 0.)
      return on_edge(h0 + k, b[(k + 1) % 3] * m.geometry[h0 + k].length);
  // the point in the frame of h0: A = (0,0), B = (L,0), C = (cx,cy)
  const Face_frame frame(m, f);
  const double px = b[1] * frame.x[1] + b[2] * frame.x[2], py = b[2] * frame.y[2];
  if(m.is_degenerate_face[f])
  {
    // on the line of the longest edge: project
    const int k = longest_edge(m, f);
    return on_edge(h0 + k, frame.projection(k, px, py));
  }
  s.kind = Seed::IN_FACE;
  s.element = f;
  s.x = px;
  s.y = py;
  return s;
}

// Starts the propagation from `seeds`: the vertices get distance 0 and act as pseudo-sources; a point
// inside an edge or a face reaches the vertices of its face(s) straight and starts a window across each
// edge of its face(s). The origin of the windows of point source i is nv + i.
inline void seed_sources(Propagation_state& st, const std::vector<Seed>& seeds)
{
  const Mesh_arrays& m = *st.mesh;
  st.line_windows = has_segments(seeds);
  st.seed_label.resize(seeds.size());
  for(std::size_t i = 0; i < seeds.size(); ++i)
    st.seed_label[i] = seeds[i].label;
  // vertices first, all at distance 0 before any of them emits; a vertex given twice is one source
  // (its label is the first one)
  std::vector<Index> vertices;
  for(const Seed& s : seeds)
    if(s.kind == Seed::AT_VERTEX && st.dist[s.element] > 0.)
    {
      st.dist[s.element] = 0.;
      st.processed[s.element] = 0.;
      st.mark_lowered(s.element);
      if(!st.label.empty())
        st.label[s.element] = s.label;
      vertices.push_back(s.element);
    }
  for(Index v : vertices)
  {
    st.emit_pseudo_source(v);
    st.sweep(v);
    st.reach_targets_through(v);
  }
  for(std::size_t i = 0; i < seeds.size(); ++i)
  {
    const Seed& s = seeds[i];
    const Index origin = m.nv + static_cast<Index>(i);
    if(s.kind == Seed::AT_VERTEX)
      continue;
    if(s.segment)
      seed_segment(st, s, origin);
    else if(s.kind == Seed::ON_EDGE)
    {
      const Index h = s.element;
      const Halfedge_geometry g = m.geometry[h];
      const double length = g.length;
      // the log map: the direction of the x-axis of h in the frame of the user's face
      const double angle = st.direction.is_active() ? st.direction.seed_angle[i] : 0.;
      st.light(m.source[h], straight_offer(s.x, origin), [&]() { return Ray_arrival{angle, -s.x, 0., h, 1., 0.}; });
      st.light(m.target(h), straight_offer(length - s.x, origin), [&]() {
        return Ray_arrival{angle, length - s.x, 0., Mesh_arrays::next(h), g.cx - length, g.cy};
      });
      st.emit_point(h, s.x, 0., origin, angle);
      if(m.opposite[h] != NO_INDEX)
        st.emit_point(m.opposite[h], length - s.x, 0., origin, angle + TANGENT_FRAME_PI);
      // targets in the faces of the edge are reached straight
      const Index sides[2] = { h, m.opposite[h] };
      const double abscissa[2] = { s.x, length - s.x };
      for(int j = 0; j < 2; ++j)
        if(sides[j] != NO_INDEX)
          st.stop.for_each_target_in_face(Mesh_arrays::face(sides[j]), [&](Index t) {
            const Target& target = st.stop.targets()[static_cast<std::size_t>(t)];
            const std::size_t k = static_cast<std::size_t>(sides[j] % 3);
            const double dx = target.x[k] - abscissa[j], dy = target.y[k];
            st.offer_to_target(t, std::sqrt(dx * dx + dy * dy), origin);
          });
    }
    else
    {
      const Index h0 = 3 * s.element;
      const Face_frame frame(m, s.element);
      // the log map: the direction of the x-axis of h0 in the frame of the user's face
      const double angle = st.direction.is_active() ? st.direction.seed_angle[i] : 0.;
      for(int k = 0; k < 3; ++k)
      {
        const double dx = s.x - frame.x[k], dy = s.y - frame.y[k];
        st.light(m.source[h0 + k], straight_offer(std::sqrt(dx * dx + dy * dy), origin), [&]() {
          const std::array<double, 2> g = halfedge_vector_in_frame(m, h0, h0 + k);
          return Ray_arrival{angle, -dx, -dy, h0 + k, g[0], g[1]};
        });
      }
      st.stop.for_each_target_in_face(s.element, [&](Index t) {
        const Target& target = st.stop.targets()[static_cast<std::size_t>(t)];
        const double dx = target.x[0] - s.x, dy = target.y[0] - s.y;
        st.offer_to_target(t, std::sqrt(dx * dx + dy * dy), origin);
      });
      for(int k = 0; k < 3; ++k)
      {
        const Index o = m.opposite[h0 + k];
        if(o == NO_INDEX)
          continue;
        // the point in the frame of h0 + k (from vertex k to vertex k+1), then in the frame of its opposite
        double ux, uy, x, y;
        if(!(frame.direction(k, ux, uy) > 0.))
          continue;
        frame.to_edge_frame(k, s.x, s.y, x, y);
        Window w;
        w.b0 = 0.;
        w.b1 = m.geometry[o].length;
        w.sx = w.b1 - x;
        w.sy = -y;
        w.sigma = 0.;
        w.angle = angle + halfedge_direction_in_frame(m, h0, h0 + k) + TANGENT_FRAME_PI;  // o, the reverse of h0 + k
        w.origin = origin;
        if(w.sy < 0.)
          st.store_emitted(o, w);
      }
    }
  }
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_SEEDING_H
