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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PROPAGATION_DATA_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PROPAGATION_DATA_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Triangle_propagation.h>
#include <CGAL/VTP_geodesics/internal/windows/Window_storage.h>
#include <CGAL/VTP_geodesics/internal/log_map/Direction_record.h>
#include <CGAL/VTP_geodesics/internal/propagation/Known_vertices.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_record.h>
#include <CGAL/VTP_geodesics/internal/propagation/Stop_rule.h>
#include <CGAL/VTP_geodesics/internal/propagation/Vertex_schedule.h>
#include <CGAL/VTP_geodesics/internal/field/Kept_field.h>
#include <CGAL/VTP_geodesics/internal/propagation/Window_reset.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// What the caller asks of one propagation, in the engine's unit of length.
struct Propagation_settings
{
  double minimum_window_ratio = 1e-9;  // windows shorter than this times their edge are dropped
  double reset_step = std::numeric_limits<double>::infinity();  // lambda h (AVTP / PAVTP)
  double reset_guard = 0.;             // lambda_g h
  bool want_labels = false;            // nearest-source labels
  double limit = std::numeric_limits<double>::infinity();  // distance limit
  bool stop_at_targets = false;        // stop once the targets are final
  bool record_paths = false;           // keep what the path trace-back needs
  double unit = 1.;                    // the engine's unit of length, in the unit of the output distances
  bool virtual_sources = false;        // one virtual source per vertex (VSP / PVSP) instead of windows
  bool second_virtual_source = false;  // with virtual_sources: a second one per vertex, of another root
  bool known_distances = false;        // the run starts from distances already known (Known_vertices.h)
  bool log_map = false;                // the log map (Direction_record.h)
  bool log_map_strict = false;         // with log_map: the strict polyhedral theta behind pseudo-sources
  bool keep_field = false;             // every window that crosses a face (field/Kept_field.h)
};

// The buffers of one thread: a list being propagated, its children, and counters.
struct alignas(64) Propagation_scratch
{
  std::vector<Window> in, out_ac, out_cb;
  List_scratch list;
  std::size_t propagated = 0, created = 0;
  Stop_events events;
  Field_piece_buffer crossed;          // the kept field (field/Kept_field.h), until gathered
};

// The data of one propagation (Propagation_state.h holds the steps that the loops share): per vertex a
// distance upper bound and the distance it was taken at, per face whether it is swept, per half-edge its
// window list and whether it is queued, the schedule, the reset policy, the stop rule and the path record;
// its start, and the start of a run that goes on from the field of the previous one.
class Propagation_data
{
public:
  // ------------------------------------------------------------------------------------------
  // per-run data (read by the loops)
  // ------------------------------------------------------------------------------------------
  const Mesh_arrays* mesh = nullptr;
  Propagation_settings settings;
  std::vector<double> dist;            // per vertex
  std::vector<Index> label;            // per vertex, the nearest source found (if settings.want_labels)
  std::vector<Index> seed_label;       // per point source (origin nv + i), its label
  std::vector<unsigned char> swept;    // per face
  std::vector<unsigned char> queued;   // per half-edge: its list is in a queue
  std::vector<double> processed;       // per vertex: the distance it was taken at, -1 if never
  Window_storage store;
  Vertex_schedule schedule;
  Window_reset reset;
  Stop_rule stop;
  Path_record record;
  Kept_field field;                    // the windows that crossed each face (keep_field)
  Direction_record direction;          // the log map
  std::vector<Index> fifo;             // queued lists (sequential scheduling: FIFO order)
  Known_vertices known;                // runs from known distances
  // whether a source is a piece of a curve, so that the lists may hold line windows (set by seed_sources();
  // without, the lists are filtered and propagated without testing the kind of each window)
  bool line_windows = false;
  // if set, every vertex whose distance becomes finite through light() is appended (Local_propagation.h)
  std::vector<Index>* reached = nullptr;

  // counters
  std::size_t created = 0, propagated = 0, vertices_processed = 0, pseudo_sources = 0;

