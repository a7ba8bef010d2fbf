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


#ifndef CGAL_VTP_GEODESICS_FARTHEST_POINT_SAMPLING_H
#define CGAL_VTP_GEODESICS_FARTHEST_POINT_SAMPLING_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Farthest_point_samples.h>
#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/geodesic_distances.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <cstddef>

namespace CGAL {
namespace VTP_geodesics {

/// \cond SKIP_IN_MANUAL
namespace internal {

template <class Samples, class Vertices>
void write_fps_map(const Samples&, const Vertices&, CGAL::internal_np::Param_not_found, bool)
{}

template <class Samples, class Vertices, class Map>
void write_fps_map(const Samples& r, const Vertices& vertices, Map map, bool labels)
{
  for(std::size_t i = 0; i < vertices.size(); ++i)
  {
    if(labels)
      put(map, vertices[i], r.labels[i]);
    else
      put(map, vertices[i], r.distances[i]);
  }
}

template <class Samples>
void write_radii(const Samples&, CGAL::internal_np::Param_not_found)
{}

template <class Samples, class OutputIterator>
void write_radii(const Samples& r, OutputIterator out)
{
  for(double d : r.radii)
    *out++ = d;
}

} // namespace internal
/// \endcond

/// \ingroup PkgVTPGeodesicsRef
/// Farthest-point sampling with exact geodesic distances: takes up to `k` vertices of `tm`, the first one
/// given (or the vertex farthest from the first vertex of `vertices(tm)`), then each time the vertex
/// farthest from the samples taken so far (ties: the first in the order of `vertices(tm)`), until `k`
/// samples or until every vertex is within `sampling_radius` of a sample. A vertex that no sample reaches
/// (another connected component, an isolated vertex) is at distance `+infinity`: it is the farthest, so
/// every component gets a sample before any component gets a second one.
///
/// Each new sample is added to the distance field of the samples before it by a computation from known
/// distances (named parameter `initial_distances` of `compute_geodesic_distances()`): its windows are
/// pruned against the distances already known, so that its work is that of the region it wins (its
/// geodesic Voronoi cell and the border around it), and the largest distance is kept in a heap updated
/// with the vertices that changed: `k` samples cost about `log k` full computations, not `k`, and no
/// step costs O(V). The samples, radii, distances and labels are those of a full computation from all
/// the samples so far at every step (to rounding: two vertices whose distances differ by about 1e-12 of
/// the largest distance may be taken in either order).
///
/// With `virtual_sources(true)` (one virtual source per vertex, VSP / PVSP), the distances are those of
/// virtual source propagation, each the length of a path from the sample of its label, so never below the
/// exact distance: each sample is then the vertex farthest by these distances. Each new sample's run takes
/// only the vertices it lowers and keeps the virtual sources of the others, so the field is not that of
/// a full VSP computation from all the samples (both are upper bounds); the same on any number of threads,
/// bit for bit. On the isotropic remeshing of camel (173K vertices), 1,000 samples: 0.90 s against 7.62 s
/// for VTP (`vtp_query_benchmark --fps 1000 --vsp`), the field 0.14% above the exact distances to its
/// samples on average, and the exact covering radius of its samples within 1% of that of the exact
/// sampling. With `virtual_sources_per_vertex(2)` (VSP2 / PVSP2), the same with two virtual sources per
/// vertex (a vertex that a new sample does not lower may still get a better second one, which it walks only
/// if a later sample lowers it).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (VTP, VSP) or `CGAL::Parallel_tag` (PVTP, PVSP, each
///   computation on `number_of_threads` threads).
/// \param tm the triangle mesh
/// \param k the number of samples wanted
/// \param samples an output iterator receiving the samples (`vertex_descriptor`), in order
/// \param np an optional sequence of named parameters among: `first_sample` (a `vertex_descriptor`; default
///   as above), `sampling_radius` (`double >= 0`: stop once the covering radius is at most this; default 0),
///   `covering_radii` (an output iterator receiving, as `double`, the covering radius after each sample: the
///   largest distance of a vertex to its nearest sample, non-increasing), `vertex_distance_map` (a
///   `WritablePropertyMap` receiving, per vertex, the distance to the nearest sample), `nearest_source_map`
///   (receiving the index of the nearest sample in the order taken, i.e. the geodesic Voronoi cell of the
///   vertex, `no_source` if none), `statistics` (summed over the computations), `lambda` and `lambda_g`
///   (approximate distances: AVTP / PAVTP, each still an upper bound), `virtual_sources` and
///   `virtual_sources_per_vertex` (VSP / PVSP, VSP2 / PVSP2, see above), `minimum_window_length`,
///   `number_of_threads`, `vertex_point_map` and `geom_traits`, as in `compute_geodesic_distances()`.
/// \returns the output iterator after the last sample.
/// \throws Invalid_input_error if `tm` is not a valid triangle mesh, `first_sample` is not one of its vertices,
/// or a parameter is invalid (`maximum_distance`, `targets`, `record_paths`, `keep_field` and `initial_distances` are not
/// taken).
template <class ConcurrencyTag = CGAL::Sequential_tag,
          class TriangleMesh,
          class OutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator farthest_point_sampling(const TriangleMesh& tm,
                                       std::size_t k,
                                       OutputIterator samples,
                                       const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  typename internal::Solver_for<TriangleMesh, NamedParameters>::type solver =
    internal::solver_for<ConcurrencyTag>(tm, np);
  const auto r = solver.template farthest_point_sampling<ConcurrencyTag>(k, np);
  for(const auto& v : r.samples)
    *samples++ = v;
  internal::write_radii(r, get_parameter(np, internal_np::covering_radii));
  internal::write_fps_map(r, solver.vertex_list(), get_parameter(np, internal_np::vertex_distance_map), false);
  internal::write_fps_map(r, solver.vertex_list(), get_parameter(np, internal_np::nearest_source_map), true);
  Propagation_statistics* st = choose_parameter<Propagation_statistics*>(get_parameter(np, internal_np::statistics));
  if(st != nullptr)
    *st = r.statistics;
  return samples;
}

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_FARTHEST_POINT_SAMPLING_H
