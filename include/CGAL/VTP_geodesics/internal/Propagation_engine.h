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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_ENGINE_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_ENGINE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/options_and_statistics.h>
#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/Triangle_propagation.h>
#include <CGAL/VTP_geodesics/internal/Window_storage.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
#include <intrin.h>
#endif

#ifdef _OPENMP
#include <omp.h>
#endif

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A barrier for the threads of the parallel scheduling. Most waits are short (a few microseconds of
// sequential work by thread 0), so a waiting thread first spins, with the processor's spin-wait hint
// (which leaves the core's resources to a hardware sibling and lets a hypervisor see the spin); after
// about a hundred microseconds it sleeps on a condition variable, so that a long wait, or a machine
// busy with other work, does not cost a processor to the thread it waits for.
class alignas(64) Team_barrier
{
public:
  void reset(int n)
  {
    m_n = n;
    m_count.store(0, std::memory_order_relaxed);
    m_generation.store(0, std::memory_order_relaxed);
    m_sleepers.store(0, std::memory_order_relaxed);
  }

  void wait()
  {
    const unsigned generation = m_generation.load(std::memory_order_acquire);
    if(m_count.fetch_add(1, std::memory_order_acq_rel) + 1 == m_n)
    {
      m_count.store(0, std::memory_order_relaxed);
      m_generation.fetch_add(1, std::memory_order_seq_cst);
      if(m_sleepers.load(std::memory_order_seq_cst) > 0)
      {
        { std::lock_guard<std::mutex> lock(m_mutex); }
        m_wake.notify_all();
      }
      return;
    }
    for(int spins = 0; spins < 4096; ++spins)
    {
      if(m_generation.load(std::memory_order_acquire) != generation)
        return;
      spin_pause();
    }
    std::unique_lock<std::mutex> lock(m_mutex);
    m_sleepers.fetch_add(1, std::memory_order_seq_cst);
    while(m_generation.load(std::memory_order_seq_cst) == generation)
      m_wake.wait(lock);
    m_sleepers.fetch_sub(1, std::memory_order_relaxed);
  }

private:
  static void spin_pause()
  {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __builtin_ia32_pause();
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
    _mm_pause();
#endif
  }

  int m_n = 1;
  std::atomic<int> m_count{ 0 };
  std::atomic<unsigned> m_generation{ 0 };
  std::atomic<int> m_sleepers{ 0 };
  std::mutex m_mutex;
  std::condition_variable m_wake;
};

// The propagation engine: one loop, two orthogonal policies.
//
// State: a distance upper bound per vertex (always the length of a real surface path), the set of
// swept faces (the one-rings of the vertices taken so far), and per half-edge the list of windows
// waiting to cross its face. A vertex taken from the schedule first emits windows if it is a
// pseudo-source (saddle or boundary vertex), then sweeps its one-ring: every waiting list whose
// face is swept is propagated, and so are the lists it feeds inside the swept region, until the
// windows wait on the wavefront (the border of the swept region).
//
// Scheduling policy:
//  - sequential (VTP, Qin et al. 2016): a binary heap of vertices; lists propagated one at a time
//    in FIFO order;
//  - parallel (PVTP, Du et al. 2020, Section 4): buckets of width h / tau; each round takes an
//    adaptive number of vertices, gathers at most 100 T lists, propagates them on T threads by
//    face units (a unit's children go to lists no other unit writes: Rule 3 without locks), then
//    lowers distances and fills the buckets (serially, in unit order); the lists fed inside the
//    swept region make the next array, until it is empty. The output does not depend on thread
//    timing.
//
// Reset policy: never (exact), or, when the nearest wavefront vertex passes (R+1) lambda h, delete
// the waiting windows next to the wavefront vertices closer than (R+1) lambda h + lambda_g h and
// restart from all wavefront vertices as pseudo-sources (AVTP, Du et al. 2020, Section 5).
//
// Exactness (without resets) does not depend on the order: windows are only cut where another
// real path is shorter; the order only decides how many windows are created.
class Propagation_engine
{
public:
  template <class ConcurrencyTag>
  void run(const Mesh_arrays& m, Index s, const Propagation_options& options,
           std::vector<double>& dist, Propagation_statistics& st)
  {
    const bool parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
#ifndef _OPENMP
    static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                  "Parallel_tag is enabled but OpenMP is unavailable "
                  "(link CGAL::VTP_geodesics_OpenMP_support, or compile with -fopenmp).");
#endif
    const auto t0 = std::chrono::steady_clock::now();
    int threads = 1;
    if(parallel)
    {
      threads = options.number_of_threads;
#ifdef _OPENMP
      if(threads <= 0)
        threads = omp_get_max_threads();
#endif
      threads = (std::max)(1, (std::min)(threads, 126));
    }
    start(m, s, options, dist, static_cast<std::size_t>(threads));
    if(parallel)
    {
      run_parallel(threads);
      threads = m_threads;
    }
    else
      run_sequential();
    const bool approximate = m_reset_step < std::numeric_limits<double>::infinity();
    finish(st, parallel ? (approximate ? "pavtp" : "pvtp") : (approximate ? "avtp" : "vtp"), threads);
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

private:
  typedef std::pair<double, Index> Entry;

  // ------------------------------------------------------------------------------------------
  // setup
  // ------------------------------------------------------------------------------------------
  void start(const Mesh_arrays& m, Index s, const Propagation_options& options, std::vector<double>& dist,
             std::size_t pools)
  {
    m_mesh = &m;
    m_dist = &dist;
    m_source = s;
    m_min_ratio = options.minimum_window_length;
    const std::size_t nh = m.source.size();
    dist.assign(static_cast<std::size_t>(m.nv), std::numeric_limits<double>::infinity());
    m_swept.assign(static_cast<std::size_t>(m.nf), 0);
    m_queued.assign(nh, 0);
    m_processed.assign(static_cast<std::size_t>(m.nv), -1.);
    m_store.reset(nh, pools);
    m_heap.clear();
    m_fifo.clear();
    m_fifo_head = 0;
    m_created = m_propagated = m_vertices_processed = m_pseudo_sources = m_resets = 0;
    m_rounds = m_parallel_rounds = 0;
    m_selection_seconds = m_propagation_seconds = m_merge_seconds = 0.;
    m_use_buckets = false;

    // reset policy
    const double h = m.mean_edge_length;
    m_reset_step = (options.lambda < std::numeric_limits<double>::infinity() && h > 0.)
                     ? options.lambda * h : std::numeric_limits<double>::infinity();
    m_reset_guard = options.lambda_g * h;
    m_next_reset = m_reset_step;
    if(m_reset_step < std::numeric_limits<double>::infinity())
      m_forced_pseudo_source.assign(static_cast<std::size_t>(m.nv), 0);
    else
      m_forced_pseudo_source.clear();
  }

  void finish(Propagation_statistics& st, const char* method, int threads) const
  {
    const Mesh_arrays& m = *m_mesh;
    st = Propagation_statistics();
    st.vertices = static_cast<std::size_t>(m.nv);
    st.faces = static_cast<std::size_t>(m.nf);
    st.method = method;
    st.threads = threads;
    st.windows_created = m_created;
    st.windows_propagated = m_propagated;
    st.peak_live_windows = m_store.peak_live_windows();
    st.peak_window_bytes = m_store.peak_bytes();
    st.vertices_processed = m_vertices_processed;
    st.pseudo_sources = m_pseudo_sources;
    st.resets = m_resets;
    st.rounds = m_rounds;
    st.parallel_rounds = m_parallel_rounds;
    st.selection_seconds = m_selection_seconds;
    st.propagation_seconds = m_propagation_seconds;
    st.merge_seconds = m_merge_seconds;
    for(double d : *m_dist)
      if(d < std::numeric_limits<double>::infinity())
      {
        ++st.reached_vertices;
        st.max_distance = (std::max)(st.max_distance, d);
      }
  }

  // ------------------------------------------------------------------------------------------
  // shared steps
  // ------------------------------------------------------------------------------------------

  // Starts the propagation from the source vertex.
  void seed()
  {
    (*m_dist)[m_source] = 0.;
    m_processed[m_source] = 0.;
    emit_pseudo_source(m_source);
    sweep(m_source);
  }

  // Processes vertex v taken from the schedule at distance dv; returns false for a stale entry.
  bool take_vertex(Index v, double dv)
  {
    if(dv > (*m_dist)[v] || m_processed[v] == dv)
      return false; // stale entry, or already processed at this distance
    if(dv > m_next_reset)
    {
      reset_windows(dv);
      m_forced_pseudo_source[v] = 1; // v was the nearest wavefront vertex
    }
    m_processed[v] = dv;
    ++m_vertices_processed;
    if(m_mesh->is_pseudo_source[v] || (!m_forced_pseudo_source.empty() && m_forced_pseudo_source[v]))
      emit_pseudo_source(v);
    sweep(v);
    return true;
  }

  void light(Index v, double value)
  {
    std::vector<double>& d = *m_dist;
    if(value < d[v])
    {
      d[v] = value;
      if(m_use_buckets)
        bucket_push(v, value);
      else
      {
        m_heap.push_back(Entry(value, v));
        std::push_heap(m_heap.begin(), m_heap.end(), std::greater<Entry>());
      }
    }
  }

  void enqueue(Index h)
  {
    if(!m_queued[h])
    {
      m_queued[h] = 1;
      m_fifo.push_back(h);
    }
  }

  // A (pseudo-)source v: its neighbours are reached straight, and a window covering each edge
  // opposite to v starts towards the face beyond that edge. Through a zero-area face, v reaches
  // the face beyond as a point of its edge (emit_through_degenerate_faces()).
  void emit_pseudo_source(Index v)
  {
    const Mesh_arrays& m = *m_mesh;
    std::vector<double>& d = *m_dist;
    const double dv = d[v];
    if(v != m_source)
      ++m_pseudo_sources;
    for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
    {
      const Index h = m.corners[c];
      light(m.target(h), dv + m.geometry[h].length);
      light(m.source[Mesh_arrays::prev(h)], dv + m.geometry[h].l_prev);
    }
    for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
    {
      const Index h = m.corners[c];
      const Index e = Mesh_arrays::next(h);   // B -> C, the edge opposite to v
      const Index o = m.opposite[e];          // C -> B, in the face beyond
      if(o == NO_INDEX)
        continue;
      const Halfedge_geometry& ge = m.geometry[e];
      if(m.is_degenerate_face[Mesh_arrays::face(h)])
      {
        // v lies on the line of B-C (up to rounding): no window can start from it
        emit_through_degenerate_faces(dv, o, ge.length - ge.cx);
        continue;
      }
      Window w;
      w.b0 = 0.;
      w.b1 = ge.length;
      w.sx = ge.length - ge.cx;
      w.sy = -ge.cy;
      w.sigma = dv;
      if(!(w.sy < 0.))
        continue;
      store_emitted(o, w);
    }
  }

  // A pseudo-source at distance dv lying at abscissa t on the half-edge o (the other side of a
  // zero-area face): if it is inside the edge, it is a point source for face(o). When face(o) is
  // itself of zero area, the point is carried on through the edge of face(o) that contains it
  // (lighting the third vertex, on the line), a bounded number of times.
  void emit_through_degenerate_faces(double dv, Index o, double t)
  {
    const Mesh_arrays& m = *m_mesh;
    for(int step = 0; step < 64 && o != NO_INDEX; ++step)
    {
      const Halfedge_geometry& g = m.geometry[o];
      if(!(t > 0. && t < g.length))
        return;
      const Index c = m.source[Mesh_arrays::prev(o)];
      const Index h_ac = m.opposite[Mesh_arrays::prev(o)];
      const Index h_cb = m.opposite[Mesh_arrays::next(o)];
      if(!m.is_degenerate_face[Mesh_arrays::face(o)])
      {
        m_emit_ac.clear();
        m_emit_cb.clear();
        light(c, propagate_edge_point(g, t, dv, h_ac != NO_INDEX, h_cb != NO_INDEX, m_emit_ac, m_emit_cb));
        for(const Window& w : m_emit_ac)
          store_emitted(h_ac, w);
        for(const Window& w : m_emit_cb)
          store_emitted(h_cb, w);
        return;
      }
      const double dx = g.cx - t;
      light(c, dv + std::sqrt(dx * dx + g.cy * g.cy));
      if(t < g.cx)
        o = h_ac;            // A -> C, same abscissa
      else if(t > g.cx)
      {
        o = h_cb;            // C -> B, from C
        t -= g.cx;
      }
      else
        return;              // the point is C itself
    }
  }

  // Stores a window started by a pseudo-source on the list of h (trimmed by the ends of h).
  void store_emitted(Index h, Window w)
  {
    const Mesh_arrays& m = *m_mesh;
    const std::vector<double>& d = *m_dist;
    const double length = m.geometry[h].length;
    if(!trim_by_vertices(w, length, d[m.source[h]], d[m.target(h)]))
      return;
    if(!(w.b1 - w.b0 > m_min_ratio * length))
      return;
    m_store.push(h, w);
    ++m_created;
    if(m_swept[Mesh_arrays::face(h)])
      enqueue(h);
  }

  // Adds the one-ring of v to the swept region; waiting lists of newly swept faces are queued.
  void sweep(Index v)
  {
    const Mesh_arrays& m = *m_mesh;
    for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
    {
      const Index f = Mesh_arrays::face(m.corners[c]);
      if(m_swept[f])
        continue;
      m_swept[f] = 1;
      for(Index k = 0; k < 3; ++k)
        if(!m_store.empty(3 * f + k))
          enqueue(3 * f + k);
    }
  }

  // Appends children to the list of h with blocks of pool p; if the face of h is swept, h is
  // queued into `to_queue` (m_fifo, or the queue of a face unit: the caller owns every list it
  // writes, see propagation_phase()). Returns the number of windows stored.
  template <class Queue>
  std::size_t store_children(Index h, const Window* begin, const Window* end, std::size_t p,
                             Queue& to_queue)
  {
    if(begin == end)
      return 0;
    for(const Window* w = begin; w != end; ++w)
      m_store.push(h, *w, p);
    if(m_swept[Mesh_arrays::face(h)] && !m_queued[h])
    {
      m_queued[h] = 1;
      to_queue.push_back(h);
    }
    return static_cast<std::size_t>(end - begin);
  }

  // Thread-independent work on one list: filter it, propagate it across its face.
  struct alignas(64) Scratch
  {
    std::vector<Window> in, out_ac, out_cb;
    std::vector<double> xc, reach;
    std::size_t propagated = 0, created = 0;
  };

  // Returns the distance offered to the opposite vertex; children are left in s.out_ac / s.out_cb.
  double propagate_one(Index h, Scratch& s) const
  {
    const Mesh_arrays& m = *m_mesh;
    const std::vector<double>& d = *m_dist;
    const Halfedge_geometry& g = m.geometry[h];
    const Index a = m.source[h];
    const Index b = m.source[Mesh_arrays::next(h)];
    filter_list(s.in, g.length, d[a], d[b], m_min_ratio * g.length, s.reach);
    if(s.in.empty())
      return std::numeric_limits<double>::infinity();
    const Index h_cb = m.opposite[Mesh_arrays::next(h)];
    const Index h_ac = m.opposite[Mesh_arrays::prev(h)];
    const Propagation_result r = propagate_list(g, s.in, m_min_ratio, h_ac != NO_INDEX, h_cb != NO_INDEX,
                                                s.out_ac, s.out_cb, s.xc);
    s.propagated += r.propagated;
    return r.distance_to_C;
  }

  // ------------------------------------------------------------------------------------------
  // sequential scheduling (VTP / AVTP)
  // ------------------------------------------------------------------------------------------
  void run_sequential()
  {
    m_use_buckets = false;
    seed();
    drain();
    while(!m_heap.empty())
    {
      std::pop_heap(m_heap.begin(), m_heap.end(), std::greater<Entry>());
      const Entry e = m_heap.back();
      m_heap.pop_back();
      if(take_vertex(e.second, e.first))
        drain();
    }
  }

  // Propagates queued lists until every window waits on the wavefront.
  void drain()
  {
    const Mesh_arrays& m = *m_mesh;
    Scratch& s = m_scratch_sequential;
    while(m_fifo_head < m_fifo.size())
    {
      const Index h = m_fifo[m_fifo_head++];
      m_queued[h] = 0;
      if(m_store.empty(h))
        continue;
      s.in.clear();
      m_store.take(h, s.in);
      s.out_ac.clear();
      s.out_cb.clear();
      const double dc = propagate_one(h, s);
      light(m.source[Mesh_arrays::prev(h)], dc);
      m_created += store_children(m.opposite[Mesh_arrays::prev(h)], s.out_ac.data(),
                                  s.out_ac.data() + s.out_ac.size(), 0, m_fifo);
      m_created += store_children(m.opposite[Mesh_arrays::next(h)], s.out_cb.data(),
                                  s.out_cb.data() + s.out_cb.size(), 0, m_fifo);
      m_store.update_peaks();
    }
    m_propagated += s.propagated;
    s.propagated = 0;
    m_fifo.clear();
    m_fifo_head = 0;
  }

  // ------------------------------------------------------------------------------------------
  // parallel scheduling (PVTP / PAVTP)
  // ------------------------------------------------------------------------------------------
  void bucket_push(Index v, double value)
  {
    const double b = value * m_inv_bucket_width;
    const double max_bucket = double(std::size_t(1) << 26);
    std::size_t i = static_cast<std::size_t>((std::min)(b, max_bucket));
    if(i < m_bucket_current)
      i = m_bucket_current;
    if(i >= m_buckets.size())
    {
      m_buckets.resize(i + 1);
      m_bucket_read.resize(i + 1, 0);
    }
    m_buckets[i].push_back(Entry(value, v));
    ++m_bucket_pending;
    if(value > m_round_limit)
      ++m_updated_large;
    else
      ++m_updated_small;
  }

  bool bucket_pop(Entry& e)
  {
    while(m_bucket_current < m_buckets.size())
    {
      std::vector<Entry>& b = m_buckets[m_bucket_current];
      std::size_t& r = m_bucket_read[m_bucket_current];
      if(r < b.size())
      {
        e = b[r++];
        --m_bucket_pending;
        return true;
      }
      b.clear();
      r = 0;
      ++m_bucket_current;
    }
    return false;
  }

  // Puts back the entry that bucket_pop() just returned.
  void bucket_unpop()
  {
    CGAL_assertion(m_bucket_current < m_buckets.size() && m_bucket_read[m_bucket_current] > 0);
    --m_bucket_read[m_bucket_current];
    ++m_bucket_pending;
  }

  void run_parallel(int threads)
  {
    const Mesh_arrays& m = *m_mesh;
    m_use_buckets = true;
    const double h = m.mean_edge_length;
    m_inv_bucket_width = (h > 0.) ? m.anisotropy / h : 1.;
    for(std::vector<Entry>& b : m_buckets)
      b.clear();
    m_buckets.clear();
    m_bucket_read.clear();
    m_bucket_current = 0;
    m_bucket_pending = 0;
    m_round_limit = std::numeric_limits<double>::infinity();
    m_updated_large = m_updated_small = 0;
    m_scratch.resize(static_cast<std::size_t>(threads));
    for(Scratch& s : m_scratch)
      s.propagated = s.created = 0;
    m_unit_of_face.assign(static_cast<std::size_t>(m.nf), NO_INDEX);
    m_ranges.reset(new Range[static_cast<std::size_t>(threads)]);
    m_threads = threads;
    m_in_selection = false;
    m_k_ad = 0;

    seed();

    // One team for the whole propagation. Thread 0 does the sequential steps (selection, the
    // short tail of each round, and the rounds too small to share); the team meets only for the
    // parallel phase of the large rounds, at a barrier that spins briefly, then sleeps (see
    // Team_barrier).
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if(threads > 1)
#endif
    {
      int t = 0;
#ifdef _OPENMP
      t = omp_get_thread_num();
      // the runtime may give fewer threads than asked for: the team is what we got
#pragma omp single
      {
        m_threads = omp_get_num_threads();
        m_barrier.reset(m_threads);
      }
#else
      m_barrier.reset(1);
#endif
      const bool team = m_threads > 1;
      for(;;)
      {
        if(t == 0)
          m_team_has_round = next_parallel_round();
        if(team)
          m_barrier.wait();
        if(!m_team_has_round)
          break;
        propagation_phase(t);
        if(team)
          m_barrier.wait();
        if(t == 0)
          finish_round();
      }
    }
    for(Scratch& s : m_scratch)
    {
      m_propagated += s.propagated;
      s.propagated = 0;
    }
  }

  // Thread 0: runs the sequential steps until a round large enough for the team is ready
  // (returns true), or the propagation is over (returns false).
  bool next_parallel_round()
  {
    const Mesh_arrays& m = *m_mesh;
    if(m_k_ad < m_threads)
      m_k_ad = m_threads;
    const std::size_t max_lists = 100 * static_cast<std::size_t>(m_threads);
    for(;;)
    {
      if(m_fifo.empty())
      {
        if(m_in_selection)
        {
          // Eq. 5: more vertices next time if the wavefront moved ahead, fewer if it fell back
          m_k_ad += static_cast<long long>(m_updated_large) - static_cast<long long>(m_updated_small);
          m_k_ad = (std::max)(m_k_ad, static_cast<long long>(m_threads));
          m_k_ad = (std::min)(m_k_ad, static_cast<long long>(m.nv) + 1);
          m_in_selection = false;
        }
        if(m_bucket_pending == 0)
          return false;
        // K-window-list selection: up to k_ad vertices, and at most 100 T lists
        const auto ts = std::chrono::steady_clock::now();
        m_updated_large = m_updated_small = 0;
        long long popped = 0;
        Entry e;
        double last = 0.;
        while(popped < m_k_ad && m_fifo.size() < max_lists && bucket_pop(e))
        {
          // A reset (AVTP) deletes the waiting windows near the wavefront: the lists queued by
          // this selection must be propagated first (as the sequential scheduling does before
          // each vertex), or the vertices they would reach could be left unreached. So the
          // vertex that triggers a reset starts the next selection.
          if(e.first > m_next_reset && (popped > 0 || !m_fifo.empty()))
          {
            bucket_unpop();
            break;
          }
          if(take_vertex(e.second, e.first))
          {
            ++popped;
            last = e.first;
          }
        }
        // distances are compared with the end of the last bucket popped from (Eq. 5)
        m_round_limit = (std::floor(last * m_inv_bucket_width) + 1.) / m_inv_bucket_width;
        m_in_selection = true;
        m_selection_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count();
        continue;
      }
      start_round();
      if(m_team > 1)
        return true;
      propagation_phase(0);
      finish_round();
    }
  }

  // A face unit (at most 3 lists, see start_round()): the detached windows of its lists, the
  // distances they offer to their opposite vertices, and the lists its children make ready (at most
  // 3: those across the edges of the face). One cache line per unit: units taken by different
  // threads share no line.
  struct alignas(64) Unit
  {
    double distance_to_C[3];
    Index chain[3];
    Index queued[3];
    int number_queued = 0;
    void push_back(Index h)
    {
      CGAL_assertion(number_queued < 3);
      queued[number_queued++] = h;
    }
  };

  // A round propagates the queued lists (the array A_from) and stores their children; the lists
  // it feeds inside the swept region make the next round (A_to), until none is left.
  //
  // The windows of the lists of the round are detached from their half-edges first (serially),
  // so the children stored during the round go to fresh lists and the detached windows are read
  // by one thread only. The children of the lists of face f only go to the lists of the
  // half-edges across the edges of f, which no other face writes to: the lists are grouped by
  // face into units, a thread takes a whole unit, propagates its lists in list order and stores
  // their children at once (Rule 3, delayed writes: nothing else is written). The tail (thread 0,
  // one step per list) lowers the distances and queues the next lists in unit order. The result
  // does not depend on thread timing.
  void start_round()
  {
    m_round_start = std::chrono::steady_clock::now();
    m_from.swap(m_fifo);
    m_fifo.clear();
    const std::size_t n = m_from.size();
    // small arrays are not worth waking the team: same work, same result, one thread
    m_team = (n >= 4 * static_cast<std::size_t>(m_threads)) ? m_threads : 1;
    ++m_rounds;
    if(m_team > 1)
      ++m_parallel_rounds;
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
    m_units.resize(units);
    for(std::size_t i = 0; i < n; ++i)
    {
      const Index h = m_from[i];
      const std::size_t u = static_cast<std::size_t>(m_unit_of_face[static_cast<std::size_t>(Mesh_arrays::face(h))]);
      const std::size_t k = m_unit_fill[u]++;
      CGAL_assertion(k - m_unit_begin[u] < 3); // a face has 3 half-edges, each queued once
      m_unit_lists[k] = i;
      m_queued[h] = 0;
      m_units[u].chain[k - m_unit_begin[u]] = m_store.detach(h);
    }
    for(Index h : m_from)
      m_unit_of_face[static_cast<std::size_t>(Mesh_arrays::face(h))] = NO_INDEX;
    // Affinity: a unit goes first to the thread that wrote its windows (the pool of the first
    // list's blocks), so that most windows are read by the core that wrote them, and each
    // thread keeps to its own parts of the wavefront. The units are sorted by thread into
    // ranges; a thread takes units from the front of its range, then steals from the back of
    // the others'. Which thread propagates a unit has no effect on the result.
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
    for(std::size_t t = 0; t < team; ++t)
      m_ranges[t].set(m_range_begin[t], m_range_begin[t + 1]);
  }

  void propagation_phase(int t)
  {
    if(t >= m_team)
      return;
    Scratch& s = m_scratch[static_cast<std::size_t>(t)];
    const std::size_t p = static_cast<std::size_t>(t);
    const std::size_t team = static_cast<std::size_t>(m_team);
    std::size_t i;
    while(m_ranges[p].take_front(i))
      propagate_unit(m_unit_order[i], s, p);
    for(std::size_t k = 1; k < team; ++k)
    {
      Range& r = m_ranges[(p + k) % team];
      while(r.take_back(i))
        propagate_unit(m_unit_order[i], s, p);
    }
  }

  void propagate_unit(std::size_t u, Scratch& s, std::size_t p)
  {
    const Mesh_arrays& m = *m_mesh;
    Unit& unit = m_units[u];
    unit.number_queued = 0;
    for(std::size_t k = m_unit_begin[u]; k < m_unit_begin[u + 1]; ++k)
    {
      const std::size_t j = k - m_unit_begin[u];
      const Index h = m_from[m_unit_lists[k]];
      s.in.clear();
      m_store.take_chain(unit.chain[j], s.in, p);
      s.out_ac.clear();
      s.out_cb.clear();
      unit.distance_to_C[j] = propagate_one(h, s);
      s.created += store_children(m.opposite[Mesh_arrays::prev(h)], s.out_ac.data(),
                                  s.out_ac.data() + s.out_ac.size(), p, unit);
      s.created += store_children(m.opposite[Mesh_arrays::next(h)], s.out_cb.data(),
                                  s.out_cb.data() + s.out_cb.size(), p, unit);
    }
  }

  void finish_round()
  {
    const Mesh_arrays& m = *m_mesh;
    const auto tm = std::chrono::steady_clock::now();
    m_propagation_seconds += std::chrono::duration<double>(tm - m_round_start).count();
    for(std::size_t u = 0; u < m_units.size(); ++u)
    {
      const Unit& unit = m_units[u];
      for(std::size_t k = m_unit_begin[u]; k < m_unit_begin[u + 1]; ++k)
        light(m.source[Mesh_arrays::prev(m_from[m_unit_lists[k]])], unit.distance_to_C[k - m_unit_begin[u]]);
      m_fifo.insert(m_fifo.end(), unit.queued, unit.queued + unit.number_queued);
    }
    for(int t = 0; t < m_team; ++t)
    {
      m_created += m_scratch[static_cast<std::size_t>(t)].created;
      m_scratch[static_cast<std::size_t>(t)].created = 0;
    }
    m_store.flush_returns();
    m_store.update_peaks();
    m_from.clear();
    m_merge_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - tm).count();
  }

  // ------------------------------------------------------------------------------------------
  // reset policy (AVTP / PAVTP)
  // ------------------------------------------------------------------------------------------

  // Called when the vertex taken next is beyond the current reset radius: deletes the waiting
  // windows near the wavefront (but those of lists whose both ends are beyond the guard band) and
  // makes every wavefront vertex a pseudo-source. Every distance stays the length of a real path.
  void reset_windows(double dv)
  {
    const Mesh_arrays& m = *m_mesh;
    const std::vector<double>& d = *m_dist;
    while(m_next_reset < dv)
      m_next_reset += m_reset_step;
    const double keep_beyond = (m_next_reset - m_reset_step) + m_reset_guard;
    ++m_resets;
    // wavefront vertices: reached, not processed yet
    m_wavefront.clear();
    auto collect = [&](const Entry& e) {
      const Index v = e.second;
      if(e.first == d[v] && m_processed[v] != e.first) // one live entry per vertex
        m_wavefront.push_back(v);
    };
    if(m_use_buckets)
    {
      for(std::size_t b = m_bucket_current; b < m_buckets.size(); ++b)
        for(std::size_t i = m_bucket_read[b]; i < m_buckets[b].size(); ++i)
          collect(m_buckets[b][i]);
    }
    else
      for(const Entry& e : m_heap)
        collect(e);
    for(Index v : m_wavefront)
    {
      if(d[v] > keep_beyond)
        continue;
      for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
      {
        const Index h = m.corners[c];
        const Index edges[2] = { h, Mesh_arrays::prev(h) };
        for(Index e : edges)
        {
          const Index a = m.source[e], b = m.target(e);
          if(d[a] > keep_beyond || d[b] > keep_beyond)
            continue;
          m_store.clear(e);
          if(m.opposite[e] != NO_INDEX)
            m_store.clear(m.opposite[e]);
        }
      }
    }
    for(Index v : m_wavefront)
      m_forced_pseudo_source[v] = 1;
  }

  // ------------------------------------------------------------------------------------------
  const Mesh_arrays* m_mesh = nullptr;
  std::vector<double>* m_dist = nullptr;
  Index m_source = 0;
  double m_min_ratio = 0.;

  Window_storage m_store;
  std::vector<unsigned char> m_swept;
  std::vector<unsigned char> m_queued;
  std::vector<double> m_processed;
  std::vector<Index> m_fifo;
  std::size_t m_fifo_head = 0;

  std::vector<Window> m_emit_ac, m_emit_cb;

  // sequential scheduling
  std::vector<Entry> m_heap;
  Scratch m_scratch_sequential;

  // parallel scheduling
  bool m_use_buckets = false;
  std::vector<std::vector<Entry> > m_buckets;
  std::vector<std::size_t> m_bucket_read;
  std::size_t m_bucket_current = 0;
  std::size_t m_bucket_pending = 0;
  double m_inv_bucket_width = 1.;
  double m_round_limit = 0.;
  std::size_t m_updated_large = 0, m_updated_small = 0;
  std::vector<Scratch> m_scratch;
  std::vector<Index> m_from;
  int m_threads = 1, m_team = 1;
  long long m_k_ad = 1;
  bool m_in_selection = false;
  bool m_team_has_round = false;
  std::chrono::steady_clock::time_point m_round_start;
  // face units of the current round (see start_round())
  std::vector<Index> m_unit_of_face;                 // per face, NO_INDEX between rounds
  std::vector<std::size_t> m_unit_begin, m_unit_fill, m_unit_lists;
  std::vector<Unit> m_units;
  // The units of one thread, [front, back) of m_unit_order, packed in one atomic word: the
  // owner takes from the front, the other threads steal from the back.
  struct alignas(64) Range
  {
    std::atomic<std::uint64_t> bounds{ 0 };
    void set(std::size_t front, std::size_t back)
    {
      bounds.store((std::uint64_t(back) << 32) | std::uint64_t(front), std::memory_order_relaxed);
    }
    bool take_front(std::size_t& i) { return take(false, i); }
    bool take_back(std::size_t& i) { return take(true, i); }
    bool take(bool from_back, std::size_t& i)
    {
      std::uint64_t b = bounds.load(std::memory_order_relaxed);
      for(;;)
      {
        std::uint64_t front = b & 0xffffffffu, back = b >> 32;
        if(front >= back)
          return false;
        i = static_cast<std::size_t>(from_back ? --back : front++);
        if(bounds.compare_exchange_weak(b, (back << 32) | front, std::memory_order_relaxed))
          return true;
      }
    }
  };
  std::unique_ptr<Range[]> m_ranges;                 // one per thread
  std::vector<std::size_t> m_range_begin, m_unit_thread, m_unit_order;
  Team_barrier m_barrier;

  // reset policy
  double m_reset_step = std::numeric_limits<double>::infinity();
  double m_reset_guard = 0.;
  double m_next_reset = std::numeric_limits<double>::infinity();
  std::vector<unsigned char> m_forced_pseudo_source;
  std::vector<Index> m_wavefront;

  std::size_t m_created = 0, m_propagated = 0, m_vertices_processed = 0, m_pseudo_sources = 0, m_resets = 0;
  std::size_t m_rounds = 0, m_parallel_rounds = 0;
  double m_selection_seconds = 0., m_propagation_seconds = 0., m_merge_seconds = 0.;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_ENGINE_H
