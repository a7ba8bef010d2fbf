// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_TRIANGLE_MESH_FROM_SOUP_H
#define VTP_SUPPORT_TRIANGLE_MESH_FROM_SOUP_H

#include <vtp_support/soup_repair_report.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace vtp_support {

// Checks what no repair can fix: the soup has points and faces, finite coordinates and indices in range. Throws
// `CGAL::VTP_geodesics::Invalid_input_error` with a one-line message that says which vertex or face is wrong.
template <class Point>
void check_soup_values(const std::vector<Point>& points, const std::vector<std::vector<std::size_t> >& polygons)
{
  typedef CGAL::VTP_geodesics::Invalid_input_error Error;
  const std::size_t n = points.size();
  if(n == 0)
    throw Error("the mesh has no vertices");
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isfinite(CGAL::to_double(points[i].x())) || !std::isfinite(CGAL::to_double(points[i].y()))
       || !std::isfinite(CGAL::to_double(points[i].z())))
      throw Error("vertex " + std::to_string(i) + " has a non-finite coordinate");
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t id : polygons[f])
      if(id >= n)
        throw Error("face " + std::to_string(f) + " refers to vertex " + std::to_string(id) + ", out of range (there are "
                    + std::to_string(n) + " vertices)");
  if(polygons.empty())
    throw Error("the mesh has no faces");
}

