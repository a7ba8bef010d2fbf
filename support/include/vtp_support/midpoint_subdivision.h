// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_MIDPOINT_SUBDIVISION_H
#define VTP_SUPPORT_MIDPOINT_SUBDIVISION_H

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace vtp_support {

// Performs `levels` rounds of 1-to-4 midpoint subdivision of the triangle mesh `m`: a new vertex
// is inserted at the midpoint of every edge and every triangle is split into four triangles (three
// corner triangles and the middle one), with the orientation of the original face. No smoothing:
// the original vertices keep their positions, and borders stay borders.
//
// The mesh is rebuilt from a polygon soup: after the call the first vertices of `vertices(m)` are the
// original vertices, in their original order (for `Surface_mesh`, with indices 0..n-1), followed by
// one vertex per edge midpoint. Isolated vertices are kept. Property maps attached to `m` (other
// than the points) are lost. `levels <= 0` leaves the mesh unchanged.
//
// \pre `CGAL::is_triangle_mesh(m)`
template <class PolygonMesh>
void midpoint_subdivide(PolygonMesh& m, int levels = 1)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef std::array<std::size_t, 3> Triangle;

  CGAL_precondition(CGAL::is_triangle_mesh(m));

  for(int level = 0; level < levels; ++level)
  {
    std::vector<Point> points;
    std::vector<Triangle> triangles;
    {
      // The dynamic maps must be released before the mesh is cleared.
      typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type
        Vertex_id_map;
      typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_halfedge_property_t<std::size_t> >::type
        Halfedge_id_map;
      Vertex_point_map vpm = get(CGAL::vertex_point, m);
      Vertex_id_map vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
      Halfedge_id_map mid = get(CGAL::dynamic_halfedge_property_t<std::size_t>(), m);
      typename Kernel::Construct_midpoint_3 midpoint = Kernel().construct_midpoint_3_object();

      points.reserve(num_vertices(m) + num_edges(m));
      triangles.reserve(4 * num_faces(m));

      for(vertex_descriptor v : vertices(m))
      {
        put(vid, v, points.size());
        points.push_back(get(vpm, v));
      }
      for(edge_descriptor e : edges(m))
      {
        const halfedge_descriptor h = halfedge(e, m);
        put(mid, h, points.size());
        put(mid, opposite(h, m), points.size());
        points.push_back(midpoint(get(vpm, source(h, m)), get(vpm, target(h, m))));
      }
      for(face_descriptor f : faces(m))
      {
        const halfedge_descriptor h0 = halfedge(f, m);
        const halfedge_descriptor h1 = next(h0, m);
        const halfedge_descriptor h2 = next(h1, m);
        const std::size_t v0 = get(vid, source(h0, m)), v1 = get(vid, target(h0, m)), v2 = get(vid, target(h1, m));
        const std::size_t m0 = get(mid, h0), m1 = get(mid, h1), m2 = get(mid, h2);
        triangles.push_back(Triangle{{v0, m0, m2}});
        triangles.push_back(Triangle{{v1, m1, m0}});
        triangles.push_back(Triangle{{v2, m2, m1}});
        triangles.push_back(Triangle{{m0, m1, m2}});
      }
    }
    CGAL::clear(m);
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, m);
  }
}

} // namespace vtp_support

#endif // VTP_SUPPORT_MIDPOINT_SUBDIVISION_H
