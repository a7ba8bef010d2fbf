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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_ENGINE_VIRTUAL_SOURCE_FRONT_H
#define CGAL_VTP_GEODESICS_INTERNAL_ENGINE_VIRTUAL_SOURCE_FRONT_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/engine/Path_record.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_state.h>
#include <CGAL/VTP_geodesics/internal/engine/Seeding.h>
#include <CGAL/VTP_geodesics/internal/engine/Stop_rule.h>
#include <CGAL/VTP_geodesics/internal/engine/Targets.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// Virtual source propagation (VSP): one virtual source per vertex instead of lists of windows per
// half-edge (the limit of the reset family AVTP as lambda goes to 0).
//
// Each reached vertex u keeps, in the 2D frame of one half-edge `h` whose source is u (u at the origin, the
// target of h on the positive x axis, the face of h above it), the image s of its *root* (a vertex, or a
// source point) unfolded along a straight line, and the *wedge* of directions from s, bounded by L (counter-
// clockwise) and R (clockwise), through which that line really crosses the unfolded faces since it left the
// root: every point of the face of h inside the wedge is joined to the root by a straight segment that stays
// in the faces. The distance of u is d(root) + |s - u|.
//
// Vertices are taken in the order of a binary heap (Dijkstra). A vertex u taken offers to its neighbours:
//  - along each edge u-w: d(u) + |uw|, with u as the new root (always a real path);
//  - through its virtual source: walking around u from the face of h, clockwise and counter-clockwise,
//    crossing one edge u-x at a time and cutting the wedge to the directions that cross the segment [u, x]
//    (a crossing is taken only if the image lies strictly on the side of the face it leaves: the line goes
//    forward); the third vertex y of each face reached is offered d(root) + |s - y| if y lies in the wedge.
//    An edge u-x whose x is the root itself is crossed with the wedge of the root's corner in the next face.
// A vertex keeps the smallest offer; a vertex taken is never changed again. The heap is not monotone (an
// offer through a virtual source may be smaller than the distance of the vertex making it, by at most one
// edge), so a run with a distance limit goes on until the heap passes the limit plus the longest edge: it
// then gives the full run's distances within the limit; a run stopped at its targets gives the full run's
// distances of the vertices taken.
//
// Upper bound: every offer is the length of a path on the surface (a straight segment in an unfolding whose
// faces it crosses, after a path to the root realised by induction), hence never below the geodesic distance.
class Virtual_source_front
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

  // With settings.known_distances, `initial` (and `initial_labels`) give the starting field (see
  // Propagation_state): a known vertex is not taken unless the new sources lower it.
  void run(const Mesh_arrays& m, const std::vector<Seed>& seeds, std::vector<Target>&& targets,
           const Propagation_settings& settings, Propagation_statistics& st,
           const std::vector<double>* initial = nullptr, const std::vector<Index>* initial_labels = nullptr)
  {
    m_mesh = &m;
    m_seeds = &seeds;
    m_settings = settings;
    const std::size_t nv = static_cast<std::size_t>(m.nv);
    dist.assign(nv, std::numeric_limits<double>::infinity());
    m_taken.assign(nv, 0);
    m_src.resize(nv);
    if(settings.want_labels)
      label.assign(nv, NO_INDEX);
    else
      label.clear();
    if(settings.known_distances)
    {
      CGAL_precondition(initial != nullptr && initial->size() == nv);
      dist = *initial;
      if(settings.want_labels && initial_labels != nullptr)
        label = *initial_labels;
    }
    m_heap.clear();
    m_targets = std::move(targets);
    m_target_value.assign(m_targets.size(), std::numeric_limits<double>::infinity());
    m_target_offer.assign(m_targets.size(), Offer());
    m_taken_count = 0;
    m_stopped = false;
    m_peak_heap = 0;

    seed(seeds);
    propagate();
    finish();

    record.start(settings.record_paths, nv, m_targets.size());
    if(settings.record_paths)
    {
      for(std::size_t v = 0; v < nv; ++v)
        if(dist[v] < std::numeric_limits<double>::infinity())
          record.vertex[v] = offer_of(static_cast<Index>(v));
      for(std::size_t t = 0; t < m_targets.size(); ++t)
        record.target[t] = m_target_offer[t];
    }
    if(settings.unit != 1.)
    {
      for(double& d : dist)
        d *= settings.unit;
    }
    st.vertices_processed = m_taken_count;
    st.stopped_early = m_stopped;
    st.peak_live_windows = 0;
    st.peak_window_bytes = nv * (sizeof(Vertex_source) + sizeof(double) + 1 + (label.empty() ? 0 : sizeof(Index)))
                           + m_peak_heap * sizeof(Heap_entry);
  }

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

