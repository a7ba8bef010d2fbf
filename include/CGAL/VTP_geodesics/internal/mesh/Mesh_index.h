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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_INDEX_H
#define CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_INDEX_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>
#include <CGAL/VTP_geodesics/internal/propagation/Targets.h>
#include <CGAL/VTP_geodesics/internal/mesh/Source_forms.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The mesh as the engine sees it, and the way between the two: the dense indices of the vertices and
// faces (dynamic property maps, and the descriptors in index order), the arrays of the engine
// (Mesh_arrays) and the unit of length of the engine (a power of two, see Mesh_import.h). It checks the
// descriptors the user gives (sources, targets) and turns them into the seeds and targets of the engine.
template <class TriangleMesh>
class Mesh_index
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<Index> >::const_type
    Vertex_id_map;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<Index> >::const_type
    Face_id_map;

  explicit Mesh_index(const TriangleMesh& m)
    : tm(m),
      vertex_id(get(CGAL::dynamic_vertex_property_t<Index>(), m)),
      face_id(get(CGAL::dynamic_face_property_t<Index>(), m))
  {}

  const TriangleMesh& tm;
  Vertex_id_map vertex_id;
  Face_id_map face_id;
  // The engine numbers the vertices along a space-filling curve (Mesh_import.h), for the locality of its
  // per-vertex arrays; users see them numbered in the order of vertices(tm) (their *position*).
  std::vector<vertex_descriptor> vertices;           // in index order
  std::vector<vertex_descriptor> vertices_in_order;  // in the order of vertices(tm)
  std::vector<Index> position;                       // per index, the position of the vertex in vertices(tm)
  std::vector<face_descriptor> faces;                // in index order (by their least vertex index)
  std::vector<Index> face_position;                  // per face index, the position of the face in faces(tm)
  Mesh_arrays arrays;
  double length_scale = 1.;                 // the engine's unit of length, in the unit of the mesh

  // the position in vertices(tm) of the vertex of index i
  std::size_t position_of(Index i) const { return static_cast<std::size_t>(position[static_cast<std::size_t>(i)]); }

  // `values` (per index) in the order of vertices(tm)
  template <class T>
  void to_positions(const std::vector<T>& values, std::vector<T>& out) const
  {
    CGAL_precondition(values.size() == position.size());
    out.resize(values.size());
    for(std::size_t i = 0; i < values.size(); ++i)
      out[static_cast<std::size_t>(position[i])] = values[i];
  }

  // ------------------------------------------------------------------------------------------------
  // descriptors -> indices (checked)
  // ------------------------------------------------------------------------------------------------
  bool is_vertex(vertex_descriptor v) const
  {
    if(!internal::is_live_index(tm, v))
      return false;
    const std::size_t id = static_cast<std::size_t>(get(vertex_id, v));
    return id < vertices.size() && vertices[id] == v;
  }

  // the index of face f, NO_INDEX if f is not a face of the mesh
  Index face_index(face_descriptor f) const
  {
    if(!internal::is_live_index(tm, f))
      return NO_INDEX;
    const Index id = get(face_id, f);
    const bool valid = id >= 0 && static_cast<std::size_t>(id) < faces.size() && faces[static_cast<std::size_t>(id)] == f;
    return valid ? id : NO_INDEX;
  }

  // What the error messages call a source or target: `role` and its position in the user's list (none
  // for no_position).
  static constexpr std::size_t no_position = static_cast<std::size_t>(-1);
  static std::string name_of(const char* role, std::size_t position)
  {
    return position == no_position ? std::string(role) : std::string(role) + " " + std::to_string(position);
  }

  // The seed of source number `label` (its position in the user's list).
  Seed seed_of(vertex_descriptor v, Index label) const { return seed_of(v, label, "source", std::size_t(label)); }

  template <class FT>
  Seed seed_of(const std::pair<face_descriptor, std::array<FT, 3> >& location, Index label) const
  {
    return seed_of(location, label, "source", std::size_t(label));
  }

  Seed seed_of(vertex_descriptor v, Index label, const char* role, std::size_t position) const
  {
    if(!is_vertex(v))
      throw Invalid_input_error(name_of(role, position) + " is not a vertex of the mesh");
    Seed s;
    s.kind = Seed::AT_VERTEX;
    s.element = get(vertex_id, v);
    s.label = label;
    return s;
  }

  template <class FT>
  Seed seed_of(const std::pair<face_descriptor, std::array<FT, 3> >& location, Index label, const char* role,
               std::size_t position) const
  {
    const Index id = face_index(location.first);
    if(id == NO_INDEX)
      throw Invalid_input_error(name_of(role, position) + " (a face location) is not in a face of the mesh");
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
      throw Invalid_input_error("the barycentric coordinates of " + name_of(role, position) + " (in face "
                                + std::to_string(face_position[static_cast<std::size_t>(id)]) + ") must be finite, non-negative and of sum 1");
    sum = 0.;
    for(int k = 0; k < 3; ++k)
    {
      b[k] = (std::max)(0., b[k]);
      sum += b[k];
    }
    Seed s = seed_from_barycentric(arrays, id, b[0] / sum, b[1] / sum, b[2] / sum, label);
    s.user_face = id;
    return s;
  }

  // the edge of half-edge h for the seeds of a source of edges: {its source, its target, a face of it} in
  // indices (source_curves/Curve_seeds.h); `label` names the source in the error message
  template <class Halfedge>
  std::array<Index, 3> edge_of(const Halfedge& h, Index label) const
  {
    const std::string name = "source " + std::to_string(label) + " (edges)";
    const vertex_descriptor a = source(h, tm), b = target(h, tm);
    if(!is_vertex(a) || !is_vertex(b))
      throw Invalid_input_error(name + ": a half-edge is not a half-edge of the mesh");
    face_descriptor f = face(h, tm);
    if(f == boost::graph_traits<TriangleMesh>::null_face())
      f = face(opposite(h, tm), tm);
    const Index fi = f == boost::graph_traits<TriangleMesh>::null_face() ? NO_INDEX : face_index(f);
    if(fi == NO_INDEX)
      throw Invalid_input_error(name + ": a half-edge has no face of the mesh");
    return { get(vertex_id, a), get(vertex_id, b), fi };
  }

  // the target of a vertex or a face location (validated as sources are; `role` and `position` name it in
  // the error messages)
  Target target_of(vertex_descriptor v, const char* role = "target", std::size_t position = no_position) const
  {
    Target t;
    t.vertex = seed_of(v, 0, role, position).element;
    return t;
  }

  template <class FT>
  Target target_of(const std::pair<face_descriptor, std::array<FT, 3> >& location, const char* role = "target",
                   std::size_t position = no_position) const
  {
    const Seed s = seed_of(location, 0, role, position); // validates
    if(s.kind == Seed::AT_VERTEX)
    {
      Target t;
      t.vertex = s.element;
      return t;
    }
    const Index f = get(face_id, location.first);
    double b[3], sum = 0.;
    for(int k = 0; k < 3; ++k)
    {
      b[k] = (std::max)(0., CGAL::to_double(location.second[static_cast<std::size_t>(k)]));
      sum += b[k];
    }
    return target_from_barycentric(arrays, f, b[0] / sum, b[1] / sum, b[2] / sum);
  }

  // the seeds of a source or a range of sources, labelled by their positions
  template <class SourceOrRange>
  std::vector<Seed> seeds_of(const SourceOrRange& sources) const
  {
    std::vector<Seed> seeds;
    if constexpr(is_one<SourceOrRange>())
      seeds.push_back(seed_of(sources, 0));
    else
    {
      static_assert(Is_range<SourceOrRange>::value,
                    "a source must be a vertex_descriptor, a face location, or a range of either");
      for(const auto& s : sources)
        seeds.push_back(seed_of(s, static_cast<Index>(seeds.size())));
    }
    return seeds;
  }

  // the targets of a target or a range of targets (none if the named parameter is absent)
  template <class TargetOrRange>
  std::vector<Target> targets_of(const TargetOrRange& targets) const
  {
    std::vector<Target> r;
    if constexpr(is_one<TargetOrRange>())
      r.push_back(target_of(targets, "target", 0));
    else
    {
      static_assert(Is_range<TargetOrRange>::value,
                    "a target must be a vertex_descriptor, a face location, or a range of either");
      for(const auto& t : targets)
        r.push_back(target_of(t, "target", r.size()));
    }
    return r;
  }

  std::vector<Target> targets_of(CGAL::internal_np::Param_not_found) const { return {}; }

private:
  // whether T is one source or target (not a range)
  template <class T>
  static constexpr bool is_one()
  {
    return std::is_same<T, vertex_descriptor>::value || Is_face_location<T, face_descriptor>::value;
  }
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_INDEX_H
