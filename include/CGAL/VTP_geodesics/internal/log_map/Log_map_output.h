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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_LOG_MAP_OUTPUT_H
#define CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_LOG_MAP_OUTPUT_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/internal/log_map/Tangent_frame.h>
#include <CGAL/VTP_geodesics/internal/log_map/Direction_record.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_data.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The log map seen from the solver: its named parameters (log_map, log_map_via, log_map_strict,
// reference_direction) read into the settings, the frames of the sources (Tangent_frame.h) handed to the
// engine's Direction_record, and the results written into the user's maps.

// a 3D direction given as a CGAL vector (x(), y(), z()) or as an array of three numbers
template <class V>
auto direction_3d(const V& v, int) -> decltype(v.x(), Vector_3d())
{
  return {CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())};
}
template <class V>
Vector_3d direction_3d(const V& v, long)
{
  return {CGAL::to_double(v[0]), CGAL::to_double(v[1]), CGAL::to_double(v[2])};
}

// Reads the log map's parameters into `settings`; throws Invalid_input_error for a method that does not
// carry directions (the approximate ones and the virtual sources) or a run from known distances.
template <class NamedParameters>
void log_map_settings(const NamedParameters& np, Propagation_settings& settings)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  settings.log_map = !is_default_parameter<NamedParameters, internal_np::log_map_t>::value
                     || !is_default_parameter<NamedParameters, internal_np::log_map_via_t>::value;
  settings.log_map_strict = choose_parameter(get_parameter(np, internal_np::log_map_strict), false);
  if(!settings.log_map)
    return;
  if(settings.virtual_sources || settings.reset_step < std::numeric_limits<double>::infinity())
    throw Invalid_input_error("the log map needs an exact method (VTP or PVTP): the windows of AVTP and PAVTP are "
                              "reset at vertices that are not on the geodesics, and VSP keeps no direction");
  if(settings.known_distances)
    throw Invalid_input_error("the log map cannot start from known distances (initial_distances)");
}

// The frames of the sources of a run of the log map, in the engine's Direction_record: the vertex sources
// with their reference half-edges, the point sources with the direction of their half-edge in the frame of
// the face given; each minus the theta of the user's reference direction (if given).
template <class MeshIndex, class VertexPointMap, class NamedParameters>
void prepare_log_map(const MeshIndex& index, VertexPointMap vpm, const NamedParameters& np,
                     const std::vector<Seed>& seeds, Direction_record& record)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  const Mesh_arrays& m = index.arrays;
  const bool has_reference = !is_default_parameter<NamedParameters, internal_np::reference_direction_t>::value;
  Vector_3d reference{1., 0., 0.};
  if constexpr(!is_default_parameter<NamedParameters, internal_np::reference_direction_t>::value)
  {
    reference = direction_3d(get_parameter(np, internal_np::reference_direction), 0);
    check_direction_3d(reference, "the reference direction");
  }
  const auto point = [&](Index i) {
    const auto& p = get(vpm, index.vertices[static_cast<std::size_t>(i)]);
    return Vector_3d{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  record.vertex_sources.clear();
  record.seed_angle.assign(seeds.size(), 0.);
  for(std::size_t i = 0; i < seeds.size(); ++i)
  {
    const Seed& s = seeds[i];
    if(s.kind == Seed::AT_VERTEX)
    {
      Log_map_source source;
      source.vertex = s.element;
      source.reference = vertex_reference_halfedge(index, index.vertices[static_cast<std::size_t>(s.element)]);
      Vertex_frame frame;
      if(!make_vertex_frame(m, s.element, source.reference, frame))
        throw Invalid_input_error("the log map needs a source vertex whose faces form one fan around it (source "
                                  + std::to_string(i) + ")");
      if(has_reference)
        source.offset = vertex_theta_of_3d(m, frame, point, reference);
      bool repeated = false;
      for(const Log_map_source& t : record.vertex_sources)
        repeated = repeated || t.vertex == source.vertex;
      if(!repeated)
        record.vertex_sources.push_back(source);
      continue;
    }
    const Index f = s.user_face;  // the face given (sources are face locations here)
    CGAL_assertion(f != NO_INDEX);
    // the direction of the seed's half-edge (edge) or of 3f (face) in the frame of f
    double angle = 0.;
    if(s.kind == Seed::ON_EDGE)
    {
      const Index h = s.element;
      angle = Mesh_arrays::face(h) == f ? halfedge_direction_in_frame(m, 3 * f, h)
                                        : halfedge_direction_in_frame(m, 3 * f, m.opposite[h]) + TANGENT_FRAME_PI;
    }
    if(has_reference)
    {
      const Index h = 3 * f;
      const std::array<Vector_3d, 3> corners{point(m.source[h]), point(m.target(h)),
                                             point(m.source[Mesh_arrays::prev(h)])};
      angle -= face_theta_of_3d(corners, reference, "the reference direction");
    }
    record.seed_angle[i] = angle;
  }
}

// The log map's settings from `np` and, when a log map is asked for, the frames of its sources.
template <class NamedParameters, class MeshIndex, class VertexPointMap>
void start_log_map(const NamedParameters& np, Propagation_settings& settings, const MeshIndex& index,
                   VertexPointMap vpm, const std::vector<Seed>& seeds, Direction_record& record)
{
  log_map_settings(np, settings);
  if(settings.log_map)
    prepare_log_map(index, vpm, np, seeds, record);
}

template <class Vertex, class Index_map>
void write_log_map_via(const std::vector<Vertex>&, const Index_map&, CGAL::internal_np::Param_not_found)
{}

template <class Vertex, class Direction, class ViaMap>
void write_log_map_via(const std::vector<Vertex>& vertices, const Direction& record, ViaMap via)
{
  for(std::size_t i = 0; i < vertices.size(); ++i)
  {
    const Index w = record.via[i];
    put(via, vertices[i], w >= 0 ? vertices[static_cast<std::size_t>(w)] : Vertex());
  }
}

template <class Vertex>
void write_log_map_coordinates(const std::vector<Vertex>&, const std::vector<double>&, const Direction_record&,
                               CGAL::internal_np::Param_not_found)
{}

template <class Vertex, class LogMap>
void write_log_map_coordinates(const std::vector<Vertex>& vertices, const std::vector<double>& distances,
                               const Direction_record& record, LogMap map)
{
  const double inf = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < vertices.size(); ++i)
  {
    const double rho = distances[i], theta = record.theta[i];
    const std::array<double, 2> x = rho < inf ? std::array<double, 2>{rho * std::cos(theta), rho * std::sin(theta)}
                                               : std::array<double, 2>{inf, inf};
    put(map, vertices[i], x);
  }
}

// Writes the log map of the last run (if asked for) into the named parameters `log_map` and `log_map_via`
// (no vertex: the default-constructed descriptor, for Surface_mesh the null vertex).
template <class Vertex, class Engine, class NamedParameters>
void write_log_map(const std::vector<Vertex>& vertices, const Engine& engine, const NamedParameters& np)
{
  using CGAL::parameters::get_parameter;
  if(!engine.direction().is_active())
    return;
  write_log_map_coordinates(vertices, engine.distances(), engine.direction(), get_parameter(np, internal_np::log_map));
  write_log_map_via(vertices, engine.direction(), get_parameter(np, internal_np::log_map_via));
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_LOG_MAP_OUTPUT_H
