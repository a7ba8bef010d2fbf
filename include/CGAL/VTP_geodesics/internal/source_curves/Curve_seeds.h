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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_SEEDS_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_SEEDS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A source curve as seeds: its points (point seeds) and, between two consecutive points of one face, the
// segment joining them in that face, seen from both sides (segment seeds, propagation/Seeding.h). All carry
// the label of the curve. Two consecutive points that share no face are joined before (by the solver: the
// shortest geodesic between them, whose consecutive points share a face).

// Whether two seeds are the same point of the surface.
inline bool same_point(const Seed& a, const Seed& b)
{
  return !a.segment && !b.segment && a.kind == b.kind && a.element == b.element && a.x == b.x && a.y == b.y;
}

// The faces that contain the point seed s (the faces around a vertex, the one or two faces of an edge).
inline void faces_of(const Mesh_arrays& m, const Seed& s, std::vector<Index>& out)
{
  out.clear();
  if(s.kind == Seed::AT_VERTEX)
  {
    for(Index c = m.corner_begin[s.element]; c < m.corner_begin[s.element + 1]; ++c)
      out.push_back(Mesh_arrays::face(m.corners[c]));
  }
  else if(s.kind == Seed::ON_EDGE)
  {
    out.push_back(Mesh_arrays::face(s.element));
    if(m.opposite[s.element] != NO_INDEX)
      out.push_back(Mesh_arrays::face(m.opposite[s.element]));
  }
  else
    out.push_back(s.element);
}

// A face that contains both point seeds (not of zero area if there is one), or NO_INDEX.
inline Index common_face(const Mesh_arrays& m, const Seed& a, const Seed& b)
{
  std::vector<Index> fa, fb;
  faces_of(m, a, fa);
  faces_of(m, b, fb);
  Index found = NO_INDEX;
  for(Index f : fa)
    for(Index g : fb)
      if(f == g && (found == NO_INDEX || (m.is_degenerate_face[found] && !m.is_degenerate_face[f])))
        found = f;
  return found;
}

// The point seed s (in face f) in the frame of 3 f.
inline std::array<double, 2> point_in_face(const Mesh_arrays& m, const Seed& s, Index f)
{
  const Face_frame frame(m, f);
  const Index h0 = 3 * f;
  if(s.kind == Seed::IN_FACE)
    return { s.x, s.y };
  if(s.kind == Seed::AT_VERTEX)
  {
    for(int k = 0; k < 3; ++k)
      if(m.source[h0 + k] == s.element)
        return { frame.x[k], frame.y[k] };
    CGAL_assertion(false);
    return { 0., 0. };
  }
  // on an edge: abscissa x on half-edge s.element, which is h0 + k or its opposite
  for(int k = 0; k < 3; ++k)
  {
    const Index h = h0 + k;
    if(h != s.element && m.opposite[h] != s.element)
      continue;
    const double L = m.geometry[h].length;
    const double t = (h == s.element ? s.x : L - s.x) / (L > 0. ? L : 1.);
    return { frame.x[k] + t * frame.ex(k), frame.y[k] + t * frame.ey(k) };
  }
  CGAL_assertion(false);
  return { 0., 0. };
}

// Appends the two sides of the segment from point seed a to point seed b in face f (a != b).
inline void add_segment(const Mesh_arrays& m, const Seed& a, const Seed& b, Index f, Index label,
                        std::vector<Seed>& seeds)
{
  const std::array<double, 2> p = point_in_face(m, a, f), q = point_in_face(m, b, f);
  if(p[0] == q[0] && p[1] == q[1])
    return;
  for(int side : { 1, -1 })
  {
    Seed s;
    s.kind = Seed::IN_FACE;
    s.element = f;
    s.segment = true;
    s.side = side;
    s.x = p[0];
    s.y = p[1];
    s.x1 = q[0];
    s.y1 = q[1];
    s.label = label;
    seeds.push_back(s);
  }
}

// Appends the seeds of the curve through `points` (point seeds; consecutive ones share a face; the curve is
// closed when the last is the first), with `label`.
inline void add_curve_seeds(const Mesh_arrays& m, const std::vector<Seed>& points, Index label,
                            std::vector<Seed>& seeds)
{
  const bool closed = points.size() > 2 && same_point(points.back(), points[0]);
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(i + 1 == points.size() && closed)
      break;  // the end of a closed curve is its start
    Seed s = points[i];
    s.label = label;
    s.curve_end = !closed && (i == 0 || i + 1 == points.size());
    seeds.push_back(s);
  }
  for(std::size_t i = 0; i + 1 < points.size(); ++i)
  {
    if(same_point(points[i], points[i + 1]))
      continue;
    const Index f = common_face(m, points[i], points[i + 1]);
    CGAL_precondition(f != NO_INDEX);
    add_segment(m, points[i], points[i + 1], f, label, seeds);
  }
}

// The border of the mesh (every border edge, each loop oriented with the surface on its left), as edges for
// add_edge_seeds().
inline std::vector<std::array<Index, 3> > border_edges(const Mesh_arrays& m)
{
  std::vector<std::array<Index, 3> > edges;
  const Index nh = static_cast<Index>(m.source.size());
  for(Index h = 0; h < nh; ++h)
    if(m.opposite[h] == NO_INDEX)
      edges.push_back({ m.source[h], m.target(h), Mesh_arrays::face(h) });
  return edges;
}

// The seeds of the edges `edges` (and of their vertices), with `label`: each edge as {a, b, f}, from vertex a to
// vertex b, f a face of the edge (its left side is the left of a -> b). A vertex of one edge only ends an
// open curve.
inline void add_edge_seeds(const Mesh_arrays& m, const std::vector<std::array<Index, 3> >& edges, Index label,
                           std::vector<Seed>& seeds)
{
  std::vector<unsigned char> seen(m.nv, 0);
  std::vector<Index> degree(m.nv, 0);
  for(const std::array<Index, 3>& e : edges)
  {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  for(const std::array<Index, 3>& e : edges)
  {
    Seed a, b;
    a.element = e[0];
    b.element = e[1];
    a.label = b.label = label;
    a.curve_end = degree[a.element] == 1;
    b.curve_end = degree[b.element] == 1;
    for(const Seed& v : { a, b })
      if(!seen[v.element])
      {
        seen[v.element] = 1;
        seeds.push_back(v);
      }
    add_segment(m, a, b, e[2], label, seeds);
  }
}

// Whether no seed ends an open curve.
inline bool every_curve_closed(const std::vector<Seed>& seeds)
{
  for(const Seed& s : seeds)
    if(s.curve_end)
      return false;
  return true;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_SEEDS_H
