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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_STOP_RULE_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_STOP_RULE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>
#include <CGAL/VTP_geodesics/internal/propagation/Targets.h>
#include <CGAL/VTP_geodesics/internal/propagation/Vertex_schedule.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// What the threads of one round (or the sequential loop, after each list) report to the stop rule:
// new smallest window bounds of lists, and new distances of targets.
struct Stop_events
{
  std::vector<std::pair<double, Index> > list_bounds;  // (bound, half-edge)
  std::vector<std::pair<double, Index> > targets;      // (distance, target)
  void clear()
  {
    list_bounds.clear();
    targets.clear();
  }
};

// The stopping policy: never (the propagation runs until no window is left), at a distance limit R, or
// once the distance of every target is final.
//
// Why the stop is exact. Whatever the propagation does from now on derives from the windows waiting in
// lists and from the vertices waiting in the schedule: a waiting vertex offers paths of length at least
// its current distance (it emits windows from it when it is a pseudo-source), a window offers paths at
// least as long as its smallest distance on its own edge (its children and the distances it offers lie
// farther along the same straight rays). So no distance can ever be lowered below
//     L = min(smallest key waiting in the schedule, smallest window bound of the waiting lists),
// and L never decreases. A vertex or target whose current distance is <= L is final; once L > R, every
// vertex whose final distance is <= R has it already. The same holds for the approximate variants (a
// reset only deletes windows and makes waiting vertices pseudo-sources), with their own distances. The
// parallel scheduling checks at the start of each selection, when no list is queued.
//
// The window bounds are kept in a lazy heap: each list records the smallest bound pushed since it was
// last emptied; an entry whose bound differs from its list's record is stale.
class Stop_rule
{
public:
  // With keep_list_bounds, the bounds of the lists are those the caller has put back to +infinity
  // (on_list_emptied() on every list of the previous run, Local_propagation.h).
  void start(const Mesh_arrays& m, double limit, bool stop_at_targets, std::vector<Target>&& targets,
             bool keep_list_bounds = false)
  {
    m_limit = limit;
    m_stop_at_targets = stop_at_targets && !targets.empty();
    m_targets = std::move(targets);
    m_tracking = m_limit < std::numeric_limits<double>::infinity() || m_stop_at_targets;
    m_bound_heap.clear();
    m_target_heap.clear();
    m_lower_bound = 0.;
    m_stopped = false;
    if(m_tracking && !(keep_list_bounds && m_list_bound.size() == m.source.size()))
      m_list_bound.assign(m.source.size(), std::numeric_limits<double>::infinity());
    else if(!m_tracking)
      m_list_bound.clear();
    const std::size_t nt = m_targets.size();
    m_value.assign(nt, std::numeric_limits<double>::infinity());
    m_resolved.assign(nt, 0);
    m_unresolved = nt;
    // face -> its targets, vertex -> its targets, vertex -> the face targets of its faces
    m_face_first.clear();
    m_vertex_first.clear();
    m_corner_first.clear();
    m_next.assign(nt, NO_INDEX);
    m_corner_links.clear();
    if(nt == 0)
      return;
    m_face_first.assign(static_cast<std::size_t>(m.nf), NO_INDEX);
    m_vertex_first.assign(static_cast<std::size_t>(m.nv), NO_INDEX);
    m_corner_first.assign(static_cast<std::size_t>(m.nv), NO_INDEX);
    for(std::size_t t = 0; t < nt; ++t)
    {
      const Target& target = m_targets[t];
      if(target.vertex != NO_INDEX)
      {
        m_next[t] = m_vertex_first[target.vertex];
        m_vertex_first[target.vertex] = static_cast<Index>(t);
        continue;
      }
      m_next[t] = m_face_first[target.face];
      m_face_first[target.face] = static_cast<Index>(t);
      for(Index k = 0; k < 3; ++k)
      {
        const Index v = m.source[3 * target.face + k];
        m_corner_links.push_back(Corner_link{ static_cast<Index>(t), k, m_corner_first[v] });
        m_corner_first[v] = static_cast<Index>(m_corner_links.size() - 1);
      }
    }
  }

