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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOLVER_SETTINGS_FROM_PARAMETERS_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOLVER_SETTINGS_FROM_PARAMETERS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/propagation/Propagation_state.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The defaults of the named parameters of a computation (the manual lists them with
// compute_geodesic_distances()). The constructor of the solver has its own default for
// number_of_threads: 1 (its preprocessing is short; a solver built on one thread stays cheap to build
// next to others), see Geodesic_distance_solver.
constexpr double default_lambda_g = 1.;
constexpr double default_minimum_window_length = 1e-9;
constexpr int default_number_of_threads = 0;  // OpenMP's default, see number_of_threads()
constexpr int default_preprocessing_threads = 1;  // of the constructor of the solver

// The settings of a propagation from the named parameters `np` (validated), on a mesh of mean edge
// length `mean_edge_length` in the engine's unit, `length_scale` (the engine's unit in the unit of the
// mesh); the number of threads asked for goes to `threads`.
template <class NamedParameters>
Propagation_settings settings_from_parameters(const NamedParameters& np, double mean_edge_length,
                                              double length_scale, int& threads)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  const double lambda = choose_parameter(get_parameter(np, internal_np::lambda),
                                         std::numeric_limits<double>::infinity());
  const double lambda_g = choose_parameter(get_parameter(np, internal_np::lambda_g), default_lambda_g);
  threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), default_number_of_threads);
  const double min_length = choose_parameter(get_parameter(np, internal_np::minimum_window_length),
                                             default_minimum_window_length);
  const double limit = choose_parameter(get_parameter(np, internal_np::maximum_distance),
                                        std::numeric_limits<double>::infinity());
  if(!(lambda > 0.))
    throw Invalid_input_error("lambda must be > 0 (infinity for the exact algorithm), got " + std::to_string(lambda));
  if(!(lambda_g >= 0.) || std::isinf(lambda_g))
    throw Invalid_input_error("lambda_g must be finite and >= 0, got " + std::to_string(lambda_g));
  if(threads < 0)
    throw Invalid_input_error("the number of threads must be >= 0, got " + std::to_string(threads));
  if(!(min_length >= 0.) || !(min_length < 1.))
    throw Invalid_input_error("minimum_window_length must be in [0, 1)");
  const int per_vertex = choose_parameter(get_parameter(np, internal_np::virtual_sources_per_vertex), 1);
  if(per_vertex != 1 && per_vertex != 2)
    throw Invalid_input_error("virtual_sources_per_vertex must be 1 or 2, got " + std::to_string(per_vertex));
  if(!(limit >= 0.))
    throw Invalid_input_error("the maximum distance must be >= 0 (+infinity for none), got " + std::to_string(limit));

  Propagation_settings settings;
  settings.minimum_window_ratio = min_length;
  const double h = mean_edge_length;
  if(lambda < std::numeric_limits<double>::infinity() && h > 0.)
    settings.reset_step = lambda * h;
  settings.reset_guard = lambda_g * h;
  settings.want_labels = !is_default_parameter<NamedParameters, internal_np::nearest_source_map_t>::value;
  settings.limit = limit / length_scale;
  settings.stop_at_targets = choose_parameter(get_parameter(np, internal_np::stop_at_targets), true);
  settings.record_paths = choose_parameter(get_parameter(np, internal_np::record_paths), false);
  settings.unit = length_scale;
  settings.virtual_sources = choose_parameter(get_parameter(np, internal_np::virtual_sources), false);
  // the kept field (field/Kept_field.h): every window crossing a face; exact methods only
  settings.keep_field = choose_parameter(get_parameter(np, internal_np::keep_field), false);
  if(settings.keep_field)
  {
    if(settings.virtual_sources || settings.reset_step < std::numeric_limits<double>::infinity())
      throw Invalid_input_error("keep_field needs an exact method (VTP or PVTP: lambda = infinity, no virtual "
                                "sources)");
    settings.want_labels = true;  // (the field of the faces needs the corners' labels, not their paths)
  }
  settings.second_virtual_source = settings.virtual_sources && per_vertex == 2;
  return settings;
}

// The same for the mesh of a solver (its Mesh_index: the engine's arrays and unit).
template <class NamedParameters, class MeshIndex>
Propagation_settings settings_from_parameters(const NamedParameters& np, const MeshIndex& mesh, int& threads)
{
  return settings_from_parameters(np, mesh.arrays.mean_edge_length, mesh.length_scale, threads);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOLVER_SETTINGS_FROM_PARAMETERS_H
