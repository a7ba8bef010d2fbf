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

#ifndef CGAL_VTP_GEODESICS_GEODESIC_DISTANCE_SOLVER_H
#define CGAL_VTP_GEODESICS_GEODESIC_DISTANCE_SOLVER_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Farthest_point_samples.h>
#include <CGAL/VTP_geodesics/Geodesic_traits_3.h>
#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Polar_patches.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/Surface_polyline.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/field/Field_queries.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/log_map/Log_map_output.h>
#include <CGAL/VTP_geodesics/internal/solver/Many_sources.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_import.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_index.h>
#include <CGAL/VTP_geodesics/internal/solver/Output_maps.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_queries.h>
#include <CGAL/VTP_geodesics/internal/log_map/Polar_patch_rows.h>
#include <CGAL/VTP_geodesics/internal/solver/Settings_from_parameters.h>
#include <CGAL/VTP_geodesics/internal/solver/Solver_run.h>
#include <CGAL/VTP_geodesics/internal/source_curves/Curve_join.h>
#include <CGAL/VTP_geodesics/internal/straightest/Straightest_queries.h>
#include <CGAL/VTP_geodesics/internal/sampling/Farthest_point_sampler.h>
#include <CGAL/VTP_geodesics/internal/mesh/Source_forms.h>

#include <CGAL/disable_warnings.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Default.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// \brief computes exact (or, on request, approximate) geodesic distances from sources to all vertices of
/// a triangle mesh by vertex-oriented triangle propagation (VTP).
///
/// A source is a vertex, or a point of the surface given as a face location (a face and three barycentric
/// coordinates, as `CGAL::Polygon_mesh_processing::Face_location` and `CGAL::Surface_mesh_shortest_path`
/// take it); there can be any number of sources, and the distance of a vertex is its distance to the
/// nearest one.
///
/// The per-mesh preprocessing (compact half-edge arrays, edge lengths, corner angles, saddle and boundary
/// flags, mean edge length and anisotropy) is done once, in the constructor; `compute()` can then be called
/// any number of times. The mesh must not be modified while the solver is in use.
///
/// Sources are given in one of two ways: as an argument of `compute()` (a vertex, a face location, or a
/// range of either), or as a source set built with `add_source()` / `clear_sources()` and used by the
/// `compute()` that takes no source. The nearest-source label of a vertex is the index of a source in that
/// range (or in the order the sources were added).
///
/// \tparam TriangleMesh a triangulated surface mesh, model of `FaceListGraph` and `HalfedgeListGraph`.
/// \tparam Traits a model of `VTPGeodesicTraits_3`. The default is
///   `Geodesic_traits_3<Kernel_traits<Point>::Kernel>` where `Point` is the value type of the vertex point map.
/// \tparam VertexPointMap a `ReadablePropertyMap` with `vertex_descriptor` as key type and `Traits::Point_3`
///   as value type. The default is `boost::property_map<TriangleMesh, CGAL::vertex_point_t>::%const_type`.
template <class TriangleMesh,
          class Traits = Default,
          class VertexPointMap = Default>
class Geodesic_distance_solver
{
public:
  /// \name Types
  /// @{
  typedef TriangleMesh Triangle_mesh;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;
  typedef typename Default::Get<Traits,
            Geodesic_traits_3<typename Kernel_traits<Point_3>::Kernel> >::type Geom_traits;
  /// A point of the surface: a face and the barycentric coordinates of the point with respect to
  /// `source(halfedge(f))`, `target(halfedge(f))` and `target(next(halfedge(f)))` (the type of
  /// `CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>`). Locations with another number
  /// type are accepted too. The one location type of the package: `CGAL::VTP_geodesics::Face_location<face_descriptor>`.
  typedef VTP_geodesics::Face_location<face_descriptor> Face_location;
  /// A polyline on the surface (a shortest path: `shortest_path()`), `Surface_polyline<face_descriptor, Point_3>`.
  typedef Surface_polyline<face_descriptor, Point_3> Polyline;
  /// @}

private:
  typedef internal::Index Index;
public:
  /// \name Creation
  /// @{

