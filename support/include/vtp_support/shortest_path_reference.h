// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_SHORTEST_PATH_REFERENCE_H
#define VTP_SUPPORT_SHORTEST_PATH_REFERENCE_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vtp_support {

// Reference distances computed with `CGAL::Surface_mesh_shortest_path` (Chen and Han / Xin and Wang),
// with the traits `Surface_mesh_shortest_path_traits<K, Surface_mesh<Point>>`, `K` being the kernel of
// `Point` (Epick for the usual `Surface_mesh<Epick::Point_3>`): the distance to the nearest source, the sources
// being mesh vertices and points of the surface given as face locations (a face and barycentric coordinates
// with respect to source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))), as
// CGAL::Polygon_mesh_processing::locate gives them).
//
// Returns one distance per vertex, indexed by the vertex index (the order of `vertices(mesh)`).
// Vertices outside the connected components of the sources (other components, isolated vertices) get
// `+infinity`: they are found by a breadth-first search over the edges and are not queried.
// SMSP itself reports a negative value for unreached vertices; such values are also mapped to `+infinity`.
//
// Throws `std::invalid_argument` if a source vertex is not a valid vertex of `mesh` or if `mesh` has garbage
// (removed elements not yet collected).
// \pre `CGAL::is_triangle_mesh(mesh)`
template <class Point>
std::vector<double>
shortest_path_reference_distances(
  const CGAL::Surface_mesh<Point>& mesh,
  const std::vector<typename CGAL::Surface_mesh<Point>::Vertex_index>& vertex_sources,
  const std::vector<std::pair<typename CGAL::Surface_mesh<Point>::Face_index, std::array<double, 3> > >& point_sources)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh> Traits;
  typedef CGAL::Surface_mesh_shortest_path<Traits> Shortest_path;

  if(mesh.has_garbage())
    throw std::invalid_argument("shortest_path_reference_distances: the mesh has garbage");
  const std::size_t n = static_cast<std::size_t>(mesh.number_of_vertices());
  std::vector<double> distances(n, std::numeric_limits<double>::infinity());

  // The connected components of the sources, by a breadth-first search over the edges.
  std::vector<unsigned char> in_component(n, 0);
  std::vector<Vertex_index> component;
  auto reach = [&](Vertex_index v) {
    if(!in_component[static_cast<std::size_t>(v)])
    {
      in_component[static_cast<std::size_t>(v)] = 1;
      component.push_back(v);
    }
  };
  for(Vertex_index s : vertex_sources)
  {
    if(!(static_cast<std::size_t>(s) < n) || mesh.is_removed(s))
      throw std::invalid_argument("shortest_path_reference_distances: invalid source vertex");
    distances[static_cast<std::size_t>(s)] = 0.;
    if(!mesh.is_isolated(s))
      reach(s);
  }
  for(const auto& l : point_sources)
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(l.first), mesh))
      reach(v);
  if(component.empty())
    return distances;
  for(std::size_t i = 0; i < component.size(); ++i)
    for(typename Mesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(component[i]), mesh))
      reach(mesh.source(h));

  Shortest_path shortest_path(mesh);
  for(Vertex_index s : vertex_sources)
    if(!mesh.is_isolated(s))
      shortest_path.add_source_point(s);
  for(const auto& l : point_sources)
  {
    typename Traits::Barycentric_coordinates b = { { l.second[0], l.second[1], l.second[2] } };
    shortest_path.add_source_point(l.first, b);
  }
  shortest_path.build_sequence_tree();
  for(Vertex_index v : component)
  {
    const double d = CGAL::to_double(shortest_path.shortest_distance_to_source_points(v).first);
    distances[static_cast<std::size_t>(v)] = (d < 0. || std::isnan(d)) ? std::numeric_limits<double>::infinity() : d;
  }
  for(Vertex_index s : vertex_sources)
    distances[static_cast<std::size_t>(s)] = 0.;
  return distances;
}

// The same from one source vertex.
template <class Point>
std::vector<double>
shortest_path_reference_distances(const CGAL::Surface_mesh<Point>& mesh,
                                  typename CGAL::Surface_mesh<Point>::Vertex_index source)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  return shortest_path_reference_distances(
    mesh, std::vector<typename Mesh::Vertex_index>(1, source),
    std::vector<std::pair<typename Mesh::Face_index, std::array<double, 3> > >());
}

// Result of `compare_distances()`.
struct Distance_comparison
{
  // Largest |a[i] - b[i]| over the entries that are finite in both vectors.
  double max_abs_diff = 0.;
  // `max_abs_diff` divided by the largest finite distance of the reference b (not divided if that is 0): a
  // method that gives huge finite values where b is infinite (another component) does not change it.
  double max_rel_diff = 0.;
  // Mean of |a[i] - b[i]| over the entries finite in both, divided by the same scale.
  double mean_rel_diff = 0.;
  // Pointwise relative differences |a[i] - b[i]| / b[i] over the entries finite in both with b[i] > 0
  // (b is the reference): the largest and the mean.
  double max_pointwise_rel_diff = 0.;
  double mean_pointwise_rel_diff = 0.;
  // Number of entries where exactly one of a[i], b[i] is infinite, or where one of them is NaN,
  // plus the difference of the sizes if the sizes differ.
  std::size_t mismatched_infinities = 0;
};

// Compares two distance vectors entry by entry, b the reference (see `Distance_comparison`).
inline Distance_comparison compare_distances(const std::vector<double>& a, const std::vector<double>& b)
{
  Distance_comparison result;
  const std::size_t n = (std::min)(a.size(), b.size());
  result.mismatched_infinities = (std::max)(a.size(), b.size()) - n;

  double scale = 0.;
  for(double x : b) if(std::isfinite(x)) scale = (std::max)(scale, std::abs(x));

  double sum = 0., sum_pointwise = 0.;
  std::size_t count = 0, count_pointwise = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double x = a[i], y = b[i];
    if(std::isnan(x) || std::isnan(y)) { ++result.mismatched_infinities; continue; }
    const bool fx = std::isfinite(x), fy = std::isfinite(y);
    if(fx != fy) { ++result.mismatched_infinities; continue; }
    if(!fx) continue; // both infinite
    const double d = std::abs(x - y);
    result.max_abs_diff = (std::max)(result.max_abs_diff, d);
    sum += d;
    ++count;
    if(y > 0.)
    {
      const double r = d / y;
      result.max_pointwise_rel_diff = (std::max)(result.max_pointwise_rel_diff, r);
      sum_pointwise += r;
      ++count_pointwise;
    }
  }
  result.mean_pointwise_rel_diff = count_pointwise > 0 ? sum_pointwise / static_cast<double>(count_pointwise) : 0.;
  const double divisor = scale > 0. ? scale : 1.;
  result.max_rel_diff = result.max_abs_diff / divisor;
  result.mean_rel_diff = count > 0 ? sum / static_cast<double>(count) / divisor : 0.;
  return result;
}

} // namespace vtp_support

#endif // VTP_SUPPORT_SHORTEST_PATH_REFERENCE_H
