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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PROPAGATION_STATE_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PROPAGATION_STATE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Triangle_propagation.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_data.h>

#include <CGAL/assertions.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The state of one propagation and the steps that the sequential and the parallel loops share.
//
// A distance upper bound per vertex (always the length of a real surface path), the set of swept faces
// (the one-rings of the vertices taken so far), per half-edge the list of windows waiting to cross its
// face, the schedule of the vertices waiting to be taken, and the reset policy. A vertex taken from the
// schedule first emits windows if it is a pseudo-source (saddle or boundary vertex, or made one by a
// reset), then sweeps its one-ring: every waiting list whose face is swept is queued; the loops
// propagate the queued lists, and those they feed inside the swept region, until every window waits on
// the wavefront (the border of the swept region).
//
// Exactness (without resets) does not depend on the order: windows are only cut where another real path
// is shorter; the order only decides how many windows are created.
//
// A run from known distances (settings.known_distances) starts from the field of earlier sources and wakes
// the known vertices that new windows reach: Known_vertices.h.
class Propagation_state : public Propagation_data
{
public:
  // ------------------------------------------------------------------------------------------
  // shared steps
  // ------------------------------------------------------------------------------------------

  // Lowers the distance of v to what `offer` (of a window) offers if that is shorter, and schedules v.
  void light(Index v, const Offer& offer) { light(v, offer, [&]() { return window_arrival(offer); }); }

  // The same for any offer; arrival() gives the ray that reaches v (Direction_record.h), asked for only when
  // the log map is.
  template <class Arrival>
  void light(Index v, const Offer& offer, const Arrival& arrival)
  {
    const double old = dist[v];
    if(offer.distance < old)
    {
      if(reached != nullptr && !(old < std::numeric_limits<double>::infinity()))
        reached->push_back(v);  // local runs (Local_propagation.h)
      dist[v] = offer.distance;
      if(!label.empty())
        label[v] = label_of_origin(offer.origin);
      mark_lowered(v);
      record.on_vertex_lowered(v, offer);
      if(direction.is_active())
        direction.on_offer(v, offer.origin, offer.distance, old, arrival);
      schedule.push(v, offer.distance);
    }
    else if(direction.is_active() && offer.distance <= old * (1. + Path_record::tie)
            && old < std::numeric_limits<double>::infinity())
      direction.on_offer(v, offer.origin, offer.distance, old, arrival);  // a tie
  }

  // The ray of a window's offer to the third vertex C of face(h), in the frame of h. A path bent at an end of
  // its edge that is a vertex (it ties the straight offer of that vertex) comes from that vertex.
  Ray_arrival window_arrival(const Offer& o)
  {
    CGAL_assertion(o.halfedge != NO_INDEX);
    const Mesh_arrays& m = *mesh;
    const Index h = o.halfedge;
    const Halfedge_geometry g = m.geometry[h];
    if(!std::isnan(o.bend) && (o.bend <= 0. || o.bend >= g.length))
    {
      const Index end = o.bend <= 0. ? m.source[h] : m.target(h);
      const bool emits = m.is_pseudo_source[end] || direction.is_source(end);
      if(emits && direction.emission_angles(end, m_bend_angles))
      {
        if(o.bend <= 0.)  // from A along A -> C
          return Ray_arrival{Direction_record::angle_of(m_bend_angles, h), g.cx, g.cy, Mesh_arrays::prev(h), -g.cx, -g.cy,
                             end};
        const Index bc = Mesh_arrays::next(h);  // from B along B -> C, in the frame of B -> C
        const std::array<double, 2> c = halfedge_vector_in_frame(m, bc, Mesh_arrays::prev(h));
        return Ray_arrival{Direction_record::angle_of(m_bend_angles, bc), g.l_next, 0., Mesh_arrays::prev(h), c[0],
                           c[1], end};
      }
      if(emits)  // strict: theta of the vertex
        return Ray_arrival{0., 1., 0., NO_INDEX, 1., 0., end};
    }
    if(!std::isnan(o.bend))
    {
      // bent at a vertex that does not turn geodesics (nearly flat) or inside the edge (an upper bound): the
      // direction of the ray to the bend, the length of the path
      const double ax = o.bend - o.sx, ay = -o.sy, bx = g.cx - o.bend, by = g.cy;
      const double a = std::sqrt(ax * ax + ay * ay), scale = a > 0. ? (a + std::sqrt(bx * bx + by * by)) / a : 1.;
      return Ray_arrival{o.angle, ax * scale, ay * scale, Mesh_arrays::prev(h), -g.cx, -g.cy};
    }
    return Ray_arrival{o.angle, g.cx - o.sx, g.cy - o.sy, Mesh_arrays::prev(h), -g.cx, -g.cy};
  }

