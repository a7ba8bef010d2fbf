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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_TRACE_H
#define CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_TRACE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_record.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_trace_ends.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>
#include <CGAL/VTP_geodesics/internal/propagation/Targets.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The trace-back of geodesic paths from the record of a propagation (Path_record): from a vertex or a
// target back to its nearest source, through the (pseudo-)sources its path turns at.
//
// Between two consecutive (pseudo-)sources the path is a straight line in the unfolding: from the point,
// it goes straight to the image of its origin recorded with the offer that gave the point its distance
// (possibly bent first at an end of that window), and is followed face by face: in each face, the line
// leaves through the edge on its side of the third vertex; the image is re-expressed in the frame of the
// half-edge across that edge. It ends in the face whose third vertex is the origin (or that holds the
// source point). A line that crosses an edge at one of its ends (within rounding, or a zero-length edge)
// goes through that vertex, and on from there along the vertex's own path if that path has the length left
// of the line (always, with exact distances), else straight on through the vertex (see through_vertex()).
// The length of the polyline is the distance, up to rounding; a path that cannot be followed so is not
// followed by other rules (the query throws: a defect, which the tests and the fuzzer look for). Where a
// straight part ends, and the points of the path: Path_trace_ends.h.
class Path_trace : public Path_trace_ends
{
public:
  Path_trace(const Mesh_arrays& m, const Path_record& record, const std::vector<Seed>& seeds)
    : Path_trace_ends(m, record, seeds)
  {}

  // The path from vertex v (first) to its source (last). Returns false if it cannot be followed (which
  // would be a defect: then `out` holds what was followed).
  bool from_vertex(Index v, std::vector<Trace_point>& out) const
  {
    m_straight_attempts = 0;
    out.clear();
    push(out, vertex_point(v));
    return from_vertex_on(v, out);
  }

  // The path from target t (first) to its source (last).
  bool from_target(const Target& target, const Offer& offer, std::vector<Trace_point>& out) const
  {
    if(target.vertex != NO_INDEX)
      return from_vertex(target.vertex, out);
    m_straight_attempts = 0;
    return from_point(target, offer, out);
  }

private:
  bool from_point(const Target& target, const Offer& offer, std::vector<Trace_point>& out) const
  {
    out.clear();
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
  // With `strict` (the line goes on straight through a vertex, see straight_through()), it does not end where
  // its image lies in a face it enters, only at its origin (see ends_in_face()).
  bool follow(const Offer& offer, double px, double py, std::vector<Trace_point>& out, Index& origin,
              bool strict = false) const
  {
    if(offer.sy > 0.)
      return follow_line(offer, px, py, out, origin);
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
    // the distance of the origin: the offer's less the straight parts from the point to the edge and on to
    // the image
    const double sigma = offer.distance - std::sqrt((px - x) * (px - x) + py * py)
                         - std::sqrt((x - sx) * (x - sx) + sy * sy);
    const int through = through_vertex(h, x, sx, sy, sigma, out, origin);
    if(through != 0)
      return through > 0;
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
      if(ends_in_face(f, o, sx, sy, origin, strict, out))
        return true;
      if(!(sy > 0.))
        return false;
      const Face_exit out_of = leave_face(o, xo, sx - xo, sy);
      const Index e = out_of.e;
      const double p0x = out_of.p0x, p0y = out_of.p0y, wx = out_of.wx, wy = out_of.wy, w = out_of.w;
      if(!(w > 0.))
        return false;
      const double ux = wx / w, uy = wy / w;
      // the image in the frame of e
      double ex, ey;
      rotate_into(sx - p0x, sy - p0y, ux, uy, ex, ey);
      h = e;
      x = (std::min)((std::max)(out_of.position * (m.geometry[e].length / w), 0.), m.geometry[e].length);
      sx = ex;
      sy = ey;
      const int through_end = through_vertex(h, x, sx, sy, sigma, out, origin);
      if(through_end != 0)
        return through_end > 0;
      p.element = e;
      p.x = x;
      push(out, p);
    }
    return false;
  }

