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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOLVER_KNOWN_FIELD_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOLVER_KNOWN_FIELD_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/propagation/Known_vertices.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The field a computation starts from (named parameters initial_distances, initial_nearest_sources and
// first_source_label), read from the maps of the user into the engine's unit (Known_field, per vertex index:
// propagation/Known_vertices.h) and validated.

// (without initial_nearest_sources, the known distances have no label)
template <class MeshIndex>
void read_known_labels(const MeshIndex& mesh, CGAL::internal_np::Param_not_found, std::vector<Index>& labels)
{
  labels.assign(mesh.vertices.size(), NO_INDEX);
}

// (read in the order of vertices(tm), so that an error names the first bad vertex in that order)
template <class MeshIndex, class VertexSourceMap>
void read_known_labels(const MeshIndex& mesh, VertexSourceMap vsm, std::vector<Index>& labels)
{
  labels.resize(mesh.vertices_in_order.size());
  for(std::size_t i = 0; i < labels.size(); ++i)
  {
    const auto v = mesh.vertices_in_order[i];
    const std::size_t l = static_cast<std::size_t>(get(vsm, v));
    const std::size_t id = static_cast<std::size_t>(get(mesh.vertex_id, v));
    if(l == no_source)
      labels[id] = NO_INDEX;
    else if(l >= static_cast<std::size_t>((std::numeric_limits<Index>::max)()))
      throw Invalid_input_error("the initial nearest source of vertex " + std::to_string(i) + " is too large ("
                                + std::to_string(l) + ")");
    else
      labels[id] = static_cast<Index>(l);
  }
}

// (returns whether there are known distances)
template <class MeshIndex>
bool read_known_distances(const MeshIndex&, double, CGAL::internal_np::Param_not_found, std::vector<double>&)
{
  return false;
}

// (read in the order of vertices(tm), so that an error names the first bad vertex in that order)
template <class MeshIndex, class VertexDistanceMap>
bool read_known_distances(const MeshIndex& mesh, double length_scale, VertexDistanceMap vdm,
                          std::vector<double>& distances)
{
  distances.resize(mesh.vertices_in_order.size());
  for(std::size_t i = 0; i < distances.size(); ++i)
  {
    const auto v = mesh.vertices_in_order[i];
    const double d = static_cast<double>(get(vdm, v));
    if(!(d >= 0.))
      throw Invalid_input_error("the initial distance of vertex " + std::to_string(i) + " is "
                                + (std::isnan(d) ? std::string("NaN") : std::to_string(d))
                                + " (it must be >= 0, +infinity for none)");
    distances[static_cast<std::size_t>(get(mesh.vertex_id, v))] = d / length_scale;
  }
  return true;
}

// Reads the known field of `np` (if any) for a run with `settings` (which it marks), and numbers the labels
// of `seeds` from first_source_label. Throws Invalid_input_error for a combination that a run from known
// distances does not support (a distance limit, targets, paths) or for bad values.
template <class MeshIndex, class NamedParameters>
Known_field known_field_of(const NamedParameters& np, const MeshIndex& mesh, double length_scale,
                           Propagation_settings& settings, std::vector<Seed>& seeds)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  Known_field field;
  const bool known =
      read_known_distances(mesh, length_scale, get_parameter(np, internal_np::initial_distances), field.distances);
  const bool has_labels = !is_default_parameter<NamedParameters, internal_np::initial_nearest_sources_t>::value;
  const std::size_t first = choose_parameter(get_parameter(np, internal_np::first_source_label), std::size_t(0));
  if(!known && (has_labels || first != 0))
    throw Invalid_input_error("initial_nearest_sources and first_source_label need initial_distances");
  if(first > static_cast<std::size_t>((std::numeric_limits<Index>::max)()) - seeds.size())
    throw Invalid_input_error("first_source_label is too large (" + std::to_string(first) + ")");
  for(Seed& s : seeds)
    s.label += static_cast<Index>(first);
  if(!known)
    return field;
  if(settings.limit < std::numeric_limits<double>::infinity() || settings.record_paths
     || !is_default_parameter<NamedParameters, internal_np::targets_t>::value)
    throw Invalid_input_error("a computation from initial distances takes no maximum_distance, targets nor "
                              "record_paths");
  settings.known_distances = true;
  if(settings.want_labels)
    read_known_labels(mesh, get_parameter(np, internal_np::initial_nearest_sources), field.labels);
  return field;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOLVER_KNOWN_FIELD_H
