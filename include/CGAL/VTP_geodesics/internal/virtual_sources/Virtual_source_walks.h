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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_WALKS_H
#define CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_WALKS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_field.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The offers of a vertex u taken by virtual source propagation (Virtual_source_front.h) to the vertices
// around it, the walks of its straight lines through the faces around it:
//  - along each edge u-w: d(u) + |uw|, with u as the new root (always a real path);
//  - through its virtual source: walking around u from the face of h, clockwise and counter-clockwise,
//    crossing one edge u-x at a time and cutting the wedge to the directions that cross the segment [u, x]
//    (a crossing is taken only if the image lies strictly on the side of the face it leaves: the line goes
//    forward); the third vertex y of each face reached is offered d(root) + |s - y| if y lies in the wedge;
//    and the line goes on, forward, across the edge opposite u into the face beyond, whose third vertex z
//    (two edges from u) is offered d(root) + |s - z| if it lies in the wedge cut to that edge
//    (reach_beyond()). An edge u-x whose x is the root itself is crossed with the wedge of the root's corner
//    in the next face.
// With a second virtual source per vertex, u walks both. Lines never cross a face of (almost) zero area
// (Mesh_arrays::is_degenerate_face): the trace-back of a path could not follow them there.
//
// The offers go to a sink (Virtual_source_rounds.h), which applies them or keeps them for the thread that
// owns their vertex.
class Virtual_source_walks : public Virtual_source_field
{
protected:
  // Vertex u is taken: its offers to its neighbours, each given to sink(v, d, source, label) if v is not
  // taken and d is not above its distance (an offer equal to it may still win the tie, see
  // Virtual_source_rounds::better()); the distance of v is read only if sink.reads(v) (another thread may
  // be lowering it: the offer is then given unfiltered).
  template <class Sink>
  void take(Index u, Sink& sink) const
  {
    const Mesh_arrays& m = *m_mesh;
    const double du = dist[static_cast<std::size_t>(u)];
    const Vertex_source su = m_src[static_cast<std::size_t>(u)];
    const Index lab = label.empty() ? NO_INDEX : label[static_cast<std::size_t>(u)];
    // the walks through the virtual sources first: their offers are most often the better ones, and an
    // offer along an edge that is not better is then turned away by wanted() before it is written (the
    // order changes no result: see Virtual_source_rounds::better())
    if(su.root != u && su.h != NO_INDEX)  // (a source vertex: the edges are its straight lines)
    {
      const double sigma = root_distance(su.root);
      walk<true>(u, su, sigma, lab, sink);
      walk<false>(u, su, sigma, lab, sink);
    }
    if(has_second(static_cast<std::size_t>(u)))
    {
      const Vertex_source s2 = m_src2[static_cast<std::size_t>(u)];
      const double sigma2 = root_distance(s2.root);
      const Index lab2 = root_label(s2.root);
      walk<true>(u, s2, sigma2, lab2, sink);
      walk<false>(u, s2, sigma2, lab2, sink);
    }
    // along the edges, u as the new root
    for(Index c = m.corner_begin[u]; c < m.corner_begin[u + 1]; ++c)
    {
      const Index h = m.corners[c];
      const Index b = m.source[Mesh_arrays::next(h)];
      const double db = du + m.geometry.faces[static_cast<std::size_t>(h / 3)].length[h % 3];
      if(!m_taken[static_cast<std::size_t>(b)] && wanted(b, db, sink))
      {
        const Halfedge_geometry g = m.geometry[Mesh_arrays::next(h)];  // B at the origin, C on the x axis, u above
        offer_along_edge(b, db, g.cx, g.cy, -g.cx, -g.cy, g.length - g.cx, -g.cy, Mesh_arrays::next(h), u, lab, sink);
      }
      const Index p = Mesh_arrays::prev(h);
      if(m.opposite[p] == NO_INDEX)
      {
        // a border edge C -> u: C is reached only from this face
        const Halfedge_geometry gp = m.geometry[p];  // C at the origin, u = (length, 0), B above
        offer_along_edge(m.source[p], du + gp.length, gp.length, 0., gp.cx - gp.length, gp.cy, -gp.length, 0., p, u,
                         lab, sink);
      }
    }
  }

