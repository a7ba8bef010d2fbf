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

#ifndef CGAL_VTP_GEODESICS_STRAIGHTEST_GEODESIC_H
#define CGAL_VTP_GEODESICS_STRAIGHTEST_GEODESIC_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Surface_polyline.h>

#include <array>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// The result of a straightest geodesic (the exponential map: `Geodesic_distance_solver::straightest_geodesic()`).
///
/// The walk goes straight inside each face and across each edge (the next face unfolded into the plane of
/// the one before); at a vertex it leaves so that the angles on its two sides are equal, each half of the
/// vertex's angle sum (Polthier and Schmies' straightest geodesics; at a vertex whose angle sum is 2 pi the
/// line goes straight on). It stops after the length asked for, or exactly on the border when it reaches it
/// (an edge of the border, or a border vertex: the rule has no meaning there), or on the edge of a face of
/// (almost) zero area, which has no plane to walk in.
///
/// It is a `Surface_polyline` (`points` and `locations`): the start, each crossing of an edge (located in the
/// face the walk leaves), each vertex passed (in the face the walk arrives from) and the end (in its face). Two
/// consecutive points may be the same point of the surface in two faces (a start on an edge, a vertex the walk
/// turns at).
///
/// \tparam FaceDescriptor the face descriptor of the mesh.
/// \tparam Point3 the point type of the vertex point map.
template <class FaceDescriptor, class Point3>
struct Straightest_geodesic : Surface_polyline<FaceDescriptor, Point3>
{
  /// the location type of this package (`CGAL::VTP_geodesics::Face_location<FaceDescriptor>`).
  typedef VTP_geodesics::Face_location<FaceDescriptor> Face_location;

  /// the end point: `locations.back()` and `points.back()`.
  Face_location end_location;
  Point3 end_point;
  /// the unit direction of the walk at its end, a tangent vector of the end's face.
  std::array<double, 3> end_direction = { { 0., 0., 0. } };
  /// the length walked: the length asked for, or less if the walk stopped before.
  double length = 0.;
  /// whether the walk stopped on the border before its length.
  bool reached_border = false;
  /// whether the walk stopped at a face of (almost) zero area before its length.
  bool reached_degenerate_face = false;
};

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_STRAIGHTEST_GEODESIC_H
