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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_JOIN_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_JOIN_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_trace.h>
#include <CGAL/VTP_geodesics/internal/propagation/Targets.h>
#include <CGAL/VTP_geodesics/internal/source_curves/Curve_seeds.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The points of a source curve as given, completed so that consecutive points share a face: two that share
// none are joined by the shortest geodesic between them (one exact run from the first, stopped at the second,
// and its trace-back). Returns false if two consecutive points are not connected (`bad` is then the first).
inline bool join_curve_points(const Mesh_arrays& m, const std::vector<Seed>& points, std::vector<Seed>& out,
                              std::size_t& bad)
{
  out.clear();
  Propagation_engine engine;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(i > 0 && common_face(m, points[i - 1], points[i]) == NO_INDEX)
    {
      const Seed& a = points[i - 1];
      const Seed& b = points[i];
      Target target;
      if(b.kind == Seed::AT_VERTEX)
        target.vertex = b.element;
      else
      {
        const Index f = b.kind == Seed::IN_FACE ? b.element : Mesh_arrays::face(b.element);
        const std::array<double, 2> p = point_in_face(m, b, f);
        target = face_target(m, f, p[0], p[1]);
      }
      Propagation_settings settings;
      settings.stop_at_targets = true;
      settings.record_paths = true;
      Propagation_statistics unused;
      std::vector<Seed> from(1, a);
      from[0].label = 0;
      engine.template run<CGAL::Sequential_tag>(m, from, std::vector<Target>(1, target), settings, 1, unused);
      if(!(engine.target_distance(0) < std::numeric_limits<double>::infinity()))
      {
        bad = i - 1;
        return false;
      }
      std::vector<Trace_point> trace;
      const Path_trace tracer(m, engine.path_record(), engine.seeds());
      const bool ok = target.vertex != NO_INDEX
                        ? tracer.from_vertex(target.vertex, trace)
                        : tracer.from_target(engine.targets()[0], engine.path_record().target[0], trace);
      if(!ok || trace.size() < 2)
      {
        bad = i - 1;
        return false;
      }
      // the trace goes from b back to a: its inner points, from a's side (its ends are b and a, possibly written
      // otherwise: a point of an edge as a point of a face)
      for(std::size_t k = trace.size() - 1; k-- > 1;)
      {
        Seed s;
        static_cast<Surface_point&>(s) = trace[k];
        if(same_point(s, a) || same_point(s, b) || (!out.empty() && same_point(s, out.back())))
          continue;
        out.push_back(s);
      }
    }
    out.push_back(points[i]);
  }
  return true;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOURCE_CURVES_CURVE_JOIN_H
