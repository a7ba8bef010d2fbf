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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_MESH_SURFACE_POINT_H
#define CGAL_VTP_GEODESICS_INTERNAL_MESH_SURFACE_POINT_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A point of the surface, in the terms of the mesh arrays: a vertex, a point of an edge, or a point inside a
// face. The sources of a propagation (Seed, propagation/Seeding.h) and the points of a path (Trace_point,
// paths/Path_trace_ends.h) are such points.
struct Surface_point
{
  enum Kind { AT_VERTEX, ON_EDGE, IN_FACE };
  Kind kind = AT_VERTEX;
  Index element = NO_INDEX;  // AT_VERTEX: the vertex; ON_EDGE: a half-edge of the edge; IN_FACE: the face
  double x = 0., y = 0.;     // ON_EDGE: abscissa on the half-edge; IN_FACE: the point in the frame of 3f
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_MESH_SURFACE_POINT_H
