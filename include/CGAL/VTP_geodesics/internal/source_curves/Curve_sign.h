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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_SIGN_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_SIGN_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>

#include <string>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The sign of the distances from curves (negative on the left of a curve: face normal x direction of travel).
//
// The curves cut the surface into parts: the vertices on a curve and the edges with a point of a curve inside
// them separate the others (the connected parts of what is left). A vertex whose nearest point lies inside a
// piece of a curve (its label is a segment seed, seen from one side) is on that side. A part whose vertices of
// that kind are all on one side is that side, all of its vertices. A part with vertices on both sides (the
// curves do not separate it: an open curve, a loop around a handle) keeps the side of each vertex whose nearest
// point lies inside a piece; a vertex nearest to a point where pieces meet takes the side of the first such
// vertex found from it along the edges of the part (breadth first, through vertices of its kind: the wedge beyond
// a corner of a curve lies between two strips of the same side), and a vertex nearest to an end of an open curve
// is positive; when every curve is closed, such a part is an error (the curves are not oriented consistently,
// or do not bound).
//
// `label` holds, per vertex, the index in `seeds` of the seed of its nearest point (NO_INDEX: unreached);
// `dist` is signed in place. `position`: the numbers of the vertices for the error message.
inline void sign_distances(const Mesh_arrays& m, const std::vector<Seed>& seeds, const std::vector<Index>& label,
                           bool every_curve_closed, std::vector<double>& dist, const std::vector<Index>& position)
{
  const Index nv = m.nv;
  const Index nh = static_cast<Index>(m.source.size());
  // the separators: the vertices of the curves, the edges with a point of a curve inside
  std::vector<unsigned char> on_curve(nv, 0), cut(nh, 0);
  for(const Seed& s : seeds)
  {
    if(s.segment)
      continue;
    if(s.kind == Seed::AT_VERTEX)
      on_curve[s.element] = 1;
    else if(s.kind == Seed::ON_EDGE)
    {
      cut[s.element] = 1;
      if(m.opposite[s.element] != NO_INDEX)
        cut[m.opposite[s.element]] = 1;
    }
  }
  // the parts: a flood over the edges that are not cut, from vertex to vertex
  std::vector<Index> part(nv, NO_INDEX), stack;
  Index parts = 0;
  for(Index v0 = 0; v0 < nv; ++v0)
  {
    if(part[v0] != NO_INDEX || on_curve[v0])
      continue;
    part[v0] = parts;
    stack.assign(1, v0);
    while(!stack.empty())
    {
      const Index v = stack.back();
      stack.pop_back();
      for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
      {
        const Index h = m.corners[c];  // v -> w, and the edge from v to the third vertex (prev(h), reversed)
        const Index e[2] = { h, Mesh_arrays::prev(h) };
        for(Index g : e)
        {
          if(cut[g])
            continue;
          const Index w = g == h ? m.target(h) : m.source[g];
          if(part[w] == NO_INDEX && !on_curve[w])
          {
            part[w] = parts;
            stack.push_back(w);
          }
        }
      }
    }
    ++parts;
  }
  // the sides seen in each part: bit 1 left, bit 2 right
  std::vector<unsigned char> seen(parts, 0);
  std::vector<Index> example(parts, NO_INDEX);
  for(Index v = 0; v < nv; ++v)
    if(part[v] != NO_INDEX && label[v] != NO_INDEX && seeds[label[v]].segment)
    {
      seen[part[v]] |= seeds[label[v]].side > 0 ? 1 : 2;
      example[part[v]] = v;
    }
  for(Index p = 0; p < parts; ++p)
    if(seen[p] == 3 && every_curve_closed)
      throw Invalid_input_error("signed distance: the curves are not oriented consistently or do not bound a part "
                                "of the surface (the part around vertex "
                                + std::to_string(position[example[p]])
                                + " lies on the left of a piece of a curve and on the right of another)");
  // the sides in the parts on both sides: from the vertices nearest to the inside of a piece, breadth first to
  // those nearest to a point where pieces meet (not to the ends of open curves)
  std::vector<signed char> side(nv, 0);
  std::vector<Index> queue;
  for(Index v = 0; v < nv; ++v)
    if(part[v] != NO_INDEX && seen[part[v]] == 3 && label[v] != NO_INDEX && seeds[label[v]].segment)
    {
      side[v] = seeds[label[v]].side > 0 ? 1 : -1;
      queue.push_back(v);
    }
  for(std::size_t i = 0; i < queue.size(); ++i)
  {
    const Index v = queue[i];
    for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
    {
      const Index h = m.corners[c];
      const Index e[2] = { h, Mesh_arrays::prev(h) };
      for(Index g : e)
      {
        if(cut[g])
          continue;
        const Index w = g == h ? m.target(h) : m.source[g];
        if(side[w] != 0 || part[w] != part[v] || label[w] == NO_INDEX)
          continue;
        const Seed& s = seeds[label[w]];
        if(s.segment || s.curve_end)
          continue;
        side[w] = side[v];
        queue.push_back(w);
      }
    }
  }
  for(Index v = 0; v < nv; ++v)
  {
    if(part[v] == NO_INDEX || label[v] == NO_INDEX || !(dist[v] > 0.))
      continue;
    const bool left = seen[part[v]] == 1 || (seen[part[v]] == 3 && side[v] > 0);
    if(left)
      dist[v] = -dist[v];
  }
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_SIGN_H