  // A hint to the memory system for a vertex u that take() will reach soon (the rounds call it for the
  // vertices a few places ahead in their list, each stage later in a pipeline): stage 2, its virtual source
  // and corner range; stage 1, its corners; stage 0, the faces and half-edges around it. Stages 1 and 0
  // read what the earlier stage asked for. Nothing changes but the time: the vertices of a round are taken
  // from all over the front, and on large meshes their data comes from main memory.
  void prefetch(Index u, int stage) const
  {
    const Mesh_arrays& m = *m_mesh;
    const std::size_t i = static_cast<std::size_t>(u);
    if(stage == 2)
    {
      hint(&m_src[i]);
      hint(reinterpret_cast<const char*>(&m_src[i]) + sizeof(Vertex_source) - 1);
      hint(&m.corner_begin[i]);
      return;
    }
    const Index begin = m.corner_begin[i], end = m.corner_begin[i + 1];
    if(stage == 1)
    {
      if(begin == end)  // a vertex of no face
        return;
      hint(&m.corners[static_cast<std::size_t>(begin)]);
      hint(&m.corners[static_cast<std::size_t>(end - 1)]);
      return;
    }
    for(Index c = begin; c < end; ++c)
    {
      const std::size_t h = static_cast<std::size_t>(m.corners[static_cast<std::size_t>(c)]);
      hint(&m.geometry.faces[h / 3]);
      hint(&m.source[h]);
      hint(&m.opposite[h]);
    }
  }

  static void hint(const void* p)
  {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
  }

  // Whether an offer d to v (not taken) can change it: not above its distance, or with a second source per
  // vertex, not above that of its second one (it may be kept as the second, Virtual_source_field::
  // second_offer()); every offer if the sink may not read v (v's owner is lowering it).
  template <class Sink>
  bool wanted(Index v, double d, const Sink& sink) const
  {
    if(!sink.reads(v))
      return true;
    const std::size_t i = static_cast<std::size_t>(v);
    return d <= dist[i] || (!m_dist2.empty() && d <= m_dist2[i]);
  }

  template <class Sink>
  void offer_along_edge(Index v, double d, double sx, double sy, double rx, double ry, double lx, double ly, Index h,
                        Index root, Index lab, Sink& sink) const
  {
    if(m_taken[static_cast<std::size_t>(v)] || !wanted(v, d, sink))
      return;
    Vertex_source s;
    s.sx = sx; s.sy = sy;
    s.rx = rx; s.ry = ry;
    s.lx = lx; s.ly = ly;
    s.h = h;
    s.root = root;
    sink(v, d, s, lab);
  }

  // The walk through the faces around u from the face of s.h (geometry g), counter-clockwise (the faces
  // after it) or clockwise (those before it): in each face the line enters, the third vertex and the vertex
  // of the face beyond are offered their distance through s.
  template <bool counterclockwise, class Sink>
  void walk(Index u, Vertex_source s, double sigma, Index lab, Sink& sink) const
  {
    const Mesh_arrays& m = *m_mesh;
    const Index degree = m.corner_begin[u + 1] - m.corner_begin[u];
    Halfedge_geometry g = m.geometry[s.h];  // u at the origin, B = (length, 0), C = (cx, cy)
    for(Index step = 0; step < 2 * degree + 2; ++step)
    {
      if(!(counterclockwise ? cross_counterclockwise(s, g) : cross_clockwise(s, g)))
        return;
      reach_third_vertex(s, g, counterclockwise ? Mesh_arrays::prev(s.h) : Mesh_arrays::next(s.h), sigma, lab,
                         sink);
      reach_beyond(s, g, sigma, lab, sink);
    }
  }

