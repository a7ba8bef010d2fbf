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

#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_buckets.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_field.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The schedule of virtual source propagation (VSP on one thread, PVSP on several): rounds of buckets.
//
// The vertices waiting are kept in buckets of distances of a fixed width (Virtual_source_buckets.h). A
// round takes every vertex of the lowest bucket at once (they are then final). Each vertex is owned by a
// thread (blocks of 2^owner_bits consecutive indices, dealt round-robin: the solver numbers the vertices
// along a space-filling curve, so most neighbours of a vertex have the same owner); each thread of the team
// computes the offers of the vertices of the round it owns (Virtual_source_walks::take()), applies at once
// those to its own vertices and keeps the others, by owner, for the second phase, in which each thread
// applies the offers of the others to its own vertices; a thread puts the vertices it lowered in its own
// buckets. A thread reads the distance of another's vertex only between the phases (the offers to it go
// unfiltered). A vertex not taken keeps the least offer in a total order (distance first, then the virtual
// source, see better()), and no offer depends on another of the same round: so neither the order of the
// round nor the number of threads changes a bit of the distances, labels and paths (take() lets through
// every offer not above the vertex's distance, so an offer that ties with one applied before it still meets
// it in better()). A round that one thread runs alone (VSP, and the small rounds of PVSP) applies every
// offer at once.
//
// Vertices of one round cannot lower each other (a heap, taking them one at a time, would let them): a
// cost in accuracy that the benchmark measures (with buckets of half a short edge it is small). Every offer is
// still the length of a path on the surface (the same walks make them), so the distances are never below
// the exact ones.
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
      m_capture.run([&] { setup(front); });
    };
    run_team(threads, start, [&](int t) {
      Clock::time_point t0, t1, t2;
      for(;;)
      {
        if(t == 0)
        {
          // small rounds on thread 0 alone (the team waits at the barrier), until a large one or the end
          for(;;)
          {
            t0 = Clock::now();
            m_capture.run([&] { next_round(front); });
            t1 = Clock::now();
            selection_seconds += seconds(t0, t1);
            if(m_done || m_capture.failed() || (m_team > 1 && m_batch.size() >= min_parallel))
              break;
            m_capture.run([&] { take_alone(front); });
            propagation_seconds += seconds(t1, Clock::now());
          }
        }
        barrier();
        if(m_done || m_capture.failed())
          break;
        m_capture.run([&] { compute(front, t); });
        barrier();
        if(t == 0)
        {
          t2 = Clock::now();
          propagation_seconds += seconds(t1, t2);
        }
        m_capture.run([&] { apply(front, t); });
        barrier();
        if(t == 0)
          merge_seconds += seconds(t2, Clock::now());
      }
    });
    peak_bytes = m_batch.capacity() * sizeof(Index) + m_buckets.peak_bytes();
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

  typedef std::vector<std::vector<Pending>> Offers;  // the offers of one thread, by owner

  static double seconds(Clock::time_point a, Clock::time_point b)
  {
    return std::chrono::duration<double>(b - a).count();
  }

  static void barrier()
  {
#ifdef _OPENMP
#pragma omp barrier
#endif
  }

  // the thread that owns vertex v (with a mask when the team is a power of two: a division costs as
  // much as a good part of an offer, and take() asks for the owner of every vertex it offers to)
  Index owner(Index v) const
  {
    const Index block = v >> owner_bits;
    return m_team_mask >= 0 ? (block & m_team_mask) : block % static_cast<Index>(m_team);
  }

  // The sinks of take(): one thread alone (it reads and lowers every vertex), or thread t of the team in
  // the first phase (it lowers its own vertices, keeps the offers to the others for their owners).
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
  struct Team_sink
  {
    Virtual_source_rounds& rounds;
    Front& front;
    Ring& ring;
    Offers& offers;
    Index t;
    bool reads(Index v) const { return rounds.owner(v) == t; }
    void operator()(Index v, double d, const Vertex_source& s, Index lab)
    {
      const Index o = rounds.owner(v);
      if(o == t)
      {
        rounds.lower(front, ring, v, d, s, lab);
        return;
      }
      Pending p;
      p.s = s;
      p.d = d;
      p.v = v;
      p.label = lab;
      offers[static_cast<std::size_t>(o)].push_back(p);
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
    m_team_mask = (m_team & (m_team - 1)) == 0 ? static_cast<Index>(m_team - 1) : Index(-1);
    m_offers.resize(static_cast<std::size_t>(m_team));
    for(Offers& o : m_offers)
      o.resize(static_cast<std::size_t>(m_team));
    front.m_seeded.clear();
    m_remaining_targets = front.mark_targets(m_is_target);
    m_cutoff = front.m_settings.limit + m_buckets.span();
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
    if(m_team > 1 && m_batch.size() >= min_parallel)
      ++parallel_rounds;
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

  // thread t, first phase: the offers of its vertices of the round; those to its own vertices applied
  template <class Front>
  void compute(Front& front, int t)
  {
    Offers& offers = m_offers[static_cast<std::size_t>(t)];
    for(std::vector<Pending>& b : offers)
      b.clear();
    Team_sink<Front> sink{ *this, front, m_buckets.ring(t), offers, static_cast<Index>(t) };
    take_batch(front, sink, static_cast<Index>(t));
  }

  // The vertices of the round (those of owner t; all if t is NO_INDEX) are taken in order, each a few
  // places after asking the memory for its data (Virtual_source_walks::prefetch()): a pipeline of three
  // stages, 12, 8 and 4 vertices ahead (on 1M-vertex meshes 12-15% faster than without).
  template <class Front, class Sink>
  void take_batch(const Front& front, Sink& sink, Index t) const
  {
    const std::size_t n = m_batch.size();
    const auto mine = [&](std::size_t k) { return k < n && (t == NO_INDEX || owner(m_batch[k]) == t); };
    for(std::size_t k = 0; k < n; ++k)
    {
      if(mine(k + 12))
        front.prefetch(m_batch[k + 12], 2);
      if(mine(k + 8))
        front.prefetch(m_batch[k + 8], 1);
      if(mine(k + 4))
        front.prefetch(m_batch[k + 4], 0);
      if(mine(k))
        front.take(m_batch[k], sink);
    }
  }

  // thread t: the offers of every thread to the vertices it owns
  template <class Front>
  void apply(Front& front, int t)
  {
    Ring& ring = m_buckets.ring(t);
    for(const Offers& from : m_offers)
      for(const Pending& p : from[static_cast<std::size_t>(t)])
        lower(front, ring, p.v, p.d, p.s, p.label);
  }

  // thread 0 alone: the offers of the round, each applied at once
  template <class Front>
  void take_alone(Front& front)
  {
    Alone_sink<Front> sink{ *this, front, m_buckets.ring(0) };
    take_batch(front, sink, NO_INDEX);
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

  // the vertices a thread owns come in blocks of 2^owner_bits; the least round the team runs (smaller
  // ones cost less than the barriers: with 2 threads, 64 against 256 took the fastest of alternated first
  // runs of pvsp from 0.569 to 0.500 s (then 0.431 to 0.417 s) on a 1M-vertex remeshing and from 0.079 to
  // 0.069 s at 173K; no change beyond noise on a 1M Loop subdivision and at 156K; 32 was no better)
  static constexpr int owner_bits = 9;
  static constexpr std::size_t min_parallel = 64;

  Virtual_source_buckets m_buckets;  // the vertices waiting, a ring of buckets per thread
  std::vector<Offers> m_offers;      // per thread
  std::vector<Index> m_batch;  // the vertices of the round
  std::vector<unsigned char> m_is_target;
  std::size_t m_remaining_targets = 0;
  double m_cutoff = 0.;
  int m_team = 1;
  Index m_team_mask = 0;  // m_team - 1 if m_team is a power of two, otherwise -1
  bool m_done = false;
  Exception_capture m_capture;  // an exception of the team, thrown again after the region
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_ROUNDS_H
