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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_ROUNDS_H
#define CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_ROUNDS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/parallel/Round_team.h>
#include <CGAL/VTP_geodesics/internal/parallel/Stealing_ranges.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_buckets.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_field.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The schedule of virtual source propagation (VSP on one thread, PVSP on several): rounds of buckets.
//
// The vertices waiting are kept in buckets of distances of a fixed width (Virtual_source_buckets.h). A
// round takes every vertex of the lowest bucket at once (they are then final). The vertices are dealt in G
// groups (blocks of 2^owner_bits consecutive indices, dealt round-robin; G is 8 per thread: the solver
// numbers the vertices along a space-filling curve, so most neighbours of a vertex are in its group). A
// round of the team has two phases, each of one work item per group, which the threads take (Round_team,
// Stealing_ranges.h: own range first, then what the others have not taken; so a thread the system does not
// run holds nobody back unless it stopped in the middle of an item). First phase, the item of group g: the
// offers of the vertices of g in the round (Virtual_source_walks::take()), those to vertices of g applied at
// once, the others kept by group; second phase: the offers kept for g applied. An item reads the distance
// of a vertex of another group only between the phases (the offers to it go unfiltered). A vertex not
// taken keeps the least offer in a total order (distance first, then the virtual source, see better()),
// and no offer depends on another of the same round: so neither the order of the round, nor which thread
// runs an item, nor the number of threads changes a bit of the distances, labels and paths (take() lets
// through every offer not above the vertex's distance, so an offer that ties with one applied before it
// still meets it in better()). A round that thread 0 runs alone (VSP, the small rounds of PVSP, all of
// them while that is faster: see master()) applies every offer at once.
//
// Vertices of one round cannot lower each other (a heap, taking them one at a time, would let them): a
// cost in accuracy that the benchmark measures (with buckets of half a short edge it is small). Every
// offer is still the length of a path on the surface (the same walks make them), so the distances are
// never below the exact ones.
class Virtual_source_rounds
{
public:
  typedef Virtual_source_field::Vertex_source Vertex_source;

  // statistics of the last run: rounds, those run on several threads, bytes of the buckets and buffers;
  // seconds (thread 0) choosing the rounds, computing the offers (with the wait for the team; in a round of
  // thread 0 alone, applying them too), applying them (rounds of the team)
  std::size_t rounds = 0, parallel_rounds = 0, peak_bytes = 0;
  double selection_seconds = 0., propagation_seconds = 0., merge_seconds = 0.;
  // whether the next run is on the mesh of the last one (its short edge length is then not measured again:
  // a farthest-point sampling runs once per sample)
  bool keep_width = false;

  // Runs the propagation of `front` (seeded: m_seeded holds the seeds) on `threads` threads; returns the
  // number of threads of the team.
  template <class Front>
  int propagate(Front& front, int threads)
  {
    threads = (std::max)(threads, 1);
    rounds = parallel_rounds = 0;
    selection_seconds = propagation_seconds = merge_seconds = 0.;
    m_done = false;
    m_capture.reset();
    const auto start = [&](int team) {
      m_team = team;
      m_sync.reset(team);
      m_capture.run([&] { setup(front); });
    };
    run_team(threads, start, [&](int t) {
      if(t == 0)
        master(front);
      else
        worker(front, t);
    });
    peak_bytes = (m_batch.capacity() + m_by_group.capacity()) * sizeof(Index) + m_buckets.peak_bytes();
    for(const Offers& o : m_offers)
      for(const std::vector<Pending>& b : o)
        peak_bytes += b.capacity() * sizeof(Pending);
    m_capture.rethrow();
    return m_team;
  }

private:
  typedef Virtual_source_buckets::Entry Entry;
  typedef Virtual_source_buckets::Ring Ring;
  typedef std::chrono::steady_clock Clock;

  struct Pending
  {
    Vertex_source s;
    double d;
    Index v;
    Index label;
  };

  typedef std::vector<std::vector<Pending>> Offers;  // the offers of the item of one group, by group

  static double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

