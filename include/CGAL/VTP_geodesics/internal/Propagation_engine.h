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
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The propagation engine: the loop of VTP (Qin et al. 2016) over the per-mesh arrays.
//
// State: a distance upper bound per vertex (always the length of a real surface path), the set of
// swept faces (the one-rings of the vertices taken so far), and per half-edge the list of windows
// waiting to cross its face. A vertex taken from the queue (in increasing distance) first emits
// windows if it is a pseudo-source (saddle or boundary vertex), then sweeps its one-ring: every
// waiting list whose face is swept is propagated, and so are, in FIFO order, the lists it feeds
// inside the swept region, until the windows wait on the wavefront (the border of the region).
//
// Exactness does not depend on the order: windows are only cut where another real path is
// shorter, so the order only decides how many windows are created.
class Propagation_engine
{
public:
  template <class ConcurrencyTag>
  void run(const Mesh_arrays& m, Index s, const Propagation_options& options,
           std::vector<double>& dist, Propagation_statistics& st)
  {
    static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                  "CGAL::Parallel_tag (PVTP) is not implemented yet in VTP_geodesics.");
    const auto t0 = std::chrono::steady_clock::now();
    start(m, s, options, dist);
    run_sequential();
    finish(st, "vtp", 1);
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

private:
  typedef std::pair<double, Index> Entry;

  void start(const Mesh_arrays& m, Index s, const Propagation_options& options, std::vector<double>& dist)
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
    m_store.reset(nh);
    m_heap.clear();
    m_fifo.clear();
    m_fifo_head = 0;
    m_created = m_propagated = m_vertices_processed = m_pseudo_sources = 0;
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
    for(double d : *m_dist)
      if(d < std::numeric_limits<double>::infinity())
      {
        ++st.reached_vertices;
        st.max_distance = (std::max)(st.max_distance, d);
      }
  }

  void run_sequential()
  {
    std::vector<double>& d = *m_dist;
    const Mesh_arrays& m = *m_mesh;
    d[m_source] = 0.;
    m_processed[m_source] = 0.;
    emit_pseudo_source(m_source);
    sweep(m_source);
    drain();
    while(!m_heap.empty())
    {
      std::pop_heap(m_heap.begin(), m_heap.end(), std::greater<Entry>());
      const Entry e = m_heap.back();
      m_heap.pop_back();
      const Index v = e.second;
      if(e.first > d[v] || m_processed[v] == e.first)
        continue; // stale entry, or already processed at this distance
      m_processed[v] = e.first;
      ++m_vertices_processed;
      if(m.is_pseudo_source[v])
        emit_pseudo_source(v);
      sweep(v);
      drain();
    }
  }

  void light(Index v, double value)
  {
    std::vector<double>& d = *m_dist;
    if(value < d[v])
    {
      d[v] = value;
      m_heap.push_back(Entry(value, v));
      std::push_heap(m_heap.begin(), m_heap.end(), std::greater<Entry>());
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
  // opposite to v starts towards the face beyond that edge.
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
      Window w;
      w.b0 = 0.;
      w.b1 = ge.length;
      w.sx = ge.length - ge.cx;
      w.sy = -ge.cy;
      w.sigma = dv;
      if(!(w.sy < 0.))
        continue; // degenerate face: nothing crosses
      if(!trim_by_vertices(w, ge.length, d[m.source[o]], d[m.target(o)]))
        continue;
      if(!(w.b1 - w.b0 > m_min_ratio * ge.length))
        continue;
      m_store.push(o, w);
      ++m_created;
      if(m_swept[Mesh_arrays::face(o)])
        enqueue(o);
    }
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

  // Propagates queued lists until every window waits on the wavefront.
  void drain()
  {
    const Mesh_arrays& m = *m_mesh;
    std::vector<double>& d = *m_dist;
    while(m_fifo_head < m_fifo.size())
    {
      const Index h = m_fifo[m_fifo_head++];
      m_queued[h] = 0;
      if(m_store.empty(h))
        continue;
      m_in.clear();
      m_store.take(h, m_in);
      const Halfedge_geometry& g = m.geometry[h];
      const Index a = m.source[h];
      const Index b = m.source[Mesh_arrays::next(h)];
      const Index c = m.source[Mesh_arrays::prev(h)];
      filter_list(m_in, g.length, d[a], d[b], m_min_ratio * g.length, m_reach);
      if(m_in.empty())
        continue;
      const Index h_cb = m.opposite[Mesh_arrays::next(h)];
      const Index h_ac = m.opposite[Mesh_arrays::prev(h)];
      m_out_ac.clear();
      m_out_cb.clear();
      const Propagation_result r =
        propagate_list(g, m_in, m_min_ratio, h_ac != NO_INDEX, h_cb != NO_INDEX,
                       m_out_ac, m_out_cb, m_xc);
      m_propagated += r.propagated;
      light(c, r.distance_to_C);
      store_children(h_ac, m_out_ac);
      store_children(h_cb, m_out_cb);
    }
    m_fifo.clear();
    m_fifo_head = 0;
  }

  void store_children(Index h, const std::vector<Window>& ws)
  {
    if(ws.empty())
      return;
    for(const Window& w : ws)
      m_store.push(h, w);
    m_created += ws.size();
    if(m_swept[Mesh_arrays::face(h)])
      enqueue(h);
  }

  const Mesh_arrays* m_mesh = nullptr;
  std::vector<double>* m_dist = nullptr;
  Index m_source = 0;
  double m_min_ratio = 0.;

  Window_storage m_store;
  std::vector<unsigned char> m_swept;
  std::vector<unsigned char> m_queued;
  std::vector<double> m_processed;
  std::vector<Entry> m_heap;
  std::vector<Index> m_fifo;
  std::size_t m_fifo_head = 0;

  std::vector<Window> m_in, m_out_ac, m_out_cb;
  std::vector<double> m_xc, m_reach;

  std::size_t m_created = 0, m_propagated = 0, m_vertices_processed = 0, m_pseudo_sources = 0;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_ENGINE_H