  // Target t is reached at distance d straight from `origin` (serial).
  void offer_to_target(Index t, double d, Index origin)
  {
    if(stop.offer(t, d))
      record.on_target_reached_straight(t, d, origin);
  }

  void enqueue(Index h)
  {
    if(!queued[h])
    {
      queued[h] = 1;
      fifo.push_back(h);
    }
  }

  // Processes vertex v taken from the schedule at distance dv; returns false for a stale entry.
  bool take_vertex(Index v, double dv)
  {
    if(dv > dist[v] || processed[v] == dv)
      return false; // stale entry, or already processed at this distance
    if(reset.is_due(dv))
      reset.apply(v, dv, *mesh, schedule, dist, processed, store, [&](Index h) { stop.on_list_emptied(h); });
    processed[v] = dv;
    ++vertices_processed;
    // a known vertex only woken (not lowered) emits nothing, unless a reset forces it (AVTP)
    if((mesh->is_pseudo_source[v] && known.lowered(v)) || reset.is_forced(v))
      emit_pseudo_source(v);
    sweep(v);
    reach_targets_through(v);
    return true;
  }

  // The targets of v and of the faces around v get what v offers (serial).
  void reach_targets_through(Index v)
  {
    if(!stop.has_targets())
      return;
    stop.on_vertex_processed(v, dist[v], [&](Index t, Index) {
      record.on_target_reached_straight(t, stop.target_value(static_cast<std::size_t>(t)), v);
    });
  }

  // A (pseudo-)source v: its neighbours are reached straight, and a window covering each edge opposite
  // to v starts towards the face beyond that edge. Through a zero-area face, v reaches the face beyond as
  // a point of its edge (emit_point(), below).
  void emit_pseudo_source(Index v)
  {
    const Mesh_arrays& m = *mesh;
    const double dv = dist[v];
    if(dv > 0.)
      ++pseudo_sources;
    // the log map: the direction of each half-edge leaving v in the turning frame of v
    const bool angles = direction.is_active() && direction.emission_angles(v, m_angles);
    for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
    {
      const Index h = m.corners[c];
      const Halfedge_geometry gh = m.geometry[h];
      const double base = angles ? Direction_record::angle_of(m_angles, h) : 0.;
      light(m.target(h), straight_offer(dv + gh.length, v), [&]() {
        return Ray_arrival{base, gh.length, 0., Mesh_arrays::next(h), gh.cx - gh.length, gh.cy};
      });
      light(m.source[Mesh_arrays::prev(h)], straight_offer(dv + gh.l_prev, v), [&]() {
        return Ray_arrival{base, gh.cx, gh.cy, Mesh_arrays::prev(h), -gh.cx, -gh.cy};
      });
    }
    for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
    {
      const Index h = m.corners[c];
      const Index e = Mesh_arrays::next(h);   // B -> C, the edge opposite to v
      const Index o = m.opposite[e];          // C -> B, in the face beyond
      if(o == NO_INDEX)
        continue;
      const Halfedge_geometry& ge = m.geometry[e];
      double angle = 0.;  // the direction of C -> B in the turning frame of v (the log map)
      if(angles)
      {
        const Halfedge_geometry gh = m.geometry[h];
        angle = Direction_record::angle_of(m_angles, h) + std::atan2(-gh.cy, gh.length - gh.cx);
      }
      if(m.is_degenerate_face[Mesh_arrays::face(h)])
      {
        // v lies on the line of B-C (up to rounding): no window can start from it
        emit_point(o, ge.length - ge.cx, dv, v, angle);
        continue;
      }
      Window w;
      w.b0 = 0.;
      w.b1 = ge.length;
      w.sx = ge.length - ge.cx;
      w.sy = -ge.cy;
      w.sigma = dv;
      w.angle = angle;
      w.origin = v;
      if(!(w.sy < 0.))
        continue;
      store_emitted(o, w);
    }
  }