  // the group of vertex v
  std::size_t group(Index v) const { return static_cast<std::size_t>(v >> owner_bits) & (m_groups - 1); }

  // The sinks of take(): one thread alone (it reads and lowers every vertex), or the item of group g in
  // the first phase (it lowers the vertices of g, keeps the offers to the others for their groups).
  template <class Front>
  struct Alone_sink
  {
    Virtual_source_rounds& rounds;
    Front& front;
    Ring& ring;
    bool reads(Index) const { return true; }
    void operator()(Index v, double d, const Vertex_source& s, Index lab) { rounds.lower(front, ring, v, d, s, lab); }
  };

  template <class Front>
  struct Group_sink
  {
    Virtual_source_rounds& rounds;
    Front& front;
    Ring& ring;
    Offers& offers;
    std::size_t g;
    bool reads(Index v) const { return rounds.group(v) == g; }
    void operator()(Index v, double d, const Vertex_source& s, Index lab)
    {
      const std::size_t o = rounds.group(v);
      if(o == g)
      {
        rounds.lower(front, ring, v, d, s, lab);
        return;
      }
      offers[o].push_back(Pending{ s, d, v, lab });
    }
  };

  // whether (d, s) is a better offer than the vertex's (d0, s0): a total order, so that the least offer of
  // a round does not depend on the order in which they are applied
  static bool better(double d, const Vertex_source& s, double d0, const Vertex_source& s0)
  {
    if(d != d0)
      return d < d0;
    if(s.root != s0.root)
      return s.root < s0.root;
    if(s.h != s0.h)
      return s.h < s0.h;
    const double a[6] = { s.sx, s.sy, s.lx, s.ly, s.rx, s.ry };
    const double b[6] = { s0.sx, s0.sy, s0.lx, s0.ly, s0.rx, s0.ry };
    for(int k = 0; k < 6; ++k)
      if(a[k] != b[k])
        return a[k] < b[k];
    return false;
  }

  template <class Front>
  void setup(Front& front)
  {
    m_buckets.start(*front.m_mesh, keep_width, m_team, front.m_seeded);
    // a power of two, 8 groups per thread (at most 256): items small enough to share a round evenly
    for(m_groups = 1; m_team > 1 && m_groups < 8 * static_cast<std::size_t>(m_team) && m_groups < 256;)
      m_groups *= 2;
    m_offers.resize(m_groups);
    for(Offers& o : m_offers)
    {
      o.resize(m_groups);
      for(std::vector<Pending>& b : o)
        b.clear();
    }
    m_sent.assign(m_groups, 0);
    m_ranges.resize(static_cast<std::size_t>(m_team));
    m_round_number = 0;
    m_choice.reset(Clock::now());
    front.m_seeded.clear();
    m_remaining_targets = front.mark_targets(m_is_target);
    m_cutoff = front.m_settings.limit + m_buckets.span();
  }

  // Thread 0: chooses the rounds, runs the small ones alone, and the others alone too when that was measured
  // faster than the team (Team_choice in Round_team.h: the machine is busy with other work), publishes the
  // phases of the others and takes its share of their items.
  template <class Front>
  void master(Front& front)
  {
    for(;;)
    {
      const Clock::time_point t0 = Clock::now();
      m_capture.run([&] { next_round(front); });
      const Clock::time_point t1 = Clock::now();
      selection_seconds += seconds(t0, t1);
      if(m_done || m_capture.failed())
        break;
      const double work = static_cast<double>(m_batch.size());
      if(m_team == 1 || m_batch.size() < min_parallel || !m_choice.team())
      {
        m_capture.run([&] { take_alone(front); });
        const Clock::time_point t2 = Clock::now();
        propagation_seconds += seconds(t1, t2);
        m_choice.record(work, t2);
        continue;
      }
      ++parallel_rounds;
      sort_by_group();
      run_phase(front, m_round_number + 1 + (m_round_number & 1));  // odd: computing
      const Clock::time_point t2 = Clock::now();
      propagation_seconds += seconds(t1, t2);
      if(std::find(m_sent.begin(), m_sent.end(), 1) != m_sent.end())
        run_phase(front, m_round_number + 1);  // even: applying the offers kept
      const Clock::time_point t3 = Clock::now();
      merge_seconds += seconds(t2, t3);
      m_choice.record(work, t3);
    }
    m_sync.finish();
  }

