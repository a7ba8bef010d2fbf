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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_FIELD_H
#define CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_FIELD_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/memory/Huge_page_allocator.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_record.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>
#include <CGAL/VTP_geodesics/internal/propagation/Stop_rule.h>
#include <CGAL/VTP_geodesics/internal/propagation/Targets.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The field of virtual source propagation (the propagation itself is Virtual_source_front.h): per vertex its
// distance, its label and its virtual source (the image of its root and the wedge of directions of its
// straight line), and with settings.second_virtual_source a second one (see second_offer()), the vertices
// seeded (for the first round), the seeding by the sources, and the end of a run (cutoff, targets in faces,
// trace-back offers); and the wedge geometry, which the propagation and the targets share.
class Virtual_source_field
{
public:
  struct Vertex_source
  {
    double sx, sy;  // image of the root in the frame of h
    double lx, ly;  // counter-clockwise bound of the wedge (a direction from s)
    double rx, ry;  // clockwise bound of the wedge
    Index h;        // half-edge whose source is the vertex: the frame
    Index root;     // a vertex, or nv + i for source point i
  };

  std::vector<double> dist;
  std::vector<Index> label;
  Path_record record;

  // The distance of target t, in the unit of the output (+infinity if not reached or beyond the limit).
  double target_distance(std::size_t t) const
  {
    const Target& target = m_targets[t];
    if(target.vertex != NO_INDEX)
      return dist[static_cast<std::size_t>(target.vertex)];
    const double d = m_target_value[t];
    return d <= m_settings.limit ? d * m_settings.unit : std::numeric_limits<double>::infinity();
  }
  const std::vector<Target>& targets() const { return m_targets; }

protected:
  typedef std::pair<double, Index> Seeded_entry;

  // ------------------------------------------------------------------------------------------
  // wedge geometry
  // ------------------------------------------------------------------------------------------
  static double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

  // whether the point (px, py) lies in the closed wedge of a vertex source
  static bool in_wedge(const Vertex_source& s, double px, double py)
  {
    const double dx = px - s.sx, dy = py - s.sy;
    return cross(s.rx, s.ry, dx, dy) >= 0. && cross(dx, dy, s.lx, s.ly) >= 0.;
  }

  // Cuts the wedge of s to the directions through the segment from the origin to P; t0 is the end at the
  // origin. Returns false if empty.
  static bool clip(const Vertex_source& s, double Px, double Py, double& t0, double& t1)
  {
    t0 = 0.;
    t1 = 1.;
    // cross(R, tP - s) >= 0 and cross(tP - s, L) >= 0
    const double a1 = cross(s.rx, s.ry, Px, Py), b1 = cross(s.rx, s.ry, s.sx, s.sy);
    const double a2 = cross(Px, Py, s.lx, s.ly), b2 = cross(s.sx, s.sy, s.lx, s.ly);
    if(!bound(a1, b1, t0, t1) || !bound(a2, b2, t0, t1))
      return false;
    return t0 <= t1;
  }

  // a t - b >= 0
  static bool bound(double a, double b, double& t0, double& t1)
  {
    if(a > 0.)
      t0 = (std::max)(t0, b / a);
    else if(a < 0.)
      t1 = (std::min)(t1, b / a);
    else if(b > 0.)
      return false;
    return true;
  }

  static void rotate(double co, double si, double& x, double& y)
  {
    const double nx = x * co - y * si, ny = x * si + y * co;
    x = nx;
    y = ny;
  }

  double root_distance(Index root) const
  {
    return root < m_mesh->nv ? dist[static_cast<std::size_t>(root)] : 0.;
  }

  // the label of the paths through a root (that of its own path, or of its source point)
  Index root_label(Index root) const
  {
    if(label.empty())
      return NO_INDEX;
    return root < m_mesh->nv ? label[static_cast<std::size_t>(root)]
                             : (*m_seeds)[static_cast<std::size_t>(root - m_mesh->nv)].label;
  }

  // Whether vertex v has a second virtual source.
  bool has_second(std::size_t v) const
  {
    return !m_src2.empty() && m_dist2[v] < std::numeric_limits<double>::infinity();
  }

  // With a second virtual source per vertex, vertex v (not taken, distance d0 with source s0) is offered
  // (d, s), which is not better than (d0, s0): v keeps as its second source the best offer whose root is not
  // that of its first one (the same total order as the first, see Virtual_source_rounds::better(), so the
  // pair kept does not depend on the order of the offers).
  template <class Better>
  void second_offer(std::size_t v, double d, const Vertex_source& s, Better better)
  {
    if(s.root != m_src[v].root && better(d, s, m_dist2[v], m_src2[v]))
    {
      m_dist2[v] = d;
      m_src2[v] = s;
    }
  }

