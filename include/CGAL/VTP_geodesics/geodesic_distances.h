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
#include <CGAL/VTP_geodesics/parameters.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

namespace CGAL {
namespace VTP_geodesics {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The solver that the free functions build for `tm` with the named parameters `np`: the vertex point map and
// the traits of `np`; with CGAL::Parallel_tag, the preprocessing on the threads of the computation.
template <class TriangleMesh, class NamedParameters>
struct Solver_for
{
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters,
                                                             Geodesic_traits_3<Kernel> >::type GT;
  typedef Geodesic_distance_solver<TriangleMesh, GT, VPM> type;
};

template <class ConcurrencyTag, class TriangleMesh, class NamedParameters>
typename Solver_for<TriangleMesh, NamedParameters>::type solver_for(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Solver_for<TriangleMesh, NamedParameters> S;
  const typename S::VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                               get_const_property_map(CGAL::vertex_point, tm));
  const typename S::GT gt = choose_parameter<typename S::GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const int threads = is_parallel<ConcurrencyTag>()
                        ? choose_parameter(get_parameter(np, internal_np::number_of_threads), default_number_of_threads)
                        : 1;
  return typename S::type(tm, parameters::vertex_point_map(vpm).geom_traits(gt).number_of_threads(threads));
}

} // namespace internal
/// \endcond