  // thread 0: publishes the phase `round` (one item per group), takes its items, waits for the others'
  template <class Front>
  void run_phase(Front& front, std::uint32_t round)
  {
    CGAL_assertion(round > m_round_number);  // (at most 2 per round of 64 vertices or more: no wrap)
    m_round_number = round;
    call_round_team_test_hook(-1);
    const std::size_t team = static_cast<std::size_t>(m_team);
    for(std::size_t t = 0; t < team; ++t)
      m_ranges[t].set(t * m_groups / team, (t + 1) * m_groups / team, round);
    m_sync.publish(round, m_groups, std::uint32_t(1) << (Stealing_range::ROUND_BITS - 1));
    take_items(front, 0, round);
    m_sync.wait_for_items();
  }

  // threads 1 ... T-1: the items they can take of each phase published
  template <class Front>
  void worker(Front& front, int t)
  {
    m_sync.serve(t, [&](std::uint32_t round) { take_items(front, t, round); });
  }

  template <class Front>
  void take_items(Front& front, int t, std::uint32_t round)
  {
    m_ranges.for_each_taken(static_cast<std::size_t>(t), static_cast<std::size_t>(m_team), round, [&](std::size_t g) {
      call_round_team_test_hook(t);
      if(round & 1)
        m_capture.run([&] { compute(front, t, g); });
      else
        m_capture.run([&] { apply(front, t, g); });
      m_sync.item_finished(t);
    });
  }

  // thread 0: the vertices of the round by group (each group in the order of the round)
  void sort_by_group()
  {
    m_group_begin.assign(m_groups + 1, 0);
    for(Index v : m_batch)
      ++m_group_begin[group(v) + 1];
    for(std::size_t g = 0; g < m_groups; ++g)
      m_group_begin[g + 1] += m_group_begin[g];
    m_group_fill.assign(m_group_begin.begin(), m_group_begin.end() - 1);
    m_by_group.resize(m_batch.size());
    for(Index v : m_batch)
      m_by_group[m_group_fill[group(v)]++] = v;
  }

  // thread 0: the vertices of the next round (m_batch, taken), or m_done
  template <class Front>
  void next_round(Front& front)
  {
    m_batch.clear();
    while(m_buckets.pending() > 0)
    {
      const bool beyond = m_buckets.next_bucket() > m_cutoff;
      m_buckets.empty_current([&](const Entry& e) {
        const std::size_t v = static_cast<std::size_t>(e.second);
        if(front.m_taken[v] || front.dist[v] != e.first)
          return;
        if(beyond && e.first > m_cutoff)
        {
          // past the limit (see Virtual_source_front.h): a vertex this far is not taken; it waits no more
          // (a later offer within the cutoff puts it back)
          front.m_stopped = true;
          return;
        }
        front.m_taken[v] = 1;
        m_batch.push_back(e.second);
      });
      if(!m_batch.empty())
        break;
    }
    if(m_batch.empty())
    {
      m_done = true;
      return;
    }
    ++rounds;
    front.m_taken_count += m_batch.size();
    if(front.m_incremental)
      front.m_touched.insert(front.m_touched.end(), m_batch.begin(), m_batch.end());
    if(m_remaining_targets > 0)
    {
      for(Index v : m_batch)
        if(m_is_target[static_cast<std::size_t>(v)])
        {
          m_is_target[static_cast<std::size_t>(v)] = 0;
          --m_remaining_targets;
        }
      if(m_remaining_targets == 0)
      {
        // the vertices of this round are final; the others are not needed
        front.m_stopped = has_waiting(front);
        m_done = true;
      }
    }
  }

  template <class Front>
  bool has_waiting(const Front& front) const
  {
    return m_buckets.any_of([&](const Entry& e) {
      const std::size_t v = static_cast<std::size_t>(e.second);
      return !front.m_taken[v] && front.dist[v] == e.first;
    });
  }

