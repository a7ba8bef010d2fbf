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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_TRACE_ENDS_H
#define CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_TRACE_ENDS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/mesh/Surface_point.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_record.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A point of a path: a vertex, a point of an edge (abscissa x along a half-edge), or a point inside a
// face (x, y in the frame of half-edge 3f).
typedef Surface_point Trace_point;

// The ends of the straight parts of a path traced back (Path_trace.h): the points of the path, which it
// appends, and whether a straight part towards the image of its origin ends in a face it enters (at the
// origin, a vertex of the face or a source point in it, or, where the image itself lies in the face, at the
// image and then straight to the origin); and what the record of the propagation says of a vertex.
class Path_trace_ends
{
protected:
  Path_trace_ends(const Mesh_arrays& m, const Path_record& record, const std::vector<Seed>& seeds)
    : m_mesh(m), m_record(record), m_seeds(seeds)
  {}

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
    // (a source point is a point of the path as it is; a source vertex, without its coordinates; a piece of a
    // curve, the foot of the last point on it)
    const Seed& s = m_seeds[static_cast<std::size_t>(origin - m_mesh.nv)];
    if(s.segment)
    {
      double px = 0., py = 0.;
      if(!out.empty() && point_in_frame(out.back(), s.element, px, py))
        push(out, foot_on_piece(s, px, py));
      return origin;
    }
    push(out, s.kind == Seed::AT_VERTEX ? vertex_point(s.element) : static_cast<const Trace_point&>(s));
    return origin;
  }

  // The point of piece s (a segment seed) nearest to (px, py) (frame of its face), as a point of the path.
  static Trace_point foot_on_piece(const Seed& s, double px, double py)
  {
    const double dx = s.x1 - s.x, dy = s.y1 - s.y;
    const double d2 = dx * dx + dy * dy;
    double t = d2 > 0. ? ((px - s.x) * dx + (py - s.y) * dy) / d2 : 0.;
    t = (std::min)((std::max)(t, 0.), 1.);
    Trace_point p;
    p.kind = Trace_point::IN_FACE;
    p.element = s.element;
    p.x = s.x + t * dx;
    p.y = s.y + t * dy;
    return p;
  }

  // The point q in the frame of face f (a vertex of f, a point of an edge of f, or a point of f); false if it
  // is not in f.
  bool point_in_frame(const Trace_point& q, Index f, double& px, double& py) const
  {
    const Mesh_arrays& m = m_mesh;
    const Face_frame frame(m, f);
    if(q.kind == Trace_point::IN_FACE)
    {
      px = q.x;
      py = q.y;
      return q.element == f;
    }
    for(int k = 0; k < 3; ++k)
    {
      const Index h = 3 * f + static_cast<Index>(k);
      if(q.kind == Trace_point::AT_VERTEX && m.source[h] == q.element)
      {
        px = frame.x[k];
        py = frame.y[k];
        return true;
      }
      if(q.kind == Trace_point::ON_EDGE && (q.element == h || m.opposite[h] == q.element))
      {
        frame.from_edge_frame(k, q.element == h ? q.x : m.geometry[h].length - q.x, 0., px, py);
        return true;
      }
    }
    return false;
  }

  // Whether the image (ix, iy) is at the point (px, py) of the same frame, to 1e-6 of the image's distance
  // from the frame's origin (and of the length of its edge): far above rounding, far below the miss of a line
  // unfolded on the wrong side of a vertex or turned around one (see reaches_origin()).
  static bool image_at(double ix, double iy, double px, double py, double edge_length)
  {
    return (ix - px) * (ix - px) + (iy - py) * (iy - py) <= 1e-12 * (ix * ix + iy * iy + edge_length * edge_length);
  }

  // the distance recorded for reached vertex v (0 for a source)
  double recorded_distance(Index v) const
  {
    const Offer& offer = m_record.vertex[static_cast<std::size_t>(v)];
    return offer.origin != NO_INDEX ? offer.distance : 0.;
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
  // Appends the end of the path so far. The image in f ends it only if not `strict` (a line gone straight
  // through a vertex on the wrong side of it can have its image in any face).
  bool ends_in_face(Index f, Index o, double sx, double sy, Index origin, bool strict,
                    std::vector<Trace_point>& out) const
  {
    if(reaches_origin(f, o, sx, sy, origin, out))
      return true;
    const Mesh_arrays& m = m_mesh;
    if(strict || m.is_degenerate_face[f])
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

  // Whether face f (entered through o) ends the straight part towards the image (sx, sy) (frame of o) of
  // `origin`: the origin is the third vertex of f, or the source point lies in f, and the image is at it (to
  // 1e-6 of the image's distance, far above rounding); appends its point. (A line of an approximation can
  // cross a face of its origin before it ends there: VSP's lines can turn around a vertex whose angles add
  // up to less than pi, and the line that a source point's face sees again is not the line that ends there.)
  bool reaches_origin(Index f, Index o, double sx, double sy, Index origin, std::vector<Trace_point>& out) const
  {
    const Mesh_arrays& m = m_mesh;
    if(origin < m.nv)
    {
      const Halfedge_geometry& g = m.geometry[o];
      if(m.source[Mesh_arrays::prev(o)] != origin || !image_at(sx, sy, g.cx, g.cy, g.length))
        return false;
      push(out, vertex_point(origin));
      return true;
    }
    if(!image_at_seed(f, o, sx, sy, origin))
      return false;
    straight_to(origin, out);
    return true;
  }

  // Whether the source point `origin` (nv + its index) lies in face f and the image (sx, sy) (frame of o, a
  // half-edge of f) is at it (as in reaches_origin()).
  bool image_at_seed(Index f, Index o, double sx, double sy, Index origin) const
  {
    if(!seed_in_face(origin, f))
      return false;
    const Mesh_arrays& m = m_mesh;
    // the source point and the image in the frame of the face
    const Seed& s = m_seeds[static_cast<std::size_t>(origin - m.nv)];
    const Face_frame frame(m, f);
    double px = s.x, py = s.y;
    if(s.kind == Seed::ON_EDGE)
    {
      if(Mesh_arrays::face(s.element) == f)
        frame.from_edge_frame(static_cast<int>(s.element % 3), s.x, 0., px, py);
      else
      {
        const Index e = m.opposite[s.element];
        frame.from_edge_frame(static_cast<int>(e % 3), m.geometry[e].length - s.x, 0., px, py);
      }
    }
    double ix, iy;
    frame.from_edge_frame(static_cast<int>(o % 3), sx, sy, ix, iy);
    return image_at(ix, iy, px, py, m.geometry[o].length);
  }

  // whether the source point `origin` (nv + its index) lies in face f (inside, or on one of its edges)
  bool seed_in_face(Index origin, Index f) const
  {
    const Mesh_arrays& m = m_mesh;
    const Seed& s = m_seeds[static_cast<std::size_t>(origin - m.nv)];
    return (s.kind == Seed::IN_FACE && s.element == f)
           || (s.kind == Seed::ON_EDGE
               && (Mesh_arrays::face(s.element) == f
                   || (m.opposite[s.element] != NO_INDEX && Mesh_arrays::face(m.opposite[s.element]) == f)));
  }

  const Mesh_arrays& m_mesh;
  const Path_record& m_record;
  const std::vector<Seed>& m_seeds;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_TRACE_ENDS_H
