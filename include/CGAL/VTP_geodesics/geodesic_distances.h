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

#ifndef CGAL_VTP_GEODESICS_GEODESIC_DISTANCES_H
#define CGAL_VTP_GEODESICS_GEODESIC_DISTANCES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// computes the geodesic distance from `source` to every vertex of `tm` and writes it into `vdm`;
/// unreachable vertices get `+infinity`. For many sources on the same mesh, build one
/// `Geodesic_distance_solver` and call its `compute()` instead: the per-mesh preprocessing is then done once.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (VTP / AVTP) or `CGAL::Parallel_tag` (PVTP / PAVTP).
/// \tparam TriangleMesh a triangulated surface mesh, model of `FaceListGraph` and `HalfedgeListGraph`.
/// \tparam VertexDistanceMap a `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///   as key type and `double` as value type.
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param tm the triangle mesh
/// \param vdm the output distance map
/// \param source the source vertex
/// \param options see `Propagation_options`; the defaults give the exact result
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `VTPGeodesicTraits_3`}
///     \cgalParamDefault{a \cgal kernel deduced from the point type, wrapped in `Geodesic_traits_3`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the statistics of the propagation.
/// \throws Invalid_input_error on invalid input (not a triangle mesh, source not a vertex of `tm`, invalid options).
template <class ConcurrencyTag = CGAL::Sequential_tag,
          class TriangleMesh,
          class VertexDistanceMap,
          class NamedParameters = parameters::Default_named_parameters>
Propagation_statistics
compute_geodesic_distances(const TriangleMesh& tm,
                           VertexDistanceMap vdm,
                           typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
                           const Propagation_options& options = Propagation_options(),
                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;

  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef typename internal_np::Lookup_named_param_def<internal_np::geom_traits_t, NamedParameters,
                                                       Geodesic_traits_3<Kernel> >::type GT;

  VPM vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                             get_const_property_map(CGAL::vertex_point, tm));
  GT gt = choose_parameter<GT>(get_parameter(np, internal_np::geom_traits));

  Geodesic_distance_solver<TriangleMesh, GT, VPM> solver(tm, vpm, gt);
  return solver.template compute<ConcurrencyTag>(source, vdm, options);
}

} // namespace VTP_geodesics
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_VTP_GEODESICS_GEODESIC_DISTANCES_H