  // ... v's first source (d0, s0), a virtual source (not the start of a known field), gives way to an offer
  // of root `root`: it is the best offer so far, so it becomes the second if its root differs (otherwise the
  // second, of another root than both, stays).
  void demote_first(std::size_t v, Index root)
  {
    if(dist[v] < std::numeric_limits<double>::infinity() && m_src[v].h != NO_INDEX && m_src[v].root != root)
    {
      m_dist2[v] = dist[v];
      m_src2[v] = m_src[v];
    }
  }

  void push(Index v, double d)
  {
    m_seeded.emplace_back(d, v);
    m_peak_seeded = (std::max)(m_peak_seeded, m_seeded.size());
  }

  // Lowers the distance of v (not taken) to d with source s, if smaller (the seeding by source points).
  void offer(Index v, double d, const Vertex_source& s, Index lab)
  {
    const std::size_t i = static_cast<std::size_t>(v);
    if(m_taken[i] || !(d < dist[i]))
      return;
    if(!m_src2.empty())
      demote_first(i, s.root);
    dist[i] = d;
    m_src[i] = s;
    if(!label.empty())
      label[i] = lab;
    push(v, d);
  }

  // ------------------------------------------------------------------------------------------
  // seeding
  // ------------------------------------------------------------------------------------------
  void seed(const std::vector<Seed>& seeds)
  {
    const Mesh_arrays& m = *m_mesh;
    for(std::size_t i = 0; i < seeds.size(); ++i)
    {
      const Seed& sd = seeds[i];
      const Index origin = m.nv + static_cast<Index>(i);
      if(sd.kind == Seed::AT_VERTEX)
      {
        const std::size_t v = static_cast<std::size_t>(sd.element);
        if(!(0. < dist[v]))
          continue;
        dist[v] = 0.;
        Vertex_source s;
        s.sx = s.sy = s.lx = s.ly = s.rx = s.ry = 0.;
        s.h = m.corner_begin[sd.element] < m.corner_begin[sd.element + 1] ? m.corners[m.corner_begin[sd.element]] : NO_INDEX;
        s.root = sd.element;
        m_src[v] = s;
        if(!label.empty())
          label[v] = sd.label;
        push(sd.element, 0.);
      }
      else if(sd.kind == Seed::IN_FACE)
        seed_point_in_face(3 * sd.element, sd.x, sd.y, origin, sd.label);
      else
      {
        seed_point_in_face(sd.element, sd.x, 0., origin, sd.label);
        const Index o = m.opposite[sd.element];
        if(o != NO_INDEX)
          seed_point_in_face(o, m.geometry[o].length - sd.x, 0., origin, sd.label);
      }
    }
  }

  // the point (px, py) in the frame of h reaches the three vertices of the face of h straight
  void seed_point_in_face(Index h, double px, double py, Index origin, Index lab)
  {
    const Mesh_arrays& m = *m_mesh;
    for(int k = 0; k < 3; ++k)
    {
      const double d = std::sqrt(px * px + py * py);
      Vertex_source s;
      s.h = h;
      if(d > 0.)
      {
        s.sx = px; s.sy = py;
        // the half-plane of directions towards the vertex (any wedge will do: the whole face is seen)
        const double dx = -px, dy = -py;
        s.lx = -dy; s.ly = dx;
        s.rx = dy; s.ry = -dx;
        s.root = origin;
      }
      else
      {
        // the vertex is at the point: it is its own root, as a source vertex (its edges are its lines)
        s.sx = s.sy = s.lx = s.ly = s.rx = s.ry = 0.;
        s.root = m.source[h];
      }
      offer(m.source[h], d, s, lab);
      // the point in the frame of next(h)
      const Halfedge_geometry g = m.geometry[h];
      const double ln = g.l_next;
      if(!(ln > 0.))
        break;
      const double ux = (g.cx - g.length) / ln, uy = g.cy / ln;
      const double x = px - g.length, y = py;
      px = x * ux + y * uy;
      py = -x * uy + y * ux;
      h = Mesh_arrays::next(h);
    }
    // the targets in the same face
    if(!m_targets.empty())
    {
      const Index f = Mesh_arrays::face(h);
      for(std::size_t t = 0; t < m_targets.size(); ++t)
        if(m_targets[t].vertex == NO_INDEX && m_targets[t].face == f)
        {
          const int k = static_cast<int>(h % 3);
          const double dx = m_targets[t].x[k] - px, dy = m_targets[t].y[k] - py;
          const double d = std::sqrt(dx * dx + dy * dy);
          if(d < m_target_value[t])
          {
            m_target_value[t] = d;
            m_target_offer[t] = straight_offer(d, origin);
          }
        }
    }
  }

