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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOLVER_OUTPUT_MAPS_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOLVER_OUTPUT_MAPS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <chrono>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

namespace internal {

template <class Vertex>
void write_label_map(const std::vector<Vertex>&, const Propagation_engine&, CGAL::internal_np::Param_not_found)
{}

template <class Vertex, class VertexSourceMap>
void write_label_map(const std::vector<Vertex>& vertices, const Propagation_engine& engine, VertexSourceMap vsm)
{
  const std::vector<Index>& l = engine.labels();
  for(std::size_t i = 0; i < vertices.size(); ++i)
    put(vsm, vertices[i], l[i] == NO_INDEX ? no_source : static_cast<std::size_t>(l[i]));
}

// Writes the results of the last run of `engine` into the maps of the user: the distances into `vdm`, the
// labels into the named parameter nearest_source_map (if given), and `statistics` (with the time of this
// output) into the named parameter `statistics` (if given). `vertices` are the vertices in index order.
template <class Vertex, class VertexDistanceMap, class NamedParameters>
void write_output_maps(const std::vector<Vertex>& vertices, const Propagation_engine& engine, VertexDistanceMap vdm,
                       const NamedParameters& np, Propagation_statistics& statistics)
{
  using CGAL::parameters::get_parameter;
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<double>& d = engine.distances();
  for(std::size_t i = 0; i < vertices.size(); ++i)
    put(vdm, vertices[i], d[i]);
  write_label_map(vertices, engine, get_parameter(np, internal_np::nearest_source_map));
  statistics.output_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Propagation_statistics* st = CGAL::parameters::choose_parameter<Propagation_statistics*>(
    get_parameter(np, internal_np::statistics));
  if(st != nullptr)
    *st = statistics;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOLVER_OUTPUT_MAPS_H
