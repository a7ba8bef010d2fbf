// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_LOCATE_H
#define VTP_GEODESICS_APP_LOCATE_H

// Points given on the command line (--source-point, --target-point, --path-to-point), located on the mesh of
// the computation: the nearest point of the surface, as a face location (vtp_support/surface_locator.h), or an
// error that names the option and the point.

#include <vtp_support/read_mesh.h>
#include <vtp_support/surface_locator.h>

#include <array>
#include <string>

namespace vtp_geodesics_app {

// A face and the barycentric coordinates of the point with respect to source(halfedge(f)), target(halfedge(f)),
// target(next(halfedge(f))): the face location of CGAL::Polygon_mesh_processing and of the library.
typedef vtp_support::Surface_locator::Face_location Face_location;

struct Located_point
{
  Face_location location;          // finite, non-negative coordinates of sum 1
  std::array<double, 3> point;     // the point of the surface it denotes
};

// Locates points on a mesh: one AABB tree of its faces, built by the constructor.
class Point_locator
{
public:
  // `mesh` must have a face, and must outlive the locator.
  explicit Point_locator(const vtp_support::Mesh& mesh) : m_locator(mesh) {}

  // The point of the surface nearest to `p`. Throws Tool_error, naming `option` and the point, if it cannot be
  // located (e.g. its nearest face is degenerate).
  Located_point locate(const std::array<double, 3>& p, const std::string& option) const;

private:
  vtp_support::Surface_locator m_locator;
};

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_LOCATE_H
