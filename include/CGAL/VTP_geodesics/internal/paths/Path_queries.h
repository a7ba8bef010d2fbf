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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_QUERIES_H
#define CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_QUERIES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_trace.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_index.h>

#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The path queries of the solver: the trace-back of the path from a vertex or a point to its nearest
// source after a computation, from the record of that computation when it has one for the point, else
// from a run of its own (same sources and parameters, stopped once the point is final, recording), in a
// workspace of its own; and the conversion of the points of a path into face locations or points.
class Path_queries
{
public:
  // A computation was made with `settings`, with the parallel scheduling or not, on `threads` threads.
  void remember(const Propagation_settings& settings, bool parallel, int threads)
  {
    m_settings = settings;
    m_parallel = parallel;
    m_threads = threads;
    m_has_run = true;
  }

  // The path from `target` back to its nearest source for the last computation of `engine`, on `arrays`.
  // (`position`: per vertex index, the number of the vertex in the error messages)
  std::vector<Trace_point> trace(const Mesh_arrays& arrays, const Propagation_engine& engine, const Target& target,
                                 const std::vector<Index>& position)
  {
    if(!m_has_run)
      throw Invalid_input_error("a path was asked for before any computation");
    if(m_settings.known_distances)
      throw Invalid_input_error("no path after a computation from initial distances (the paths to the earlier "
                                "sources are not known)");
    const Propagation_engine* from = &engine;
    std::size_t index = 0;
    if(!(find_target(engine, target, index) && is_reached(engine, target, index)))
    {
      // run again from the same sources until the point is final, recording the trace-back
      if(!m_engine)
        m_engine.reset(new Propagation_engine());
      Propagation_settings settings = m_settings;
      settings.want_labels = false;
      settings.stop_at_targets = true;
      settings.record_paths = true;
      Propagation_statistics unused;
      std::vector<Target> targets(1, target);
      if(m_parallel)
      {
#ifdef _OPENMP
        m_engine->template run<CGAL::Parallel_tag>(arrays, engine.seeds(), std::move(targets), settings, m_threads,
                                                   unused);
#endif
      }
      else
        m_engine->template run<CGAL::Sequential_tag>(arrays, engine.seeds(), std::move(targets), settings, m_threads,
                                                     unused);
      from = m_engine.get();
      index = 0;
      if(!is_reached(*from, target, index))
      {
        const std::string what = target.vertex != NO_INDEX
                                   ? "vertex " + std::to_string(position[static_cast<std::size_t>(target.vertex)])
                                   : std::string("the point");
        throw Invalid_input_error("no path: " + what
                                  + " is not reached by any source (or lies beyond the distance limit)");
      }
    }
    std::vector<Trace_point> points;
    const Path_trace tracer(arrays, from->path_record(), from->seeds());
    const bool ok = target.vertex != NO_INDEX
                      ? tracer.from_vertex(target.vertex, points)
                      : tracer.from_target(from->targets()[index], from->path_record().target[index], points);
    if(!ok)
      throw std::runtime_error("the geodesic path could not be traced back through the faces it crosses");
    return points;
  }

private:
  // whether `target` can be traced from the record of `engine`: a vertex (from its own record), or a point
  // that was its target `index`
  static bool find_target(const Propagation_engine& engine, const Target& target, std::size_t& index)
  {
    if(!engine.path_record().is_active())
      return false;
    if(target.vertex != NO_INDEX)
      return true;
    const std::vector<Target>& targets = engine.targets();
    for(std::size_t i = 0; i < targets.size(); ++i)
      if(targets[i].face == target.face && targets[i].x[0] == target.x[0] && targets[i].y[0] == target.y[0])
      {
        index = i;
        return true;
      }
    return false;
  }

  static bool is_reached(const Propagation_engine& engine, const Target& target, std::size_t index)
  {
    const double d = target.vertex != NO_INDEX ? engine.distances()[static_cast<std::size_t>(target.vertex)]
                                               : engine.target_distance(index);
    return d < std::numeric_limits<double>::infinity();
  }

  bool m_has_run = false;
  Propagation_settings m_settings;
  bool m_parallel = false;
  int m_threads = 0;
  std::unique_ptr<Propagation_engine> m_engine;
};

// The face location of a point of a path: a vertex as a corner of one of its faces, an edge point in the
// face of its half-edge.
template <class TriangleMesh>
std::pair<typename Mesh_index<TriangleMesh>::face_descriptor, std::array<double, 3> >
location_of(const Mesh_index<TriangleMesh>& index, const Trace_point& p)
{
  const Mesh_arrays& m = index.arrays;
  std::array<double, 3> b = { { 0., 0., 0. } };
  Index f;
  if(p.kind == Trace_point::AT_VERTEX)
  {
    const Index v = p.element;
    if(m.corner_begin[v] == m.corner_begin[v + 1])
      throw Invalid_input_error("vertex " + std::to_string(index.position_of(v)) + " is isolated: it has no face location");
    const Index h = m.corners[m.corner_begin[v]];
    f = Mesh_arrays::face(h);
    b[static_cast<std::size_t>(h % 3)] = 1.;
  }
  else if(p.kind == Trace_point::ON_EDGE)
  {
    const Index h = p.element;
    f = Mesh_arrays::face(h);
    const double length = m.geometry[h].length;
    const double t = length > 0. ? (std::min)((std::max)(p.x / length, 0.), 1.) : 0.;
    b[static_cast<std::size_t>(h % 3)] = 1. - t;
    b[static_cast<std::size_t>((h + 1) % 3)] = t;
  }
  else
  {
    f = p.element;
    const Halfedge_geometry g = m.geometry[3 * f];
    b[2] = g.cy > 0. ? p.y / g.cy : 0.;
    b[1] = g.length > 0. ? (p.x - b[2] * g.cx) / g.length : 0.;
    b[0] = 1. - b[1] - b[2];
  }
  return std::make_pair(index.faces[static_cast<std::size_t>(f)], b);
}

// The point of a point of a path, with the vertex point map `vpm`.
template <class Point_3, class TriangleMesh, class VertexPointMap>
Point_3 point_of(const Mesh_index<TriangleMesh>& index, VertexPointMap vpm, const Trace_point& p)
{
  const TriangleMesh& tm = index.tm;
  if(p.kind == Trace_point::AT_VERTEX)
    return get(vpm, index.vertices[static_cast<std::size_t>(p.element)]);
  const auto l = location_of(index, p);
  const auto h = halfedge(l.first, tm);
  const Point_3 q[3] = { get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)) };
  double c[3] = { 0., 0., 0. };
  for(int k = 0; k < 3; ++k)
    for(int j = 0; j < 3; ++j)
      c[j] += l.second[static_cast<std::size_t>(k)] * CGAL::to_double(q[k][j]);
  return Point_3(c[0], c[1], c[2]);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PATHS_PATH_QUERIES_H
