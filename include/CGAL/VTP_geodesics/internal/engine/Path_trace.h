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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PATH_TRACE_H
#define CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PATH_TRACE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/Window.h>
#include <CGAL/VTP_geodesics/internal/engine/Path_record.h>
#include <CGAL/VTP_geodesics/internal/engine/Seeding.h>
#include <CGAL/VTP_geodesics/internal/engine/Targets.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A point of a path: a vertex, a point of an edge (abscissa x along a half-edge), or a point inside a
// face (x, y in the frame of half-edge 3f).
struct Trace_point
{
  enum Kind { AT_VERTEX, ON_EDGE, IN_FACE };
  Kind kind = AT_VERTEX;
  Index element = NO_INDEX;
  double x = 0., y = 0.;
};

// The trace-back of geodesic paths from the record of a propagation (Path_record): from a vertex or a
// target back to its nearest source, through the (pseudo-)sources its path turns at.
//
// Between two consecutive (pseudo-)sources the path is a straight line in the unfolding: from the point,
// it goes straight to the image of its origin recorded with the offer that gave the point its distance
// (possibly bent first at an end of that window), and is followed face by face: in each face, the line
// leaves through the edge on its side of the third vertex; the image is re-expressed in the frame of the
// half-edge across that edge. It ends in the face whose third vertex is the origin (or that holds the
// source point). A line that crosses an edge at one of its ends (within rounding, or a zero-length edge)
// goes through that vertex, and on from there along the vertex's own path (see through_vertex()). The
// length of the polyline is the distance, up to rounding.
class Path_trace
{
public:
  Path_trace(const Mesh_arrays& m, const Path_record& record, const std::vector<Seed>& seeds)
    : m_mesh(m), m_record(record), m_seeds(seeds)
  {}

  // The path from vertex v (first) to its source (last). Returns false if it cannot be followed (which
  // would be a defect: then `out` holds what was followed).
  bool from_vertex(Index v, std::vector<Trace_point>& out) const
  {
    out.clear();
    push(out, vertex_point(v));
    return from_vertex_on(v, out);
  }

  // The path from target t (first) to its source (last).
  bool from_target(const Target& target, const Offer& offer, std::vector<Trace_point>& out) const
  {
    out.clear();
    if(target.vertex != NO_INDEX)
      return from_vertex(target.vertex, out);
    Trace_point p;
    p.kind = Trace_point::IN_FACE;
    p.element = target.face;
    p.x = target.x[0];
    p.y = target.y[0];
    push(out, p);
    if(offer.origin == NO_INDEX)
      return false;
    Index origin;
    if(offer.halfedge == NO_INDEX)
      origin = straight_to(offer.origin, out);
    else
    {
      const std::size_t k = static_cast<std::size_t>(offer.halfedge % 3);
      if(!follow(offer, target.x[k], target.y[k], out, origin))
        return false;
    }
    return origin >= m_mesh.nv || from_vertex_on(origin, out);
  }

private:
  static Trace_point vertex_point(Index v)
  {
    Trace_point p;
    p.kind = Trace_point::AT_VERTEX;
    p.element = v;
    return p;
  }

  static bool same(const Trace_point& a, const Trace_point& b)
  {
    return a.kind == b.kind && a.element == b.element && a.x == b.x && a.y == b.y;
  }

  static void push(std::vector<Trace_point>& out, const Trace_point& p)
  {
    if(out.empty() || !same(out.back(), p))
      out.push_back(p);
  }

  // Appends the point of `origin` (a vertex or a source point); returns it.
  Index straight_to(Index origin, std::vector<Trace_point>& out) const
  {
    if(origin < m_mesh.nv)
    {
      push(out, vertex_point(origin));
      return origin;
    }
    const Seed& s = m_seeds[static_cast<std::size_t>(origin - m_mesh.nv)];
    Trace_point p;
    p.kind = s.kind == Seed::IN_FACE ? Trace_point::IN_FACE : Trace_point::ON_EDGE;
    p.element = s.element;
    p.x = s.x;
    p.y = s.y;
    if(s.kind == Seed::AT_VERTEX)
      p = vertex_point(s.element);
    push(out, p);
    return origin;
  }

