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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PROPAGATION_ENGINE_H
#define CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PROPAGATION_ENGINE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/propagation/Known_vertices.h>
#include <CGAL/VTP_geodesics/internal/propagation/Parallel_loop.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>
#include <CGAL/VTP_geodesics/internal/propagation/Sequential_loop.h>
#include <CGAL/VTP_geodesics/internal/propagation/Stop_rule.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_front.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// One propagation engine, two orthogonal choices (and the seeding by sources):
//
// |                                      | never reset (exact) | reset every lambda h |
// | Sequential_tag: vertex heap          | VTP                 | AVTP                 |
// | Parallel_tag: buckets, K lists, T th.| PVTP                | PAVTP                |
//
// (A front of another kind, one virtual source per vertex, is a third row: its own loop and per-vertex
// field, virtual_sources/. A start from known distances is another seeding: the state starts from the known
// field and wakes the known vertices that new windows reach, Known_vertices.h.) This file wires them.
//
// The map of which file holds what: the manual's File map page, doc/VTP_geodesics/file_map.txt.
//
// An engine is a workspace: it reads the mesh arrays (shared, read-only) and owns everything one
// propagation writes, so that several engines can run on one mesh at the same time.
class Propagation_engine
{
public:
  // With settings.known_distances, the run starts from the field `known` (which it takes over), see
  // Known_vertices.h.
  template <class ConcurrencyTag>
  void run(const Mesh_arrays& m, const std::vector<Seed>& seeds, std::vector<Target>&& targets,
           const Propagation_settings& settings, int requested_threads, Propagation_statistics& statistics,
           Known_field known = Known_field())
  {
    const bool parallel = is_parallel<ConcurrencyTag>();
    const auto t0 = std::chrono::steady_clock::now();
    m_virtual_sources = settings.virtual_sources;
    if(m_virtual_sources)
    {
      // one virtual source per vertex (virtual_sources/Virtual_source_front.h); the parallel tag runs it in
      // rounds (virtual_sources/Virtual_source_rounds.h)
      m_seeds = seeds;
      statistics = Propagation_statistics();
      const int threads = m_vsp.run(m, m_seeds, std::move(targets), settings, statistics,
                                    parallel ? number_of_threads(requested_threads) : 0, std::move(known));
      statistics.method = std::string(parallel ? "pvsp" : "vsp") + (settings.second_virtual_source ? "2" : "");
      statistics.threads = threads;
      statistics.vertices = static_cast<std::size_t>(m.nv);
      statistics.faces = static_cast<std::size_t>(m.nf);
      for(double d : m_vsp.dist)
        if(d < std::numeric_limits<double>::infinity())
        {
          ++statistics.reached_vertices;
          statistics.max_distance = (std::max)(statistics.max_distance, d);
        }
      statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      return;
    }
    // at most 126 threads (one pool of window blocks each, see Window_storage)
    int threads = parallel ? (std::min)(number_of_threads(requested_threads), 126) : 1;
    m_seeds = seeds;
    m_state.start(m, settings, static_cast<std::size_t>(threads), std::move(targets));
    if(settings.known_distances)
      known.move_into(m_state.dist, m_state.label, settings.want_labels);
    threads = propagate(parallel, threads);
    m_state.field.finish();
    m_state.direction.finish(m_state.dist);  // the log map behind pseudo-sources
    apply_cutoff();
    if(settings.unit != 1.)
      for(double& d : m_state.dist)
        d *= settings.unit;
    collect_statistics(parallel, threads, statistics);
    for(double d : m_state.dist)
      if(d < std::numeric_limits<double>::infinity())
      {
        ++statistics.reached_vertices;
        statistics.max_distance = (std::max)(statistics.max_distance, d);
      }
    statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  // Adds `seed` to the field of the previous run (a run from known distances, or the first such run on
  // an empty field), in the engine's unit: the work and the resetting are those of the region the seed
  // wins (Propagation_data::start_again()). No limit, targets nor paths. With settings.virtual_sources,
  // the same with one or two virtual sources per vertex
  // (Virtual_source_front::run_again()); the field must then be that of the previous run_again() with
  // virtual sources (or that of none). The vertices whose distance changed are those of touched() with
  // the LOWERED flag. Statistics: windows, vertices and time of this run only (not the reached vertices nor
  // the largest distance, which would cost O(V)).
  template <class ConcurrencyTag>
  void run_again(const Mesh_arrays& m, const Seed& seed, const Propagation_settings& settings,
                 int requested_threads, Propagation_statistics& statistics)
  {
    CGAL_precondition(settings.known_distances && settings.unit == 1.);
    const bool parallel = is_parallel<ConcurrencyTag>();
    const auto t0 = std::chrono::steady_clock::now();
    if(settings.virtual_sources)
    {
      m_virtual_sources = true;
      m_seeds.assign(1, seed);
      statistics = Propagation_statistics();
      const int threads = m_vsp.run_again(m, m_seeds, settings, statistics,
                                          parallel ? number_of_threads(requested_threads) : 0);
      statistics.method = std::string(parallel ? "pvsp" : "vsp") + (settings.second_virtual_source ? "2" : "");
      statistics.threads = threads;
      statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      return;
    }
    m_virtual_sources = false;
    int threads = parallel ? (std::min)(number_of_threads(requested_threads), 126) : 1;
    if(m_state.mesh != &m || !m_state.known.active() || !m_state.settings.known_distances)
      m_state.start(m, settings, static_cast<std::size_t>(threads), std::vector<Target>());
    else
      m_state.start_again(settings, static_cast<std::size_t>(threads));
    m_seeds.assign(1, seed);
    threads = propagate(parallel, threads);
    collect_statistics(parallel, threads, statistics);
    statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  // Moves the distances and labels of the last run out of the engine (which then holds no field).
  void release_field(std::vector<double>& distances, std::vector<Index>& labels)
  {
    distances.swap(m_virtual_sources ? m_vsp.dist : m_state.dist);
    labels.swap(m_virtual_sources ? m_vsp.label : m_state.label);
  }
  // the vertices lowered or woken by the last run from known distances, and their flags (not listed after the
  // first run_again() on an empty field: every reached vertex was lowered then)
  // (with virtual sources: the vertices the last run took, each lowered)
  const std::vector<Index>& touched() const { return m_virtual_sources ? m_vsp.touched() : m_state.known.touched(); }
  bool was_lowered(Index v) const { return m_virtual_sources || m_state.known.lowered(v); }

  // the distances of the last run (per vertex, in the unit of the output: Propagation_settings::unit)
  std::vector<double>& distances() { return m_virtual_sources ? m_vsp.dist : m_state.dist; }
  const std::vector<double>& distances() const { return m_virtual_sources ? m_vsp.dist : m_state.dist; }
  // the nearest-source labels of the last run (empty unless asked for; NO_INDEX where unreached)
  const std::vector<Index>& labels() const { return m_virtual_sources ? m_vsp.label : m_state.label; }
  // the same, to be rewritten (the signed distances from curves, solver/Solver_run.h)
  std::vector<Index>& labels_to_rewrite() { return m_virtual_sources ? m_vsp.label : m_state.label; }
  // the distance of target t of the last run (+infinity if not final: beyond the limit or unreached)
  double target_distance(std::size_t t) const
  {
    if(m_virtual_sources)
      return m_vsp.target_distance(t);
    const Target& target = m_state.stop.targets()[t];
    if(target.vertex != NO_INDEX)
      return m_state.dist[target.vertex];
    const double d = m_state.stop.target_value(t);
    return d <= m_state.stop.cutoff() ? d * m_state.settings.unit : std::numeric_limits<double>::infinity();
  }
  std::size_t number_of_targets() const { return targets().size(); }
  // the sources, the targets and the trace-back record of the last run
  const std::vector<Seed>& seeds() const { return m_seeds; }
  const std::vector<Target>& targets() const { return m_virtual_sources ? m_vsp.targets() : m_state.stop.targets(); }
  const Path_record& path_record() const { return m_virtual_sources ? m_vsp.record : m_state.record; }
  // the windows that crossed each face in the last run (active with settings.keep_field; not with virtual
  // sources nor resets)
  const Kept_field& kept_field() const { return m_virtual_sources ? m_no_field : m_state.field; }
  // the distance up to which the last run's distances are final (engine unit; +infinity after a full run)
  double cutoff() const { return m_virtual_sources ? std::numeric_limits<double>::infinity() : m_state.stop.cutoff(); }
  // the log map: its sources (set before a run) and its angles after the run
  Direction_record& direction() { return m_state.direction; }
  const Direction_record& direction() const { return m_state.direction; }

private:
  // Seeds m_seeds into the started state and runs the loop; returns the number of threads.
  int propagate(bool parallel, int threads)
  {
    if(parallel)
    {
      const double h = m_state.mesh->mean_edge_length;
      m_state.schedule.start_buckets(h > 0. ? m_state.mesh->anisotropy / h : 1.);
      seed_sources(m_state, m_seeds);
      return m_parallel.run(m_state, threads);
    }
    m_state.schedule.start_heap();
    seed_sources(m_state, m_seeds);
    m_sequential.run(m_state);
    return 1;
  }

  // Distances that are not final when the propagation stopped early (or beyond the limit) become +infinity.
  void apply_cutoff()
  {
    const double cutoff = m_state.stop.cutoff();
    if(!(cutoff < std::numeric_limits<double>::infinity()))
      return;
    for(std::size_t v = 0; v < m_state.dist.size(); ++v)
      if(m_state.dist[v] > cutoff)
      {
        m_state.dist[v] = std::numeric_limits<double>::infinity();
        if(!m_state.label.empty())
          m_state.label[v] = NO_INDEX;
      }
  }

  // The statistics of the last run (window propagation), but the reached vertices and the largest distance.
  void collect_statistics(bool parallel, int threads, Propagation_statistics& st) const
  {
    const Mesh_arrays& m = *m_state.mesh;
    const bool approximate = m_state.reset.is_active();
    st = Propagation_statistics();
    st.method = parallel ? (approximate ? "pavtp" : "pvtp") : (approximate ? "avtp" : "vtp");
    st.threads = threads;
    st.vertices = static_cast<std::size_t>(m.nv);
    st.faces = static_cast<std::size_t>(m.nf);
    st.windows_created = m_state.created;
    st.windows_propagated = m_state.propagated;
    st.peak_live_windows = m_state.store.peak_live_windows();
    st.peak_window_bytes = m_state.store.peak_bytes();
    st.vertices_processed = m_state.vertices_processed;
    st.pseudo_sources = m_state.pseudo_sources;
    st.field_pieces = m_state.field.size();
    st.field_bytes = m_state.field.bytes();
    st.resets = m_state.reset.number_of_resets();
    st.stopped_early = m_state.stop.stopped_early();
    if(parallel)
    {
      st.rounds = m_parallel.rounds;
      st.parallel_rounds = m_parallel.parallel_rounds;
      st.selection_seconds = m_parallel.selection_seconds;
      st.propagation_seconds = m_parallel.propagation_seconds;
      st.merge_seconds = m_parallel.merge_seconds;
    }
  }

  std::vector<Seed> m_seeds;
  Propagation_state m_state;
  Sequential_loop m_sequential;
  Parallel_loop m_parallel;
  Virtual_source_front m_vsp;
  bool m_virtual_sources = false;  // the last run was virtual source propagation
  Kept_field m_no_field;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_ENGINE_PROPAGATION_ENGINE_H