  // whether window bounds must be reported (a limit or targets to stop at)
  bool is_tracking() const { return m_tracking; }
  bool has_targets() const { return !m_targets.empty(); }
  bool has_face_targets(Index f) const { return !m_face_first.empty() && m_face_first[f] != NO_INDEX; }
  double limit() const { return m_limit; }

  // Calls f(t) for each target t inside face f.
  template <class F>
  void for_each_target_in_face(Index f, F&& fn) const
  {
    if(!has_face_targets(f))
      return;
    for(Index t = m_face_first[f]; t != NO_INDEX; t = m_next[static_cast<std::size_t>(t)])
      fn(t);
  }

  // ------------------------------------------------------------------------------------------------
  // hooks (the ones that may run on several threads at once only touch the lists and faces of their
  // caller, and report through its Stop_events)
  // ------------------------------------------------------------------------------------------------

  // The list of h was emptied (propagated or deleted).
  void on_list_emptied(Index h)
  {
    if(m_tracking)
      m_list_bound[h] = std::numeric_limits<double>::infinity();
  }

  // Windows were appended to the list of h.
  void on_windows_stored(Index h, const Window* begin, const Window* end, Stop_events& events)
  {
    if(!m_tracking || begin == end)
      return;
    double b = std::numeric_limits<double>::infinity();
    for(const Window* w = begin; w != end; ++w)
      b = (std::min)(b, window_lower_bound(*w));
    if(b < m_list_bound[h])
    {
      m_list_bound[h] = b;
      events.list_bounds.push_back(std::make_pair(b, h));
    }
  }

  // The filtered list ws of h is about to cross face(h): it offers distances to the targets of that face.
  // on_improved(t, window) is called for each target whose distance the list lowers (on the calling
  // thread, which owns face(h) and so its targets).
  template <class OnImproved>
  void on_list_crossing(Index h, const std::vector<Window>& ws, Stop_events& events, OnImproved on_improved)
  {
    if(ws.empty() || !has_face_targets(Mesh_arrays::face(h)))
      return;
    const std::size_t k = static_cast<std::size_t>(h % 3);
    for(Index t = m_face_first[Mesh_arrays::face(h)]; t != NO_INDEX; t = m_next[static_cast<std::size_t>(t)])
    {
      const Target& target = m_targets[static_cast<std::size_t>(t)];
      double best = std::numeric_limits<double>::infinity();
      std::size_t best_window = 0;
      for(std::size_t i = 0; i < ws.size(); ++i)
      {
        const double d = window_distance_at(ws[i], target.x[k], target.y[k]);
        if(d < best)
        {
          best = d;
          best_window = i;
        }
      }
      if(best < m_value[static_cast<std::size_t>(t)])
      {
        m_value[static_cast<std::size_t>(t)] = best;
        events.targets.push_back(std::make_pair(best, t));
        on_improved(t, ws[best_window]);
      }
    }
  }

  // Serial: target t is reached at distance d (by a path that the caller records).
  bool offer(Index t, double d)
  {
    if(!(d < m_value[static_cast<std::size_t>(t)]))
      return false;
    m_value[static_cast<std::size_t>(t)] = d;
    m_target_heap.push_back(std::make_pair(d, t));
    std::push_heap(m_target_heap.begin(), m_target_heap.end(), std::greater<std::pair<double, Index> >());
    return true;
  }