  // One step of the counter-clockwise walk: the line of s (frame of s.h, geometry g: u at the origin, B =
  // (length, 0), C = (cx, cy)) goes on across u-C into the face after, whose frame and geometry s and g then
  // are; false if it cannot.
  bool cross_counterclockwise(Vertex_source& s, Halfedge_geometry& g) const
  {
    const Mesh_arrays& m = *m_mesh;
    const Index p = Mesh_arrays::prev(s.h);
    const Index o = m.opposite[p];
    if(o == NO_INDEX || !(g.l_prev > 0.))
      return false;
    const Index c = m.source[p];
    if(c != s.root)
    {
      // the line goes on across u-C only if the image is strictly on the side of the face it leaves
      if(!(cross(g.cx, g.cy, s.sx, s.sy) < 0.))
        return false;
      double t0, t1;
      if(!clip(s, g.cx, g.cy, t0, t1))
        return false;
      const double lx = t0 * g.cx - s.sx, ly = t0 * g.cy - s.sy;
      const double rx = t1 * g.cx - s.sx, ry = t1 * g.cy - s.sy;
      // rotate by minus the angle of C
      const double inv = 1. / g.l_prev, co = g.cx * inv, si = g.cy * inv;
      rotate(co, -si, s.sx, s.sy);
      s.lx = lx; s.ly = ly; rotate(co, -si, s.lx, s.ly);
      s.rx = rx; s.ry = ry; rotate(co, -si, s.rx, s.ry);
    }
    if(m.is_degenerate_face[static_cast<std::size_t>(Mesh_arrays::face(o))])
      return false;  // (a line never enters a face of zero area)
    const Halfedge_geometry go = m.geometry[o];  // u at the origin, C = (length, 0), D = (cx, cy)
    if(c == s.root)
    {
      s.sx = go.length; s.sy = 0.;
      s.rx = go.cx - go.length; s.ry = go.cy;
      s.lx = -go.length; s.ly = 0.;
    }
    s.h = o;
    g = go;
    return true;
  }

  // One step of the clockwise walk: the line of s (frame of s.h, geometry g) goes on across u-B into the
  // face before, whose frame and geometry s and g then are; false if it cannot.
  bool cross_clockwise(Vertex_source& s, Halfedge_geometry& g) const
  {
    const Mesh_arrays& m = *m_mesh;
    const Index o = m.opposite[s.h];
    if(o == NO_INDEX)
      return false;
    const Index hg = Mesh_arrays::next(o);
    const Index b = m.source[o];
    // the line goes on across u-B only if the image is strictly above it (the side of the face it leaves)
    double t0 = 0., t1 = 1.;
    if(b != s.root && (!(s.sy > 0.) || !clip(s, g.length, 0., t0, t1)))
      return false;
    if(m.is_degenerate_face[static_cast<std::size_t>(Mesh_arrays::face(o))])
      return false;  // (a line never enters a face of zero area)
    const Halfedge_geometry gg = m.geometry[hg];  // u at the origin, E = (length, 0), B = (cx, cy)
    if(!(gg.l_prev > 0.))
      return false;
    if(b == s.root)
    {
      s.sx = gg.cx; s.sy = gg.cy;
      s.rx = -gg.cx; s.ry = -gg.cy;
      s.lx = gg.length - gg.cx; s.ly = -gg.cy;
    }
    else
    {
      const double rx = t0 * g.length - s.sx, ry = -s.sy;
      const double lx = t1 * g.length - s.sx, ly = -s.sy;
      const double inv = 1. / gg.l_prev, co = gg.cx * inv, si = gg.cy * inv;
      rotate(co, si, s.sx, s.sy);
      s.lx = lx; s.ly = ly; rotate(co, si, s.lx, s.ly);
      s.rx = rx; s.ry = ry; rotate(co, si, s.rx, s.ry);
    }
    s.h = hg;
    g = gg;
    return true;
  }

