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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PARALLEL_LOOP_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PARALLEL_LOOP_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window_storage.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>
#include <CGAL/VTP_geodesics/internal/parallel/Stealing_ranges.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/parallel/Round_team.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The parallel scheduling (PVTP, Du et al. 2020, Section 4): the schedule is made of buckets of width
// h / tau; a selection takes an adaptive number of vertices (Eq. 5) and gathers at most 100 T lists; a
// round propagates the queued lists on T threads and stores their children; the lists it feeds inside
// the swept region make the next round, until none is left; then the next selection.
//
// A round: the windows of its lists are detached from their half-edges first (serially), so the children
// stored during the round go to fresh lists and the detached windows are read by one thread only. The
// children of the lists of face f only go to the lists of the half-edges across the edges of f, which no
// other face writes to: the lists are grouped by face into units; a thread takes a whole unit, propagates
// its lists in list order and stores their children at once (Rule 3, delayed writes: nothing else is
// written). The tail (thread 0) lowers the distances and queues the next lists in unit order. So the
// result does not depend on thread timing.
//
// One OpenMP team for the whole propagation. Thread 0 (the master) does the sequential steps (selection,
// the short tail of each round, and the rounds too small to share) and publishes the large rounds; no
// thread waits for another one to arrive (Round_team): each takes face units of the current round as
// long as there are some, and the master goes on once every unit is finished. So a thread that does not
// run (the machine is busy with other work) holds the others back only if it stopped in the middle of a
// unit, or when the master itself is descheduled. So the master measures the windows created per second
// with the team and alone, and runs the rounds the faster way (Team_choice in Round_team.h).
class Parallel_loop
{
public:
  // Runs the propagation seeded in `st` (whose schedule was started with buckets) on `threads` threads
  // to its end; returns the number of threads the OpenMP runtime gave.
  int run(Propagation_state& st, int threads)
  {
    const Mesh_arrays& m = *st.mesh;
    m_state = &st;
    m_scratch.resize(static_cast<std::size_t>(threads));
    for(Propagation_scratch& s : m_scratch)
      s.propagated = s.created = 0;
    if(m_unit_of_face.size() != static_cast<std::size_t>(m.nf))
      m_unit_of_face.assign(static_cast<std::size_t>(m.nf), NO_INDEX);  // NO_INDEX between rounds
    m_ranges.resize(static_cast<std::size_t>(threads));
    m_threads = threads;
    m_in_selection = false;
    m_k_ad = 0;
    m_round_number = 0;
    m_choice.reset(std::chrono::steady_clock::now());
    m_created_before = st.created;
    selection_seconds = propagation_seconds = merge_seconds = 0.;
    rounds = parallel_rounds = 0;

    // (the runtime may give fewer threads than asked for: the team is what we got)
    run_team(threads,
             [&](int team) {
               m_threads = team;
               m_sync.reset(team);
             },
             [&](int t) {
               if(t == 0)
                 master();
               else
                 worker(t);
             });
    for(Propagation_scratch& s : m_scratch)
    {
      st.field.gather(s.crossed);
      st.propagated += s.propagated;
      s.propagated = 0;
    }
    return m_threads;
  }

  // statistics of the last run
  std::size_t rounds = 0, parallel_rounds = 0;
  double selection_seconds = 0., propagation_seconds = 0., merge_seconds = 0.;

private:
  // Thread 0: runs the sequential steps until a round large enough for the team is ready (returns true),
  // or the propagation is over (returns false).
  bool next_parallel_round()
  {
    Propagation_state& st = *m_state;
    const Mesh_arrays& m = *st.mesh;
    if(m_k_ad < m_threads)
      m_k_ad = m_threads;
    const std::size_t max_lists = 100 * static_cast<std::size_t>(m_threads);
    for(;;)
    {
      if(st.fifo.empty())
      {
        if(m_in_selection)
        {
          // Eq. 5: more vertices next time if the wavefront moved ahead, fewer if it fell back
          m_k_ad += static_cast<long long>(st.schedule.pushed_beyond())
                    - static_cast<long long>(st.schedule.pushed_within());
          m_k_ad = (std::max)(m_k_ad, static_cast<long long>(m_threads));
          m_k_ad = (std::min)(m_k_ad, static_cast<long long>(m.nv) + 1);
          m_in_selection = false;
        }
        if(st.schedule.empty() || (st.stop.is_tracking() && st.stop.is_done(st.schedule)))
          return false;
        // K-window-list selection: up to k_ad vertices, and at most 100 T lists
        const auto ts = std::chrono::steady_clock::now();
        st.schedule.reset_push_counts();
        long long popped = 0;
        Vertex_schedule::Entry e;
        double last = 0.;
        while(popped < m_k_ad && st.fifo.size() < max_lists && st.schedule.pop(e))
        {
          // A reset (AVTP) deletes the waiting windows near the wavefront: the lists queued by this
          // selection must be propagated first (as the sequential scheduling does before each vertex), or
          // the vertices they would reach could be left unreached. So the vertex that triggers a reset
          // starts the next selection.
          if(st.reset.is_due(e.first) && (popped > 0 || !st.fifo.empty()))
          {
            st.schedule.unpop();
            break;
          }
          if(st.take_vertex(e.second, e.first))
          {
            ++popped;
            last = e.first;
          }
        }
        // distances are compared with the end of the last bucket popped from (Eq. 5)
        st.schedule.set_round_limit(st.schedule.end_of_bucket(last));
        m_in_selection = true;
        selection_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count();
        continue;
      }
      start_round();
      if(m_team > 1)
        return true;
      propagation_phase(0, 0);
      finish_round();
      record_round();
    }
  }

