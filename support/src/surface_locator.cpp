// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The nearest point of a mesh's surface (see surface_locator.h).

#include <vtp_support/surface_locator.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/exceptions.h>

#include <algorithm>
#include <cmath>

namespace vtp_support {

struct Surface_locator::Tree
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > tree;
};

Surface_locator::Surface_locator(const Mesh& mesh) : m_mesh(mesh), m_tree(new Tree)
{
  CGAL::Polygon_mesh_processing::build_AABB_tree(mesh, m_tree->tree);
}

Surface_locator::~Surface_locator() = default;

bool Surface_locator::locate(const Point_3& p, Face_location& location) const
{
  CGAL::Polygon_mesh_processing::Face_location<Mesh, double> l;
  try
  {
    l = CGAL::Polygon_mesh_processing::locate_with_AABB_tree(p, m_tree->tree, m_mesh);
  }
  catch(const CGAL::Failure_exception&)
  {
    // (a build with CGAL's assertions on: its barycentric coordinates assert that the nearest face is not
    // degenerate, where a build without them gives coordinates that are not finite, refused below)
    return false;
  }
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

std::array<double, 3> Surface_locator::point_of(const Face_location& l) const
{
  const Mesh::Halfedge_index h = m_mesh.halfedge(l.first);
  const Point_3 q[3] = { m_mesh.point(m_mesh.source(h)), m_mesh.point(m_mesh.target(h)),
                         m_mesh.point(m_mesh.target(m_mesh.next(h))) };
  std::array<double, 3> r;
  for(int j = 0; j < 3; ++j)
    r[std::size_t(j)] = l.second[0] * q[0][j] + l.second[1] * q[1][j] + l.second[2] * q[2][j];
  return r;
}

double bounding_box_diagonal(const Mesh& mesh)
{
  bool first = true;
  double lo[3] = { 0., 0., 0. }, hi[3] = { 0., 0., 0. };
  for(Vertex_index v : mesh.vertices())
  {
    const Point_3& p = mesh.point(v);
    const double x[3] = { p.x(), p.y(), p.z() };
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = first ? x[k] : (std::min)(lo[k], x[k]);
      hi[k] = first ? x[k] : (std::max)(hi[k], x[k]);
    }
    first = false;
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1])
                   + (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

} // namespace vtp_support
