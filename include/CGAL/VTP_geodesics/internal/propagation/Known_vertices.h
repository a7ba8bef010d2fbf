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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_KNOWN_VERTICES_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_KNOWN_VERTICES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The field a run from known distances (Propagation_settings::known_distances) starts from, per vertex: the
// distances, in the engine's unit, upper bounds realised by real paths (the field of earlier sources), and
// their labels if labels are wanted (solver/Known_field.h reads them from the named parameters
// initial_distances and initial_nearest_sources). Both fronts, the windows and the virtual sources, start
// from it (move_into()).
struct Known_field
{
  std::vector<double> distances;
  std::vector<Index> labels;

  // The per-vertex arrays of a run, `dist` and (if `want_labels`) `label`, of the size of the field, take
  // its values over (the field is then moved from).
  void move_into(std::vector<double>& dist, std::vector<Index>& label, bool want_labels)
  {
    CGAL_precondition(distances.size() == dist.size());
    CGAL_precondition(!want_labels || labels.size() == label.size());
    dist = std::move(distances);
    if(want_labels)
      label = std::move(labels);
  }
};

// The vertices of a run from known distances (Propagation_settings::known_distances), for Propagation_state.
//
// `dist` (and `label`) start from upper bounds realised by real paths (the field of earlier sources); only the
// new sources are seeded, and a known vertex is not scheduled unless the new sources lower it. The windows of
// the new sources are pruned against the known distances like against any other, so the result is, at every
// vertex, the minimum of the known distance and of the distance from the new sources, and the work is that of
// the region the new sources win. A window list that arrives at a face none of whose corners was taken waits
// there like any other; so that it is not left waiting, the known corners of that face are woken: scheduled at
// their known distance, and taken in order like the others (a woken vertex sweeps its one-ring but emits no
// window: a path of a new source through it is not shorter than its known distance).
//
// Per vertex, whether this run LOWERED or WOKE it; the vertices so flagged are listed in `touched` (what the
// next run from this field has to reset, and where the field changed), except in the first run on a field
// (`all`), after which every flag is reset at once.
class Known_vertices
{
public:
  enum Flag : unsigned char { LOWERED = 1, WOKEN = 2 };

  bool active() const { return !m_flag.empty(); }
  // whether vertex v was lowered by this run (every vertex is, when the run is not from known distances)
  bool lowered(Index v) const { return m_flag.empty() || (m_flag[v] & LOWERED) != 0; }
  const std::vector<Index>& touched() const { return m_touched; }

  // A first run on `nv` vertices (inactive unless `known`).
  void start(std::size_t nv, bool known)
  {
    m_flag.clear();
    m_touched.clear();
    m_all = known;
    if(known)
      m_flag.assign(nv, 0);
  }

  // Another run on the same field: the flags of the vertices of the previous run are cleared, with their
  // `processed` entry and the faces around them in `swept` (everything after a first run).
  void restart(const Mesh_arrays& m, std::vector<double>& processed, std::vector<unsigned char>& swept)
  {
    if(m_all || m_flag.size() != static_cast<std::size_t>(m.nv))
    {
      m_flag.assign(static_cast<std::size_t>(m.nv), 0);
      processed.assign(static_cast<std::size_t>(m.nv), -1.);
      swept.assign(static_cast<std::size_t>(m.nf), 0);
      m_all = false;
    }
    for(Index v : m_touched)
    {
      m_flag[v] = 0;
      processed[v] = -1.;
      for(Index c = m.corner_begin[v]; c < m.corner_begin[v + 1]; ++c)
        swept[Mesh_arrays::face(m.corners[c])] = 0;
    }
    m_touched.clear();
  }

  void mark_lowered(Index v)
  {
    if(m_flag.empty())
      return;
    if(m_flag[v] == 0 && !m_all)
      m_touched.push_back(v);
    m_flag[v] |= LOWERED;
  }

  // A list waits on face f (not swept): its known corners that nothing scheduled yet are scheduled at their
  // known distance.
  template <class Schedule>
  void wake_corners(const Mesh_arrays& m, Index f, const std::vector<double>& dist, Schedule& schedule)
  {
    for(Index k = 0; k < 3; ++k)
    {
      const Index v = m.source[3 * f + k];
      if(m_flag[v] == 0 && dist[v] < std::numeric_limits<double>::infinity())
      {
        m_flag[v] = WOKEN;
        if(!m_all)
          m_touched.push_back(v);
        schedule.push(v, dist[v]);
      }
    }
  }

private:
  std::vector<unsigned char> m_flag;
  std::vector<Index> m_touched;
  bool m_all = false;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_KNOWN_VERTICES_H