  // ------------------------------------------------------------------------------------------
  // end of the run: targets in faces, cutoff
  // ------------------------------------------------------------------------------------------
  void finish()
  {
    const Mesh_arrays& m = *m_mesh;
    const double inf = std::numeric_limits<double>::infinity();
    // vertices not taken are not final (a stop) or beyond the limit; but those of a known field (never
    // lowered: a run from known distances goes to its end) keep their distance
    for(std::size_t v = 0; v < dist.size(); ++v)
      if((!m_taken[v] && !m_settings.known_distances) || dist[v] > m_settings.limit)
      {
        dist[v] = inf;
        m_taken[v] = 0;
        if(!label.empty())
          label[v] = NO_INDEX;
      }
    for(std::size_t t = 0; t < m_targets.size(); ++t)
    {
      const Target& target = m_targets[t];
      if(target.vertex != NO_INDEX)
      {
        const Index v = target.vertex;
        if(dist[static_cast<std::size_t>(v)] < inf)
          m_target_offer[t] = offer_of(v);
        continue;
      }
      for(int k = 0; k < 3; ++k)
      {
        const Index h = 3 * target.face + k;
        const Index a = m.source[h];
        if(!m_taken[static_cast<std::size_t>(a)])
          continue;
        const double da = dist[static_cast<std::size_t>(a)];
        const double d = da + target.corner_distance[k];
        if(d < m_target_value[t])
        {
          m_target_value[t] = d;
          m_target_offer[t] = straight_offer(d, a);
        }
        reach_target(t, k, m_src[static_cast<std::size_t>(a)], h, a);
        if(has_second(static_cast<std::size_t>(a)))
          reach_target(t, k, m_src2[static_cast<std::size_t>(a)], h, a);
      }
    }
  }

  // target t, in the face of h = s.h, through the virtual source s of the corner a = source(h)
  void reach_target(std::size_t t, int k, const Vertex_source& s, Index h, Index a)
  {
    const Target& target = m_targets[t];
    if(s.h != h || s.root == a || !in_wedge(s, target.x[k], target.y[k]))
      return;
    const double dx = target.x[k] - s.sx, dy = target.y[k] - s.sy;
    const double ds = root_distance(s.root) + std::sqrt(dx * dx + dy * dy);
    if(ds < m_target_value[t])
    {
      m_target_value[t] = ds;
      m_target_offer[t] = image_offer(ds, s);
    }
  }

  // whether the root of s (a vertex or a source point) lies on the face of s.h
  bool root_in_face(const Vertex_source& s) const
  {
    const Mesh_arrays& m = *m_mesh;
    const Index f = Mesh_arrays::face(s.h);
    if(s.root < m.nv)
      return m.source[3 * f] == s.root || m.source[3 * f + 1] == s.root || m.source[3 * f + 2] == s.root;
    const Seed& sd = (*m_seeds)[static_cast<std::size_t>(s.root - m.nv)];
    if(sd.kind == Seed::IN_FACE)
      return sd.element == f;
    if(sd.kind == Seed::ON_EDGE)
      return Mesh_arrays::face(sd.element) == f
             || (m.opposite[sd.element] != NO_INDEX && Mesh_arrays::face(m.opposite[sd.element]) == f);
    return false;
  }

  // the offer of the straight line from the image of s, given in the frame of the edge opposite the vertex
  Offer image_offer(double d, const Vertex_source& s) const
  {
    if(root_in_face(s))
      return straight_offer(d, s.root);
    const Halfedge_geometry g = m_mesh->geometry[s.h];
    const Index e = Mesh_arrays::next(s.h);
    Offer o;
    o.distance = d;
    o.origin = s.root;
    o.halfedge = e;
    if(!(g.l_next > 0.))
      return straight_offer(d, s.root);
    const double ux = (g.cx - g.length) / g.l_next, uy = g.cy / g.l_next;
    const double x = s.sx - g.length, y = s.sy;
    o.sx = x * ux + y * uy;
    o.sy = -x * uy + y * ux;
    return o;
  }

  // the trace-back record of vertex v
  Offer offer_of(Index v) const
  {
    const Vertex_source& s = m_src[static_cast<std::size_t>(v)];
    if(s.root == v)
      return Offer();  // a source vertex
    return image_offer(dist[static_cast<std::size_t>(v)], s);
  }

  const Mesh_arrays* m_mesh = nullptr;
  const std::vector<Seed>* m_seeds = nullptr;
  Propagation_settings m_settings;
  typedef std::vector<Vertex_source, Huge_page_allocator<Vertex_source>> Source_array;
  Source_array m_src;
  Source_array m_src2;  // the second virtual sources (empty without), of distances m_dist2
  std::vector<double> m_dist2;
  std::vector<unsigned char> m_taken;
  std::vector<Seeded_entry> m_seeded;  // the vertices seeded, for the first round (Virtual_source_rounds.h)
  std::vector<Target> m_targets;
  std::vector<double> m_target_value;
  std::vector<Offer> m_target_offer;
  std::size_t m_taken_count = 0;
  std::size_t m_peak_seeded = 0;
  bool m_stopped = false;
  // runs from known distances that add one seed each (Virtual_source_front::run_again()): the vertices
  // taken by the last one
  bool m_incremental = false;
  std::vector<Index> m_touched;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_FIELD_H
