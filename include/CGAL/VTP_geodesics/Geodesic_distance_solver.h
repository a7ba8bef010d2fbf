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

#include <CGAL/VTP_geodesics/Geodesic_traits_3.h>
#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/engine/Path_trace.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/source_forms.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <iterator>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// The value that a nearest-source map receives for a vertex that no source reaches.
constexpr std::size_t no_source = (std::numeric_limits<std::size_t>::max)();

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
  /// type are accepted too.
  typedef std::pair<face_descriptor, std::array<double, 3> > Face_location;
  /// @}

private:
  typedef internal::Index Index;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<Index> >::const_type
    Vertex_id_map;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<Index> >::const_type
    Face_id_map;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<Index> >::const_type
    Halfedge_id_map;

public:
  /// \name Creation
  /// @{

  /// builds the per-mesh data of `tm`, with the vertex point map `get(CGAL::vertex_point, tm)`.
  /// \throws Invalid_input_error if `tm` is not a triangle mesh, an edge length is not finite, or `tm` has
  /// more than 2^31 - 1 vertices or (2^31 - 1) / 3 faces.
  explicit Geodesic_distance_solver(const TriangleMesh& tm)
    : Geodesic_distance_solver(tm, get(CGAL::vertex_point, tm))
  {}

  /// builds the per-mesh data of `tm` with the vertex point map `vpm` and the traits `traits`.
  /// \throws Invalid_input_error as the constructor above.
  Geodesic_distance_solver(const TriangleMesh& tm, Vertex_point_map vpm, const Geom_traits& traits = Geom_traits())
    : m_tm(tm), m_vpm(vpm), m_traits(traits),
      m_vertex_id(get(CGAL::dynamic_vertex_property_t<Index>(), tm)),
      m_face_id(get(CGAL::dynamic_face_property_t<Index>(), tm))
  {
    build(1);
  }

  /// builds the per-mesh data of `tm` with the named parameters `np`: `vertex_point_map` (of type
  /// `Vertex_point_map`), `geom_traits` (of type `Geom_traits`) and `number_of_threads`, the number of
  /// OpenMP threads of the preprocessing (default 1; 0: OpenMP's default; without OpenMP, 1). The
  /// result does not depend on the number of threads. With more than one thread, the graph functions of
  /// `tm`, the vertex point map and the traits are called from several threads at once (they only read).
  /// \throws Invalid_input_error as the constructor above.
  template <class T, class Tag, class Base>
  Geodesic_distance_solver(const TriangleMesh& tm, const CGAL::Named_function_parameters<T, Tag, Base>& np)
    : m_tm(tm),
      m_vpm(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                               get_const_property_map(CGAL::vertex_point, tm))),
      m_traits(CGAL::parameters::choose_parameter<Geom_traits>(
        CGAL::parameters::get_parameter(np, CGAL::internal_np::geom_traits))),
      m_vertex_id(get(CGAL::dynamic_vertex_property_t<Index>(), tm)),
      m_face_id(get(CGAL::dynamic_face_property_t<Index>(), tm))
  {
    build(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::number_of_threads), 1));
  }
  /// @}

  /// \name Source set
  /// @{

  /// adds the vertex `v` to the source set.
  /// \throws Invalid_input_error if `v` is not a vertex of the mesh.
  void add_source(vertex_descriptor v) { m_sources.push_back(seed_of(v, static_cast<Index>(m_sources.size()))); }

  /// adds the point `location` of the surface to the source set (any number type convertible to `double`).
  /// \throws Invalid_input_error if the face is not a face of the mesh or the barycentric coordinates are not
  /// finite, non-negative and of sum 1 (up to rounding).
  template <class FT>
  void add_source(const std::pair<face_descriptor, std::array<FT, 3> >& location)
  {
    m_sources.push_back(seed_of(location, static_cast<Index>(m_sources.size())));
  }

  /// adds every vertex or face location of `range` to the source set, in order.
  template <class Range>
  void add_sources(const Range& range)
  {
    for(const auto& s : range)
      add_source(s);
  }

  /// empties the source set.
  void clear_sources() { m_sources.clear(); }

  /// the number of sources in the source set.
  std::size_t number_of_sources() const { return m_sources.size(); }
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
  ///   `geom_traits`, given at construction)
  /// \throws Invalid_input_error if the source set is empty or a parameter is invalid.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class VertexDistanceMap,
            class NP_T = bool, class NP_Tag = CGAL::internal_np::all_default_t,
            class NP_Base = CGAL::internal_np::No_property>
  void compute(VertexDistanceMap vdm,
               const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np = parameters::default_values())
  {
    run<ConcurrencyTag>(m_sources, np);
    write_outputs(vdm, np);
  }

  /// computes the geodesic distance from `sources` to every vertex of the mesh and writes it into `vdm`, as
  /// above; `sources` is a `vertex_descriptor`, a face location, or a range of either. The source set is
  /// not used (nor changed).
  /// \throws Invalid_input_error if a source is not a vertex or a point of the mesh, the range is empty, or
  /// a parameter is invalid.
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
    run<ConcurrencyTag>(seeds_of(sources), np);
    write_outputs(vdm, np);
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
  /// \throws Invalid_input_error if a source is not a vertex or a point of the mesh, or a parameter is invalid.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class SourceRange, class RowSink,
            class NP_T = bool, class NP_Tag = CGAL::internal_np::all_default_t,
            class NP_Base = CGAL::internal_np::No_property>
  void compute_each(const SourceRange& sources, RowSink sink,
                    const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np = parameters::default_values())
  {
    const bool parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
#ifndef _OPENMP
    static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                  "Parallel_tag is enabled but OpenMP is unavailable "
                  "(link CGAL::VTP_geodesics_OpenMP_support, or compile with -fopenmp).");