  /// builds the per-mesh data of `tm`, with the vertex point map `get(CGAL::vertex_point, tm)`, on one thread.
  /// \pre `tm` outlives the solver and is not modified while the solver is in use.
  /// \throws Invalid_input_error if `tm` is not a triangle mesh ("face N is not a triangle"), a vertex has a
  /// non-finite coordinate ("vertex N"), an edge length overflows, or `tm` has more than 2^31 - 1 vertices
  /// or (2^31 - 1) / 3 faces (vertices and faces numbered in the order of `vertices(tm)` and `faces(tm)`).
  explicit Geodesic_distance_solver(const TriangleMesh& tm)
    : Geodesic_distance_solver(tm, get(CGAL::vertex_point, tm))
  {}

  /// builds the per-mesh data of `tm` with the vertex point map `vpm` and the traits `traits`.
  /// \throws Invalid_input_error as the constructor above.
  Geodesic_distance_solver(const TriangleMesh& tm, Vertex_point_map vpm, const Geom_traits& traits = Geom_traits())
    : m_vpm(vpm), m_traits(traits), m_mesh(tm)
  {
    build(1);
  }

  /// builds the per-mesh data of `tm` with the named parameters `np`: `vertex_point_map` (of type
  /// `Vertex_point_map`), `geom_traits` (of type `Geom_traits`) and `number_of_threads`, the number of
  /// OpenMP threads of the preprocessing (default 1, unlike `compute()` whose default is 0; 0: OpenMP's
  /// default; without OpenMP, 1). The
  /// result does not depend on the number of threads. With more than one thread, the graph functions of
  /// `tm`, the vertex point map and the traits are called from several threads at once (they only read).
  /// \throws Invalid_input_error as the constructor above.
  template <class T, class Tag, class Base>
  Geodesic_distance_solver(const TriangleMesh& tm, const CGAL::Named_function_parameters<T, Tag, Base>& np)
    : m_vpm(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                               get_const_property_map(CGAL::vertex_point, tm))),
      m_traits(CGAL::parameters::choose_parameter<Geom_traits>(
        CGAL::parameters::get_parameter(np, CGAL::internal_np::geom_traits))),
      m_mesh(tm)
  {
    build(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::number_of_threads),
                                             internal::default_preprocessing_threads));
  }
  /// @}

  /// \name Source set
  /// @{

  /// adds the vertex `v` to the source set.
  /// \throws Invalid_input_error if `v` is not a vertex of the mesh ("source N is not a vertex of the mesh",
  /// N being the number of sources added before).
  void add_source(vertex_descriptor v) { m_sources.push_back(m_mesh.seed_of(v, next_label())); ++m_source_count; }

  /// adds the point `location` of the surface to the source set (any number type convertible to `double`).
  /// \throws Invalid_input_error if the face is not a face of the mesh or the barycentric coordinates are not
  /// finite, non-negative and of sum 1 (up to rounding); the message names the source and the face.
  template <class FT>
  void add_source(const std::pair<face_descriptor, std::array<FT, 3> >& location)
  {
    m_sources.push_back(m_mesh.seed_of(location, next_label()));
    ++m_source_count;
  }

  /// adds the curve through `points` (a range of `vertex_descriptor` or of face locations, at least two
  /// distinct points) to the source set, as one source: its distance is the distance to the nearest point of
  /// the curve. Two consecutive points in one face are joined straight inside it (along the edge when both are
  /// on it); two that share no face are joined by the shortest geodesic between them (one exact run from the
  /// first, stopped at the second). The curve is closed when its last point is its first. Its left is the
  /// side of face normal x direction of travel (`signed_distance`).
  /// \throws Invalid_input_error if a point is not a vertex or a point of the mesh, the curve has fewer than two
  /// distinct points, or two consecutive points are not connected by the surface ("source N (a curve) ...").
  template <class PointRange>
  void add_source_curve(const PointRange& points)
  {
    const Index label = next_label();
    const std::string name = "source " + std::to_string(label) + " (a curve)";
    std::vector<internal::Seed> given, joined;
    std::size_t i = 0;
    try
    {
      for(const auto& p : points)
        given.push_back(m_mesh.seed_of(p, label, "point", i++));
    }
    catch(const Invalid_input_error& e)
    {
      throw Invalid_input_error(name + ": " + e.what());
    }
    std::size_t distinct = 0;
    for(std::size_t k = 0; k < given.size(); ++k)
      if(k == 0 || !internal::same_point(given[k], given[0]))
        ++distinct;
    if(distinct < 2)
      throw Invalid_input_error(name + " needs at least two distinct points, got " + std::to_string(distinct));
    std::size_t bad = 0;
    if(!internal::join_curve_points(m_mesh.arrays, given, joined, bad))
      throw Invalid_input_error(name + ": points " + std::to_string(bad) + " and " + std::to_string(bad + 1)
                                + " are not connected by the surface");
    internal::add_curve_seeds(m_mesh.arrays, joined, label, m_sources);
    m_curves.emplace_back(static_cast<std::size_t>(label), std::move(joined));
    ++m_source_count;
  }

  /// the curve of source `i` of the source set (added by `add_source_curve()`) as the solver joined it: its
  /// points given and, between two that share no face, the points of the shortest geodesic between them (every
  /// two consecutive points share a face); a closed curve ends with its first point again.
  /// \throws Invalid_input_error if source `i` is not a curve.
  Polyline source_curve(std::size_t i) const
  {
    for(const auto& c : m_curves)
      if(c.first == i)
      {
        Polyline r;
        for(const internal::Seed& q : c.second)
        {
          r.points.push_back(internal::point_of<Point_3>(m_mesh, m_vpm, q));
          r.locations.push_back(internal::location_of(m_mesh, q));
        }
        return r;
      }
    throw Invalid_input_error("source " + std::to_string(i) + " is not a curve of the source set");
  }

  /// adds the border of the mesh (every border loop) to the source set, as one source; each loop runs with the
  /// surface on its left.
  /// \throws Invalid_input_error if the mesh has no border.
  void add_source_border()
  {
    const std::vector<std::array<Index, 3> > edges = internal::border_edges(m_mesh.arrays);
    if(edges.empty())
      throw Invalid_input_error("the mesh has no border");
    internal::add_edge_seeds(m_mesh.arrays, edges, next_label(), m_sources);
    ++m_source_count;
  }

  /// adds the edges `edges` (a range of `halfedge_descriptor`, each from its source to its target: its left
  /// is the side of its face) to the source set, as one source.
  /// \throws Invalid_input_error if the range is empty or an element is not a half-edge of the mesh.
  template <class HalfedgeRange>
  void add_source_edges(const HalfedgeRange& halfedges)
  {
    const Index label = next_label();
    std::vector<std::array<Index, 3> > edges;
    for(const auto& h : halfedges)
    {
      const std::array<Index, 3> e = m_mesh.edge_of(h, label);
      edges.push_back(e);
    }
    if(edges.empty())
      throw Invalid_input_error("source " + std::to_string(label) + " (edges) has no edge");
    internal::add_edge_seeds(m_mesh.arrays, edges, label, m_sources);
    ++m_source_count;
  }

  /// adds every vertex or face location of `range` to the source set, in order.
  /// \throws Invalid_input_error as `add_source()`; the sources before the bad one are added.
  template <class Range>
  void add_sources(const Range& range)
  {
    for(const auto& s : range)
      add_source(s);
  }

  /// empties the source set.
  void clear_sources()
  {
    m_sources.clear();
    m_curves.clear();
    m_source_count = 0;
  }

  /// the number of sources in the source set (a curve, the border, a set of edges: one each).
  std::size_t number_of_sources() const { return m_source_count; }
  /// @}

  /// \name Computation
  /// @{

  /// computes the geodesic distance from the sources of the source set to every vertex of the mesh and
  /// writes it into `vdm`. Vertices that no source can reach (other connected components, isolated
  /// vertices) get `std::numeric_limits<double>::infinity()`.
  ///
  /// \tparam ConcurrencyTag `CGAL::Sequential_tag` (VTP / AVTP) or `CGAL::Parallel_tag` (PVTP / PAVTP, needs
  ///   OpenMP).
  /// \tparam VertexDistanceMap a `WritablePropertyMap` with `vertex_descriptor` as key type and `double` as
  ///   value type.
  /// \param vdm the output distance map
  /// \param np the named parameters of `compute_geodesic_distances()` (but `vertex_point_map` and
  ///   `geom_traits`, given at construction), with the same types, defaults and meanings
  /// \pre the mesh was not modified since the construction.
  /// \throws Invalid_input_error if the source set is empty, a target is not a vertex or a point of the mesh
  /// ("target N ..."), or a parameter is invalid.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class VertexDistanceMap,
            class NP_T = bool, class NP_Tag = CGAL::internal_np::all_default_t,
            class NP_Base = CGAL::internal_np::No_property>
  void compute(VertexDistanceMap vdm,
               const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np = parameters::default_values())
  {
    run<ConcurrencyTag>(m_sources, np);
    internal::write_output_maps(m_mesh.vertices, m_engine, vdm, np, m_statistics);
    internal::write_log_map(m_mesh.vertices, m_engine, np);
  }

  /// computes the geodesic distance from `sources` to every vertex of the mesh and writes it into `vdm`, as
  /// above; `sources` is a `vertex_descriptor`, a face location, or a range of either. The source set is
  /// not used (nor changed).
  /// \throws Invalid_input_error if a source is not a vertex or a point of the mesh ("source N ...", N its
  /// position in `sources`), the range is empty, a target is invalid, or a parameter is invalid.