  // The same for the offer of a line window (a piece of a source curve, offer.sy > 0): the path runs back
  // against the direction (offer.sx, offer.sy) of the parallel front, face by face, to the face of the piece,
  // where it ends at its foot on the piece (the paths of a line window meet no vertex but by rounding: a line
  // through a vertex goes on into the face its side test picks).
  bool follow_line(const Offer& offer, double px, double py, std::vector<Trace_point>& out, Index& origin) const
  {
    const Mesh_arrays& m = m_mesh;
    origin = offer.origin;
    Index h = offer.halfedge;
    double x = offer.bend == offer.bend ? offer.bend : px - offer.sx * (py / offer.sy);
    x = (std::min)((std::max)(x, 0.), m.geometry[h].length);
    // (bx, by): the direction back to the piece, in the frame of h (below h)
    double bx = -offer.sx, by = -offer.sy;
    Trace_point p;
    p.kind = Trace_point::ON_EDGE;
    p.element = h;
    p.x = x;
    push(out, p);
    const Seed& piece = m_seeds[static_cast<std::size_t>(origin - m.nv)];
    for(Index step = 0; step < m.nf + 8; ++step)
    {
      const Index o = m.opposite[h];
      if(o == NO_INDEX)
        return false;
      const Halfedge_geometry& g = m.geometry[o];
      const double xo = g.length - x;
      bx = -bx;
      by = -by;
      const Index f = Mesh_arrays::face(o);
      if(f == piece.element)
      {
        // the foot: where the line from (xo, 0) along (bx, by) meets the line of the piece (frame of 3f)
        const Face_frame frame(m, f);
        double qx, qy, ex, ey, zx, zy;
        frame.from_edge_frame(static_cast<int>(o % 3), xo, 0., qx, qy);
        frame.from_edge_frame(static_cast<int>(o % 3), xo + bx, by, ex, ey);
        ex -= qx;
        ey -= qy;
        const double dx = piece.x1 - piece.x, dy = piece.y1 - piece.y;
        const double den = ex * dy - ey * dx;
        const double t = den != 0. ? ((piece.x - qx) * dy - (piece.y - qy) * dx) / den : 0.;
        zx = qx + t * ex;
        zy = qy + t * ey;
        push(out, foot_on_piece(piece, zx, zy));
        return true;
      }
      if(!(by > 0.))
        return false;
      const Face_exit out_of = leave_face(o, xo, bx, by);
      const Index e = out_of.e;
      const double wx = out_of.wx, wy = out_of.wy, w = out_of.w;
      if(!(w > 0.))
        return false;
      double nbx, nby;
      rotate_into(bx, by, wx / w, wy / w, nbx, nby);
      bx = nbx;
      by = nby;
      h = e;
      x = (std::min)((std::max)(out_of.position * (m.geometry[e].length / w), 0.), m.geometry[e].length);
      p.element = e;
      p.x = x;
      push(out, p);
    }
    return false;
  }

  // Where a line leaves face(o), from the point (xo, 0) of o in the direction (dx, dy) (dy > 0, frame of o): the
  // half-edge e it crosses (C -> A or B -> C, on the side of C opposite to the line), the frame of e in that of o
  // (its origin p0, its vector w, of length `w`) and the abscissa along e where it crosses (in the unit of the
  // frame of o). A face of (almost) zero area is crossed straight, as the windows cross it: the line goes on from
  // the same point into the face across C-A or B-C, whichever holds the point (as in emit_point()) (at C itself,
  // through the edge of non-zero length). Both walks use it (follow(), follow_line()).
  struct Face_exit
  {
    Index e;
    double p0x, p0y, wx, wy, w, position;
  };
  Face_exit leave_face(Index o, double xo, double dx, double dy) const
  {
    const Mesh_arrays& m = m_mesh;
    const Halfedge_geometry& g = m.geometry[o];
    const bool degenerate = m.is_degenerate_face[Mesh_arrays::face(o)] != 0;
    const bool to_ca = degenerate ? (xo < g.cx || (xo == g.cx && !(g.l_next > 0.)))
                                  : !(dx * g.cy - dy * (g.cx - xo) >= 0.);
    Face_exit r;
    if(to_ca)
    {
      r.e = Mesh_arrays::prev(o);  // C -> A
      r.p0x = g.cx; r.p0y = g.cy; r.wx = -g.cx; r.wy = -g.cy;
    }
    else
    {
      r.e = Mesh_arrays::next(o);  // B -> C
      r.p0x = g.length; r.p0y = 0.; r.wx = g.cx - g.length; r.wy = g.cy;
    }
    r.w = std::sqrt(r.wx * r.wx + r.wy * r.wy);
    if(degenerate)
      r.position = std::sqrt((xo - r.p0x) * (xo - r.p0x) + r.p0y * r.p0y);
    else
    {
      const double den = dx * r.wy - dy * r.wx;
      double v = den != 0. ? (dx * (0. - r.p0y) - dy * (xo - r.p0x)) / den : 0.;
      v = (std::min)((std::max)(v, 0.), 1.);
      r.position = v * r.w;
    }
    return r;
  }