  // s is in the frame of s.h (geometry g); the vertex y = source(hy) is the third vertex (cx, cy) when hy is
  // prev(s.h), or the target (length, 0) when hy is next(s.h). Offers y its distance through s.
  template <class Sink>
  void reach_third_vertex(const Vertex_source& s, const Halfedge_geometry& g, Index hy, double sigma, Index lab,
                          Sink& sink) const
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
    if(!wanted(y, d, sink))
      return;
    // the frame of hy: y at the origin
    double ux, uy;
    if(is_prev)
    {
      if(!(g.l_prev > 0.))
        return;
      const double inv = 1. / g.l_prev;
      ux = -g.cx * inv; uy = -g.cy * inv;  // direction from C to the origin
    }
    else
    {
      if(!(g.l_next > 0.))
        return;
      const double inv = 1. / g.l_next;
      ux = (g.cx - g.length) * inv; uy = g.cy * inv;  // direction from B to C
    }
    Vertex_source t;
    const double x = s.sx - px, yy = s.sy - py;
    t.sx = x * ux + yy * uy; t.sy = -x * uy + yy * ux;
    t.lx = s.lx * ux + s.ly * uy; t.ly = -s.lx * uy + s.ly * ux;
    t.rx = s.rx * ux + s.ry * uy; t.ry = -s.rx * uy + s.ry * ux;
    t.h = hy;
    t.root = s.root;
    sink(y, d, t, lab);
  }

  // s is in the frame of s.h (geometry g: u at the origin, B = (length, 0), C = (cx, cy)), a face around u
  // that the walk reached. The line goes on, forward, across the edge B-C opposite u into the face beyond
  // (B, C and its third vertex z): z is offered d(root) + |s - z| if it lies in the wedge cut to the
  // directions through the segment [B, C] (every point of the face beyond inside that wedge is then joined
  // to the root by a segment through the faces, as for the faces around u).
  template <class Sink>
  void reach_beyond(const Vertex_source& s, const Halfedge_geometry& g, double sigma, Index lab, Sink& sink) const
  {
    const Mesh_arrays& m = *m_mesh;
    const Index t = m.opposite[Mesh_arrays::next(s.h)];  // C -> B in the face beyond
    if(t == NO_INDEX || !(g.l_next > 0.))
      return;
    const Index hz = Mesh_arrays::prev(t);  // z -> C
    const Index z = m.source[hz];
    if(m_taken[static_cast<std::size_t>(z)])
      return;
    const double bx = g.length, cx = g.cx, cy = g.cy;
    const double ex = cx - bx, ey = cy;  // B -> C
    // forward: the image strictly on u's side of B-C; the wedge cut to the points B + t (C - B), t0 <= t <= t1
    if(!(cross(ex, ey, s.sx - bx, s.sy) > 0.))
      return;
    if(m.is_degenerate_face[static_cast<std::size_t>(Mesh_arrays::face(t))])
      return;  // (a line never enters a face of zero area)
    double t0 = 0., t1 = 1.;
    if(!bound(cross(s.rx, s.ry, ex, ey), cross(s.rx, s.ry, s.sx - bx, s.sy), t0, t1)
       || !bound(cross(ex, ey, s.lx, s.ly), cross(s.sx - bx, s.sy, s.lx, s.ly), t0, t1) || !(t0 <= t1))
      return;
    // (seen from the image, on the left of B -> C, the segment turns counter-clockwise from B to C)
    const double rx = bx + t0 * ex - s.sx, ry = t0 * ey - s.sy;
    const double lx = bx + t1 * ex - s.sx, ly = t1 * ey - s.sy;
    // z in the frame of s.h: C + a (B - C) + b (B - C) turned a quarter counter-clockwise, (a, b) the
    // coordinates of z in the frame of t (C at the origin, B on the x axis) divided by |BC|
    const Index face_t = Mesh_arrays::face(t);
    const Face_geometry& ft = m.geometry.faces[static_cast<std::size_t>(face_t)];
    const int kt = static_cast<int>(t - 3 * face_t);
    const double lt = ft.length[kt], lt_prev = ft.length[kt == 0 ? 2 : kt - 1], lt_next = ft.length[kt == 2 ? 0 : kt + 1];
    if(!(lt > 0.) || !(lt_prev > 0.))
      return;
    const double inv2 = 1. / (lt * lt);
    const double a = 0.5 * (lt * lt + lt_prev * lt_prev - lt_next * lt_next) * inv2, b = 2. * ft.area * inv2;
    const double zx = cx - a * ex + b * ey, zy = cy - a * ey - b * ex;
    const double dx = zx - s.sx, dy = zy - s.sy;
    if(cross(rx, ry, dx, dy) < 0. || cross(dx, dy, lx, ly) < 0.)
      return;
    const double d = sigma + std::sqrt(dx * dx + dy * dy);
    if(!wanted(z, d, sink))
      return;
    // the frame of hz: z at the origin, C on the x axis
    const double inv = 1. / lt_prev, vx = (cx - zx) * inv, vy = (cy - zy) * inv;
    Vertex_source r;
    const double x = s.sx - zx, y = s.sy - zy;
    r.sx = x * vx + y * vy; r.sy = -x * vy + y * vx;
    r.lx = lx * vx + ly * vy; r.ly = -lx * vy + ly * vx;
    r.rx = rx * vx + ry * vy; r.ry = -rx * vy + ry * vx;
    r.h = hz;
    r.root = s.root;
    sink(z, d, r, lab);
  }
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_WALKS_H