  // From vertex v (already in `out`), through the (pseudo-)sources, to the source.
  bool from_vertex_on(Index v, std::vector<Trace_point>& out) const
  {
    for(Index step = 0; step <= m_mesh.nv; ++step)
    {
      const Offer& offer = m_record.vertex[static_cast<std::size_t>(v)];
      if(offer.origin == NO_INDEX)
        return true;                       // a source vertex
      Index origin;
      if(offer.halfedge == NO_INDEX)
        origin = straight_to(offer.origin, out);
      else
      {
        const Halfedge_geometry& g = m_mesh.geometry[offer.halfedge];
        if(!follow(offer, g.cx, g.cy, out, origin)) // from the vertex opposite to the list's half-edge
          return false;
      }
      if(origin >= m_mesh.nv)
        return true;                       // a source point
      v = origin;
    }
    return false;
  }

  // Follows the straight path from the point (px, py) of the face of offer.halfedge (in its frame) to
  // the image of offer.origin; appends the edge points and the origin; sets `origin`.
  bool follow(const Offer& offer, double px, double py, std::vector<Trace_point>& out, Index& origin) const
  {
    const Mesh_arrays& m = m_mesh;
    origin = offer.origin;
    Index h = offer.halfedge;
    double x;
    if(offer.bend == offer.bend) // bent at an end of the window
      x = offer.bend;
    else
      x = ray_crossing(offer.sx, offer.sy, px, py, px);
    x = (std::min)((std::max)(x, 0.), m.geometry[h].length);
    double sx = offer.sx, sy = offer.sy;
    if(through_vertex(h, x, sx, sy, out, origin))
      return true;
    Trace_point p;
    p.kind = Trace_point::ON_EDGE;
    p.element = h;
    p.x = x;
    push(out, p);
    for(Index step = 0; step < m.nf + 8; ++step)
    {
      // cross edge h into the face of its opposite o, in whose frame the image is above the edge
      const Index o = m.opposite[h];
      if(o == NO_INDEX)
        return false;
      const Halfedge_geometry& g = m.geometry[o];
      const double xo = g.length - x;
      sx = g.length - sx;
      sy = -sy;
      const Index f = Mesh_arrays::face(o);
      if(ends_in_face(f, o, sx, sy, origin, out))
        return true;
      if(!(sy > 0.))
        return false;
      Index e;
      double p0x, p0y, wx, wy, position;
      if(m.is_degenerate_face[f])
      {
        // a face of (almost) zero area is crossed straight, as the windows cross it: the line goes on from
        // the same point into the face across C-A or B-C, whichever holds the point (as in emit_point())
        // (at C itself, through the edge of non-zero length)
        if(xo < g.cx || (xo == g.cx && !(g.l_next > 0.)))
        {
          e = Mesh_arrays::prev(o);  // C -> A
          p0x = g.cx; p0y = g.cy; wx = -g.cx; wy = -g.cy;
        }
        else
        {
          e = Mesh_arrays::next(o);  // B -> C
          p0x = g.length; p0y = 0.; wx = g.cx - g.length; wy = g.cy;
        }
        position = std::sqrt((xo - p0x) * (xo - p0x) + p0y * p0y);
      }
      else
      {
        // leave through C-A or B-C, on the side of C opposite to the line
        const double dx = sx - xo, dy = sy;
        const double side = dx * g.cy - dy * (g.cx - xo);
        if(side >= 0.)
        {
          e = Mesh_arrays::next(o);  // B -> C
          p0x = g.length; p0y = 0.; wx = g.cx - g.length; wy = g.cy;
        }
        else
        {
          e = Mesh_arrays::prev(o);  // C -> A
          p0x = g.cx; p0y = g.cy; wx = -g.cx; wy = -g.cy;
        }
        const double den = dx * wy - dy * wx;
        double v = den != 0. ? (dx * (0. - p0y) - dy * (xo - p0x)) / den : 0.;
        v = (std::min)((std::max)(v, 0.), 1.);
        position = v * std::sqrt(wx * wx + wy * wy);
      }
      const double w = std::sqrt(wx * wx + wy * wy);
      if(!(w > 0.))
        return false;
      const double ux = wx / w, uy = wy / w;
      // the image in the frame of e
      const double rx = sx - p0x, ry = sy - p0y;
      const double ex = rx * ux + ry * uy, ey = ux * ry - uy * rx;
      h = e;
      x = (std::min)((std::max)(position * (m.geometry[e].length / w), 0.), m.geometry[e].length);
      sx = ex;
      sy = ey;
      if(through_vertex(h, x, sx, sy, out, origin))
        return true;
      p.element = e;
      p.x = x;
      push(out, p);
    }
    return false;
  }

