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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_RECORD_H
#define CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_RECORD_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>
#include <CGAL/VTP_geodesics/internal/propagation/Targets.h>

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
  double angle = 0.;          // the window's angle (the log map, Direction_record.h)
  double b0 = 0., b1 = 0.;    // the window's interval on `halfedge` (the curves, geodesic_curves.h)
};

// Offer of a straight segment from `origin`.
inline Offer straight_offer(double distance, Index origin)
{
  Offer o;
  o.distance = distance;
  o.origin = origin;
  return o;
}

// The offer of window w of the list of h to the point (px, py) of face(h) (frame of h), at `distance`:
// straight from the image of w when the point is seen through the window, else bent at its nearer end.
inline Offer offer_through_window(double distance, Index h, const Window& w, double px, double py)
{
  Offer o;
  o.distance = distance;
  o.origin = w.origin;
  o.halfedge = h;
  o.sx = w.sx;
  o.sy = w.sy;
  o.angle = w.angle;
  o.b0 = w.b0;
  o.b1 = w.b1;
  double bend;
  if(window_bend(w, px, py, bend))
    o.bend = bend;
  return o;
}

// The trace-back record of a propagation: for each vertex and each target, the offer that gave its
// current distance. O(V + targets), filled only when paths are asked for.
//
// Like the stop rule (Stop_rule.h), the record is told what happens through hooks, which do nothing
// unless paths are recorded: the loops and the shared steps (Propagation_state.h) call them and never
// test whether the record is active. A hook that may run on several threads at once only writes the
// entries of its caller (a vertex or target of the face it owns).
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

  // ------------------------------------------------------------------------------------------------
  // hooks
  // ------------------------------------------------------------------------------------------------

  // The distance of vertex v was lowered by `offer`: it becomes v's record if it is shorter than the recorded
  // offer by more than rounding (see tie).
  void on_vertex_lowered(Index v, const Offer& offer)
  {
    if(m_active)
    {
      Offer& recorded = vertex[static_cast<std::size_t>(v)];
      if(!(offer.distance >= recorded.distance * (1. - tie)))  // (+infinity: nothing recorded yet)
        recorded = offer;
    }
  }

  // Target t was lowered to `distance`, straight from `origin` (a source point of its face, or a vertex).
  void on_target_reached_straight(Index t, double distance, Index origin)
  {
    if(m_active)
      target[static_cast<std::size_t>(t)] = straight_offer(distance, origin);
  }

  // Target t (the point `point`, inside face(h)) was lowered to `distance` by window w of the list of h.
  void on_target_reached_by_window(Index t, double distance, Index h, const Window& w, const Target& point)
  {
    if(m_active)
    {
      const std::size_t k = static_cast<std::size_t>(h % 3);
      target[static_cast<std::size_t>(t)] = offer_through_window(distance, h, w, point.x[k], point.y[k]);
    }
  }

  // The list of h offers `offer` to the third vertex (px, py) of face(h) through window w: what the
  // trace-back needs is added to the offer (which the vertex keeps if it lowers its distance).
  void on_list_offer(Offer& offer, Index h, const Window& w, double px, double py) const
  {
    if(m_active)
      offer = offer_through_window(offer.distance, h, w, px, py);
  }

  // An offer that lowers a vertex's distance by less than this share of its recorded offer is a tie, which
  // keeps the path recorded: the recorded path's length is then the distance within this share (and the
  // record holds no cycle of rounding). Without it, two vertices at the same point (a zero-length edge) can
  // lower each other by an ulp in turn, each then recording a path through the other, and the trace-back
  // of either goes round for ever: the one lowered by a window whose line reaches it at the other's
  // position (through a face of zero area between them), the other straight from it along the zero-length
  // edge (vtp_stress --seed 1 --case 1388 --max-vertices 300, test_stop_and_paths.cpp).
  static constexpr double tie = 1e-12;

private:
  bool m_active = false;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_RECORD_H