/// \ingroup PkgVTPGeodesicsRef
/// computes the geodesic distance from `sources` to every vertex of `tm` and writes it into `vdm`: the
/// distance of a vertex is its distance to the nearest source; unreachable vertices get `+infinity`.
/// For many computations on the same mesh, build one `Geodesic_distance_solver` and call its `compute()`
/// instead: the per-mesh preprocessing is then done once.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (VTP / AVTP) or `CGAL::Parallel_tag` (PVTP / PAVTP, needs
///   OpenMP; see the user manual).
/// \tparam TriangleMesh a triangulated surface mesh, model of `FaceListGraph` and `HalfedgeListGraph`.
/// \tparam VertexDistanceMap a `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///   as key type and `double` as value type.
/// \tparam SourceOrRange a `vertex_descriptor`, a face location
///   (`CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, FT>`, i.e.
///   `std::pair<face_descriptor, std::array<FT, 3> >`), or a range of either.
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param tm the triangle mesh
/// \param vdm the output distance map
/// \param sources the source(s); a point of an edge or a vertex given as a face location gives the same
///   result as that edge point or vertex, whichever face it is expressed in
/// \param np an optional sequence of named parameters among the ones listed below: CGAL's
///   (`CGAL::parameters::vertex_point_map(vpm)`) or this package's
///   (`CGAL::VTP_geodesics::parameters::lambda(8).number_of_threads(4)`)
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
///   \cgalParamNBegin{lambda}
///     \cgalParamDescription{the window-reset period of the approximate variants (AVTP / PAVTP), in multiples
///       of the mean edge length `h`; `recommended_lambda` is a good start}
///     \cgalParamType{`double`, `> 0`}
///     \cgalParamDefault{`+infinity`: windows are never reset, the result is exact}
///   \cgalParamNEnd
///   \cgalParamNBegin{lambda_g}
///     \cgalParamDescription{the guard band of the approximate variants, in multiples of `h`: at a reset, the
///       windows next to wavefront vertices farther than `(R+1) lambda h + lambda_g h` are kept}
///     \cgalParamType{`double`, finite and `>= 0`}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{the number of threads of the parallel scheduling and of the per-mesh
///       preprocessing; ignored with `CGAL::Sequential_tag` (one thread). `0` means OpenMP's default
///       (`omp_get_max_threads()`: `OMP_NUM_THREADS`, else the number of processors). The constructor of
///       `Geodesic_distance_solver` takes this parameter too, for its preprocessing alone, with the
///       default `1` there}
///     \cgalParamType{`int`, `>= 0`}
///     \cgalParamDefault{`0`: OpenMP's default}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_window_length}
///     \cgalParamDescription{windows shorter than this times the length of their edge are dropped; they
///       change distances by a second-order amount (below `1e-18` relative for the default)}
///     \cgalParamType{`double`, in `[0, 1)`}
///     \cgalParamDefault{`1e-9`}
///   \cgalParamNEnd
///   \cgalParamNBegin{nearest_source_map}
///     \cgalParamDescription{a property map receiving, for each vertex, the index in `sources` of a nearest
///       source (one of them, when several are at the same distance), or `no_source` for an unreachable
///       vertex}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///       `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{virtual_sources}
///     \cgalParamDescription{if `true`, one virtual source per vertex (VSP) instead of window lists: an
///       approximation, much faster than the exact algorithm, whose every distance is the length of a path on
///       the surface (never below the exact distance; mean relative error about 0.2-0.4% on our benchmark
///       meshes). `lambda` is then ignored; `CGAL::Parallel_tag` runs its rounds on several threads, with the same
///       distances bit for bit. See
///       \ref VTPGeodesicsVirtualSources.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{virtual_sources_per_vertex}
///     \cgalParamDescription{with `virtual_sources(true)`: 1, or 2 to keep per vertex a second virtual source
///       (the best offer of another root than the first's) and propagate both: about half the mean error, for
///       1.3-2 times the time and 64 more bytes per vertex; still an upper bound, and the same distances on
///       any number of threads. See \ref VTPGeodesicsVirtualSources. Any other value throws
///       `Invalid_input_error`.}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives the statistics of the propagation}
///     \cgalParamType{`Propagation_statistics&`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_distance}
///     \cgalParamDescription{a distance limit `R`: every vertex whose computed distance is `<= R` (`R`
///       included) gets it, exactly as without a limit; every other vertex gets `+infinity` (and `no_source`
///       in `nearest_source_map`), as if unreachable. The propagation stops once no distance `<= R` can
///       change, so its work is that of the region within `R`. A vertex at exactly `R` is inside; one whose
///       true distance is `R` may be computed one rounding error above or below it. With `virtual_sources(true)`
///       the order of the propagation is not monotone: the distances within `R` are never below the exact ones,
///       and those of a run without a limit on all but rare meshes of very stretched triangles, where some
///       may differ (see \ref VTPGeodesicsVirtualSources)}
///     \cgalParamType{`double`, `>= 0` (`+infinity`: no limit)}
///     \cgalParamDefault{`+infinity`}
///   \cgalParamNEnd
///   \cgalParamNBegin{targets}
///     \cgalParamDescription{points whose distance is wanted: with `stop_at_targets` (the default) the
///       propagation stops as soon as the distance of every target is final. Their distances are read
///       with `Geodesic_distance_solver::target_distance()` (exact, or `+infinity` if unreachable or beyond
///       `maximum_distance`); with the free function, use a solver. After a run stopped at its targets,
///       each other vertex has its exact distance if it was already final at the stop (every vertex
///       nearer to the sources than the farthest target is), else `+infinity` (and `no_source`)}
///     \cgalParamType{a `vertex_descriptor`, a face location (`std::pair<face_descriptor, std::array<FT, 3> >`),
///       or a range of either}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{stop_at_targets}
///     \cgalParamDescription{whether the propagation stops once the targets are final (`false`: it runs to
///       the end, or to `maximum_distance`, and every vertex gets its distance)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{record_paths}
///     \cgalParamDescription{whether the computation keeps what the geodesic paths of
///       `Geodesic_distance_solver::shortest_path_points()` need, for every vertex and target (O(V + targets)
///       memory, never the windows); without it a path request runs the propagation again}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{log_map}
///     \cgalParamDescription{the log map (geodesic polar coordinates): each vertex receives
///       `{rho cos(theta), rho sin(theta)}`, rho its distance, theta the direction in which its geodesic leaves its
///       nearest source, in the tangent frame of that source (counter-clockwise seen from the side the faces'
///       normals point to; at a vertex source from the edge to `source(halfedge(c))` (at a border vertex, the
///       border edge with the surface counter-clockwise of it), the angles scaled by 2 pi (pi at the border) /
///       the sum of the corner angles; at a face location from `halfedge(f)`); behind a saddle or border vertex s
///       the coordinates go on from those of s, the line turned at s by the rule of straightest geodesics (see
///       `log_map_strict`); `{+infinity, +infinity}` where unreached. Exact methods only (VTP, PVTP):
///       `Invalid_input_error` with `lambda` or `virtual_sources`}
///     \cgalParamType{a class model of `WritablePropertyMap` with `vertex_descriptor` as key type and
///       `std::array<double, 2>` as value type}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{log_map_via}
///     \cgalParamDescription{with the log map: the last vertex each vertex's geodesic passes through (where it
///       turns, a saddle or border vertex), or a default-constructed `vertex_descriptor` (none)}
///     \cgalParamType{a class model of `WritablePropertyMap` with `vertex_descriptor` as key and value type}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{log_map_strict}
///     \cgalParamDescription{with the log map: the strict polyhedral theta (a vertex behind a saddle or border
///       vertex s gets the theta of s) instead of the coordinates continued from s}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{reference_direction}
///     \cgalParamDescription{with the log map: a 3D direction, projected onto the tangent plane of each source
///       (the face's plane; at a vertex, the plane orthogonal to the angle-weighted normal), whose theta is
///       subtracted; `Invalid_input_error` if it is zero, not finite or orthogonal to the tangent plane}
///     \cgalParamType{`std::array<double, 3>` or a \cgal `Vector_3`}
///     \cgalParamDefault{none: the reference edges above}
///   \cgalParamNEnd
///   \cgalParamNBegin{initial_distances}
///     \cgalParamDescription{distances already known (for example those of earlier sources): the computation
///       adds `sources` to that field. Every vertex gets the minimum of its initial distance and of its
///       distance from `sources` (exact for the exact methods, to rounding: 1e-12 of the largest distance),
///       and its label is that of the nearer of the two. Each initial distance must be an upper bound
///       realised by a path on the surface (the distance of the vertex from some earlier sources, as computed
///       by this package, is); `+infinity` for none. A window of the new sources that cannot beat the
///       initial distances at the corners of the triangle it enters is pruned, so the work is that of the
///       region where `sources` win: a run whose sources win nothing does almost no work (see the
///       statistics), besides reading and writing the maps (O(V)). The map may be `vdm` itself. Not with
///       `maximum_distance`, `targets` or `record_paths`; no geodesic path can be asked for after such a run}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `vertex_descriptor` as key type and `double`
///       as value type, every value `>= 0`}
///     \cgalParamDefault{none: every vertex starts at `+infinity`}
///   \cgalParamNEnd
///   \cgalParamNBegin{initial_nearest_sources}
///     \cgalParamDescription{the labels of the initial distances (read when `nearest_source_map` is given;
///       without it, vertices that keep their initial distance get `no_source`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `vertex_descriptor` as key type and
///       `std::size_t` as value type (`no_source` for none)}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{first_source_label}
///     \cgalParamDescription{the label of the first of `sources` in `nearest_source_map`, the others
///       following (with `initial_distances`: number the new sources after the earlier ones)}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `tm` is not modified during the call.
///
/// \throws Invalid_input_error on invalid input, with a message that names what is wrong: not a triangle
/// mesh (face `N` is not a triangle), a non-finite coordinate (of vertex `N`), source `N` (its position in
/// `sources`) or target `N` that is not a vertex or a point of `tm`, an empty range of sources, an invalid
/// parameter (with its value). Vertices and faces are numbered in the order of `vertices(tm)` and
/// `faces(tm)`.
template <class ConcurrencyTag = CGAL::Sequential_tag,
          class TriangleMesh,
          class VertexDistanceMap,
          class SourceOrRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void compute_geodesic_distances(const TriangleMesh& tm,
                                VertexDistanceMap vdm,
                                const SourceOrRange& sources,
                                const NamedParameters& np = parameters::default_values())
{
  typename internal::Solver_for<TriangleMesh, NamedParameters>::type solver =
    internal::solver_for<ConcurrencyTag>(tm, np);
  solver.template compute<ConcurrencyTag>(vdm, sources, np);
}

} // namespace VTP_geodesics
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_VTP_GEODESICS_GEODESIC_DISTANCES_H
