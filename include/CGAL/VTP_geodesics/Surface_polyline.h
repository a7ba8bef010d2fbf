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

#ifndef CGAL_VTP_GEODESICS_SURFACE_POLYLINE_H
#define CGAL_VTP_GEODESICS_SURFACE_POLYLINE_H

#include <CGAL/license/VTP_geodesics.h>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// A point of the surface: a face and the barycentric coordinates of the point with respect to
/// `source(halfedge(f))`, `target(halfedge(f))` and `target(next(halfedge(f)))`. It is the type of
/// `CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>`, and the one type of a location in this
/// package: sources, targets and starts are given as it (the functions that take one accept any number type
/// convertible to `double` too), and every polyline gives its points as it (`Surface_polyline::locations`).
/// `Geodesic_distance_solver::Face_location` and `Straightest_geodesic::Face_location` are this type.
template <class FaceDescriptor>
using Face_location = std::pair<FaceDescriptor, std::array<double, 3> >;

/// \ingroup PkgVTPGeodesicsRef
/// A polyline on the surface: its points in space and the same points as face locations, one each, in order.
/// Two consecutive points lie in a common face (they are joined by a segment inside it, or are the same point
/// of the surface seen from two faces). It is the one type of a polyline of this package: a shortest path
/// (`Geodesic_distance_solver::shortest_path()`), a straightest geodesic (`Straightest_geodesic`, which adds
/// where and why the walk ended) and an isoline or a cell border (`Geodesic_curve`, which adds its level or
/// cells and whether it is closed) are one.
///
/// \tparam FaceDescriptor the face descriptor of the mesh.
/// \tparam Point the point type of the vertex point map.
template <class FaceDescriptor, class Point>
struct Surface_polyline
{
  typedef VTP_geodesics::Face_location<FaceDescriptor> Face_location;
  /// the points in space (from the barycentric coordinates and the vertex point map).
  std::vector<Point> points;
  /// the same points as face locations (`locations.size() == points.size()`).
  std::vector<Face_location> locations;

  /// the number of points.
  std::size_t size() const { return points.size(); }
  /// whether the polyline has no point.
  bool empty() const { return points.empty(); }
};

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_SURFACE_POLYLINE_H