  // Serial: vertex v was processed at distance dv. Its vertex targets take dv; the face targets of its
  // faces are reached through it: on_improved(t, k) is called for each one improved (k: the corner).
  template <class OnImproved>
  void on_vertex_processed(Index v, double dv, OnImproved on_improved)
  {
    if(m_targets.empty())
      return;
    for(Index t = m_vertex_first[v]; t != NO_INDEX; t = m_next[static_cast<std::size_t>(t)])
      offer(t, dv);
    for(Index c = m_corner_first[v]; c != NO_INDEX; c = m_corner_links[static_cast<std::size_t>(c)].next)
    {
      const Corner_link& link = m_corner_links[static_cast<std::size_t>(c)];
      if(offer(link.target, dv + m_targets[static_cast<std::size_t>(link.target)].corner_distance[link.corner]))
        on_improved(link.target, link.corner);
    }
  }

  // Serial: takes the events of one list or one round.
  void merge(Stop_events& events)
  {
    for(const std::pair<double, Index>& e : events.list_bounds)
    {
      m_bound_heap.push_back(e);
      std::push_heap(m_bound_heap.begin(), m_bound_heap.end(), std::greater<std::pair<double, Index> >());
    }
    for(const std::pair<double, Index>& e : events.targets)
    {
      m_target_heap.push_back(e);
      std::push_heap(m_target_heap.begin(), m_target_heap.end(), std::greater<std::pair<double, Index> >());
    }
    events.clear();
  }

  // Serial, when no list is queued: whether the propagation can stop now.
  bool is_done(const Vertex_schedule& schedule)
  {
    if(!m_tracking)
      return false;
    typedef std::pair<double, Index> Entry;
    while(!m_bound_heap.empty() && m_bound_heap.front().first != m_list_bound[m_bound_heap.front().second])
    {
      std::pop_heap(m_bound_heap.begin(), m_bound_heap.end(), std::greater<Entry>());
      m_bound_heap.pop_back();
    }
    double lower = schedule.lower_bound();
    if(!m_bound_heap.empty())
      lower = (std::min)(lower, m_bound_heap.front().first);
    m_lower_bound = (std::max)(m_lower_bound, lower);
    if(m_stop_at_targets)
    {
      while(!m_target_heap.empty() && m_target_heap.front().first <= m_lower_bound)
      {
        const Index t = m_target_heap.front().second;
        std::pop_heap(m_target_heap.begin(), m_target_heap.end(), std::greater<Entry>());
        m_target_heap.pop_back();
        if(!m_resolved[static_cast<std::size_t>(t)])
        {
          m_resolved[static_cast<std::size_t>(t)] = 1;
          --m_unresolved;
        }
      }
      if(m_unresolved == 0)
        m_stopped = true;
    }
    if(m_lower_bound > m_limit)
      m_stopped = true;
    return m_stopped;
  }

  // After the run: the distances above this value are not final (or beyond the limit).
  double cutoff() const { return m_stopped ? (std::min)(m_limit, m_lower_bound) : m_limit; }
  bool stopped_early() const { return m_stopped; }

  // the targets and their distances (the smallest offered; final up to cutoff())
  const std::vector<Target>& targets() const { return m_targets; }
  double target_value(std::size_t t) const { return m_value[t]; }

private:
  struct Corner_link
  {
    Index target;
    Index corner;  // k: the vertex source(3f + k)
    Index next;
  };

  double m_limit = std::numeric_limits<double>::infinity();
  bool m_stop_at_targets = false;
  bool m_tracking = false;
  bool m_stopped = false;
  double m_lower_bound = 0.;
  std::vector<double> m_list_bound;                          // per half-edge
  std::vector<std::pair<double, Index> > m_bound_heap;       // (bound, half-edge), lazy
  std::vector<Target> m_targets;
  std::vector<double> m_value;                               // per target
  std::vector<unsigned char> m_resolved;
  std::size_t m_unresolved = 0;
  std::vector<std::pair<double, Index> > m_target_heap;      // (distance, target), lazy
  std::vector<Index> m_face_first, m_vertex_first, m_corner_first;  // per face / vertex: first entry
  std::vector<Index> m_next;                                         // per target: next of its face or vertex
  std::vector<Corner_link> m_corner_links;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_STOP_RULE_H
