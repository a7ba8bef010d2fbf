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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_MESH_SOURCE_FORMS_H
#define CGAL_VTP_GEODESICS_INTERNAL_MESH_SOURCE_FORMS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <iterator>
#include <type_traits>
#include <utility>

namespace CGAL {

template <class P> class Surface_mesh;

namespace VTP_geodesics {
namespace internal {

// The forms a source (or a target) can take in the API: a vertex descriptor, a face location
// (std::pair<face_descriptor, std::array<FT, 3>>, as CGAL::Polygon_mesh_processing::Face_location), or
// a range of either.

template <class T, class Face>
struct Is_face_location : std::false_type {};

template <class FT, class Face>
struct Is_face_location<std::pair<Face, std::array<FT, 3> >, Face> : std::true_type {};

// Whether T is a CGAL named-parameter chain (derives from some CGAL::Named_function_parameters).
template <class T, class Tag, class Base>
std::true_type is_named_parameters_test(const CGAL::Named_function_parameters<T, Tag, Base>*);
std::false_type is_named_parameters_test(...);

template <class T>
struct Is_named_parameters : decltype(is_named_parameters_test(std::declval<const T*>())) {};

// Whether T is a range (std::begin / std::end apply).
template <class T, class = void>
struct Is_range : std::false_type {};

template <class T>
struct Is_range<T, decltype(void(std::begin(std::declval<const T&>())), void(std::end(std::declval<const T&>())))>
  : std::true_type {};

// Whether the index of `v` lies within the index range of the mesh and denotes a live element. Generic
// meshes have no index range (the descriptor is looked up in the solver's own table); a Surface_mesh has
// one, and removed elements.
template <class TriangleMesh, class Descriptor>
bool is_live_index(const TriangleMesh&, const Descriptor&)
{
  return true;
}

template <class P>
bool is_live_index(const CGAL::Surface_mesh<P>& sm, const typename CGAL::Surface_mesh<P>::Vertex_index& v)
{
  return static_cast<std::size_t>(v) < static_cast<std::size_t>(sm.num_vertices()) && !sm.is_removed(v);
}

template <class P>
bool is_live_index(const CGAL::Surface_mesh<P>& sm, const typename CGAL::Surface_mesh<P>::Face_index& f)
{
  return static_cast<std::size_t>(f) < static_cast<std::size_t>(sm.num_faces()) && !sm.is_removed(f);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_MESH_SOURCE_FORMS_H
