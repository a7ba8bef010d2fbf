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

#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// TEMPORARY PLACEHOLDER (edge Dijkstra) so that the API compiles; replaced by the VTP engine.
class Propagation_engine
{
public:
  template <class ConcurrencyTag>
  void run(const Mesh_arrays& m, Index s, const Propagation_options&, std::vector<double>& d,
           Propagation_statistics& st)
  {
    d.assign(m.nv, std::numeric_limits<double>::infinity());
    typedef std::pair<double, Index> E;
    std::priority_queue<E, std::vector<E>, std::greater<E> > q;
    d[s] = 0; q.push(E(0, s));
    while(!q.empty()) {
      E e = q.top(); q.pop();
      if(e.first > d[e.second]) continue;
      for(Index c = m.corner_begin[e.second]; c < m.corner_begin[e.second + 1]; ++c) {
        Index h = m.corners[c];
        Index u = m.target(h);
        double nd = e.first + m.geometry[h].length;
        if(nd < d[u]) { d[u] = nd; q.push(E(nd, u)); }
        u = m.source[Mesh_arrays::prev(h)];
        nd = e.first + m.geometry[h].l_prev;
        if(nd < d[u]) { d[u] = nd; q.push(E(nd, u)); }
      }
    }
    st = Propagation_statistics();
  }
};

} } }
#endif
