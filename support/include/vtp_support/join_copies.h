// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_JOIN_COPIES_H
#define VTP_SUPPORT_JOIN_COPIES_H

// Distances through the vertices that the repair split (`vtp_geodesics --through-pinches`, Python's
// `Solver(..., through_pinches=True)`).
//
// The repair (triangle_mesh_from_soup.h) cuts the surface at a non-manifold vertex (a pinch) and at the ends of a
// non-manifold edge, making copies of the vertex; a propagation on the repaired mesh keeps the copies apart (no
// shortest path goes from one side of the cut to the other). Joining them means: the copies of one vertex are one
// point, at the least of their distances, and the field goes on from there on every side.
//
// `join_copies()` lowers a field computed on the repaired mesh to that. The split vertices are taken one at a
// time, the nearest first (as in Dijkstra's algorithm): once taken, the least distance of its copies is final
// (any path through a vertex not taken yet is at least as long), and its copies farther than that become the
// sources of a run from the known distances (the library's named parameter `initial_distances`), shifted by
// that distance so that the new sources start at 0. A run costs the region where the copies lower the field;
// one run per split vertex that a source reaches and whose copies differ. Exact for the exact methods (the field
// is the distance on the surface where the copies of every split vertex are one point); a path that crosses a
// non-manifold edge between its ends is not found (only its end points are joined).

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace vtp_support {

// `groups`: the copies of each split vertex (mesh vertex indices, at least two each); `d`: the field, per mesh
// vertex index, lowered in place; `labels` (or null): the label of each mesh vertex, a lowered vertex taking the
// label of the copy it comes from. `run_from(sources, field)`: a propagation from the mesh vertices `sources`
// that starts from the known distances `field` (each >= 0 or +infinity, per mesh vertex index) and leaves in
// `field` the least of them and of the distances from `sources`. Returns the number of runs.
template <class Vertex, class Label, class Run_from>
std::size_t join_copies(const std::vector<std::vector<Vertex> >& groups, std::vector<double>& d,
                        std::vector<Label>* labels, Run_from&& run_from)
{
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<unsigned char> taken(groups.size(), 0);
  std::vector<double> field(d.size()), before;
  std::vector<Vertex> sources;
  std::size_t runs = 0;
  for(;;)
  {
    std::size_t best = groups.size();
    double best_d = infinity;
    for(std::size_t g = 0; g < groups.size(); ++g)
    {
      if(taken[g])
        continue;
      double lo = infinity, hi = 0.;
      for(Vertex c : groups[g])
      {
        lo = (std::min)(lo, d[std::size_t(c)]);
        hi = (std::max)(hi, d[std::size_t(c)]);
      }
      if(!(lo < infinity))
        continue;
      if(!(hi > lo)) // already joined: no later run lowers a copy below lo
        taken[g] = 1;
      else if(lo < best_d)
      {
        best_d = lo;
        best = g;
      }
    }
    if(best == groups.size())
      return runs;
    taken[best] = 1;
    sources.clear();
    std::size_t from = std::size_t(groups[best].front());
    for(Vertex c : groups[best])
      if(d[std::size_t(c)] > best_d)
        sources.push_back(c);
      else
        from = std::size_t(c);
    for(std::size_t v = 0; v < d.size(); ++v)
      field[v] = d[v] > best_d ? d[v] - best_d : 0.;
    before = field;
    run_from(sources, field);
    ++runs;
    // only where the run lowered the shifted field (not where subtracting and adding back rounds)
    for(std::size_t v = 0; v < d.size(); ++v)
      if(field[v] < before[v] && field[v] + best_d < d[v])
      {
        d[v] = field[v] + best_d;
        if(labels != nullptr)
          (*labels)[v] = (*labels)[from];
      }
  }
}

} // namespace vtp_support

#endif // VTP_SUPPORT_JOIN_COPIES_H