  // thread t, first phase, the item of group g: the offers of its vertices of the round; those to its own
  // vertices applied, the others kept
  template <class Front>
  void compute(Front& front, int t, std::size_t g)
  {
    Offers& offers = m_offers[g];
    for(std::vector<Pending>& b : offers)
      b.clear();
    Group_sink<Front> sink{ *this, front, m_buckets.ring(t), offers, g };
    take_list(front, sink, m_by_group.data() + m_group_begin[g], m_group_begin[g + 1] - m_group_begin[g]);
    m_sent[g] = std::any_of(offers.begin(), offers.end(), [](const std::vector<Pending>& b) { return !b.empty(); });
  }

  // The vertices list[0 .. n) are taken in order, each a few places after asking the memory for its data
  // (Virtual_source_walks::prefetch()): a pipeline of three stages, 12, 8 and 4 vertices ahead (on
  // 1M-vertex meshes 12-15% faster than without).
  template <class Front, class Sink>
  static void take_list(const Front& front, Sink& sink, const Index* list, std::size_t n)
  {
    for(std::size_t k = 0; k < n; ++k)
    {
      if(k + 12 < n)
        front.prefetch(list[k + 12], 2);
      if(k + 8 < n)
        front.prefetch(list[k + 8], 1);
      if(k + 4 < n)
        front.prefetch(list[k + 4], 0);
      front.take(list[k], sink);
    }
  }

  // thread t, second phase, the item of group g: the offers kept for the vertices of g
  template <class Front>
  void apply(Front& front, int t, std::size_t g)
  {
    Ring& ring = m_buckets.ring(t);
    for(const Offers& from : m_offers)
      for(const Pending& p : from[g])
        lower(front, ring, p.v, p.d, p.s, p.label);
  }

  // thread 0 alone: the offers of the round, each applied at once
  template <class Front>
  void take_alone(Front& front)
  {
    Alone_sink<Front> sink{ *this, front, m_buckets.ring(0) };
    take_list(front, sink, m_batch.data(), m_batch.size());
  }

  // the vertex v (not taken) keeps the offer (d, s) if it is better than its own
  template <class Front>
  void lower(Front& front, Ring& ring, Index v, double d, const Vertex_source& s, Index lab) const
  {
    const std::size_t i = static_cast<std::size_t>(v);
    if(front.m_taken[i])
      return;
    const bool two = !front.m_src2.empty();
    if(!better(d, s, front.dist[i], front.m_src[i]))
    {
      if(two)
        front.second_offer(i, d, s, better);
      return;
    }
    if(two)
      front.demote_first(i, s.root);
    front.dist[i] = d;
    front.m_src[i] = s;
    if(!front.label.empty())
      front.label[i] = lab;
    m_buckets.push(ring, v, d);
  }

  // the groups are made of blocks of 2^owner_bits vertices; the least round the team runs (smaller ones
  // cost more than they share; measured with the former barriers, see performance.txt)
  static constexpr int owner_bits = 9;
  static constexpr std::size_t min_parallel = 64;

  Virtual_source_buckets m_buckets;  // the vertices waiting, a ring of buckets per thread
  std::vector<Offers> m_offers;      // per group
  std::vector<unsigned char> m_sent; // per group: whether its item kept offers for other groups
  std::vector<Index> m_batch;        // the vertices of the round
  std::vector<Index> m_by_group;     // the same by group, group g at [m_group_begin[g], m_group_begin[g + 1])
  std::vector<std::size_t> m_group_begin, m_group_fill;
  std::vector<unsigned char> m_is_target;
  std::size_t m_remaining_targets = 0;
  double m_cutoff = 0.;
  int m_team = 1;
  std::size_t m_groups = 1;          // a power of two
  bool m_done = false;
  Exception_capture m_capture;  // an exception of the team, thrown again after the region
  Round_team m_sync;                 // the team (see master())
  Stealing_ranges m_ranges;
  Team_choice m_choice;
  std::uint32_t m_round_number = 0;  // of the last phase published
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_ROUNDS_H
