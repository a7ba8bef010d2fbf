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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOLVER_MESH_INDEX_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOLVER_MESH_INDEX_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/engine/Seeding.h>
#include <CGAL/VTP_geodesics/internal/engine/Targets.h>
#include <CGAL/VTP_geodesics/internal/source_forms.h>

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
  std::vector<vertex_descriptor> vertices;  // in index order
  std::vector<face_descriptor> faces;       // in index order
  Mesh_arrays arrays;
  double length_scale = 1.;                 // the engine's unit of length, in the unit of the mesh

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

  Seed seed_of(vertex_descriptor v, Index label) const
  {
    if(!is_vertex(v))
      throw Invalid_input_error("a source is not a vertex of the mesh");
    Seed s;
    s.kind = Seed::AT_VERTEX;
    s.element = get(vertex_id, v);
    s.label = label;
    return s;
  }

  template <class FT>
  Seed seed_of(const std::pair<face_descriptor, std::array<FT, 3> >& location, Index label) const
  {
    const Index id = face_index(location.first);
    if(id == NO_INDEX)
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
    return seed_from_barycentric(arrays, id, b[0] / sum, b[1] / sum, b[2] / sum, label);
  }

  // the target of a vertex or a face location (validated as sources are)
  Target target_of(vertex_descriptor v) const
  {
    Target t;
    t.vertex = seed_of(v, 0).element;
    return t;
  }

  template <class FT>
  Target target_of(const std::pair<face_descriptor, std::array<FT, 3> >& location) const
  {
    const Seed s = seed_of(location, 0); // validates
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
      r.push_back(target_of(targets));
    else
    {
      static_assert(Is_range<TargetOrRange>::value,
                    "a target must be a vertex_descriptor, a face location, or a range of either");
      for(const auto& t : targets)
        r.push_back(target_of(t));
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

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOLVER_MESH_INDEX_H