#endif
    typedef typename std::iterator_traits<decltype(std::begin(sources))>::value_type Source;
    const std::vector<Source> items(std::begin(sources), std::end(sources));
    std::vector<internal::Seed> seeds;
    seeds.reserve(items.size());
    for(const Source& item : items)
      seeds.push_back(seed_of(item, 0));  // validated here, serially
    int threads = 0;
    internal::Propagation_settings settings = settings_of(np, threads);
    settings.want_labels = false;
    settings.record_paths = false;
    settings.stop_at_targets = false;
    if(!parallel)
      threads = 1;
#ifdef _OPENMP
    else if(threads <= 0)
      threads = omp_get_max_threads();
#endif
    threads = (std::max)(1, (std::min)(threads, static_cast<int>((std::max)(std::size_t(1), seeds.size()))));
    while(m_workspaces.size() < static_cast<std::size_t>(threads))
      m_workspaces.emplace_back(new internal::Propagation_engine());
    std::vector<Propagation_statistics> per_thread(static_cast<std::size_t>(threads));

    const auto t0 = std::chrono::steady_clock::now();
    std::exception_ptr error;         // written in the critical section only
    std::atomic<bool> failed{ false };
    const long long n = static_cast<long long>(seeds.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) if(threads > 1)
#endif
    for(long long i = 0; i < n; ++i)
    {
      int t = 0;
#ifdef _OPENMP
      t = omp_get_thread_num();
#endif
      if(failed.load(std::memory_order_relaxed))
        continue;
      internal::Propagation_engine& workspace = *m_workspaces[static_cast<std::size_t>(t)];
      try
      {
        Propagation_statistics st;
        workspace.template run<CGAL::Sequential_tag>(m_arrays, std::vector<internal::Seed>(1, seeds[static_cast<std::size_t>(i)]),
                                                     std::vector<internal::Target>(), settings, 1, st);
        add_row_statistics(st, per_thread[static_cast<std::size_t>(t)]);
      }
      catch(...)
      {
#ifdef _OPENMP
#pragma omp critical(vtp_geodesics_compute_each)
#endif
        {
          if(!error)
            error = std::current_exception();
          failed.store(true, std::memory_order_relaxed);
        }
        continue;
      }
#ifdef _OPENMP
#pragma omp critical(vtp_geodesics_compute_each)
#endif
      {
        if(!failed.load(std::memory_order_relaxed))
        {
          try
          {
            sink(static_cast<std::size_t>(i), items[static_cast<std::size_t>(i)], workspace.distances());
          }
          catch(...)
          {
            error = std::current_exception();
            failed.store(true, std::memory_order_relaxed);
          }
        }
      }
    }
    m_statistics = Propagation_statistics();
    m_statistics.vertices = m_vertices.size();
    m_statistics.faces = static_cast<std::size_t>(m_arrays.nf);
    m_statistics.method = settings.reset_step < std::numeric_limits<double>::infinity() ? "avtp" : "vtp";
    m_statistics.threads = threads;
    m_statistics.sources = seeds.size();
    for(const Propagation_statistics& st : per_thread)
      add_row_statistics(st, m_statistics);
    m_statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if(error)
      std::rethrow_exception(error);
  }
  /// @}

  /// \name Results of the last computation
  /// @{

  /// the distances, indexed by `vertex_id()`.
  const std::vector<double>& distances() const { return m_engine.distances(); }
  /// the distance of `v`.
  double distance(vertex_descriptor v) const { return m_engine.distances()[vertex_id(v)]; }
  /// the number of targets (named parameter `targets`).
  std::size_t number_of_targets() const { return m_engine.number_of_targets(); }
  /// the distance of target `i` (in the order given): exact, or `+infinity` if it is unreachable or
  /// beyond the distance limit.
  double target_distance(std::size_t i) const
  {
    CGAL_precondition(i < number_of_targets());
    return m_engine.target_distance(i);
  }
  /// the statistics.
  const Propagation_statistics& statistics() const { return m_statistics; }
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
  /// \throws Invalid_input_error if there was no computation yet, if the point is not a vertex or a point
  /// of the mesh, or if no source reaches it (or it lies beyond the distance limit).
  /// \throws std::runtime_error if the path cannot be followed through the faces (a numerical failure, which
  /// the tests have not met on meshes without faces of zero area); no partial path is written then.
  /// @{

  /// writes the points of the path from `v` to its nearest source, `v` first, to `out` (value type
  /// `Point_3`): the vertices, the crossings of edges, and the source.
  template <class OutputIterator>
  OutputIterator shortest_path_points(vertex_descriptor v, OutputIterator out)
  {
    return points_of(trace(target_of(v)), out);
  }

  /// the same from a point of the surface.
  template <class FT, class OutputIterator>
  OutputIterator shortest_path_points(const std::pair<face_descriptor, std::array<FT, 3> >& location,
                                      OutputIterator out)
  {
    return points_of(trace(target_of(location)), out);
  }

  /// writes the same path as `shortest_path_points()` as face locations to `out` (value type
  /// `Face_location`): a vertex as a corner of one of its faces, an edge point in one of its two faces.
  template <class OutputIterator>
  OutputIterator shortest_path_locations(vertex_descriptor v, OutputIterator out)
  {
    return locations_of(trace(target_of(v)), out);
  }

  /// the same from a point of the surface.
  template <class FT, class OutputIterator>
  OutputIterator shortest_path_locations(const std::pair<face_descriptor, std::array<FT, 3> >& location,
                                         OutputIterator out)
  {
    return locations_of(trace(target_of(location)), out);
  }
  /// @}

  /// \name Mesh
  /// @{

  /// the dense index of `v` (vertices are numbered in the order of `vertices(tm)`).
  std::size_t vertex_id(vertex_descriptor v) const { return static_cast<std::size_t>(get(m_vertex_id, v)); }
  /// the vertices, in the order of their dense indices.
  const std::vector<vertex_descriptor>& vertex_list() const { return m_vertices; }
  /// number of vertices and faces of the mesh.
  std::size_t number_of_vertices() const { return m_vertices.size(); }
  std::size_t number_of_faces() const { return static_cast<std::size_t>(m_arrays.nf); }
  /// mean edge length `h` of the mesh.
  double mean_edge_length() const { return m_arrays.mean_edge_length * m_length_scale; }
  /// anisotropy degree `tau` of the mesh (1 for equilateral triangles).
  double anisotropy() const { return m_arrays.anisotropy; }
  /// number of saddle or boundary vertices (pseudo-source candidates).
  std::size_t number_of_pseudo_source_vertices() const
  {
    std::size_t n = 0;
    for(unsigned char c : m_arrays.is_pseudo_source) n += c;
    return n;
  }
  /// seconds spent in the constructor.
  double preprocessing_seconds() const { return m_preprocessing_seconds; }
  /// @}

  /// \cond SKIP_IN_MANUAL
  const internal::Mesh_arrays& mesh_arrays() const { return m_arrays; }
  /// \endcond

