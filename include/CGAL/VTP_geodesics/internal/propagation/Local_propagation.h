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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_LOCAL_PROPAGATION_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_LOCAL_PROPAGATION_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>
#include <CGAL/VTP_geodesics/internal/propagation/Sequential_loop.h>

#include <CGAL/assertions.h>

#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A workspace for many small runs on one mesh (the polar patches: one run from each centre, stopped at a
// radius), whose cost is that of the region each run reaches, not that of the mesh.
//
// The first run starts the per-vertex, per-face and per-half-edge arrays once (O(V)). Each run lists the
// vertices whose distance it made finite (the hook Propagation_data::reached, in light(), and the seed
// vertex); before the next run, only what those vertices touched is put back: their distance, `processed`
// and log map entries, the faces around them (`swept`) and the window lists on the edges of those faces and
// on the opposite half-edges (the windows a stopped run leaves waiting, and their bounds in the stop rule).
// That covers everything a run writes: a window is stored on h only from the face of opposite(h), which is
// swept (so around a processed vertex) or around an emitting vertex or a seed, all of them reached; the
// FIFO flags are clear after every run (the loop drains it); the schedule, the stop rule's heaps and the
// window pool start again in O(1) (Window_storage::restart() checks, in debug builds, that no window is
// left). So a run gives the same bits as a run of Propagation_engine with the sequential scheduling and
// the same settings (test_polar_patches.cpp checks it).
//
// Exact sequential runs only: no labels, paths, targets, resets, virtual sources nor known distances.
class Local_propagation
{
public:
  // Runs from `seed` with `settings` (the log map's sources set in direction() before, if settings.log_map).
  void run(const Mesh_arrays& m, const Seed& seed, const Propagation_settings& settings)
  {
    CGAL_precondition(!settings.virtual_sources && !settings.want_labels && !settings.record_paths);
    CGAL_precondition(!settings.known_distances && !(settings.reset_step < std::numeric_limits<double>::infinity()));
    if(m_state.mesh != &m || !m_complete)  // (a run that threw left its state half done: start afresh)
    {
      m_state.start(m, settings, 1, std::vector<Target>());
      m_reached.clear();
    }
    else
    {
      put_back();
      m_state.start_local(settings, m_reached);
      m_reached.clear();
    }
    m_complete = false;
    m_state.reached = &m_reached;
    m_seeds.assign(1, seed);
    if(seed.kind == Seed::AT_VERTEX)
      m_reached.push_back(seed.element);  // given distance 0 by the seeding, not through light()
    m_state.schedule.start_heap();
    seed_sources(m_state, m_seeds);
    m_loop.run(m_state);
    m_state.direction.finish(m_state.dist, &m_reached);  // the log map behind pseudo-sources
    m_state.reached = nullptr;
    m_complete = true;
  }

  // The vertices the last run reached (each once), in the order they were first reached; those whose distance
  // is at most cutoff() have their final distance (in the engine's unit), the others are beyond the limit.
  const std::vector<Index>& reached() const { return m_reached; }
  double cutoff() const { return m_state.stop.cutoff(); }
  const std::vector<double>& distances() const { return m_state.dist; }
  Direction_record& direction() { return m_state.direction; }
  const Direction_record& direction() const { return m_state.direction; }
  // the counts of the last run
  std::size_t windows_created() const { return m_state.created; }
  std::size_t windows_propagated() const { return m_state.propagated; }
  std::size_t vertices_processed() const { return m_state.vertices_processed; }
  std::size_t pseudo_sources() const { return m_state.pseudo_sources; }
  bool stopped_early() const { return m_state.stop.stopped_early(); }

private:
  // Puts back what the last run changed (see above).
  void put_back()
  {
    const Mesh_arrays& m = *m_state.mesh;
    CGAL_assertion(m_state.fifo.empty());
    for(Index v : m_reached)
    {
      m_state.dist[v] = std::numeric_limits<double>::infinity();
      m_state.processed[v] = -1.;
      for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
      {
        const Index f = Mesh_arrays::face(m.corners[c]);
        m_state.swept[f] = 0;
        for(Index k = 0; k < 3; ++k)
        {
          const Index hs[2] = { 3 * f + k, m.opposite[3 * f + k] };
          for(Index h : hs)
            if(h != NO_INDEX && !m_state.store.empty(h))
            {
              m_state.store.clear(h);
              m_state.stop.on_list_emptied(h);  // (only non-empty lists have a finite bound)
            }
        }
      }
    }
  }

  Propagation_state m_state;
  Sequential_loop m_loop;
  std::vector<Seed> m_seeds;
  std::vector<Index> m_reached;
  bool m_complete = false;  // the last run went to its end (put_back() then suffices)
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_LOCAL_PROPAGATION_H