  // A point source at distance dv lying at abscissa t on the half-edge o: if it is inside the edge, it is
  // a point source for face(o) (the windows it starts cover the two other edges of face(o)). When face(o)
  // has zero area, the point is carried on through the edge of face(o) that contains it (lighting the
  // third vertex, on the line), a bounded number of times. `angle`: the direction of the x-axis of o in the
  // turning frame of the origin (the log map).
  void emit_point(Index o, double t, double dv, Index origin, double angle)
  {
    const Mesh_arrays& m = *mesh;
    for(int step = 0; step < 64 && o != NO_INDEX; ++step)
    {
      const Halfedge_geometry& g = m.geometry[o];
      if(!(t > 0. && t < g.length))
        return;
      const Index c = m.source[Mesh_arrays::prev(o)];
      const Index h_ac = m.opposite[Mesh_arrays::prev(o)];
      const Index h_cb = m.opposite[Mesh_arrays::next(o)];
      const auto arrival = [&]() {
        return Ray_arrival{angle, g.cx - t, g.cy, Mesh_arrays::prev(o), -g.cx, -g.cy};
      };
      if(!m.is_degenerate_face[Mesh_arrays::face(o)])
      {
        m_emit_ac.clear();
        m_emit_cb.clear();
        light(c, straight_offer(propagate_edge_point(g, t, dv, origin, angle, h_ac != NO_INDEX, h_cb != NO_INDEX,
                                                     m_emit_ac, m_emit_cb), origin), arrival);
        for(const Window& w : m_emit_ac)
          store_emitted(h_ac, w);
        for(const Window& w : m_emit_cb)
          store_emitted(h_cb, w);
        return;
      }
      const double dx = g.cx - t;
      light(c, straight_offer(dv + std::sqrt(dx * dx + g.cy * g.cy), origin), arrival);
      if(t < g.cx)
      {
        o = h_ac;            // A -> C, same abscissa
        angle += std::atan2(g.cy, g.cx);
      }
      else if(t > g.cx)
      {
        o = h_cb;            // C -> B, from C
        t -= g.cx;
        angle += std::atan2(-g.cy, g.length - g.cx);
      }
      else
        return;              // the point is C itself
    }
  }

  // Stores a window started by a (pseudo-)source on the list of h (trimmed by the ends of h).
  void store_emitted(Index h, Window w)
  {
    const Mesh_arrays& m = *mesh;
    const double length = m.geometry[h].length;
    if(!trim_by_vertices(w, length, dist[m.source[h]], dist[m.target(h)]))
      return;
    if(!(w.b1 - w.b0 > settings.minimum_window_ratio * length))
      return;
    store.push(h, w);
    ++created;
    if(stop.is_tracking())
    {
      stop.on_windows_stored(h, &w, &w + 1, m_events);
      stop.merge(m_events);
    }
    if(swept[Mesh_arrays::face(h)])
      enqueue(h);
    else
      wake_corners(Mesh_arrays::face(h));
  }

