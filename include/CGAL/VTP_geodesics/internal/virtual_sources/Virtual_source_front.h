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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_FRONT_H
#define CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_FRONT_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/propagation/Known_vertices.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_field.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_rounds.h>
#include <CGAL/VTP_geodesics/internal/virtual_sources/Virtual_source_walks.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// Virtual source propagation (VSP): one virtual source per vertex instead of lists of windows per
// half-edge (the limit of the reset family AVTP as lambda goes to 0).
//
// Each reached vertex u keeps, in the 2D frame of one half-edge `h` whose source is u (u at the origin, the
// target of h on the positive x axis, the face of h above it), the image s of its *root* (a vertex, or a
// source point) unfolded along a straight line, and the *wedge* of directions from s, bounded by L (counter-
// clockwise) and R (clockwise), through which that line really crosses the unfolded faces since it left the
// root: every point of the face of h inside the wedge is joined to the root by a straight segment that stays
// in the faces. The distance of u is d(root) + |s - u|.
//
// Vertices are taken in rounds of buckets of distances (Dijkstra by buckets of half a short edge, on one thread
// or several: Virtual_source_rounds.h). A vertex u taken offers to its neighbours, along its edges and
// through its virtual source, walking around u through the faces around it and into the faces beyond them
// (Virtual_source_walks.h).
// A vertex keeps the smallest offer; a vertex taken is never changed again. With a second virtual source
// per vertex (settings.second_virtual_source), it also keeps the best offer of another root than that of the
// smallest, and walks both: a line of another root, a little longer at this vertex, can reach vertices that
// the first one's wedge does not see. The offers beyond the faces around u do the same for lines that pass
// by u on the far side of a vertex that took another line (without them, a line dies as soon as the thin
// triangle between it and the line of the vertex that should carry it holds a vertex). The order is not
// monotone (an offer through a virtual source may be smaller than the distance of the vertex making it, by
// at most two edges: Virtual_source_buckets::reach), and since such offers can follow each other, a vertex
// can be taken rounds after the buckets passed its distance. So a run with a distance limit R takes, once
// the buckets pass R plus four longest edges, only the vertices offered at most that much (the others wait
// no more, and an offer that low brings them back): what it gives within R is always the length of a path,
// and most often the full run's distance, but not always (a vertex left out may have lowered others in the
// full run, and a vertex that the full run takes early at a large distance may get a smaller one here). A
// run stopped at its targets gives the full run's distances of the vertices taken.
//
// Upper bound: every offer is the length of a path on the surface (a straight segment in an unfolding whose
// faces it crosses, after a path to the root realised by induction), hence never below the geodesic distance.
//
// The per-vertex data, the seeding and the end of a run are in Virtual_source_field.h; this file holds a
// run, from the start of the field to the statistics.
class Virtual_source_front : public Virtual_source_walks
{
public:
  // With settings.known_distances, the run starts from the field `known` (which it takes over, see
  // Known_vertices.h): a known vertex is not taken unless the new sources lower it.
  // On `threads` threads (VSP: 1; PVSP: any number, the same distances, see Virtual_source_rounds.h).
  // Returns the number of threads of the team.
  int run(const Mesh_arrays& m, const std::vector<Seed>& seeds, std::vector<Target>&& targets,
          const Propagation_settings& settings, Propagation_statistics& st, int threads, Known_field&& known)
  {
    m_mesh = &m;
    m_seeds = &seeds;
    m_settings = settings;
    m_incremental = false;
    m_touched.clear();
    m_rounds.keep_width = false;
    const std::size_t nv = static_cast<std::size_t>(m.nv);
    dist.assign(nv, std::numeric_limits<double>::infinity());
    m_taken.assign(nv, 0);
    m_src.resize(nv);
    reset_second_sources(settings.second_virtual_source ? nv : 0);
    if(settings.want_labels)
      label.assign(nv, NO_INDEX);
    else
      label.clear();
    if(settings.known_distances)
    {
      known.move_into(dist, label, settings.want_labels);
      if(settings.second_virtual_source)
        for(std::size_t v = 0; v < nv; ++v)
          m_src[v].h = NO_INDEX;  // a known distance is not a virtual source (demote_first())
    }
    m_seeded.clear();
    m_targets = std::move(targets);
    m_target_value.assign(m_targets.size(), std::numeric_limits<double>::infinity());
    m_target_offer.assign(m_targets.size(), Offer());
    m_taken_count = 0;
    m_stopped = false;
    m_peak_seeded = 0;

    seed(seeds);
    threads = m_rounds.propagate(*this, threads);
    finish();

    record.start(settings.record_paths, nv, m_targets.size());
    if(settings.record_paths)
    {
      for(std::size_t v = 0; v < nv; ++v)
        if(dist[v] < std::numeric_limits<double>::infinity())
          record.vertex[v] = offer_of(static_cast<Index>(v));
      for(std::size_t t = 0; t < m_targets.size(); ++t)
        record.target[t] = m_target_offer[t];
    }
    if(settings.unit != 1.)
    {
      for(double& d : dist)
        d *= settings.unit;
    }
    st.vertices_processed = m_taken_count;
    st.stopped_early = m_stopped;
    st.peak_live_windows = 0;
    st.peak_window_bytes = nv * (sizeof(Vertex_source) + sizeof(double) + 1 + (label.empty() ? 0 : sizeof(Index)))
                           + m_src2.size() * (sizeof(Vertex_source) + sizeof(double))
                           + (std::max)(m_rounds.peak_bytes, m_peak_seeded * sizeof(Seeded_entry));
    copy_round_statistics(st);
    return threads;
  }

