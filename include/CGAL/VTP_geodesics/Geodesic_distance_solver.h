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
#include <CGAL/VTP_geodesics/options_and_statistics.h>
#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/Propagation_engine.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// \brief computes exact (or, on request, approximate) geodesic distances from a source vertex
/// to all vertices of a triangle mesh by vertex-oriented triangle propagation (VTP).
///
/// The per-mesh preprocessing (compact half-edge arrays, edge lengths, corner angles, saddle and
/// boundary flags, mean edge length and anisotropy) is done once, in the constructor; `compute()`
/// can then be called for as many sources as needed. The mesh must not be modified while the solver
/// is in use.
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
  /// @}

private:
  typedef internal::Index Index;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<Index> >::const_type
    Vertex_id_map;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<Index> >::const_type
    Halfedge_id_map;

public:
  /// builds the per-mesh data of `tm`, with the vertex point map `get(CGAL::vertex_point, tm)`.
  /// \throws Invalid_input_error if `tm` is not a triangle mesh, an edge length is not finite, or `tm` has
  /// more than 2^31 - 1 vertices or (2^31 - 1) / 3 faces.
  explicit Geodesic_distance_solver(const TriangleMesh& tm)
    : Geodesic_distance_solver(tm, get(CGAL::vertex_point, tm))
  {}

  /// builds the per-mesh data of `tm` with the vertex point map `vpm` and the traits `traits`.
  /// \throws Invalid_input_error if `tm` is not a triangle mesh, an edge length is not finite, or `tm` has
  /// more than 2^31 - 1 vertices or (2^31 - 1) / 3 faces.
  Geodesic_distance_solver(const TriangleMesh& tm, Vertex_point_map vpm, const Geom_traits& traits = Geom_traits())
    : m_tm(tm), m_vpm(vpm), m_traits(traits),
      m_vertex_id(get(CGAL::dynamic_vertex_property_t<Index>(), tm))
  {
    build();
  }

  /// computes the geodesic distance from `source` to every vertex of the mesh and writes it into `vdm`.
  /// Vertices that cannot be reached from `source` (other connected components, isolated vertices)
  /// get `std::numeric_limits<double>::infinity()`.
  ///
  /// \tparam ConcurrencyTag `CGAL::Sequential_tag` (VTP / AVTP) or `CGAL::Parallel_tag` (PVTP / PAVTP, needs OpenMP).
  /// \tparam VertexDistanceMap a `WritablePropertyMap` with `vertex_descriptor` as key type and `double` as value type.
  /// \param source the source vertex
  /// \param vdm the output distance map
  /// \param options see `Propagation_options`; the defaults give the exact result.
  /// \returns the statistics of the propagation, also available through `statistics()`.
  /// \throws Invalid_input_error if `source` is not a vertex of the mesh or the options are invalid.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class VertexDistanceMap>
  const Propagation_statistics& compute(vertex_descriptor source,
                                        VertexDistanceMap vdm,
                                        const Propagation_options& options = Propagation_options())
  {
    compute_dense<ConcurrencyTag>(source, options);
    const auto t0 = std::chrono::steady_clock::now();
    for(std::size_t i = 0; i < m_vertices.size(); ++i)
      put(vdm, m_vertices[i], m_distances[i]);
    m_statistics.output_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return m_statistics;
  }

  /// computes the distances from `source` and keeps them inside the solver only, readable with
  /// `distance()` or `distances()`.
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  const Propagation_statistics& compute_dense(vertex_descriptor source,
                                              const Propagation_options& options = Propagation_options())
  {
    const Index s = checked_vertex_id(source);
    check_options(options);
    m_engine.template run<ConcurrencyTag>(m_arrays, s, options, m_distances, m_statistics);
    if(m_length_scale != 1.)
    {
      for(double& d : m_distances)
        d *= m_length_scale;
      m_statistics.max_distance *= m_length_scale;
    }
    return m_statistics;
  }

  /// \name Access
  /// @{

  /// the distances of the last computation, indexed by `vertex_id()`.
  const std::vector<double>& distances() const { return m_distances; }
  /// the distance of `v` in the last computation.
  double distance(vertex_descriptor v) const { return m_distances[vertex_id(v)]; }
  /// the dense index of `v` (vertices are numbered in the order of `vertices(tm)`).
  std::size_t vertex_id(vertex_descriptor v) const { return static_cast<std::size_t>(get(m_vertex_id, v)); }
  /// the vertices, in the order of their dense indices.
  const std::vector<vertex_descriptor>& vertex_list() const { return m_vertices; }
  /// statistics of the last computation.
  const Propagation_statistics& statistics() const { return m_statistics; }
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
  void build()
  {
    const auto t0 = std::chrono::steady_clock::now();
    if(!CGAL::is_triangle_mesh(m_tm))
      throw Invalid_input_error("the mesh is not a triangle mesh (some face is not a triangle)");
    // The per-mesh arrays number vertices and half-edges with 32-bit integers.
    const std::size_t max_index = static_cast<std::size_t>((std::numeric_limits<Index>::max)());
    if(static_cast<std::size_t>(num_vertices(m_tm)) > max_index
       || static_cast<std::size_t>(num_faces(m_tm)) > max_index / 3)
      throw Invalid_input_error("the mesh is too large (more than " + std::to_string(max_index) + " vertices or "
                                + std::to_string(max_index / 3) + " faces)");

    typename Geom_traits::Compute_squared_distance_3 sqd = m_traits.compute_squared_distance_3_object();
    typename Geom_traits::Compute_squared_area_3 sqa = m_traits.compute_squared_area_3_object();

    Index nv = 0;
    for(vertex_descriptor v : vertices(m_tm))
    {
      put(m_vertex_id, v, nv++);
      m_vertices.push_back(v);
    }
    Halfedge_id_map hid = get(CGAL::dynamic_halfedge_property_t<Index>(), m_tm);
    std::vector<halfedge_descriptor> hds;
    hds.reserve(3 * num_faces(m_tm));
    for(face_descriptor f : faces(m_tm))
    {
      halfedge_descriptor h = halfedge(f, m_tm);
      for(int k = 0; k < 3; ++k)
      {
        put(hid, h, static_cast<Index>(hds.size()));
        hds.push_back(h);
        h = next(h, m_tm);
      }
    }
    const std::size_t nh = hds.size();
    std::vector<Index> tri(nh), opp(nh);
    std::vector<double> len(nh);
    for(std::size_t i = 0; i < nh; ++i)
    {
      const halfedge_descriptor h = hds[i];
      tri[i] = get(m_vertex_id, source(h, m_tm));
      const halfedge_descriptor o = opposite(h, m_tm);
      opp[i] = is_border(o, m_tm) ? internal::NO_INDEX : get(hid, o);
      const double l2 = CGAL::to_double(sqd(get(m_vpm, source(h, m_tm)), get(m_vpm, target(h, m_tm))));
      const double l = std::sqrt(l2);
      if(!std::isfinite(l))
        throw Invalid_input_error("the mesh has an edge of non-finite length (non-finite or too large coordinates)");
      len[i] = l;
    }
    // The engine works on lengths scaled by a power of two (exact in floating point) that brings the
    // longest edge into [0.5, 1): its squares and fourth powers can then neither overflow nor
    // underflow, whatever the scale of the coordinates. Distances are scaled back on output.
    double longest = 0.;
    for(double l : len)
      longest = (std::max)(longest, l);
    int exponent = 0;
    if(longest > 0.)
      std::frexp(longest, &exponent);
    m_length_scale = std::ldexp(1., exponent);
    for(double& l : len)
      l = std::ldexp(l, -exponent);
    // face areas from the points (accurate for nearly flat triangles, see VTPGeodesicTraits_3);
    // -1 where that overflows or underflows: the engine then uses the lengths
    std::vector<double> area(nh / 3, -1.);
    for(std::size_t f = 0; f < nh / 3; ++f)
    {
      const halfedge_descriptor h = hds[3 * f];
      const double a2 = CGAL::to_double(sqa(get(m_vpm, source(h, m_tm)), get(m_vpm, target(h, m_tm)),
                                            get(m_vpm, target(next(h, m_tm), m_tm))));
      const double a = std::ldexp(std::sqrt(a2), -2 * exponent);
      // a zero is trusted only where the squared area of a face of relative height 1e-12
      // could not have underflowed (edges longer than 1e-60)
      const double longest_edge = std::ldexp((std::max)(len[3 * f], (std::max)(len[3 * f + 1], len[3 * f + 2])), exponent);
      if(std::isfinite(a2) && std::isfinite(a) && (a > 0. || (a2 == 0. && longest_edge > 1e-60)))
        area[f] = a;
    }
    m_arrays.build(nv, std::move(tri), std::move(opp), len, &area);
    m_distances.assign(static_cast<std::size_t>(nv), std::numeric_limits<double>::infinity());
    m_preprocessing_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  Index checked_vertex_id(vertex_descriptor v) const
  {
    // A descriptor that is not a vertex of the mesh (for example a removed vertex of a
    // Surface_mesh) must not be used as a key of the dynamic map: look for it first.
    bool found = false;
    for(const vertex_descriptor& w : m_vertices)
      if(w == v) { found = true; break; }
    if(!found)
      throw Invalid_input_error("the source is not a vertex of the mesh");
    return get(m_vertex_id, v);
  }

  static void check_options(const Propagation_options& o)
  {
    if(!(o.lambda > 0.))
      throw Invalid_input_error("lambda must be > 0 (infinity for the exact algorithm), got " + std::to_string(o.lambda));
    if(!(o.lambda_g >= 0.) || std::isinf(o.lambda_g))
      throw Invalid_input_error("lambda_g must be finite and >= 0, got " + std::to_string(o.lambda_g));
    if(o.number_of_threads < 0)
      throw Invalid_input_error("the number of threads must be >= 0");
    if(!(o.minimum_window_length >= 0.) || !(o.minimum_window_length < 1.))
      throw Invalid_input_error("minimum_window_length must be in [0, 1)");
  }

  const TriangleMesh& m_tm;
  Vertex_point_map m_vpm;
  Geom_traits m_traits;
  Vertex_id_map m_vertex_id;
  std::vector<vertex_descriptor> m_vertices;
  internal::Mesh_arrays m_arrays;
  internal::Propagation_engine m_engine;
  std::vector<double> m_distances;
  Propagation_statistics m_statistics;
  double m_preprocessing_seconds = 0.;
  double m_length_scale = 1.; // the engine's unit of length (a power of two)
};

} // namespace VTP_geodesics
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_VTP_GEODESICS_GEODESIC_DISTANCE_SOLVER_H