#ifdef DOXYGEN_RUNNING
  template <class ConcurrencyTag = CGAL::Sequential_tag, class VertexDistanceMap, class SourceOrRange,
            class NamedParameters = CGAL::parameters::Default_named_parameters>
  void compute(VertexDistanceMap vdm, const SourceOrRange& sources, const NamedParameters& np = parameters::default_values());
#else
  template <class ConcurrencyTag = CGAL::Sequential_tag, class VertexDistanceMap, class SourceOrRange,
            class NP_T = bool, class NP_Tag = CGAL::internal_np::all_default_t,
            class NP_Base = CGAL::internal_np::No_property>
  typename std::enable_if<!internal::Is_named_parameters<SourceOrRange>::value>::type
  compute(VertexDistanceMap vdm, const SourceOrRange& sources,
          const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np = parameters::default_values())
  {
    run<ConcurrencyTag>(m_mesh.seeds_of(sources), np);
    internal::write_output_maps(m_mesh.vertices, m_engine, vdm, np, m_statistics);
    internal::write_log_map(m_mesh.vertices, m_engine, np);
  }
#endif
  /// @}

  /// \name Many sources
  /// @{

  /// computes the distances from each source of `sources` on its own, one row per source, and hands each row
  /// to `sink`: `sink(i, source, distances)` where `i` is the index of the source in `sources`, `source` the
  /// source itself, and `distances` a `const std::vector<double>&` indexed by `vertex_id()` (valid during the
  /// call only). With `CGAL::Parallel_tag`, the rows are computed in parallel over the sources (OpenMP, dynamic
  /// schedule, `number_of_threads` threads), each with the sequential scheduling in a workspace of its thread
  /// (the per-mesh data of the solver is shared, read-only); with `CGAL::Sequential_tag`, one after the other.
  /// The sink is called by one thread at a time, never concurrently, in any order of the rows. A row is
  /// bitwise equal to the distances of `compute()` from the same source with the same parameters (and the
  /// sequential scheduling). Memory: one workspace (O(V)) per thread, besides what the sink keeps.
  ///
  /// If the sink throws, no further row is handed to it and the exception is thrown again from `compute_each()`
  /// once the rows under way are done; so does an exception of the computation.
  ///
  /// \tparam SourceRange a range of `vertex_descriptor` or of face locations.
  /// \tparam RowSink a callable as `sink(std::size_t i, const Source& source, const std::vector<double>& distances)`.
  /// \param sources the sources, one row each (they may repeat).
  /// \param sink receives the rows, one call per source.
  /// \param np the named parameters `lambda`, `lambda_g`, `minimum_window_length`, `maximum_distance` (beyond it,
  ///   `+infinity`: rows become sparse) and `number_of_threads` of `compute_geodesic_distances()`.
  /// \throws Invalid_input_error if a source is not a vertex or a point of the mesh ("source N ...", N its
  /// position in `sources`), or a parameter is invalid; before any row is computed.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class SourceRange, class RowSink,
            class NP_T = bool, class NP_Tag = CGAL::internal_np::all_default_t,
            class NP_Base = CGAL::internal_np::No_property>
  void compute_each(const SourceRange& sources, RowSink sink,
                    const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np = parameters::default_values())
  {
    internal::compute_each_row(m_mesh, sources, sink, np, internal::is_parallel<ConcurrencyTag>(), m_workspaces,
                               m_statistics);
  }
  /// @}

  /// \name Polar patches
  /// The log map from each centre of `centres` on its own, cut at `radius`: all patches in CSR form, or each patch
  /// handed to `sink` as `compute_each()` does; see `Polar_patches`, which documents both. @{
  template <class ConcurrencyTag = CGAL::Sequential_tag, class Centres, class NP = CGAL::parameters::Default_named_parameters>
  Polar_patches polar_patches(const Centres& centres, double radius, const NP& np = parameters::default_values())
  { return internal::polar_patches_of<ConcurrencyTag>(m_mesh, m_vpm, centres, radius, np, m_patches, m_statistics); }
  template <class ConcurrencyTag = CGAL::Sequential_tag, class Centres, class Sink, class NP = CGAL::parameters::Default_named_parameters>
  void compute_each_polar_patch(const Centres& centres, double radius, Sink sink, const NP& np = parameters::default_values())
  { internal::compute_patch_rows<ConcurrencyTag>(m_mesh, m_vpm, centres, radius, sink, np, m_patches, m_statistics); } /// @}

  /// \name Farthest-point sampling
  /// @{
  /// takes up to `k` samples, each the vertex farthest from those before, as `farthest_point_sampling()` (the
  /// free function, which says it all) on the mesh of the solver, with the same named parameters (but
  /// `vertex_point_map` and `geom_traits`); the results of the last computation do not change.
  /// \returns the samples, the covering radius after each, the distances and the nearest-sample labels.
  /// \throws Invalid_input_error for a `first_sample` that is not a vertex or an invalid parameter.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class NP_T = bool,
            class NP_Tag = CGAL::internal_np::all_default_t, class NP_Base = CGAL::internal_np::No_property>
  Farthest_point_samples<vertex_descriptor>
  farthest_point_sampling(std::size_t k, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np
                                         = parameters::default_values()) const
  {
    return internal::farthest_point_samples_of<ConcurrencyTag>(m_mesh, k, np);
  }
  /// @}

  /// \name Results of the last computation
  /// @{

  /// the distances, indexed by `vertex_id()`.
  const std::vector<double>& distances() const { return m_distances; }
  /// the distance of `v`.
  /// \pre `v` is a vertex of the mesh.
  double distance(vertex_descriptor v) const
  {
    return m_engine.distances()[static_cast<std::size_t>(get(m_mesh.vertex_id, v))];
  }
  /// the number of targets (named parameter `targets`).
  std::size_t number_of_targets() const { return m_engine.number_of_targets(); }
  /// the distance of target `i` (in the order given): exact, or `+infinity` if it is unreachable or
  /// beyond the distance limit.
  /// \pre `i < number_of_targets()`.
  double target_distance(std::size_t i) const
  {
    CGAL_precondition(i < number_of_targets());
    return m_engine.target_distance(i);
  }
  /// the statistics.
  const Propagation_statistics& statistics() const { return m_statistics; }
  /// @}

  /// \name The kept field
  /// With the named parameter `keep_field(true)` (exact methods: VTP, PVTP), a computation keeps every window
  /// that crossed a face (O(windows propagated) memory: `field_bytes()`), until the next computation. The
  /// distance inside a face is the least, over its corners, the sources in it and those windows, of the
  /// length of a real path to the point, which is the exact geodesic distance (the manual, curves, says why).
  /// These queries answer from it, without a new propagation; so do `geodesic_isolines()`,
  /// `geodesic_cell_borders()` and `geodesic_voronoi_cell_areas()`. They are not to be called concurrently.
  /// @{

  /// whether the last computation kept the field.
  bool has_kept_field() const { return m_engine.kept_field().is_active(); }
  /// the bytes the kept field holds (0 without it).
  std::size_t field_bytes() const { return m_engine.kept_field().bytes(); }
  /// the pieces of the kept field in face `f`: the windows that crossed it (0 without the field).
  std::size_t number_of_field_pieces(face_descriptor f) const
  {
    const internal::Kept_field& k = m_engine.kept_field();
    const internal::Index i = m_mesh.face_index(f);
    if(!k.is_active() || i == internal::NO_INDEX)
      return 0;
    return k.last(i) - k.first(i);
  }
  /// the exact distance of the last computation at `p` (a `vertex_descriptor` or a face location): its
  /// distance to the nearest source, `+infinity` if no source reaches it or it lies beyond the distance limit.
  /// \throws Invalid_input_error if the last computation did not keep the field, or `p` is not a vertex or a
  /// point of the mesh.
  template <class VertexOrLocation>
  double field_distance(const VertexOrLocation& p) const
  {
    return field_at(p).first;
  }
  /// the nearest source of the last computation at `p` (its index, as the named parameter
  /// `nearest_source_map` gives it), `no_source` where `field_distance(p)` is infinite. Where two sources are
  /// equally near, either. \throws Invalid_input_error as `field_distance()`.
  template <class VertexOrLocation>
  std::size_t field_nearest_source(const VertexOrLocation& p) const
  {
    return field_at(p).second;
  }
  /// @}

  /// \name Geodesic paths
  /// The shortest path from a vertex or a point of the surface back to its nearest source, after a
  /// computation. With the named parameter `record_paths(true)` the computation keeps, for each vertex and
  /// each target, what the trace-back needs (O(V + targets) memory, never the windows); otherwise (or for
  /// a point that was not a target), a path request runs the propagation again from the same sources, with
  /// the same parameters, until the point is reached, in a separate workspace (the results above do not
  /// change). The path is straight in the unfolding of the faces it crosses, turns only at saddle or
  /// boundary vertices (and, for the approximate variants, at vertices where windows were reset), and its
  /// length is the computed distance (up to rounding).
  /// \pre the mesh was not modified since the construction.
  /// \throws Invalid_input_error if there was no computation yet, if the point is not a vertex or a point
  /// of the mesh, or if no source reaches it (or it lies beyond the distance limit): "no path: vertex N is
  /// not reached ...".
  /// \throws std::runtime_error if the path cannot be followed through the faces with the length of the
  /// distance (a numerical failure: none is known; the tests check every path of every method on random,
  /// degenerate and real meshes); no partial path is written then.
  /// @{

  /// the path from `p` to its nearest source, `p` first, as a `Surface_polyline`: the points of
  /// `shortest_path_points()` and, one each, the face locations of `shortest_path_locations()` (one trace-back).
  /// `p` is a `vertex_descriptor` or a face location (any number type `FT` convertible to `double`).
  /// \throws Invalid_input_error as the two below (and for a source vertex without a face, which has no location).
  template <class VertexOrLocation>
  Polyline shortest_path(const VertexOrLocation& p)
  {
    Polyline r;
    for(const internal::Trace_point& q : trace_of(p))
    {
      r.points.push_back(internal::point_of<Point_3>(m_mesh, m_vpm, q));
      r.locations.push_back(internal::location_of(m_mesh, q));
    }
    return r;
  }

  /// writes the points of the path from `p` to its nearest source, `p` first, to `out` (value type
  /// `Point_3`): the vertices, the crossings of edges, and the source. `p` is a `vertex_descriptor` or a face
  /// location (`std::pair<face_descriptor, std::array<FT, 3> >`, any number type `FT` convertible to `double`).
  /// \returns the output iterator after the last point written.
  template <class VertexOrLocation, class OutputIterator>
  OutputIterator shortest_path_points(const VertexOrLocation& p, OutputIterator out)
  {
    for(const internal::Trace_point& q : trace_of(p))
      *out++ = internal::point_of<Point_3>(m_mesh, m_vpm, q);
    return out;
  }

  /// writes the same path as `shortest_path_points()` as face locations to `out` (value type
  /// `Face_location`): a vertex as a corner of one of its faces, an edge point in one of its two faces.
  /// \returns the output iterator after the last location written.
  template <class VertexOrLocation, class OutputIterator>
  OutputIterator shortest_path_locations(const VertexOrLocation& p, OutputIterator out)
  {
    for(const internal::Trace_point& q : trace_of(p))
      *out++ = internal::location_of(m_mesh, q);
    return out;
  }
  /// @}

  /// \name Straightest geodesics (the exponential map)
  /// A walk from `start` (a `vertex_descriptor` or a face location) in `direction` (a `std::array<double, 2>` in
  /// the tangent frame of the start, that of the log map, or a `std::array<double, 3>`, projected) for `length`:
  /// see `Straightest_geodesic`. Many walks (ranges of equal sizes) run on `number_of_threads` threads with
  /// `CGAL::Parallel_tag`. \throws Invalid_input_error for a start not on a face of the mesh, a zero or
  /// non-finite direction (or one orthogonal to the tangent plane), a negative or non-finite length ("walk i").
  /// @{
  template <class Start, class Direction>
  Straightest_geodesic<face_descriptor, Point_3> straightest_geodesic(const Start& start, const Direction& direction,
                                                                     double length) const
  { return internal::Straightest_queries<TriangleMesh, Vertex_point_map>(m_mesh, m_vpm).walk(start, direction, length); }
  template <class ConcurrencyTag = CGAL::Sequential_tag, class StartRange, class DirectionRange, class LengthRange,
            class NP = CGAL::parameters::Default_named_parameters>
  std::vector<Straightest_geodesic<face_descriptor, Point_3> > straightest_geodesics(const StartRange& starts,
    const DirectionRange& directions, const LengthRange& lengths, const NP& np = parameters::default_values()) const
  {
    return internal::Straightest_queries<TriangleMesh, Vertex_point_map>(m_mesh, m_vpm)
      .walks(starts, directions, lengths, internal::is_parallel<ConcurrencyTag>(), np);
  } /// @}

  /// \name Mesh
  /// @{
  /// the dense index of `v` (vertices are numbered in the order of `vertices(tm)`; error messages name
  /// vertices by this index). \pre `v` is a vertex of the mesh.
  std::size_t vertex_id(vertex_descriptor v) const { return m_mesh.position_of(get(m_mesh.vertex_id, v)); }
  /// the vertices, in the order of their dense indices.
  const std::vector<vertex_descriptor>& vertex_list() const { return m_mesh.vertices_in_order; }
  /// the vertices in the order in which the solver stores their per-vertex data: along a Morton (Z-order)
  /// curve of their points, ties in the order of `vertices(tm)`, so that neighbours on the surface are near in
  /// memory (a mesh renumbered in this order is read a few cache lines at a time by other programs too).
  const std::vector<vertex_descriptor>& vertices_in_storage_order() const { return m_mesh.vertices; }
  /// number of vertices and faces of the mesh.
  std::size_t number_of_vertices() const { return m_mesh.vertices.size(); }
  std::size_t number_of_faces() const { return static_cast<std::size_t>(m_mesh.arrays.nf); }
  /// mean edge length `h` of the mesh.
  double mean_edge_length() const { return m_mesh.arrays.mean_edge_length * m_mesh.length_scale; }
  /// anisotropy degree `tau` of the mesh (1 for equilateral triangles).
  double anisotropy() const { return m_mesh.arrays.anisotropy; }
  /// number of saddle or boundary vertices (pseudo-source candidates).
  std::size_t number_of_pseudo_source_vertices() const
  {
    const std::vector<unsigned char>& p = m_mesh.arrays.is_pseudo_source;
    return static_cast<std::size_t>(std::count(p.begin(), p.end(), 1));
  }
  /// seconds spent in the constructor.
  double preprocessing_seconds() const { return m_preprocessing_seconds; }
  /// @}

  /// \cond SKIP_IN_MANUAL
  const internal::Mesh_arrays& mesh_arrays() const { return m_mesh.arrays; }
  const internal::Mesh_index<TriangleMesh>& mesh_index() const { return m_mesh; }  // (geodesic_curves.h)
  const internal::Propagation_engine& engine() const { return m_engine; }
  // the queries on the field of the last computation (built on the first call after it)
  const internal::Field_queries& field_queries() const
  {
    if(!m_field_queries)
      m_field_queries.reset(new internal::Field_queries(m_mesh.arrays, m_engine, m_mesh.length_scale));
    return *m_field_queries;
  }
  /// \endcond