  // Whether the straight part towards the image (sx, sy) (frame of h, below h) of the origin, at the
  // distance `sigma` of the origin, crosses half-edge h at one of its ends (abscissa x within vertex_slack of
  // 0 or of its length, or h of zero length): then the path goes through that vertex w, appended. If the path
  // of w has the length left of the line (sigma + |w - image|, always so with exact distances: the line is a
  // geodesic), it goes on along that path: `origin` is set to w, from which the caller goes on. Otherwise (an
  // approximation, VSP or AVTP: w may have a longer path, or a shorter one than the line through it), the line
  // goes on straight through w to the origin (straight_through(), on either side of the line), so that the
  // length of the path is the distance; if neither side can be followed, the line cannot be followed (w's
  // own path would not have the length of the distance). The line through a vertex leaves it into any face of
  // its fan, which the walk face by face cannot decide within rounding (nor can it cross a zero-length edge).
  // Only a vertex that was reached (or is a source). A vertex already on the path is not left along its own
  // path again (that would go round for ever): the line goes straight on through it (a VSP line can pass
  // through a vertex whose own line is longer and leads to the origin of this one: the path goes there and
  // back), or, if it cannot, on across h. Returns 1 if the line went through a vertex, 0 if not (the walk
  // goes on across h), -1 if it cannot be followed.
  int through_vertex(Index h, double x, double sx, double sy, double sigma, std::vector<Trace_point>& out,
                     Index& origin) const
  {
    const Mesh_arrays& m = m_mesh;
    const double length = m.geometry[h].length;
    const double tolerance = vertex_slack * (length + std::sqrt(sx * sx + sy * sy));
    Index w = NO_INDEX;
    if(x <= tolerance && x <= length - x)
      w = m.source[h];
    else if(length - x <= tolerance)
      w = m.source[Mesh_arrays::next(h)];
    if(w == NO_INDEX || !is_reached(w))
      return 0;
    bool on_path = false;
    for(const Trace_point& q : out)
      on_path = on_path || (q.kind == Trace_point::AT_VERTEX && q.element == w);
    const std::size_t before = out.size();
    push(out, vertex_point(w));
    const std::size_t size = out.size();
    const bool at_source = w == m.source[h];
    const double wx = at_source ? 0. : length;
    const double line = sigma + std::sqrt((sx - wx) * (sx - wx) + sy * sy);
    if(on_path || !(std::abs(recorded_distance(w) - line) <= 1e-11 * line))
    {
      for(int side = 0; side < 2 && m_straight_attempts < max_straight_attempts; ++side)
      {
        ++m_straight_attempts;  // (a line through many such vertices could try 2^n ways)
        Index end = origin;
        if(straight_through(h, at_source, side == 1, sx, sy, sigma, out, end))
        {
          origin = end;
          return 1;
        }
        out.resize(size);
      }
      if(on_path)
      {
        out.resize(before);
        return 0;
      }
      return -1;
    }
    origin = w;
    return 1;
  }