  // Adds `seed` (label: its seed label) to the field of the previous run_again() (the first one, or the
  // first after run(), starts from an empty field): farthest-point sampling
  // (sampling/Farthest_point_sampler.h). A vertex is taken only if the new seed lowers it, and the arrays
  // are not set up again, so a run costs what the region the seed wins costs; the vertices it lowered are
  // then those of touched(). The vertices not lowered keep their distance, label and virtual source (still
  // the line of a real path: its root's distance can only have decreased since). With a second virtual
  // source per vertex, a vertex lowered keeps its former source as its second if the roots differ
  // (demote_first()), and one not lowered may still get a better second source, which it walks only if a
  // later run takes it. Labels are kept; no limit, targets (there are none to stop at) nor paths
  // (settings.known_distances must be set). Returns the number of threads of the team.
  int run_again(const Mesh_arrays& m, const std::vector<Seed>& seeds, const Propagation_settings& settings,
                Propagation_statistics& st, int threads)
  {
    CGAL_precondition(settings.known_distances && settings.want_labels && !settings.record_paths
                      && settings.unit == 1. && !(settings.limit < std::numeric_limits<double>::infinity()));
    const std::size_t nv = static_cast<std::size_t>(m.nv);
    if(!m_incremental || m_mesh != &m || dist.size() != nv || label.size() != nv
       || m_src2.empty() == settings.second_virtual_source)
    {
      dist.assign(nv, std::numeric_limits<double>::infinity());
      label.assign(nv, NO_INDEX);
      m_taken.assign(nv, 0);
      m_src.resize(nv);
      reset_second_sources(settings.second_virtual_source ? nv : 0);
      m_incremental = true;
      m_rounds.keep_width = false;
    }
    else
    {
      for(Index v : m_touched)
        m_taken[static_cast<std::size_t>(v)] = 0;
      m_rounds.keep_width = true;
    }
    m_touched.clear();
    m_mesh = &m;
    m_seeds = &seeds;
    m_settings = settings;
    m_seeded.clear();
    m_targets.clear();
    m_target_value.clear();
    m_target_offer.clear();
    m_taken_count = 0;
    m_stopped = false;
    m_peak_seeded = 0;
    record.start(false, nv, 0);

    seed(seeds);
    threads = m_rounds.propagate(*this, threads);

    st.vertices_processed = m_taken_count;
    st.stopped_early = false;
    st.peak_live_windows = 0;
    st.peak_window_bytes = nv * (sizeof(Vertex_source) + sizeof(double) + 1 + sizeof(Index))
                           + m_src2.size() * (sizeof(Vertex_source) + sizeof(double))
                           + m_touched.capacity() * sizeof(Index)
                           + (std::max)(m_rounds.peak_bytes, m_peak_seeded * sizeof(Seeded_entry));
    copy_round_statistics(st);
    return threads;
  }

  // the vertices lowered (and taken) by the last run_again()
  const std::vector<Index>& touched() const { return m_touched; }

private:
  friend class Virtual_source_rounds;

  // room for a second virtual source for each of n vertices (n = 0: none), none set
  void reset_second_sources(std::size_t n)
  {
    Vertex_source none;
    none.sx = none.sy = none.lx = none.ly = none.rx = none.ry = 0.;
    none.h = NO_INDEX;
    none.root = NO_INDEX;
    m_src2.assign(n, none);
    m_dist2.assign(n, std::numeric_limits<double>::infinity());
  }

  // the rounds and stage times of the last run (Virtual_source_rounds)
  void copy_round_statistics(Propagation_statistics& st) const
  {
    st.rounds = m_rounds.rounds;
    st.parallel_rounds = m_rounds.parallel_rounds;
    st.selection_seconds = m_rounds.selection_seconds;
    st.propagation_seconds = m_rounds.propagation_seconds;
    st.merge_seconds = m_rounds.merge_seconds;
  }

  // With a stop at the targets: marks the vertices to take before stopping (a target vertex, the corners
  // of a target face) and returns their number; otherwise 0.
  std::size_t mark_targets(std::vector<unsigned char>& is_target) const
  {
    std::size_t count = 0;
    is_target.clear();
    if(!m_settings.stop_at_targets || m_targets.empty())
      return 0;
    const Mesh_arrays& m = *m_mesh;
    is_target.assign(static_cast<std::size_t>(m.nv), 0);
    for(const Target& t : m_targets)
    {
      if(t.vertex != NO_INDEX)
        mark(is_target, t.vertex, count);
      else
        for(int k = 0; k < 3; ++k)
          mark(is_target, m.source[3 * t.face + k], count);
    }
    return count;
  }

  static void mark(std::vector<unsigned char>& is_target, Index v, std::size_t& count)
  {
    if(!is_target[static_cast<std::size_t>(v)])
    {
      is_target[static_cast<std::size_t>(v)] = 1;
      ++count;
    }
  }

  Virtual_source_rounds m_rounds;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_FRONT_H
