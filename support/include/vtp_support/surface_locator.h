// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_SURFACE_LOCATOR_H
#define VTP_SUPPORT_SURFACE_LOCATOR_H

// The nearest point of a mesh's surface to a position, as a face location usable as a source or a target of
// the library (shared by vtp_geodesics --source-point and the Python module's locate()): one AABB tree of the
// faces, CGAL::Polygon_mesh_processing::locate_with_AABB_tree, and the cleanup of its barycentric coordinates.
// Compiled once, in the library VTP_geodesics_support (src/surface_locator.cpp: CGAL's AABB tree and locate are
// slow to compile).

#include <vtp_support/read_mesh.h>

#include <array>
#include <memory>
#include <utility>

namespace vtp_support {

class Surface_locator
{
public:
  typedef std::pair<Mesh::Face_index, std::array<double, 3> > Face_location;

  // Builds the tree of the faces of `mesh`, which must outlive the locator and not change.
  explicit Surface_locator(const Mesh& mesh);
  ~Surface_locator();
  Surface_locator(const Surface_locator&) = delete;
  Surface_locator& operator=(const Surface_locator&) = delete;

  // The point of the surface nearest to `p` as a face location with finite, non-negative barycentric coordinates
  // of sum 1 (with respect to source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))), as the library
  // takes them): PMP::locate's coordinates may be off by a few ulps (slightly negative, sum not exactly 1; a point
  // on an edge may come out 1e-16 inside the face, which the library takes as the edge point). Returns false if
  // there is no such location (the nearest face is degenerate: no coordinates at all).
  bool locate(const Point_3& p, Face_location& location) const;

  // The point a face location denotes.
  std::array<double, 3> point_of(const Face_location& l) const;

private:
  struct Tree;
  const Mesh& m_mesh;
  std::unique_ptr<Tree> m_tree;
};

// The length of the diagonal of the bounding box of the mesh's vertices (0 without vertex).
double bounding_box_diagonal(const Mesh& mesh);

// A point of a source curve given as a position (vtp_geodesics --source-curve, the Python module's curves=)
// farther from the surface than this share of bounding_box_diagonal() is refused: the other positions are
// replaced by their nearest surface points, but a curve far off the surface is more likely a curve of another
// mesh, or in other units.
constexpr double curve_point_tolerance = 1e-6;

} // namespace vtp_support

#endif // VTP_SUPPORT_SURFACE_LOCATOR_H
