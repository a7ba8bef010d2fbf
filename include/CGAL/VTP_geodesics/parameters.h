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

#ifndef CGAL_VTP_GEODESICS_PARAMETERS_H
#define CGAL_VTP_GEODESICS_PARAMETERS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <limits>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// The reset period `lambda` we recommend for the approximate variants (AVTP / PAVTP), used by the
/// command-line tools when none is given: on our benchmark meshes it keeps the mean relative error
/// around 0.1% (see the benchmark section of the user manual).
constexpr double recommended_lambda = 8.;

/// \ingroup PkgVTPGeodesicsRef
/// The value that a nearest-source map (named parameter `nearest_source_map`) receives for a vertex that
/// no source reaches (or that lies beyond the distance limit, or whose distance is not final after a
/// run stopped at its targets).
constexpr std::size_t no_source = (std::numeric_limits<std::size_t>::max)();

/// \cond SKIP_IN_MANUAL
namespace internal_np {

enum lambda_t { lambda };
enum lambda_g_t { lambda_g };
enum number_of_threads_t { number_of_threads };
enum minimum_window_length_t { minimum_window_length };
enum nearest_source_map_t { nearest_source_map };
enum statistics_t { statistics };
enum maximum_distance_t { maximum_distance };
enum targets_t { targets };
enum stop_at_targets_t { stop_at_targets };
enum record_paths_t { record_paths };
enum virtual_sources_t { virtual_sources };
enum virtual_sources_per_vertex_t { virtual_sources_per_vertex };
enum initial_distances_t { initial_distances };
enum initial_nearest_sources_t { initial_nearest_sources };
enum first_source_label_t { first_source_label };
enum first_sample_t { first_sample };
enum sampling_radius_t { sampling_radius };
enum covering_radii_t { covering_radii };
enum vertex_distance_map_t { vertex_distance_map };

} // namespace internal_np

// CGAL's named parameters are registered centrally: a package outside CGAL cannot add names that chain
// after CGAL's own (`CGAL::parameters::vertex_point_map(vpm).lambda(8)` cannot exist). This class is a
// CGAL named-parameter chain (it derives from `CGAL::Named_function_parameters`, so CGAL's
// `get_parameter()` reads it) whose links can be the names of this package or the CGAL names it uses; a
// chain starts with a function of `CGAL::VTP_geodesics::parameters`.
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_parameters
  : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_parameters;
  typedef Named_parameters<T, Tag, Base> self;

  Named_parameters(const T& v) : Cgal_parameters(v) {}
  Named_parameters(const T& v, const Base& b) : Cgal_parameters(v, b) {}

#define CGAL_VTP_GEODESICS_LINK(NAME, TAG_TYPE)                            \
  template <class K>                                                      \
  Named_parameters<K, TAG_TYPE, self> NAME(const K& k) const              \
  {                                                                       \
    return Named_parameters<K, TAG_TYPE, self>(k, *this);                 \
  }
  CGAL_VTP_GEODESICS_LINK(lambda, internal_np::lambda_t)
  CGAL_VTP_GEODESICS_LINK(lambda_g, internal_np::lambda_g_t)
  CGAL_VTP_GEODESICS_LINK(number_of_threads, internal_np::number_of_threads_t)
  CGAL_VTP_GEODESICS_LINK(minimum_window_length, internal_np::minimum_window_length_t)
  CGAL_VTP_GEODESICS_LINK(nearest_source_map, internal_np::nearest_source_map_t)
  CGAL_VTP_GEODESICS_LINK(maximum_distance, internal_np::maximum_distance_t)
  CGAL_VTP_GEODESICS_LINK(targets, internal_np::targets_t)
  CGAL_VTP_GEODESICS_LINK(stop_at_targets, internal_np::stop_at_targets_t)
  CGAL_VTP_GEODESICS_LINK(record_paths, internal_np::record_paths_t)
  CGAL_VTP_GEODESICS_LINK(virtual_sources, internal_np::virtual_sources_t)
  CGAL_VTP_GEODESICS_LINK(virtual_sources_per_vertex, internal_np::virtual_sources_per_vertex_t)
  CGAL_VTP_GEODESICS_LINK(initial_distances, internal_np::initial_distances_t)
  CGAL_VTP_GEODESICS_LINK(initial_nearest_sources, internal_np::initial_nearest_sources_t)
  CGAL_VTP_GEODESICS_LINK(first_source_label, internal_np::first_source_label_t)
  CGAL_VTP_GEODESICS_LINK(first_sample, internal_np::first_sample_t)
  CGAL_VTP_GEODESICS_LINK(sampling_radius, internal_np::sampling_radius_t)
  CGAL_VTP_GEODESICS_LINK(covering_radii, internal_np::covering_radii_t)
  CGAL_VTP_GEODESICS_LINK(vertex_distance_map, internal_np::vertex_distance_map_t)
  CGAL_VTP_GEODESICS_LINK(vertex_point_map, CGAL::internal_np::vertex_point_t)
  CGAL_VTP_GEODESICS_LINK(geom_traits, CGAL::internal_np::geom_traits_t)