private:
  // the points of the path from `p` (a vertex or a face location) back to its nearest source (one trace-back)
  template <class VertexOrLocation>
  std::vector<internal::Trace_point> trace_of(const VertexOrLocation& p)
  {
    return m_paths.trace(m_mesh.arrays, m_engine, m_mesh.target_of(p, "the start of the path"), m_mesh.position);
  }

  Index next_label() const { return static_cast<Index>(m_source_count); }

  void build(int threads)
  {
    const auto t0 = std::chrono::steady_clock::now();
    internal::import_mesh(m_mesh, m_vpm, m_traits, internal::number_of_threads(threads));
    m_engine.distances().assign(m_mesh.vertices.size(), std::numeric_limits<double>::infinity());
    m_distances = m_engine.distances();
    m_preprocessing_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  template <class VertexOrLocation>
  std::pair<double, std::size_t> field_at(const VertexOrLocation& p) const
  {
    if(!has_kept_field())
      throw Invalid_input_error("the last computation kept no field: compute with keep_field(true)");
    const internal::Seed s = m_mesh.seed_of(p, 0, "the point", m_mesh.no_position);
    const std::pair<double, internal::Index> r = field_queries().at(s);
    return std::make_pair(r.first * m_mesh.length_scale,
                          r.second == internal::NO_INDEX ? no_source : static_cast<std::size_t>(r.second));
  }

  template <class ConcurrencyTag, class NamedParameters>
  void run(std::vector<internal::Seed> seeds, const NamedParameters& np)
  {
    m_field_queries.reset();
    internal::run_solver<ConcurrencyTag>(m_mesh, m_vpm, std::move(seeds), np, m_engine, m_distances, m_paths, m_statistics);
  }

  Vertex_point_map m_vpm;
  Geom_traits m_traits;
  internal::Mesh_index<TriangleMesh> m_mesh;  // descriptors <-> indices, the engine's arrays and unit
  double m_preprocessing_seconds = 0.;
  std::vector<internal::Seed> m_sources;  // the seeds of the source set (several for a curve)
  std::size_t m_source_count = 0;
  std::vector<std::pair<std::size_t, std::vector<internal::Seed> > > m_curves;  // (source, its joined points)
  internal::Propagation_engine m_engine;  // per vertex index
  std::vector<double> m_distances;       // those of m_engine, in the order of vertices(tm)
  Propagation_statistics m_statistics;
  internal::Path_queries m_paths;  // remembers the parameters of the last computation
  std::vector<std::unique_ptr<internal::Propagation_engine> > m_workspaces;  // of compute_each(), one per thread
  std::vector<std::unique_ptr<internal::Local_propagation> > m_patches;  // workspaces of the polar patches
  mutable std::unique_ptr<internal::Field_queries> m_field_queries;       // (field_queries())
};

} // namespace VTP_geodesics
} // namespace CGAL
#include <CGAL/enable_warnings.h>

#endif // CGAL_VTP_GEODESICS_GEODESIC_DISTANCE_SOLVER_H
