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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_SEQUENTIAL_LOOP_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_SEQUENTIAL_LOOP_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>

#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The sequential scheduling (VTP, Qin et al. 2016): vertices are taken from a binary heap, nearest first;
// after each one, the queued lists are propagated one at a time in FIFO order until every window waits on
// the wavefront.
class Sequential_loop
{
public:
  // Runs the propagation seeded in `st` (whose schedule was started as a heap) to its end, or until its
  // stop rule says it is done (checked before each vertex, when no list is queued).
  void run(Propagation_state& st)
  {
    drain(st);
    Vertex_schedule::Entry e;
    while(!(st.stop.is_tracking() && st.stop.is_done(st.schedule)) && st.schedule.pop(e))
      if(st.take_vertex(e.second, e.first))
        drain(st);
    st.field.gather(m_scratch.crossed);
  }

private:
  // Propagates the queued lists until every window waits on the wavefront.
  void drain(Propagation_state& st)
  {
    const Mesh_arrays& m = *st.mesh;
    Propagation_scratch& s = m_scratch;
    for(std::size_t head = 0; head < st.fifo.size(); ++head)
    {
      const Index h = st.fifo[head];
      st.queued[h] = 0;
      if(st.store.empty(h))
        continue;
      s.in.clear();
      st.store.take(h, s.in);
      st.stop.on_list_emptied(h);
      s.out_ac.clear();
      s.out_cb.clear();
      const Offer offer = st.propagate_one(h, s);
      st.light(m.source[Mesh_arrays::prev(h)], offer);
      st.store_all_children(h, s, 0, st.fifo);
      st.wake_beyond(h);
      st.stop.merge(s.events);
      st.store.update_peaks();
    }
    st.propagated += s.propagated;
    st.created += s.created;
    s.propagated = s.created = 0;
    st.fifo.clear();
  }

  Propagation_scratch m_scratch;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_SEQUENTIAL_LOOP_H