#undef CGAL_VTP_GEODESICS_LINK

  Named_parameters<Propagation_statistics*, internal_np::statistics_t, self>
  statistics(Propagation_statistics& s) const
  {
    return Named_parameters<Propagation_statistics*, internal_np::statistics_t, self>(&s, *this);
  }
};
/// \endcond

/// \ingroup PkgVTPGeodesicsRef
/// The named parameters of this package. A chain starts with one of these functions and goes on with
/// member functions of the same names, e.g.
/// `CGAL::VTP_geodesics::parameters::lambda(8).number_of_threads(4).nearest_source_map(labels)`;
/// it may contain `vertex_point_map` and `geom_traits` too. Functions that take named parameters also
/// take CGAL's own chains (`CGAL::parameters::vertex_point_map(vpm)`).
namespace parameters {

/// \cond SKIP_IN_MANUAL
#define CGAL_VTP_GEODESICS_FIRST_LINK(NAME, TAG_TYPE)                      \
  template <class K>                                                      \
  Named_parameters<K, TAG_TYPE> NAME(const K& k)                          \
  {                                                                       \
    return Named_parameters<K, TAG_TYPE>(k);                              \
  }
CGAL_VTP_GEODESICS_FIRST_LINK(lambda, internal_np::lambda_t)
CGAL_VTP_GEODESICS_FIRST_LINK(lambda_g, internal_np::lambda_g_t)
CGAL_VTP_GEODESICS_FIRST_LINK(number_of_threads, internal_np::number_of_threads_t)
CGAL_VTP_GEODESICS_FIRST_LINK(minimum_window_length, internal_np::minimum_window_length_t)
CGAL_VTP_GEODESICS_FIRST_LINK(nearest_source_map, internal_np::nearest_source_map_t)
CGAL_VTP_GEODESICS_FIRST_LINK(maximum_distance, internal_np::maximum_distance_t)
CGAL_VTP_GEODESICS_FIRST_LINK(targets, internal_np::targets_t)
CGAL_VTP_GEODESICS_FIRST_LINK(stop_at_targets, internal_np::stop_at_targets_t)
CGAL_VTP_GEODESICS_FIRST_LINK(record_paths, internal_np::record_paths_t)
CGAL_VTP_GEODESICS_FIRST_LINK(virtual_sources, internal_np::virtual_sources_t)
CGAL_VTP_GEODESICS_FIRST_LINK(virtual_sources_per_vertex, internal_np::virtual_sources_per_vertex_t)
CGAL_VTP_GEODESICS_FIRST_LINK(initial_distances, internal_np::initial_distances_t)
CGAL_VTP_GEODESICS_FIRST_LINK(initial_nearest_sources, internal_np::initial_nearest_sources_t)
CGAL_VTP_GEODESICS_FIRST_LINK(first_source_label, internal_np::first_source_label_t)
CGAL_VTP_GEODESICS_FIRST_LINK(first_sample, internal_np::first_sample_t)
CGAL_VTP_GEODESICS_FIRST_LINK(sampling_radius, internal_np::sampling_radius_t)
CGAL_VTP_GEODESICS_FIRST_LINK(covering_radii, internal_np::covering_radii_t)
CGAL_VTP_GEODESICS_FIRST_LINK(vertex_distance_map, internal_np::vertex_distance_map_t)
CGAL_VTP_GEODESICS_FIRST_LINK(vertex_point_map, CGAL::internal_np::vertex_point_t)
CGAL_VTP_GEODESICS_FIRST_LINK(geom_traits, CGAL::internal_np::geom_traits_t)
#undef CGAL_VTP_GEODESICS_FIRST_LINK

inline Named_parameters<Propagation_statistics*, internal_np::statistics_t>
statistics(Propagation_statistics& s)
{
  return Named_parameters<Propagation_statistics*, internal_np::statistics_t>(&s);
}

using CGAL::parameters::default_values;
/// \endcond

} // namespace parameters

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_PARAMETERS_H