private:
  void build(int threads)
  {
    const auto t0 = std::chrono::steady_clock::now();
#ifdef _OPENMP
    if(threads <= 0)
      threads = omp_get_max_threads();
#endif
    threads = (std::max)(1, threads);
    // The per-mesh arrays number vertices and half-edges with 32-bit integers.
    const std::size_t max_index = static_cast<std::size_t>((std::numeric_limits<Index>::max)());
    if(static_cast<std::size_t>(num_vertices(m_tm)) > max_index
       || static_cast<std::size_t>(num_faces(m_tm)) > max_index / 3)
      throw Invalid_input_error("the mesh is too large (more than " + std::to_string(max_index) + " vertices or "
                                + std::to_string(max_index / 3) + " faces)");

    typename Geom_traits::Compute_squared_distance_3 sqd = m_traits.compute_squared_distance_3_object();
    typename Geom_traits::Compute_squared_area_3 sqa = m_traits.compute_squared_area_3_object();

    // The numbering writes the dynamic property maps: one thread (a dynamic map may be a hash map). It
    // checks that every face is a triangle.
    Index nv = 0;
    m_vertices.reserve(num_vertices(m_tm));
    for(vertex_descriptor v : vertices(m_tm))
    {
      put(m_vertex_id, v, nv++);
      m_vertices.push_back(v);
    }
    // Half-edges are numbered face by face (3f, 3f+1, 3f+2); the arrays are filled in place (no
    // per-half-edge temporary beyond the numbering map), so that the peak memory of the
    // construction stays close to that of the arrays.
    Halfedge_id_map hid = get(CGAL::dynamic_halfedge_property_t<Index>(), m_tm);
    m_faces.reserve(num_faces(m_tm));
    for(face_descriptor f : faces(m_tm))
    {
      put(m_face_id, f, static_cast<Index>(m_faces.size()));
      const halfedge_descriptor h0 = halfedge(f, m_tm);
      halfedge_descriptor h = h0;
      for(int k = 0; k < 3; ++k)
      {
        put(hid, h, static_cast<Index>(3 * m_faces.size() + static_cast<std::size_t>(k)));
        h = next(h, m_tm);
        if((h == h0) != (k == 2))  // a face of another degree than 3
          throw Invalid_input_error("the mesh is not a triangle mesh (some face is not a triangle)");
      }
      m_faces.push_back(f);
    }
    const std::size_t nf = m_faces.size();
    std::vector<Index> tri(3 * nf), opp(3 * nf);
    std::vector<internal::Face_geometry> face_geometry(nf);
    // One pass over the faces (the mesh is read once), which only reads the mesh and the maps: the faces
    // are shared among the threads. The squared area is kept in `area` until the scale is known. An
    // exception of the traits or the maps is caught in the loop (it cannot leave a parallel region) and
    // thrown after it.
    double longest = 0.;
    bool finite = true;
    std::exception_ptr error;
    const long long nfl = static_cast<long long>(nf);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1) reduction(max : longest) reduction(&& : finite)
