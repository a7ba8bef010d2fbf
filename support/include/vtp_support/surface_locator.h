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

#include <vtp_support/read_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace vtp_support {

class Surface_locator
{
public:
  typedef std::pair<Mesh::Face_index, std::array<double, 3> > Face_location;

  // Builds the tree of the faces of `mesh`, which must outlive the locator and not change.
  explicit Surface_locator(const Mesh& mesh) : m_mesh(mesh)
  {
    CGAL::Polygon_mesh_processing::build_AABB_tree(mesh, m_tree);
  }
  Surface_locator(const Surface_locator&) = delete;
  Surface_locator& operator=(const Surface_locator&) = delete;

  // The point of the surface nearest to `p` as a face location with finite, non-negative barycentric coordinates
  // of sum 1 (with respect to source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))), as the library
  // takes them): PMP::locate's coordinates may be off by a few ulps (slightly negative, sum not exactly 1; a point
  // on an edge may come out 1e-16 inside the face, which the library takes as the edge point). Returns false if
  // there is no such location (the nearest face is degenerate: no coordinates at all).
  bool locate(const Point_3& p, Face_location& location) const
  {
    const CGAL::Polygon_mesh_processing::Face_location<Mesh, double> l =
      CGAL::Polygon_mesh_processing::locate_with_AABB_tree(p, m_tree, m_mesh);
    std::array<double, 3> b = l.second;
    double sum = 0.;
    bool finite = true;
    for(double& x : b)
    {
      finite = finite && std::isfinite(x);
      sum += (std::max)(0., x);
    }
    if(!finite || !(sum > 0.5 && sum < 1.5) || l.first == Mesh::null_face())
      return false;
    for(double& x : b)
      x = (std::max)(0., x) / sum;
    location = Face_location(l.first, b);
    return true;
  }

  // The point a face location denotes.
  std::array<double, 3> point_of(const Face_location& l) const
  {
    const Mesh::Halfedge_index h = m_mesh.halfedge(l.first);
    const Point_3 q[3] = { m_mesh.point(m_mesh.source(h)), m_mesh.point(m_mesh.target(h)),
                           m_mesh.point(m_mesh.target(m_mesh.next(h))) };
    std::array<double, 3> r;
    for(int j = 0; j < 3; ++j)
      r[std::size_t(j)] = l.second[0] * q[0][j] + l.second[1] * q[1][j] + l.second[2] * q[2][j];
    return r;
  }

private:
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > Tree;
  const Mesh& m_mesh;
  Tree m_tree;
};

} // namespace vtp_support

#endif // VTP_SUPPORT_SURFACE_LOCATOR_H