  // The line towards the image (sx, sy) (frame of h, below h) of `origin`, at the distance `sigma` of the
  // origin, goes straight on through the vertex w at an end of h (its source if `at_source`): the faces
  // around w are unfolded one by one, from the face across h (or, on the other side of the line, from the
  // face of h), away from the face the line comes from, until one holds the direction of the image; the
  // line is followed from w across that face's edge opposite w (it ends only where its image is at the
  // origin, see reaches_origin(): on the wrong side of a vertex whose angles do not add up to 2 pi, it misses
  // the origin and cannot be followed).
  bool straight_through(Index h, bool at_source, bool other_side, double sx, double sy, double sigma,
                        std::vector<Trace_point>& out, Index& origin) const
  {
    const Mesh_arrays& m = m_mesh;
    // k: a half-edge whose source is w (w at the origin of its frame), and (ix, iy) the image in its frame
    Index k;
    double ix = sx, iy = sy;
    bool counterclockwise;
    if(!other_side)
    {
      const Index o = m.opposite[h];  // the face across h, entered first
      if(o == NO_INDEX)
        return false;
      ix = m.geometry[o].length - sx;
      iy = -sy;
      k = o;
      if(at_source)
        k = to_next_frame(o, ix, iy);  // w is the target of o
      counterclockwise = at_source ? false : true;
    }
    else
    {
      k = h;  // the face of h, which does not hold the direction (the image is below h): turned away at once
      if(!at_source)
        k = to_next_frame(h, ix, iy);
      counterclockwise = at_source;
    }
    if(k == NO_INDEX)
      return false;
    const Index w = m.source[k];
    const Index degree = m.corner_begin[w + 1] - m.corner_begin[w];
    for(Index step = 0; step <= degree; ++step)
    {
      const Halfedge_geometry& g = m.geometry[k];
      // (the direction of the image along an edge, within rounding, is in both faces of the edge: the line
      // then goes on through the vertex at the other end of it)
      const double slack = direction_slack * std::sqrt(ix * ix + iy * iy);
      if(!m.is_degenerate_face[Mesh_arrays::face(k)] && iy >= -slack && ix * g.cy - iy * g.cx >= -slack * g.l_prev)
      {
        // the direction of the image is in this face: the line leaves it across e = B -> C
        const Index e = Mesh_arrays::next(k);
        double ex = ix, ey = iy;
        if(to_next_frame(k, ex, ey) == NO_INDEX)
          return false;
        const Halfedge_geometry& ge = m.geometry[e];
        if(!(ey < 0.))
        {
          // the image is in this face: at the origin, one of its vertices or a source point in it
          const bool at_origin =
              origin >= m.nv ? image_at_seed(Mesh_arrays::face(k), k, ix, iy, origin)
              : origin == m.source[e] ? image_at(ix, iy, g.length, 0., g.length)
              : origin == m.source[Mesh_arrays::next(e)] && image_at(ix, iy, g.cx, g.cy, g.length);
          if(!at_origin)
            return false;
          straight_to(origin, out);
          return true;
        }
        Offer offer;
        offer.distance = sigma + std::sqrt(ix * ix + iy * iy);
        offer.origin = origin;
        offer.halfedge = e;
        offer.sx = ex;
        offer.sy = ey;
        return follow(offer, ge.cx, ge.cy, out, origin, true);
      }
      if(counterclockwise)
      {
        // into the face across C -> w, in whose frame C is on the x axis
        const Index o = m.opposite[Mesh_arrays::prev(k)];
        if(o == NO_INDEX || !(g.l_prev > 0.))
          return false;
        const double co = g.cx / g.l_prev, si = g.cy / g.l_prev;
        const double nx = ix * co + iy * si, ny = -ix * si + iy * co;
        ix = nx;
        iy = ny;
        k = o;
      }
      else
      {
        // into the face across w -> B, in whose frame B is its third vertex
        const Index o = m.opposite[k];
        if(o == NO_INDEX)
          return false;
        const Index n = Mesh_arrays::next(o);
        const Halfedge_geometry& gn = m.geometry[n];
        if(!(gn.l_prev > 0.))
          return false;
        const double co = gn.cx / gn.l_prev, si = gn.cy / gn.l_prev;
        const double nx = ix * co - iy * si, ny = ix * si + iy * co;
        ix = nx;
        iy = ny;
        k = n;
      }
    }
    return false;
  }

  // The point (x, y) of the frame of h in the frame of next(h) (its source, the target of h, at the origin,
  // its target on the x axis); returns next(h), or NO_INDEX if that edge has no length.
  Index to_next_frame(Index h, double& x, double& y) const
  {
    const Halfedge_geometry& g = m_mesh.geometry[h];
    if(!(g.l_next > 0.))
      return NO_INDEX;
    rotate_into(x - g.length, y, (g.cx - g.length) / g.l_next, g.cy / g.l_next, x, y);
    return Mesh_arrays::next(h);
  }

  // A line crosses an edge at one of its ends (through_vertex()) if it crosses it within this share of the
  // length of the edge plus the distance of the image from the edge's source: far above the rounding of the
  // walk through thin triangles (a few 1e-13 seen, with VSP's lines on slivers), far below what changes the
  // length of a path.
  static constexpr double vertex_slack = 1e-10;

  // The angle (radians) by which the direction of an image may miss a face and still be in it, in
  // straight_through(): far above rounding, far below what changes the length of a path.
  static constexpr double direction_slack = 1e-12;

  // the ways the current trace tried through vertices (straight_through()), at most max_straight_attempts
  static constexpr int max_straight_attempts = 256;
  mutable int m_straight_attempts = 0;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_TRACE_H