  // Adds the one-ring of v to the swept region; the waiting lists of newly swept faces are queued.
  void sweep(Index v)
  {
    const Mesh_arrays& m = *mesh;
    for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
    {
      const Index f = Mesh_arrays::face(m.corners[c]);
      if(swept[f])
        continue;
      swept[f] = 1;
      for(Index k = 0; k < 3; ++k)
        if(!store.empty(3 * f + k))
          enqueue(3 * f + k);
    }
  }

  // Filters the list of h held in s.in and propagates it across face(h): the children are left in
  // s.out_ac / s.out_cb; returns what the list offers to the opposite vertex. Reads the distances and
  // the mesh, and writes only to s and to the targets of face(h) (and their records), so that the
  // parallel scheduling can call it from many threads for lists of different faces.
  Offer propagate_one(Index h, Propagation_scratch& s)
  {
    const Mesh_arrays& m = *mesh;
    const Halfedge_geometry& g = m.geometry[h];
    const Index a = m.source[h];
    const Index b = m.source[Mesh_arrays::next(h)];
    filter_list(s.in, g.length, dist[a], dist[b], settings.minimum_window_ratio * g.length, s.list, line_windows);
    Offer offer;
    if(s.in.empty())
      return offer;
    field.on_list_crossing(h, s.in, s.crossed);
    if(stop.has_targets())
      stop.on_list_crossing(h, s.in, s.events, [&](Index t, const Window& w) {
        const std::size_t i = static_cast<std::size_t>(t);
        record.on_target_reached_by_window(t, stop.target_value(i), h, w, stop.targets()[i]);
      });
    const Index h_cb = m.opposite[Mesh_arrays::next(h)];
    const Index h_ac = m.opposite[Mesh_arrays::prev(h)];
    const Propagation_result r = propagate_list(g, s.in, s.list.ends, settings.minimum_window_ratio,
                                                h_ac != NO_INDEX, h_cb != NO_INDEX, s.out_ac, s.out_cb, s.list.xc,
                                                direction.is_active(), line_windows);
    s.propagated += r.propagated;
    offer.distance = r.distance_to_C;
    if(offer.distance < std::numeric_limits<double>::infinity())
    {
      const Window& w = s.in[r.best];
      offer.origin = w.origin;
      record.on_list_offer(offer, h, w, g.cx, g.cy);
      if(direction.is_active())  // (the log map needs the ray too)
        offer = offer_through_window(offer.distance, h, w, g.cx, g.cy);
    }
    return offer;
  }

  // Appends children to the list of h with blocks of pool p; if the face of h is swept, h is queued into
  // `to_queue` (the FIFO, or the queue of a face unit: the caller owns every list it writes). Returns the
  // number of windows stored.
  template <class Queue>
  std::size_t store_children(Index h, const std::vector<Window>& children, std::size_t p, Queue& to_queue,
                             Stop_events& events)
  {
    if(children.empty())
      return 0;
    store.push(h, children.data(), children.data() + children.size(), p);
    if(stop.is_tracking())
      stop.on_windows_stored(h, children.data(), children.data() + children.size(), events);
    if(swept[Mesh_arrays::face(h)] && !queued[h])
    {
      queued[h] = 1;
      to_queue.push_back(h);
    }
    return children.size();
  }

  // Stores the children of the list of h left in s by propagate_one(), as store_children() does.
  template <class Queue>
  void store_all_children(Index h, Propagation_scratch& s, std::size_t p, Queue& to_queue)
  {
    const Mesh_arrays& m = *mesh;
    s.created += store_children(m.opposite[Mesh_arrays::prev(h)], s.out_ac, p, to_queue, s.events);
    s.created += store_children(m.opposite[Mesh_arrays::next(h)], s.out_cb, p, to_queue, s.events);
  }

private:
  std::vector<Window> m_emit_ac, m_emit_cb;
  std::vector<std::pair<Index, double> > m_angles, m_bend_angles;  // the log map: of the vertex emitting
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PROPAGATION_STATE_H
