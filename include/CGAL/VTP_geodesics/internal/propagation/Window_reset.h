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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_WINDOW_RESET_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_WINDOW_RESET_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window_storage.h>
#include <CGAL/VTP_geodesics/internal/propagation/Vertex_schedule.h>

#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The reset policy of the approximate variants (AVTP / PAVTP, Du et al. 2020, Section 5): never (exact
// propagation), or each time the vertex taken next lies beyond the current reset radius (R + 1) lambda h:
// the windows waiting next to the wavefront vertices are deleted (but those of edges whose two ends lie
// beyond the guard band lambda_g h), and every wavefront vertex becomes a pseudo-source. Every distance
// stays the length of a real surface path, so the result is never below the exact one.
class Window_reset
{
public:
  // `step` = lambda h (infinity: never reset), `guard` = lambda_g h.
  void start(double step, double guard, std::size_t number_of_vertices)
  {
    m_step = step;
    m_guard = guard;
    m_next = step;
    m_resets = 0;
    if(is_active())
      m_forced.assign(number_of_vertices, 0);
    else
      m_forced.clear();
  }

  bool is_active() const { return m_step < std::numeric_limits<double>::infinity(); }

  // Whether taking a vertex at distance dv must first reset the windows.
  bool is_due(double dv) const { return dv > m_next; }

  // Whether v was made a pseudo-source by a reset.
  bool is_forced(Index v) const { return !m_forced.empty() && m_forced[v] != 0; }

  std::size_t number_of_resets() const { return m_resets; }

  // Resets the windows before vertex v is taken at distance dv (is_due(dv) holds). The wavefront is
  // read from the schedule: the vertices reached and not processed yet, one live entry each. Each list
  // emptied is reported to on_cleared(h).
  template <class OnCleared>
  void apply(Index v, double dv, const Mesh_arrays& m, const Vertex_schedule& schedule,
             const std::vector<double>& d, const std::vector<double>& processed, Window_storage& store,
             OnCleared on_cleared)
  {
    while(m_next < dv)
      m_next += m_step;
    const double keep_beyond = (m_next - m_step) + m_guard;
    ++m_resets;
    m_wavefront.clear();
    schedule.for_each_waiting([&](const Vertex_schedule::Entry& e) {
      const Index w = e.second;
      if(e.first == d[w] && processed[w] != e.first)
        m_wavefront.push_back(w);
    });
    for(Index w : m_wavefront)
    {
      if(d[w] > keep_beyond)
        continue;
      for(Index c = m.corner_begin[w]; c < m.corner_begin[w + 1]; ++c)
      {
        const Index h = m.corners[c];
        const Index edges[2] = { h, Mesh_arrays::prev(h) };
        for(Index e : edges)
        {
          if(d[m.source[e]] > keep_beyond || d[m.target(e)] > keep_beyond)
            continue;
          store.clear(e);
          on_cleared(e);
          if(m.opposite[e] != NO_INDEX)
          {
            store.clear(m.opposite[e]);
            on_cleared(m.opposite[e]);
          }
        }
      }
    }
    for(Index w : m_wavefront)
      m_forced[w] = 1;
    m_forced[v] = 1; // v was the nearest wavefront vertex
  }

private:
  double m_step = std::numeric_limits<double>::infinity();
  double m_guard = 0.;
  double m_next = std::numeric_limits<double>::infinity();
  std::size_t m_resets = 0;
  std::vector<unsigned char> m_forced;
  std::vector<Index> m_wavefront;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_WINDOW_RESET_H