// Builds a triangle `Surface_mesh` from a polygon soup, and tells which vertices of the mesh stand
// for each point of the soup, so that results on the mesh can be reported in the soup's point order.
//
// - A soup that is a valid polygon mesh (`is_polygon_soup_a_polygon_mesh`) is converted as is: mesh
//   vertex i is point i (points in no face become isolated vertices).
// - Otherwise it is repaired with `repair_polygon_soup()` (merges coincident points, removes degenerate and
//   duplicate faces and the points left in no face) and `orient_polygon_soup()` (orients the faces
//   consistently, and cuts the surface at non-manifold edges and vertices by duplicating points).
// - Faces with more than three vertices are then split with `triangulate_faces()` (no vertex is added).
//
// On return, `copies[copy_begin[i] .. copy_begin[i+1])` lists the mesh vertices standing for point i:
// one vertex normally, several if the point was duplicated, none if it was removed. Coincident points
// merged by the repair stand for the same vertices.
//
// Throws `CGAL::VTP_geodesics::Invalid_input_error` (one-line message) if the soup has no point or no face, a
// non-finite coordinate or an index out of range (see `check_soup_values()`), no face left after the repair, or
// cannot be made a triangle mesh.
template <class Point>
Soup_repair_report
triangle_mesh_from_soup(std::vector<Point> points,
                        std::vector<std::vector<std::size_t> > polygons,
                        CGAL::Surface_mesh<Point>& mesh,
                        std::vector<std::size_t>& copy_begin,
                        std::vector<typename CGAL::Surface_mesh<Point>::Vertex_index>& copies)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef std::map<Point, std::size_t, typename Kernel::Less_xyz_3> Point_index;

  Soup_repair_report report;
  const std::size_t n = points.size();
  check_soup_values(points, polygons);

  // image[i]: the point that input point i became after the repair (NONE if it was removed);
  // copy_of[j]: the repaired point that point j of the final soup is a copy of.
  const std::size_t NONE = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> image(n);
  for(std::size_t i = 0; i < n; ++i)
    image[i] = i;
  std::vector<std::size_t> copy_of;

  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    report.repaired = true;
    const std::vector<Point> input_points = points;
    const std::size_t input_polygons = polygons.size();
    const std::size_t distinct_points =
      std::set<Point, typename Kernel::Less_xyz_3>(points.begin(), points.end()).size();

    PMP::repair_polygon_soup(points, polygons);
    report.merged_points = n - distinct_points;
    report.removed_isolated_points = distinct_points - points.size();
    if(polygons.size() < input_polygons)
      report.removed_faces = input_polygons - polygons.size();
    else
      report.split_faces = polygons.size() - input_polygons;
    if(polygons.empty())
      throw CGAL::VTP_geodesics::Invalid_input_error("no face is left after removing the degenerate faces");

    // The repaired points are pairwise distinct: find each input point among them by its coordinates.
    Point_index repaired_index;
    for(std::size_t j = 0; j < points.size(); ++j)
      repaired_index.emplace(points[j], j);
    for(std::size_t i = 0; i < n; ++i)
    {
      const auto it = repaired_index.find(input_points[i]);
      image[i] = (it == repaired_index.end()) ? NONE : it->second;
    }

    // Orientation and cuts at non-manifold simplices: the visitor reports each copy of a point.
    copy_of.resize(points.size());
    for(std::size_t j = 0; j < copy_of.size(); ++j)
      copy_of[j] = j;
    std::vector<unsigned char> duplicated(points.size(), 0);
    std::set<std::pair<std::size_t, std::size_t> > cut_edges;
    struct Visitor : public PMP::Default_orientation_visitor
    {
      Soup_repair_report* report;
      std::vector<std::size_t>* copy_of;
      std::vector<unsigned char>* duplicated;
      std::set<std::pair<std::size_t, std::size_t> >* cut_edges;
      // called once per polygon side along the edge
      void non_manifold_edge(std::size_t a, std::size_t b, std::size_t)
      {
        if(cut_edges->insert(std::make_pair((std::min)(a, b), (std::max)(a, b))).second)
          ++report->non_manifold_edges;
      }
      void polygon_orientation_reversed(std::size_t) { ++report->reversed_faces; }
      void duplicated_vertex(std::size_t v, std::size_t new_v)
      {
        if(copy_of->size() <= new_v)
          copy_of->resize(new_v + 1, 0);
        const std::size_t original = (*copy_of)[v];
        (*copy_of)[new_v] = original;
        ++report->vertex_copies;
        if(!(*duplicated)[original])
        {
          (*duplicated)[original] = 1;
          ++report->duplicated_vertices;
        }
      }
    } visitor;
    visitor.report = &report;
    visitor.copy_of = &copy_of;
    visitor.duplicated = &duplicated;
    visitor.cut_edges = &cut_edges;
    PMP::orient_polygon_soup(points, polygons, CGAL::parameters::visitor(visitor));
    if(copy_of.size() != points.size() || !PMP::is_polygon_soup_a_polygon_mesh(polygons))
      throw CGAL::VTP_geodesics::Invalid_input_error("the polygon soup cannot be repaired into a manifold polygon mesh");
  }
  else
  {
    copy_of = image;
  }

  mesh.clear();
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(mesh.number_of_vertices() != points.size() || mesh.number_of_faces() != polygons.size())
    throw CGAL::VTP_geodesics::Invalid_input_error("the polygon soup cannot be converted into a polygon mesh");

  if(!CGAL::is_triangle_mesh(mesh))
  {
    std::size_t non_triangles = 0;
    for(typename Mesh::Face_index f : mesh.faces())
      if(mesh.degree(f) != 3)
        ++non_triangles;
    if(!PMP::triangulate_faces(mesh) || !CGAL::is_triangle_mesh(mesh) || mesh.number_of_vertices() != points.size())
      throw CGAL::VTP_geodesics::Invalid_input_error("some faces with more than three vertices cannot be triangulated");
    // The triangulation removes faces (and keeps every vertex): compact the faces and half-edges;
    // vertex j stays vertex j.
    mesh.collect_garbage();
    report.triangulated_faces = non_triangles;
  }

  // Mesh vertex j is point j (polygon_soup_to_polygon_mesh inserts the points in order): group the
  // final points by the repaired point they copy, then list the group of each input point.
  const std::size_t repaired_n = copy_of.empty() ? 0 : *std::max_element(copy_of.begin(), copy_of.end()) + 1;
  std::vector<std::size_t> group_begin(repaired_n + 1, 0), group(copy_of.size());
  for(std::size_t r : copy_of)
    ++group_begin[r + 1];
  for(std::size_t r = 0; r < repaired_n; ++r)
    group_begin[r + 1] += group_begin[r];
  {
    std::vector<std::size_t> fill(group_begin.begin(), group_begin.end() - 1);
    for(std::size_t j = 0; j < copy_of.size(); ++j)
      group[fill[copy_of[j]]++] = j;
  }
  copy_begin.assign(1, 0);
  copies.clear();
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t r = image[i];
    if(r != NONE && r < repaired_n)
      for(std::size_t k = group_begin[r]; k < group_begin[r + 1]; ++k)
        copies.push_back(Vertex_index(static_cast<typename Mesh::size_type>(group[k])));
    copy_begin.push_back(copies.size());
  }
  return report;
}

} // namespace vtp_support

#endif // VTP_SUPPORT_TRIANGLE_MESH_FROM_SOUP_H