  // Prepares a run on `m` (the schedule is started by the loop).
  void start(const Mesh_arrays& m, const Propagation_settings& s, std::size_t pools, std::vector<Target>&& targets)
  {
    mesh = &m;
    settings = s;
    const std::size_t nh = m.source.size();
    dist.assign(static_cast<std::size_t>(m.nv), std::numeric_limits<double>::infinity());
    if(s.want_labels)
      label.assign(static_cast<std::size_t>(m.nv), NO_INDEX);
    else
      label.clear();
    seed_label.clear();
    swept.assign(static_cast<std::size_t>(m.nf), 0);
    queued.assign(nh, 0);
    processed.assign(static_cast<std::size_t>(m.nv), -1.);
    store.reset(nh, pools);
    fifo.clear();
    reset.start(s.reset_step, s.reset_guard, static_cast<std::size_t>(m.nv));
    const std::size_t number_of_targets = targets.size();
    stop.start(m, s.limit, s.stop_at_targets, std::move(targets));
    record.start(s.record_paths, static_cast<std::size_t>(m.nv), number_of_targets);
    field.start(s.keep_field && s.reset_step == std::numeric_limits<double>::infinity(), m.nf);
    direction.start(m, s.log_map, s.log_map_strict);
    known.start(static_cast<std::size_t>(m.nv), s.known_distances);
    m_events.clear();
    created = propagated = vertices_processed = pseudo_sources = 0;
  }

  // Prepares a run from known distances that goes on from the field left by the previous run on the same
  // mesh (dist and label kept, in the engine's unit), resetting only what that run touched: O(touched).
  // The previous run must have gone to its end (no limit, no targets: every list was consumed).
  void start_again(const Propagation_settings& s, std::size_t pools)
  {
    CGAL_precondition(mesh != nullptr && s.known_distances && settings.known_distances);
    CGAL_precondition(!(s.limit < std::numeric_limits<double>::infinity()) && !s.record_paths);
    const Mesh_arrays& m = *mesh;
    settings = s;
    known.restart(m, processed, swept);
    seed_label.clear();
    store.restart(pools);
    fifo.clear();
    reset.start(s.reset_step, s.reset_guard, static_cast<std::size_t>(m.nv));
    stop.start(m, s.limit, false, std::vector<Target>());
    field.start(false);
    m_events.clear();
    created = propagated = vertices_processed = pseudo_sources = 0;
  }

  // Prepares a run on the mesh of the previous run (not from known distances, without labels, paths, targets
  // nor resets) whose caller has put back what that run changed (Local_propagation.h): O(1) but the log map's
  // sources; the direction record clears the vertices of `previous` only.
  void start_local(const Propagation_settings& s, const std::vector<Index>& previous)
  {
    CGAL_precondition(mesh != nullptr && !s.want_labels && !s.record_paths && !s.known_distances);
    CGAL_precondition(!(s.reset_step < std::numeric_limits<double>::infinity()));
    settings = s;
    label.clear();
    seed_label.clear();
    store.restart(1);
    fifo.clear();
    reset.start(s.reset_step, s.reset_guard, static_cast<std::size_t>(mesh->nv));
    stop.start(*mesh, s.limit, false, std::vector<Target>(), /* keep_list_bounds */ true);
    record.start(false, 0, 0);
    field.start(false);
    direction.restart(*mesh, s.log_map, s.log_map_strict, previous);
    known.start(static_cast<std::size_t>(mesh->nv), false);
    m_events.clear();
    created = propagated = vertices_processed = pseudo_sources = 0;
  }

  void mark_lowered(Index v) { known.mark_lowered(v); }

  // Run from known distances: a list waits on face f; if f is not swept, its corners are woken.
  void wake_corners(Index f)
  {
    if(known.active() && !swept[f])
      known.wake_corners(*mesh, f, dist, schedule);
  }

  // Run from known distances: wakes the corners of the faces beyond the two other edges of face(h) if the
  // lists there wait (serial; called after the children of the list of h are stored).
  void wake_beyond(Index h)
  {
    if(!known.active())
      return;
    const Mesh_arrays& m = *mesh;
    const Index sides[2] = { m.opposite[Mesh_arrays::prev(h)], m.opposite[Mesh_arrays::next(h)] };
    for(Index o : sides)
      if(o != NO_INDEX && !store.empty(o))
        wake_corners(Mesh_arrays::face(o));
  }

  // The label of a window origin.
  Index label_of_origin(Index origin) const
  {
    const Index nv = mesh->nv;
    return origin < nv ? label[origin] : seed_label[static_cast<std::size_t>(origin - nv)];
  }

protected:
  Stop_events m_events;  // of the serial steps
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_PROPAGATION_DATA_H