  // Whether the straight part towards the image (sx, sy) (frame of h) of the origin crosses half-edge h at
  // one of its ends (abscissa x within rounding of 0 or of its length, or h of zero length): then the path
  // goes through that vertex w, and from there it is w's own path, of length d(w) <= |w - image| (+ the
  // distance of the origin), the geodesic distance being exact: appends w and sets `origin` to w, from which
  // the caller goes on. The line through a vertex leaves it into any face of its fan, which the walk face by
  // face cannot decide within rounding (nor can it cross a zero-length edge). Only a vertex that was reached
  // (or is a source) and is not already on the path (no cycle through coincident vertices).
  bool through_vertex(Index h, double x, double sx, double sy, std::vector<Trace_point>& out, Index& origin) const
  {
    const Mesh_arrays& m = m_mesh;
    const double length = m.geometry[h].length;
    const double tolerance = 1e-13 * length + 16. * std::numeric_limits<double>::epsilon() * std::sqrt(sx * sx + sy * sy);
    Index w = NO_INDEX;
    if(x <= tolerance && x <= length - x)
      w = m.source[h];
    else if(length - x <= tolerance)
      w = m.source[Mesh_arrays::next(h)];
    if(w == NO_INDEX || !is_reached(w))
      return false;
    for(const Trace_point& q : out)
      if(q.kind == Trace_point::AT_VERTEX && q.element == w)
        return false;
    push(out, vertex_point(w));
    origin = w;
    return true;
  }

  // Whether vertex v has a distance: it was offered one, or it is a source.
  bool is_reached(Index v) const
  {
    const Offer& offer = m_record.vertex[static_cast<std::size_t>(v)];
    if(offer.origin != NO_INDEX)
      return true;
    for(const Seed& s : m_seeds)
      if(s.kind == Seed::AT_VERTEX && s.element == v)
        return true;
    return false;
  }

  // Whether the straight part towards the image (sx, sy) (frame of o) of `origin` ends in face f, entered
  // through o: the origin is the third vertex of f, or the source point lies in f, or the image itself lies
  // in f (an image on an edge: a pseudo-source seen through a face of zero area, which it reaches straight).
  // Appends the end of the path so far.
  bool ends_in_face(Index f, Index o, double sx, double sy, Index origin, std::vector<Trace_point>& out) const
  {
    if(reaches_origin(f, o, origin, out))
      return true;
    const Mesh_arrays& m = m_mesh;
    if(m.is_degenerate_face[f])
      return false;
    const Halfedge_geometry& g = m.geometry[o];
    const double scale = (std::max)(g.length, (std::max)(g.l_next, g.l_prev));
    const double tolerance = 1e-9 * scale * scale;
    const double side_ab = sy * g.length;
    const double side_bc = (g.cx - g.length) * sy - g.cy * (sx - g.length);
    const double side_ca = -g.cx * (sy - g.cy) + g.cy * (sx - g.cx);
    if(!(side_ab >= -tolerance && side_bc >= -tolerance && side_ca >= -tolerance))
      return false;
    // the image is in f: the path reaches it, then goes straight to the origin
    Trace_point p;
    const double edge_tolerance = 1e-9 * scale;
    if(sy * g.length <= edge_tolerance * g.length)
    {
      p.kind = Trace_point::ON_EDGE;
      p.element = o;
      p.x = (std::min)((std::max)(sx, 0.), g.length);
    }
    else
    {
      p.kind = Trace_point::IN_FACE;
      p.element = f;
      Face_frame(m, f).from_edge_frame(static_cast<int>(o % 3), sx, sy, p.x, p.y);
    }
    push(out, p);
    straight_to(origin, out);
    return true;
  }

  // Whether face f (entered through o) ends the straight part towards `origin`; appends its point.
  bool reaches_origin(Index f, Index o, Index origin, std::vector<Trace_point>& out) const
  {
    const Mesh_arrays& m = m_mesh;
    if(origin < m.nv)
    {
      if(m.source[Mesh_arrays::prev(o)] != origin)
        return false;
      push(out, vertex_point(origin));
      return true;
    }
    const Seed& s = m_seeds[static_cast<std::size_t>(origin - m.nv)];
    const bool in_this_face = (s.kind == Seed::IN_FACE && s.element == f)
                              || (s.kind == Seed::ON_EDGE
                                  && (Mesh_arrays::face(s.element) == f
                                      || (m.opposite[s.element] != NO_INDEX && Mesh_arrays::face(m.opposite[s.element]) == f)));
    if(!in_this_face)
      return false;
    straight_to(origin, out);
    return true;
  }

  const Mesh_arrays& m_mesh;
  const Path_record& m_record;
  const std::vector<Seed>& m_seeds;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PATH_TRACE_H