#endif
    for(long long fl = 0; fl < nfl; ++fl)
    try
    {
      const std::size_t f = static_cast<std::size_t>(fl);
      halfedge_descriptor h = halfedge(m_faces[f], m_tm);
      vertex_descriptor corner[3];
      for(std::size_t k = 0; k < 3; ++k, h = next(h, m_tm))
      {
        corner[k] = source(h, m_tm);
        tri[3 * f + k] = get(m_vertex_id, corner[k]);
        const halfedge_descriptor o = opposite(h, m_tm);
        opp[3 * f + k] = is_border(o, m_tm) ? internal::NO_INDEX : get(hid, o);
      }
      internal::Face_geometry& g = face_geometry[f];
      for(std::size_t k = 0; k < 3; ++k)
      {
        const double l2 = CGAL::to_double(sqd(get(m_vpm, corner[k]), get(m_vpm, corner[(k + 1) % 3])));
        const double l = std::sqrt(l2);
        finite = finite && std::isfinite(l);
        g.length[k] = l;
        longest = (std::max)(longest, l);
      }
      g.area = CGAL::to_double(sqa(get(m_vpm, corner[0]), get(m_vpm, corner[1]), get(m_vpm, corner[2])));
    }
    catch(...)
    {
#ifdef _OPENMP
#pragma omp critical(vtp_geodesics_solver_build)
#endif
      {
        if(!error)
          error = std::current_exception();
      }
    }
    if(error)
      std::rethrow_exception(error);
    if(!finite)
      throw Invalid_input_error("the mesh has an edge of non-finite length (non-finite or too large coordinates)");
    // The engine works on lengths scaled by a power of two (exact in floating point) that brings the
    // longest edge into [0.5, 1): its squares and fourth powers can then neither overflow nor
    // underflow, whatever the scale of the coordinates. Distances are scaled back on output.
    int exponent = 0;
    if(longest > 0.)
      std::frexp(longest, &exponent);
    m_length_scale = std::ldexp(1., exponent);
    // multiplying by a power of two that is a normal number rounds as std::ldexp does (both are
    // correctly rounded); ldexp is kept for the extreme scales
    const bool multiply = exponent > -500 && exponent < 500;
    const double down = std::ldexp(1., -exponent), down2 = std::ldexp(1., -2 * exponent);
    auto scaled = [&](double x, int e, double factor) { return multiply ? x * factor : std::ldexp(x, e); };
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1)
#endif
    for(long long fl = 0; fl < nfl; ++fl)
    {
      internal::Face_geometry& g = face_geometry[static_cast<std::size_t>(fl)];
      const double longest_edge = (std::max)(g.length[0], (std::max)(g.length[1], g.length[2]));
      for(double& l : g.length)
        l = scaled(l, -exponent, down);
      // face areas from the points (accurate for nearly flat triangles, see VTPGeodesicTraits_3);
      // -1 where that overflows or underflows: the engine then uses the lengths
      const double a2 = g.area;  // the squared area, from the first pass
      g.area = -1.;
      const double a = scaled(std::sqrt(a2), -2 * exponent, down2);
      // a zero is trusted only where the squared area of a face of relative height 1e-12
      // could not have underflowed (edges longer than 1e-60)
      if(std::isfinite(a2) && std::isfinite(a) && (a > 0. || (a2 == 0. && longest_edge > 1e-60)))
        g.area = a;
    }
    m_arrays.build(nv, std::move(tri), std::move(opp), std::move(face_geometry), threads);
    m_engine.distances().assign(static_cast<std::size_t>(nv), std::numeric_limits<double>::infinity());
    m_preprocessing_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  // ------------------------------------------------------------------------------------------------
  // sources
  // ------------------------------------------------------------------------------------------------
  bool is_vertex(vertex_descriptor v) const
  {
    if(!internal::is_live_index(m_tm, v))
      return false;
    const std::size_t id = static_cast<std::size_t>(get(m_vertex_id, v));
    return id < m_vertices.size() && m_vertices[id] == v;
  }

  internal::Seed seed_of(vertex_descriptor v, Index label) const
  {
    if(!is_vertex(v))
      throw Invalid_input_error("a source is not a vertex of the mesh");
    internal::Seed s;
    s.kind = internal::Seed::AT_VERTEX;
    s.element = get(m_vertex_id, v);
    s.label = label;
    return s;
  }

  template <class FT>
  internal::Seed seed_of(const std::pair<face_descriptor, std::array<FT, 3> >& location, Index label) const
  {
    const face_descriptor f = location.first;
    bool valid = internal::is_live_index(m_tm, f);
    Index id = NO_FACE;
    if(valid)
    {
      id = get(m_face_id, f);
      valid = id >= 0 && static_cast<std::size_t>(id) < m_faces.size() && m_faces[static_cast<std::size_t>(id)] == f;
    }
    if(!valid)
      throw Invalid_input_error("a face location is not in a face of the mesh");
    double b[3];
    double sum = 0.;
    for(int k = 0; k < 3; ++k)
    {
      b[k] = CGAL::to_double(location.second[static_cast<std::size_t>(k)]);
      sum += b[k];
    }
    // coordinates computed in floating point (e.g. by PMP::locate) may be off by a few ulps
    const double tolerance = 1e-9;
    if(!std::isfinite(sum) || !(std::abs(sum - 1.) <= tolerance) || !(b[0] >= -tolerance) || !(b[1] >= -tolerance)
       || !(b[2] >= -tolerance))
      throw Invalid_input_error("the barycentric coordinates of a face location must be finite, non-negative "
                                "and of sum 1");
    sum = 0.;
    for(int k = 0; k < 3; ++k)
    {
      b[k] = (std::max)(0., b[k]);
      sum += b[k];
    }
    return internal::seed_from_barycentric(m_arrays, id, b[0] / sum, b[1] / sum, b[2] / sum, label);
  }

  // the target of a vertex or a face location (validated as sources are)
  internal::Target target_of(vertex_descriptor v) const
  {
    internal::Target t;
    t.vertex = seed_of(v, 0).element;
    return t;
  }

  template <class FT>
  internal::Target target_of(const std::pair<face_descriptor, std::array<FT, 3> >& location) const
  {
    const internal::Seed s = seed_of(location, 0); // validates
    if(s.kind == internal::Seed::AT_VERTEX)
    {
      internal::Target t;
      t.vertex = s.element;
      return t;
    }
    const Index f = get(m_face_id, location.first);
    double b[3], sum = 0.;
    for(int k = 0; k < 3; ++k)
    {
      b[k] = (std::max)(0., CGAL::to_double(location.second[static_cast<std::size_t>(k)]));
      sum += b[k];
    }
    return internal::target_from_barycentric(m_arrays, f, b[0] / sum, b[1] / sum, b[2] / sum);
  }

  template <class TargetOrRange>
  std::vector<internal::Target> targets_of(const TargetOrRange& targets) const
  {
    std::vector<internal::Target> r;
    if constexpr(std::is_same<TargetOrRange, vertex_descriptor>::value
                 || internal::Is_face_location<TargetOrRange, face_descriptor>::value)
      r.push_back(target_of(targets));
    else
    {
      static_assert(internal::Is_range<TargetOrRange>::value,
                    "a target must be a vertex_descriptor, a face location, or a range of either");
      for(const auto& t : targets)
        r.push_back(target_of(t));
    }
    return r;
  }

  std::vector<internal::Target> targets_of(CGAL::internal_np::Param_not_found) const { return {}; }

  template <class SourceOrRange>
  std::vector<internal::Seed> seeds_of(const SourceOrRange& sources) const
  {
    std::vector<internal::Seed> seeds;
    if constexpr(std::is_same<SourceOrRange, vertex_descriptor>::value
                 || internal::Is_face_location<SourceOrRange, face_descriptor>::value)
      seeds.push_back(seed_of(sources, 0));
    else
    {
      static_assert(internal::Is_range<SourceOrRange>::value,
                    "a source must be a vertex_descriptor, a face location, or a range of either");
      for(const auto& s : sources)
        seeds.push_back(seed_of(s, static_cast<Index>(seeds.size())));
    }
    return seeds;
  }

  // ------------------------------------------------------------------------------------------------
  // computation
  // ------------------------------------------------------------------------------------------------
  // Adds the counts of a row to a sum of rows (the peaks are maxima).
  static void add_row_statistics(const Propagation_statistics& row, Propagation_statistics& sum)
  {
    sum.windows_created += row.windows_created;
    sum.windows_propagated += row.windows_propagated;
    sum.peak_live_windows = (std::max)(sum.peak_live_windows, row.peak_live_windows);
    sum.peak_window_bytes = (std::max)(sum.peak_window_bytes, row.peak_window_bytes);
    sum.vertices_processed += row.vertices_processed;
    sum.pseudo_sources += row.pseudo_sources;
    sum.resets += row.resets;
    sum.reached_vertices += row.reached_vertices;
    sum.max_distance = (std::max)(sum.max_distance, row.max_distance);
    sum.stopped_early = sum.stopped_early || row.stopped_early;
  }

  // The settings of a propagation from the named parameters (validated); the number of threads goes to
  // `threads`.
  template <class NamedParameters>
  internal::Propagation_settings settings_of(const NamedParameters& np, int& threads) const
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    using CGAL::parameters::is_default_parameter;
    const double lambda = choose_parameter(get_parameter(np, internal_np::lambda),
                                           std::numeric_limits<double>::infinity());
    const double lambda_g = choose_parameter(get_parameter(np, internal_np::lambda_g), 1.);
    threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0);
    const double min_length = choose_parameter(get_parameter(np, internal_np::minimum_window_length), 1e-9);
    const double limit = choose_parameter(get_parameter(np, internal_np::maximum_distance),
                                          std::numeric_limits<double>::infinity());
    if(!(lambda > 0.))
      throw Invalid_input_error("lambda must be > 0 (infinity for the exact algorithm), got " + std::to_string(lambda));
    if(!(lambda_g >= 0.) || std::isinf(lambda_g))
      throw Invalid_input_error("lambda_g must be finite and >= 0, got " + std::to_string(lambda_g));
    if(threads < 0)
      throw Invalid_input_error("the number of threads must be >= 0");
    if(!(min_length >= 0.) || !(min_length < 1.))
      throw Invalid_input_error("minimum_window_length must be in [0, 1)");
    if(!(limit >= 0.))
      throw Invalid_input_error("the maximum distance must be >= 0 (+infinity for none), got " + std::to_string(limit));

    internal::Propagation_settings settings;
    settings.minimum_window_ratio = min_length;
    const double h = m_arrays.mean_edge_length;
    if(lambda < std::numeric_limits<double>::infinity() && h > 0.)
      settings.reset_step = lambda * h;
    settings.reset_guard = lambda_g * h;
    settings.want_labels = !is_default_parameter<NamedParameters, internal_np::nearest_source_map_t>::value;
    settings.limit = limit / m_length_scale;
    settings.stop_at_targets = choose_parameter(get_parameter(np, internal_np::stop_at_targets), true);
    settings.record_paths = choose_parameter(get_parameter(np, internal_np::record_paths), false);
    settings.unit = m_length_scale;
    settings.virtual_sources = choose_parameter(get_parameter(np, internal_np::virtual_sources), false);
    return settings;
  }

  template <class ConcurrencyTag, class NamedParameters>
  void run(const std::vector<internal::Seed>& seeds, const NamedParameters& np)
  {
    if(seeds.empty())
      throw Invalid_input_error("no source");
    int threads = 0;
    const internal::Propagation_settings settings = settings_of(np, threads);
    std::vector<internal::Target> targets = targets_of(CGAL::parameters::get_parameter(np, internal_np::targets));
    m_engine.template run<ConcurrencyTag>(m_arrays, seeds, std::move(targets), settings, threads, m_statistics);
    m_last_settings = settings;
    m_last_parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
    m_last_threads = threads;
    m_has_run = true;
    m_statistics.sources = seeds.size();
  }

  template <class VertexDistanceMap, class NamedParameters>
  void write_outputs(VertexDistanceMap vdm, const NamedParameters& np)
  {
    using CGAL::parameters::get_parameter;
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<double>& d = m_engine.distances();
    for(std::size_t i = 0; i < m_vertices.size(); ++i)
      put(vdm, m_vertices[i], d[i]);
    write_labels(get_parameter(np, internal_np::nearest_source_map));
    m_statistics.output_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Propagation_statistics* st = CGAL::parameters::choose_parameter<Propagation_statistics*>(
      get_parameter(np, internal_np::statistics));
    if(st != nullptr)
      *st = m_statistics;
  }

  void write_labels(CGAL::internal_np::Param_not_found) const {}

  template <class VertexSourceMap>
  void write_labels(VertexSourceMap vsm) const
  {
    const std::vector<Index>& l = m_engine.labels();
    for(std::size_t i = 0; i < m_vertices.size(); ++i)
      put(vsm, m_vertices[i], l[i] == internal::NO_INDEX ? no_source : static_cast<std::size_t>(l[i]));
  }

  // ------------------------------------------------------------------------------------------------
  // paths
  // ------------------------------------------------------------------------------------------------
  std::vector<internal::Trace_point> trace(const internal::Target& target)
  {
    if(!m_has_run)
      throw Invalid_input_error("a path was asked for before any computation");
    const internal::Propagation_engine* engine = &m_engine;
    std::size_t index = 0;
    if(!(find_target(m_engine, target, index) && is_reached(m_engine, target, index)))
    {
      // run again from the same sources until the point is final, recording the trace-back
      if(!m_path_engine)
        m_path_engine.reset(new internal::Propagation_engine());
      internal::Propagation_settings settings = m_last_settings;
      settings.want_labels = false;
      settings.stop_at_targets = true;
      settings.record_paths = true;
      Propagation_statistics unused;
      std::vector<internal::Target> targets(1, target);
      if(m_last_parallel)
      {
#ifdef _OPENMP
        m_path_engine->template run<CGAL::Parallel_tag>(m_arrays, m_engine.seeds(), std::move(targets), settings,
                                                        m_last_threads, unused);
#endif
      }
      else
        m_path_engine->template run<CGAL::Sequential_tag>(m_arrays, m_engine.seeds(), std::move(targets), settings,
                                                          m_last_threads, unused);
      engine = m_path_engine.get();
      index = 0;
      if(!is_reached(*engine, target, index))
        throw Invalid_input_error("no path: the point is not reached by any source (or lies beyond the distance "
                                  "limit)");
    }
    std::vector<internal::Trace_point> points;
    const internal::Path_trace tracer(m_arrays, engine->path_record(), engine->seeds());
    const bool ok = target.vertex != internal::NO_INDEX
                      ? tracer.from_vertex(target.vertex, points)
                      : tracer.from_target(engine->targets()[index], engine->path_record().target[index], points);
    if(!ok)
      throw std::runtime_error("the geodesic path could not be traced back through the faces it crosses");
    return points;
  }

  // whether `target` can be traced from the record of `engine`: a vertex (from its own record), or a point
  // that was its target `index`
  static bool find_target(const internal::Propagation_engine& engine, const internal::Target& target,
                          std::size_t& index)
  {
    if(!engine.path_record().is_active())
      return false;
    if(target.vertex != internal::NO_INDEX)
      return true;
    const std::vector<internal::Target>& targets = engine.targets();
    for(std::size_t i = 0; i < targets.size(); ++i)
      if(targets[i].face == target.face && targets[i].x[0] == target.x[0] && targets[i].y[0] == target.y[0])
      {
        index = i;
        return true;
      }
    return false;
  }

  static bool is_reached(const internal::Propagation_engine& engine, const internal::Target& target,
                         std::size_t index)
  {
    const double d = target.vertex != internal::NO_INDEX ? engine.distances()[static_cast<std::size_t>(target.vertex)]
                                                         : engine.target_distance(index);
    return d < std::numeric_limits<double>::infinity();
  }

  Face_location location_of(const internal::Trace_point& p) const
  {
    std::array<double, 3> b = { { 0., 0., 0. } };
    Index f;
    if(p.kind == internal::Trace_point::AT_VERTEX)
    {
      const Index v = p.element;
      if(m_arrays.corner_begin[v] == m_arrays.corner_begin[v + 1])
        throw Invalid_input_error("an isolated vertex has no face location");
      const Index h = m_arrays.corners[m_arrays.corner_begin[v]];
      f = internal::Mesh_arrays::face(h);
      b[static_cast<std::size_t>(h % 3)] = 1.;
    }
    else if(p.kind == internal::Trace_point::ON_EDGE)
    {
      const Index h = p.element;
      f = internal::Mesh_arrays::face(h);
      const double length = m_arrays.geometry[h].length;
      const double t = length > 0. ? (std::min)((std::max)(p.x / length, 0.), 1.) : 0.;
      b[static_cast<std::size_t>(h % 3)] = 1. - t;
      b[static_cast<std::size_t>((h + 1) % 3)] = t;
    }
    else
    {
      f = p.element;
      const internal::Halfedge_geometry& g = m_arrays.geometry[3 * f];
      b[2] = g.cy > 0. ? p.y / g.cy : 0.;
      b[1] = g.length > 0. ? (p.x - b[2] * g.cx) / g.length : 0.;
      b[0] = 1. - b[1] - b[2];
    }
    return Face_location(m_faces[static_cast<std::size_t>(f)], b);
  }

  Point_3 point_of(const internal::Trace_point& p) const
  {
    if(p.kind == internal::Trace_point::AT_VERTEX)
      return get(m_vpm, m_vertices[static_cast<std::size_t>(p.element)]);
    const Face_location l = location_of(p);
    const halfedge_descriptor h = halfedge(l.first, m_tm);
    const Point_3 q[3] = { get(m_vpm, source(h, m_tm)), get(m_vpm, target(h, m_tm)),
                           get(m_vpm, target(next(h, m_tm), m_tm)) };
    double c[3] = { 0., 0., 0. };
    for(int k = 0; k < 3; ++k)
      for(int j = 0; j < 3; ++j)
        c[j] += l.second[static_cast<std::size_t>(k)] * CGAL::to_double(q[k][j]);
    return Point_3(c[0], c[1], c[2]);
  }

  template <class OutputIterator>
  OutputIterator points_of(const std::vector<internal::Trace_point>& path, OutputIterator out) const
  {
    for(const internal::Trace_point& p : path)
      *out++ = point_of(p);
    return out;
  }

  template <class OutputIterator>
  OutputIterator locations_of(const std::vector<internal::Trace_point>& path, OutputIterator out) const
  {
    for(const internal::Trace_point& p : path)
      *out++ = location_of(p);
    return out;
  }

  static const Index NO_FACE = -1;

  const TriangleMesh& m_tm;
  Vertex_point_map m_vpm;
  Geom_traits m_traits;
  Vertex_id_map m_vertex_id;
  Face_id_map m_face_id;
  std::vector<vertex_descriptor> m_vertices;
  std::vector<face_descriptor> m_faces;
  internal::Mesh_arrays m_arrays;
  double m_length_scale = 1.; // the engine's unit of length (a power of two)
  double m_preprocessing_seconds = 0.;
  std::vector<internal::Seed> m_sources;
  internal::Propagation_engine m_engine;
  Propagation_statistics m_statistics;
  // the parameters of the last computation, for the paths
  bool m_has_run = false;
  internal::Propagation_settings m_last_settings;
  bool m_last_parallel = false;
  int m_last_threads = 0;
  std::unique_ptr<internal::Propagation_engine> m_path_engine;
  std::vector<std::unique_ptr<internal::Propagation_engine> > m_workspaces;  // of compute_each(), one per thread
};

} // namespace VTP_geodesics
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_VTP_GEODESICS_GEODESIC_DISTANCE_SOLVER_H
