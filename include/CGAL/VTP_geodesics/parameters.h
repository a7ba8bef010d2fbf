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

struct Geodesic_curves_report;  // geodesic_curves.h

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
// The names of the named parameters of this package, listed once: X(NAME) for each, whose tag is
// internal_np::NAME_t (but the extra results, `statistics` and `curves_report`, whose links take a reference to
// the caller's object and keep a pointer to it: see below).
#define CGAL_VTP_GEODESICS_FOR_EACH_NAMED_PARAMETER(X)                                                   \
  X(lambda) X(lambda_g) X(number_of_threads) X(minimum_window_length) X(nearest_source_map)              \
  X(maximum_distance) X(targets) X(stop_at_targets) X(record_paths) X(virtual_sources)                   \
  X(virtual_sources_per_vertex) X(initial_distances) X(initial_nearest_sources) X(first_source_label)    \
  X(first_sample) X(sampling_radius) X(covering_radii) X(vertex_distance_map) X(log_map) X(log_map_via)      \
  X(log_map_strict) X(reference_direction) X(chord_tolerance) X(exact_refinement) \
  X(keep_field) X(signed_distance)

// The extra results: X(NAME, TYPE), a link NAME(TYPE& r) that keeps &r (the function writes into r). Every
// result besides the main one (the return value or the output map) comes back this way.
#define CGAL_VTP_GEODESICS_FOR_EACH_RESULT_PARAMETER(X)                                                  \
  X(statistics, Propagation_statistics) X(curves_report, Geodesic_curves_report)

// The names of CGAL's named parameters that a chain of this package can hold: X(NAME, TAG_TYPE).
#define CGAL_VTP_GEODESICS_FOR_EACH_CGAL_NAMED_PARAMETER(X)                                              \
  X(vertex_point_map, CGAL::internal_np::vertex_point_t) X(geom_traits, CGAL::internal_np::geom_traits_t)

namespace internal_np {

#define CGAL_VTP_GEODESICS_TAG(NAME) enum NAME##_t { NAME };
CGAL_VTP_GEODESICS_FOR_EACH_NAMED_PARAMETER(CGAL_VTP_GEODESICS_TAG)
#undef CGAL_VTP_GEODESICS_TAG
#define CGAL_VTP_GEODESICS_RESULT_TAG(NAME, TYPE) enum NAME##_t { NAME };
CGAL_VTP_GEODESICS_FOR_EACH_RESULT_PARAMETER(CGAL_VTP_GEODESICS_RESULT_TAG)
#undef CGAL_VTP_GEODESICS_RESULT_TAG

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
#define CGAL_VTP_GEODESICS_PACKAGE_LINK(NAME) CGAL_VTP_GEODESICS_LINK(NAME, internal_np::NAME##_t)
  CGAL_VTP_GEODESICS_FOR_EACH_NAMED_PARAMETER(CGAL_VTP_GEODESICS_PACKAGE_LINK)
  CGAL_VTP_GEODESICS_FOR_EACH_CGAL_NAMED_PARAMETER(CGAL_VTP_GEODESICS_LINK)
#define CGAL_VTP_GEODESICS_RESULT_LINK(NAME, TYPE)                                \
  Named_parameters<TYPE*, internal_np::NAME##_t, self> NAME(TYPE& r) const         \
  {                                                                                \
    return Named_parameters<TYPE*, internal_np::NAME##_t, self>(&r, *this);        \
  }
  CGAL_VTP_GEODESICS_FOR_EACH_RESULT_PARAMETER(CGAL_VTP_GEODESICS_RESULT_LINK)
#undef CGAL_VTP_GEODESICS_RESULT_LINK
#undef CGAL_VTP_GEODESICS_PACKAGE_LINK
#undef CGAL_VTP_GEODESICS_LINK
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
#define CGAL_VTP_GEODESICS_PACKAGE_FIRST_LINK(NAME) CGAL_VTP_GEODESICS_FIRST_LINK(NAME, internal_np::NAME##_t)
CGAL_VTP_GEODESICS_FOR_EACH_NAMED_PARAMETER(CGAL_VTP_GEODESICS_PACKAGE_FIRST_LINK)
CGAL_VTP_GEODESICS_FOR_EACH_CGAL_NAMED_PARAMETER(CGAL_VTP_GEODESICS_FIRST_LINK)
#undef CGAL_VTP_GEODESICS_PACKAGE_FIRST_LINK
#undef CGAL_VTP_GEODESICS_FIRST_LINK

#define CGAL_VTP_GEODESICS_FIRST_RESULT_LINK(NAME, TYPE)                           \
  inline Named_parameters<TYPE*, internal_np::NAME##_t> NAME(TYPE& r)              \
  {                                                                                \
    return Named_parameters<TYPE*, internal_np::NAME##_t>(&r);                     \
  }
CGAL_VTP_GEODESICS_FOR_EACH_RESULT_PARAMETER(CGAL_VTP_GEODESICS_FIRST_RESULT_LINK)
#undef CGAL_VTP_GEODESICS_FIRST_RESULT_LINK

using CGAL::parameters::default_values;

#undef CGAL_VTP_GEODESICS_FOR_EACH_NAMED_PARAMETER
#undef CGAL_VTP_GEODESICS_FOR_EACH_CGAL_NAMED_PARAMETER
#undef CGAL_VTP_GEODESICS_FOR_EACH_RESULT_PARAMETER
/// \endcond

} // namespace parameters

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_PARAMETERS_H