  // Thread 0: tells the team choice the work of the round just finished (the windows it created)
  void record_round()
  {
    const std::size_t created = m_state->created;
    m_choice.record(static_cast<double>(created - m_created_before), std::chrono::steady_clock::now());
    m_created_before = created;
  }

  // Thread 0: the sequential steps, and its share of the rounds it publishes.
  void master()
  {
    while(m_threads > 1 && next_parallel_round())
    {
      call_round_team_test_hook(-1);
      m_sync.publish(m_round_number, m_units.size(), std::uint32_t(1) << (Stealing_range::ROUND_BITS - 1));
      propagation_phase(0, m_round_number);
      m_sync.wait_for_items();
      finish_round();
      record_round();
    }
    if(m_threads == 1)
      while(next_parallel_round()) {}
    m_sync.finish();
  }

  // Threads 1 ... T-1: the units they can take of each round published.
  void worker(int t)
  {
    m_sync.serve(t, [&](std::uint32_t round) { propagation_phase(t, round); });
  }

  // A face unit (at most 3 lists, see start_round()): the detached windows of its lists and the lists its
  // children make ready (at most 3: those across the edges
  // of the face). One cache line per unit: units taken by different threads share no line.
  struct alignas(64) Unit
  {
    Index chain[3];
    Index queued[3];
    int number_queued = 0;
    void push_back(Index h)
    {
      CGAL_assertion(number_queued < 3);
      queued[number_queued++] = h;
    }
  };

  void start_round()
  {
    Propagation_state& st = *m_state;
    m_round_start = std::chrono::steady_clock::now();
    m_from.swap(st.fifo);
    st.fifo.clear();
    const std::size_t n = m_from.size();
    // small arrays are not worth waking the team (same work, same result, one thread), nor are the
    // rounds while the master runs alone
    m_team = (n >= 4 * static_cast<std::size_t>(m_threads) && n <= Stealing_ranges::MAX_ITEMS
              && m_choice.team()) ? m_threads : 1;
    ++rounds;
    if(m_team > 1)
      ++parallel_rounds;
    // units: the lists of each face, faces in order of first appearance, lists in list order
    m_unit_begin.assign(1, 0);
    for(Index h : m_from)
    {
      Index& u = m_unit_of_face[static_cast<std::size_t>(Mesh_arrays::face(h))];
      if(u == NO_INDEX)
      {
        u = static_cast<Index>(m_unit_begin.size() - 1);
        m_unit_begin.push_back(0);
      }
      ++m_unit_begin[static_cast<std::size_t>(u) + 1];
    }
    const std::size_t units = m_unit_begin.size() - 1;
    for(std::size_t u = 0; u < units; ++u)
      m_unit_begin[u + 1] += m_unit_begin[u];
    m_unit_fill.assign(m_unit_begin.begin(), m_unit_begin.end() - 1);
    m_unit_lists.resize(n);
    m_offers.resize(n);
    m_units.resize(units);
    for(std::size_t i = 0; i < n; ++i)
    {
      const Index h = m_from[i];
      const std::size_t u = static_cast<std::size_t>(m_unit_of_face[static_cast<std::size_t>(Mesh_arrays::face(h))]);
      const std::size_t k = m_unit_fill[u]++;
      CGAL_assertion(k - m_unit_begin[u] < 3); // a face has 3 half-edges, each queued once
      m_unit_lists[k] = i;
      st.queued[h] = 0;
      m_units[u].chain[k - m_unit_begin[u]] = st.store.detach(h);
      st.stop.on_list_emptied(h);
    }
    for(Index h : m_from)
      m_unit_of_face[static_cast<std::size_t>(Mesh_arrays::face(h))] = NO_INDEX;
    // Affinity: a unit goes first to the thread that wrote its windows (the pool of the first list's
    // blocks), so that most windows are read by the core that wrote them, and each thread keeps to its
    // own parts of the wavefront. The units are sorted by thread into ranges; a thread takes units from the
    // front of its range, then steals from the back of the others'. Which thread propagates a unit has no
    // effect on the result.
    const std::size_t team = static_cast<std::size_t>(m_team);
    m_range_begin.assign(team + 1, 0);
    m_unit_thread.resize(units);
    for(std::size_t u = 0; u < units; ++u)
    {
      std::size_t t = Window_storage::pool_of_chain(m_units[u].chain[0], u % team);
      if(t >= team)
        t = u % team;
      m_unit_thread[u] = t;
      ++m_range_begin[t + 1];
    }
    for(std::size_t t = 0; t < team; ++t)
      m_range_begin[t + 1] += m_range_begin[t];
    m_unit_order.resize(units);
    m_unit_fill.assign(m_range_begin.begin(), m_range_begin.end() - 1);
    for(std::size_t u = 0; u < units; ++u)
      m_unit_order[m_unit_fill[m_unit_thread[u]]++] = u;
    if(m_team > 1)
    {
      ++m_round_number;
      if(m_round_number == 0)
        m_round_number = 1;   // 0 means "no round"
      for(std::size_t t = 0; t < team; ++t)
        m_ranges[t].set(m_range_begin[t], m_range_begin[t + 1], m_round_number);
    }
  }

