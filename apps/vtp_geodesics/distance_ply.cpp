// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// A distance field as a PLY file (see distance_ply.h).

#include "distance_ply.h"
#include "colour_map.h"

#include <CGAL/IO/PLY.h>
#include <CGAL/IO/io.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <array>
#include <cstddef>
#include <tuple>

namespace vtp_geodesics_app {

namespace {

using vtp_support::Mesh;
using vtp_support::Point_3;
using vtp_support::Vertex_index;

// A copy, as CGAL's PLY writers take their property writers as temporaries.
template <class T>
T copy_of(const T& t)
{
  return t;
}

template <class PointMap, class FaceMap>
void write_ply(std::ostream& os, std::size_t nv, std::size_t nf, PointMap points, FaceMap faces,
               const std::vector<double>& distances, const std::vector<int>* labels, double max_distance,
               const std::string& comment)
{
  namespace IO = CGAL::IO;
  using IO::PLY_property;
  typedef boost::counting_iterator<std::size_t> Index_iterator;
  auto distance_map = boost::make_function_property_map<std::size_t, double>(
    [&distances](std::size_t i) { return distances[i]; });
  auto label_map = boost::make_function_property_map<std::size_t, int>(
    [labels](std::size_t i) { return (*labels)[i]; });
  std::vector<Rgb> colours(nv);
  for(std::size_t i = 0; i < nv; ++i)
    colours[i] = colour_of_distance(distances[i], max_distance);
  auto red = boost::make_function_property_map<std::size_t, unsigned char>(
    [&colours](std::size_t i) { return colours[i].r; });
  auto green = boost::make_function_property_map<std::size_t, unsigned char>(
    [&colours](std::size_t i) { return colours[i].g; });
  auto blue = boost::make_function_property_map<std::size_t, unsigned char>(
    [&colours](std::size_t i) { return colours[i].b; });

  IO::set_mode(os, IO::BINARY);
  os << "ply\nformat binary_little_endian 1.0\n";
  std::string::size_type begin = 0;
  while(begin < comment.size())
  {
    std::string::size_type end = comment.find('\n', begin);
    if(end == std::string::npos)
      end = comment.size();
    os << "comment " << comment.substr(begin, end - begin) << "\n";
    begin = end + 1;
  }
  os << "element vertex " << nv << "\n";
  // with_vertex_properties(f): f(the writers of the vertex properties), with or without the labels
  auto with_vertex_properties = [&](const auto& f) {
    const auto point = IO::make_ply_point_writer(points);
    const auto distance = std::make_pair(distance_map, PLY_property<double>("distance"));
    const auto colour = std::make_tuple(std::make_pair(red, PLY_property<unsigned char>("red")),
                                        std::make_pair(green, PLY_property<unsigned char>("green")),
                                        std::make_pair(blue, PLY_property<unsigned char>("blue")));
    if(labels != nullptr)
      f(point, distance, std::make_pair(label_map, PLY_property<int>("source")), std::get<0>(colour),
        std::get<1>(colour), std::get<2>(colour));
    else
      f(point, distance, std::get<0>(colour), std::get<1>(colour), std::get<2>(colour));
  };
  with_vertex_properties(
    [&](const auto&... properties) { IO::internal::output_property_header(os, copy_of(properties)...); });
  os << "element face " << nf << "\n";
  IO::internal::output_property_header(os, std::make_pair(faces, PLY_property<std::vector<int> >("vertex_indices")));
  os << "end_header\n";

  with_vertex_properties([&](const auto&... properties) {
    for(Index_iterator it(0); it != Index_iterator(nv); ++it)
      IO::internal::output_properties(os, it, copy_of(properties)...);
  });
  for(Index_iterator it(0); it != Index_iterator(nf); ++it)
    IO::internal::output_properties(os, it, std::make_pair(faces, PLY_property<std::vector<int> >("vertex_indices")));
}

} // namespace

void write_distance_ply(std::ostream& os, const vtp_support::Input_mesh& input, const std::vector<double>& distances,
                        const std::vector<int>* labels, double max_distance, const std::string& comment)
{
  if(input.direct)
  {
    const Mesh& m = input.mesh;
    auto points = boost::make_function_property_map<std::size_t, Point_3>(
      [&m](std::size_t i) { return m.point(Vertex_index(static_cast<Mesh::size_type>(i))); });
    auto faces = boost::make_function_property_map<std::size_t, std::array<int, 3> >([&m](std::size_t f) {
      const Mesh::Halfedge_index h = m.halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(f)));
      return std::array<int, 3>{ { static_cast<int>(m.source(h)), static_cast<int>(m.target(h)),
                                   static_cast<int>(m.target(m.next(h))) } };
    });
    write_ply(os, m.number_of_vertices(), m.number_of_faces(), points, faces, distances, labels, max_distance,
              comment);
  }
  else
  {
    const std::vector<Point_3>& p = input.file_points;
    const std::vector<std::vector<std::size_t> >& f = input.file_polygons;
    auto points = boost::make_function_property_map<std::size_t, Point_3>([&p](std::size_t i) { return p[i]; });
    auto faces = boost::make_function_property_map<std::size_t, std::vector<std::size_t> >(
      [&f](std::size_t i) { return f[i]; });
    write_ply(os, p.size(), f.size(), points, faces, distances, labels, max_distance, comment);
  }
}

} // namespace vtp_geodesics_app
