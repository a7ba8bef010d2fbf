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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOLVER_SOLVER_RUN_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOLVER_SOLVER_RUN_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/solver/Known_field.h>
#include <CGAL/VTP_geodesics/internal/log_map/Log_map_output.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_queries.h>
#include <CGAL/VTP_geodesics/internal/solver/Settings_from_parameters.h>
#include <CGAL/VTP_geodesics/internal/source_curves/Curve_seeds.h>
#include <CGAL/VTP_geodesics/internal/source_curves/Curve_sign.h>

#include <CGAL/Named_function_parameters.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// One computation of Geodesic_distance_solver::compute() from `seeds` on the solver's mesh (Mesh_index `mesh`):
// the settings of `np`, the known field, the log map's frames and the targets; the engine's run; the distances
// in the order of vertices(tm) into `distances`; the parameters that path queries need.
template <class ConcurrencyTag, class MeshIndex, class VertexPointMap, class NamedParameters>
void run_solver(const MeshIndex& mesh, VertexPointMap vpm, std::vector<Seed> seeds, const NamedParameters& np,
                Propagation_engine& engine, std::vector<double>& distances, Path_queries& paths,
                Propagation_statistics& statistics)
{
  if(seeds.empty())
    throw Invalid_input_error("no source");
  int threads = 0;
  Propagation_settings settings = settings_from_parameters(np, mesh, threads);
  Known_field known = known_field_of(np, mesh, mesh.length_scale, settings, seeds);
  if(settings.keep_field && settings.known_distances)
    throw Invalid_input_error("keep_field cannot start from initial distances (the field of the known region is "
                              "not known)");
  const bool curves = has_segments(seeds);
  const bool sign = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::signed_distance),
                                                       false);
  const bool log_map = !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::log_map_t>::value
                       || !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::log_map_via_t>::value;
  if(curves && (settings.virtual_sources || log_map || settings.known_distances))
    throw Invalid_input_error("sources that are curves need windows (not virtual sources), and give no log map and "
                              "no start from initial distances");
  if(sign && !curves)
    throw Invalid_input_error("signed_distance needs a source that is a curve");
  start_log_map(np, settings, mesh, vpm, seeds, engine.direction());
  std::vector<Target> targets = mesh.targets_of(CGAL::parameters::get_parameter(np, internal_np::targets));
  if(sign)
    for(const Target& t : targets)
      if(t.vertex == NO_INDEX)
        throw Invalid_input_error("signed_distance: the targets must be vertices (a target inside a face or an edge "
                                  "is not signed)");
  // signed: each seed is its own label during the run (the side of each vertex's nearest point), then the
  // user's labels again
  std::vector<Index> user_labels;
  if(sign)
  {
    for(std::size_t i = 0; i < seeds.size(); ++i)
    {
      user_labels.push_back(seeds[i].label);
      seeds[i].label = static_cast<Index>(i);
    }
    settings.want_labels = true;
  }
  engine.template run<ConcurrencyTag>(mesh.arrays, seeds, std::move(targets), settings, threads, statistics,
                                      std::move(known));
  if(sign)
  {
    sign_distances(mesh.arrays, seeds, engine.labels(), every_curve_closed(seeds), engine.distances(), mesh.position);
    for(Index& l : engine.labels_to_rewrite())
      if(l != NO_INDEX)
        l = user_labels[static_cast<std::size_t>(l)];
  }
  mesh.to_positions(engine.distances(), distances);
  paths.remember(settings, is_parallel<ConcurrencyTag>(), threads);
  statistics.sources = seeds.size();
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOLVER_SOLVER_RUN_H
