// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#include "locate.h"
#include "arguments.h"

#include <vtp_support/number_format.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <cmath>

namespace vtp_geodesics_app {

namespace PMP = CGAL::Polygon_mesh_processing;

struct Point_locator::Tree
{
  typedef CGAL::AABB_face_graph_triangle_primitive<vtp_support::Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<vtp_support::Kernel, Primitive> > Type;
  Type tree;
};

Point_locator::Point_locator(const vtp_support::Mesh& mesh) : m_mesh(mesh), m_tree(new Tree())
{
  PMP::build_AABB_tree(mesh, m_tree->tree);
}

Point_locator::~Point_locator() = default;

Located_point Point_locator::locate(const std::array<double, 3>& p, const std::string& option) const
{
  const vtp_support::Point_3 query(p[0], p[1], p[2]);
  const PMP::Face_location<vtp_support::Mesh, double> l = PMP::locate_with_AABB_tree(query, m_tree->tree, m_mesh);
  // PMP::locate gives coordinates that may be off by a few ulps (slightly negative, sum not exactly 1; a point on
  // an edge may come out 1e-16 inside the face, which the library takes as the edge point); on a degenerate
  // face, none at all.
  std::array<double, 3> b = l.second;
  double sum = 0.;
  bool finite = true;
  for(double& x : b)
  {
    finite = finite && std::isfinite(x);
    sum += (std::max)(0., x);
  }
  if(!finite || !(sum > 0.5 && sum < 1.5) || l.first == vtp_support::Mesh::null_face())
    throw Tool_error("cannot locate the point " + vtp_support::double_to_string(p[0]) + ","
                     + vtp_support::double_to_string(p[1]) + "," + vtp_support::double_to_string(p[2]) + " of " + option
                     + " on the surface (its nearest face is degenerate)");
  for(double& x : b)
    x = (std::max)(0., x) / sum;
  Located_point r;
  r.location = Face_location(l.first, b);
  const vtp_support::Mesh::Halfedge_index h = m_mesh.halfedge(l.first);
  const vtp_support::Point_3 q[3] = { m_mesh.point(m_mesh.source(h)), m_mesh.point(m_mesh.target(h)),
                                    m_mesh.point(m_mesh.target(m_mesh.next(h))) };
  for(int j = 0; j < 3; ++j)
    r.point[j] = b[0] * q[0][j] + b[1] * q[1][j] + b[2] * q[2][j];
  return r;
}

} // namespace vtp_geodesics_app
