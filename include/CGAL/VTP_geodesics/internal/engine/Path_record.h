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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PATH_RECORD_H
#define CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PATH_RECORD_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>

#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// What a list (or a source, or a pseudo-source) offers to a vertex or a target, with what the path
// trace-back needs to follow the path back from there: the path is straight in the unfolding from the
// image (sx, sy) of its origin, given in the frame of `halfedge` (the list whose window offered it), to
// the point, possibly bent at abscissa `bend` of that half-edge (an end of the window); or, when
// `halfedge` is NO_INDEX, a straight segment from the origin itself (a neighbour along an edge, a source
// point of the same face).
struct Offer
{
  double distance = std::numeric_limits<double>::infinity();
  Index origin = NO_INDEX;    // a vertex, or nv + i for point source i
  Index halfedge = NO_INDEX;
  double sx = 0., sy = 0.;
  double bend = std::numeric_limits<double>::quiet_NaN();
};

// Offer of a straight segment from `origin`.
inline Offer straight_offer(double distance, Index origin)
{
  Offer o;
  o.distance = distance;
  o.origin = origin;
  return o;
}

// The trace-back record of a propagation: for each vertex and each target, the offer that gave its
// current distance. O(V + targets), filled only when paths are asked for.
struct Path_record
{
  std::vector<Offer> vertex;
  std::vector<Offer> target;

  void start(bool active, std::size_t number_of_vertices, std::size_t number_of_targets)
  {
    m_active = active;
    if(active)
    {
      vertex.assign(number_of_vertices, Offer());
      target.assign(number_of_targets, Offer());
    }
    else
    {
      vertex.clear();
      target.clear();
    }
  }

  bool is_active() const { return m_active; }

private:
  bool m_active = false;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PATH_RECORD_H