private:
  typedef std::pair<double, Index> Heap_entry;

  static double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

  // whether the point (px, py) lies in the closed wedge of a vertex source
  static bool in_wedge(const Vertex_source& s, double px, double py)
  {
    const double dx = px - s.sx, dy = py - s.sy;
    return cross(s.rx, s.ry, dx, dy) >= 0. && cross(dx, dy, s.lx, s.ly) >= 0.;
  }

  double root_distance(Index root) const
  {
    return root < m_mesh->nv ? dist[static_cast<std::size_t>(root)] : 0.;
  }

  void push(Index v, double d)
  {
    m_heap.emplace_back(d, v);
    std::push_heap(m_heap.begin(), m_heap.end(), std::greater<Heap_entry>());
    m_peak_heap = (std::max)(m_peak_heap, m_heap.size());
  }

  // Lowers the distance of v (not taken) to d with source s, if smaller.
  void offer(Index v, double d, const Vertex_source& s, Index lab)
  {
    const std::size_t i = static_cast<std::size_t>(v);
    if(m_taken[i] || !(d < dist[i]))
      return;
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
      if(d > 0.)
      {
        Vertex_source s;
        s.sx = px; s.sy = py;
        // the half-plane of directions towards the vertex (any wedge will do: the whole face is seen)
        const double dx = -px, dy = -py;
        s.lx = -dy; s.ly = dx;
        s.rx = dy; s.ry = -dx;
        s.h = h;
        s.root = origin;
        offer(m.source[h], d, s, lab);
      }
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
  // propagation
  // ------------------------------------------------------------------------------------------
  void propagate()
  {
    const Mesh_arrays& m = *m_mesh;
    std::size_t remaining_vertex_targets = 0;
    std::vector<unsigned char> is_target;
    const bool stop_at_targets = m_settings.stop_at_targets && !m_targets.empty();
    if(stop_at_targets)
    {
      is_target.assign(static_cast<std::size_t>(m.nv), 0);
      for(const Target& t : m_targets)
      {
        if(t.vertex != NO_INDEX)
          mark(is_target, t.vertex, remaining_vertex_targets);
        else
          for(int k = 0; k < 3; ++k)
            mark(is_target, m.source[3 * t.face + k], remaining_vertex_targets);
      }
    }
    const double cutoff = m_settings.limit + 2. * m.max_edge_length;
    while(!m_heap.empty())
    {
      std::pop_heap(m_heap.begin(), m_heap.end(), std::greater<Heap_entry>());
      const Heap_entry e = m_heap.back();
      m_heap.pop_back();
      const std::size_t u = static_cast<std::size_t>(e.second);
      if(m_taken[u] || e.first > dist[u])
        continue;
      // An offer of a vertex u is at least d(u) minus one edge (d(root) + |s - y| >= d(root) + |s - u| - |uy|,
      // y a neighbour of u): past limit + the longest edge (twice, for rounding), no offer can be within the
      // limit any more, and every vertex within it is taken, as in a full run.
      if(e.first > cutoff)
      {
        m_stopped = true;
        break;
      }
      m_taken[u] = 1;
      ++m_taken_count;
      take(e.second);
      if(stop_at_targets && is_target[u])
      {
        is_target[u] = 0;
        if(--remaining_vertex_targets == 0)
        {
          m_stopped = !m_heap.empty();
          break;
        }
      }
    }
  }

  static void mark(std::vector<unsigned char>& is_target, Index v, std::size_t& count)
  {
    if(!is_target[static_cast<std::size_t>(v)])
    {
      is_target[static_cast<std::size_t>(v)] = 1;
      ++count;
    }
  }

  // Vertex u is taken: its offers to its neighbours.
  void take(Index u)
  {
    const Mesh_arrays& m = *m_mesh;
    const double du = dist[static_cast<std::size_t>(u)];
    const Vertex_source su = m_src[static_cast<std::size_t>(u)];
    const Index lab = label.empty() ? NO_INDEX : label[static_cast<std::size_t>(u)];
    // along the edges, u as the new root
    for(Index c = m.corner_begin[u]; c < m.corner_begin[u + 1]; ++c)
    {
      const Index h = m.corners[c];
      const Index b = m.source[Mesh_arrays::next(h)];
      const double db = du + m.geometry.faces[static_cast<std::size_t>(h / 3)].length[h % 3];
      if(db < dist[static_cast<std::size_t>(b)] && !m_taken[static_cast<std::size_t>(b)])
      {
        const Halfedge_geometry g = m.geometry[Mesh_arrays::next(h)];  // B at the origin, C on the x axis, u above
        offer_along_edge(b, db, g.cx, g.cy, -g.cx, -g.cy, g.length - g.cx, -g.cy, Mesh_arrays::next(h), u, lab);
      }
      const Index p = Mesh_arrays::prev(h);
      if(m.opposite[p] == NO_INDEX)
      {
        // a border edge C -> u: C is reached only from this face
        const Halfedge_geometry gp = m.geometry[p];  // C at the origin, u = (length, 0), B above
        offer_along_edge(m.source[p], du + gp.length, gp.length, 0., gp.cx - gp.length, gp.cy, -gp.length, 0., p, u,
                         lab);
      }
    }
    if(su.root == u || su.h == NO_INDEX)
      return;  // a source vertex: the edges are its straight lines
    const double sigma = root_distance(su.root);
    walk_counterclockwise(u, su, sigma, lab);
    walk_clockwise(u, su, sigma, lab);
  }

  void offer_along_edge(Index v, double d, double sx, double sy, double rx, double ry, double lx, double ly, Index h,
                        Index root, Index lab)
  {
    if(m_taken[static_cast<std::size_t>(v)] || !(d < dist[static_cast<std::size_t>(v)]))
      return;
    Vertex_source s;
    s.sx = sx; s.sy = sy;
    s.rx = rx; s.ry = ry;
    s.lx = lx; s.ly = ly;
    s.h = h;
    s.root = root;
    offer(v, d, s, lab);
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

  // The walk through the faces after the face of s.h, counter-clockwise around u.
  void walk_counterclockwise(Index u, Vertex_source s, double sigma, Index lab)
  {
    const Mesh_arrays& m = *m_mesh;
    const Index degree = m.corner_begin[u + 1] - m.corner_begin[u];
    Index h = s.h;
    for(Index step = 0; step < 2 * degree + 2; ++step)
    {
      const Halfedge_geometry g = m.geometry[h];  // u at the origin, B = (length, 0), C = (cx, cy)
      const Index p = Mesh_arrays::prev(h);
      const Index o = m.opposite[p];
      if(o == NO_INDEX || !(g.l_prev > 0.))
        return;
      const Index c = m.source[p];
      const Halfedge_geometry go = m.geometry[o];  // u at the origin, C = (length, 0), D = (cx, cy)
      if(c == s.root)
      {
        s.sx = go.length; s.sy = 0.;
        s.rx = go.cx - go.length; s.ry = go.cy;
        s.lx = -go.length; s.ly = 0.;
      }
      else
      {
        // the line goes on across u-C only if the image is strictly on the side of the face it leaves
        if(!(cross(g.cx, g.cy, s.sx, s.sy) < 0.))
          return;
        double t0, t1;
        if(!clip(s, g.cx, g.cy, t0, t1))
          return;
        const double lx = t0 * g.cx - s.sx, ly = t0 * g.cy - s.sy;
        const double rx = t1 * g.cx - s.sx, ry = t1 * g.cy - s.sy;
        // rotate by minus the angle of C
        const double co = g.cx / g.l_prev, si = g.cy / g.l_prev;
        rotate(co, -si, s.sx, s.sy);
        s.lx = lx; s.ly = ly; rotate(co, -si, s.lx, s.ly);
        s.rx = rx; s.ry = ry; rotate(co, -si, s.rx, s.ry);
      }
      h = o;
      s.h = o;
      reach_third_vertex(s, go, Mesh_arrays::prev(o), sigma, lab);
    }
  }

  // The walk through the faces before the face of s.h, clockwise around u.
  void walk_clockwise(Index u, Vertex_source s, double sigma, Index lab)
  {
    const Mesh_arrays& m = *m_mesh;
    const Index degree = m.corner_begin[u + 1] - m.corner_begin[u];
    Index h = s.h;
    for(Index step = 0; step < 2 * degree + 2; ++step)
    {
      const Halfedge_geometry g = m.geometry[h];
      const Index o = m.opposite[h];
      if(o == NO_INDEX)
        return;
      const Index hg = Mesh_arrays::next(o);
      const Halfedge_geometry gg = m.geometry[hg];  // u at the origin, E = (length, 0), B = (cx, cy)
      if(!(gg.l_prev > 0.))
        return;
      const Index b = m.source[o];
      if(b == s.root)
      {
        s.sx = gg.cx; s.sy = gg.cy;
        s.rx = -gg.cx; s.ry = -gg.cy;
        s.lx = gg.length - gg.cx; s.ly = -gg.cy;
      }
      else
      {
        if(!(s.sy > 0.))
          return;
        double t0, t1;
        if(!clip(s, g.length, 0., t0, t1))
          return;
        const double rx = t0 * g.length - s.sx, ry = -s.sy;
        const double lx = t1 * g.length - s.sx, ly = -s.sy;
        const double co = gg.cx / gg.l_prev, si = gg.cy / gg.l_prev;
        rotate(co, si, s.sx, s.sy);
        s.lx = lx; s.ly = ly; rotate(co, si, s.lx, s.ly);
        s.rx = rx; s.ry = ry; rotate(co, si, s.rx, s.ry);
      }
      h = hg;
      s.h = hg;
      reach_third_vertex(s, gg, Mesh_arrays::next(hg), sigma, lab);
    }
  }

  static void rotate(double co, double si, double& x, double& y)
  {
    const double nx = x * co - y * si, ny = x * si + y * co;
    x = nx;
    y = ny;
  }

  // s is in the frame of s.h (geometry g); the vertex y = source(hy) is the third vertex (cx, cy) when hy is
  // prev(s.h), or the target (length, 0) when hy is next(s.h). Offers y its distance through s.
  void reach_third_vertex(const Vertex_source& s, const Halfedge_geometry& g, Index hy, double sigma, Index lab)
  {
    const Mesh_arrays& m = *m_mesh;
    const Index y = m.source[hy];
    if(m_taken[static_cast<std::size_t>(y)])
      return;
    const bool is_prev = hy == Mesh_arrays::prev(s.h);
    const double px = is_prev ? g.cx : g.length, py = is_prev ? g.cy : 0.;
    if(!in_wedge(s, px, py))
      return;
    const double dx = px - s.sx, dy = py - s.sy;
    const double d = sigma + std::sqrt(dx * dx + dy * dy);
    if(!(d < dist[static_cast<std::size_t>(y)]))
      return;
    // the frame of hy: y at the origin
    double ux, uy;
    if(is_prev)
    {
      if(!(g.l_prev > 0.))
        return;
      ux = -g.cx / g.l_prev; uy = -g.cy / g.l_prev;  // direction from C to the origin
    }
    else
    {
      if(!(g.l_next > 0.))
        return;
      ux = (g.cx - g.length) / g.l_next; uy = g.cy / g.l_next;  // direction from B to C
    }
    Vertex_source t;
    const double x = s.sx - px, yy = s.sy - py;
    t.sx = x * ux + yy * uy; t.sy = -x * uy + yy * ux;
    t.lx = s.lx * ux + s.ly * uy; t.ly = -s.lx * uy + s.ly * ux;
    t.rx = s.rx * ux + s.ry * uy; t.ry = -s.rx * uy + s.ry * ux;
    t.h = hy;
    t.root = s.root;
    offer(y, d, t, lab);
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
        const Vertex_source& s = m_src[static_cast<std::size_t>(a)];
        if(s.h != h || s.root == a)
          continue;
        if(!in_wedge(s, target.x[k], target.y[k]))
          continue;
        const double dx = target.x[k] - s.sx, dy = target.y[k] - s.sy;
        const double ds = root_distance(s.root) + std::sqrt(dx * dx + dy * dy);
        if(ds < m_target_value[t])
        {
          m_target_value[t] = ds;
          m_target_offer[t] = image_offer(ds, s);
        }
      }
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
  std::vector<Vertex_source> m_src;
  std::vector<unsigned char> m_taken;
  std::vector<Heap_entry> m_heap;
  std::vector<Target> m_targets;
  std::vector<double> m_target_value;
  std::vector<Offer> m_target_offer;
  std::size_t m_taken_count = 0;
  std::size_t m_peak_heap = 0;
  bool m_stopped = false;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_ENGINE_VIRTUAL_SOURCE_FRONT_H