  // Thread t propagates the units it takes of round `round` (0: the master alone, every unit).
  void propagation_phase(int t, std::uint32_t round)
  {
    const std::size_t p = static_cast<std::size_t>(t);
    Propagation_scratch& s = m_scratch[p];
    if(round == 0)
    {
      for(std::size_t u = 0; u < m_units.size(); ++u)
        propagate_unit(u, s, p);
      return;
    }
    m_ranges.for_each_taken(p, static_cast<std::size_t>(m_threads), round, [&](std::size_t i) {
      call_round_team_test_hook(t);
      propagate_unit(m_unit_order[i], s, p);
      m_sync.item_finished(t);
    });
  }

  void propagate_unit(std::size_t u, Propagation_scratch& s, std::size_t p)
  {
    Propagation_state& st = *m_state;
    Unit& unit = m_units[u];
    unit.number_queued = 0;
    for(std::size_t k = m_unit_begin[u]; k < m_unit_begin[u + 1]; ++k)
    {
      const std::size_t j = k - m_unit_begin[u];
      const Index h = m_from[m_unit_lists[k]];
      s.in.clear();
      st.store.take_chain(unit.chain[j], s.in, p);
      s.out_ac.clear();
      s.out_cb.clear();
      m_offers[k] = st.propagate_one(h, s);
      st.store_all_children(h, s, p, unit);
    }
  }

  void finish_round()
  {
    Propagation_state& st = *m_state;
    const Mesh_arrays& m = *st.mesh;
    const auto tm = std::chrono::steady_clock::now();
    propagation_seconds += std::chrono::duration<double>(tm - m_round_start).count();
    for(std::size_t u = 0; u < m_units.size(); ++u)
    {
      const Unit& unit = m_units[u];
      for(std::size_t k = m_unit_begin[u]; k < m_unit_begin[u + 1]; ++k)
      {
        const Index c = m.source[Mesh_arrays::prev(m_from[m_unit_lists[k]])];
        st.light(c, m_offers[k]);
        st.wake_beyond(m_from[m_unit_lists[k]]);
      }
      st.fifo.insert(st.fifo.end(), unit.queued, unit.queued + unit.number_queued);
    }
    for(int t = 0; t < m_team; ++t)
    {
      Propagation_scratch& s = m_scratch[static_cast<std::size_t>(t)];
      st.created += s.created;
      s.created = 0;
      st.stop.merge(s.events); // in thread order: the heaps do not depend on timing
    }
    st.store.flush_returns();
    st.store.update_peaks();
    m_from.clear();
    merge_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - tm).count();
  }

  Propagation_state* m_state = nullptr;
  std::vector<Propagation_scratch> m_scratch;      // one per thread
  std::vector<Index> m_from;                       // the lists of the current round
  std::size_t m_created_before = 0;                // windows created before the round (Team_choice's work)
  int m_threads = 1, m_team = 1;
  long long m_k_ad = 1;
  bool m_in_selection = false;
  std::uint32_t m_round_number = 0;                // of the last round published
  Team_choice m_choice;                            // whether the team or the master alone runs the rounds
  std::chrono::steady_clock::time_point m_round_start;
  // face units of the current round (see start_round())
  std::vector<Index> m_unit_of_face;               // per face, NO_INDEX between rounds
  std::vector<std::size_t> m_unit_begin, m_unit_fill, m_unit_lists;
  std::vector<Unit> m_units;
  std::vector<Offer> m_offers;                     // per list of the round: what it offers to its third vertex
  Stealing_ranges m_ranges;                        // one per thread
  std::vector<std::size_t> m_range_begin, m_unit_thread, m_unit_order;
  Round_team m_sync;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PARALLEL_LOOP_H
