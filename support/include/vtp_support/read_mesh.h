// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_READ_MESH_H
#define VTP_SUPPORT_READ_MESH_H

// Reading a mesh file into the triangle mesh of a computation, for the command-line tools, the benchmark and the
// Python module.
//
// `read_input_mesh(file, input)` reads every format that CGAL reads as a polygon soup (OFF, OBJ, PLY, STL, GOCAD
// TS; the format comes from the file extension) and makes a triangle `Surface_mesh` of it:
// - a valid triangle mesh in plain ASCII OFF (the common case for large meshes) is read straight into the mesh
//   by a fast reader (`fast_off_reader.h`), with vertex i of the mesh being vertex i of the file;
// - everything else goes through CGAL's readers and `triangle_mesh_from_soup()` (triangulation of polygons,
//   repair of soups that are not valid meshes), which tells which mesh vertices stand for each file vertex.
// `Input_mesh` keeps the correspondence between the vertices of the file and those of the mesh, both ways: the
// mesh vertices of a file vertex (`mesh_vertices_of()`), the file vertex of a mesh vertex (`file_vertex_of()`),
// and values of the mesh vertices reported on the file vertices (`on_file_vertices()`,
// `labels_on_file_vertices()`).
//
// read_input_mesh() is compiled once, in the library VTP_geodesics_support (src/read_mesh.cpp: CGAL's readers and
// repair are slow to compile).

#include <vtp_support/fast_off_reader.h>
#include <vtp_support/soup_repair_report.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace vtp_support {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;

// Error of the input; the message is one line that names the file and says what is wrong.
struct Input_error : std::runtime_error
{
  explicit Input_error(const std::string& what) : std::runtime_error(what) {}
};

// The mesh of the computation, and how its vertices relate to the vertices of the file.
struct Input_mesh
{
  Mesh mesh;                                   // the triangle mesh of the computation
  std::size_t file_vertices = 0, file_faces = 0;
  // true: mesh vertex i is file vertex i and mesh face j is file face j (a valid triangle mesh read as is);
  // false: see `copy_begin` / `copies`, `file_points` / `file_polygons`.
  bool direct = false;
  // Not direct: the mesh vertices standing for file vertex i are copies[copy_begin[i] .. copy_begin[i+1]) (none
  // for a vertex the repair removed, several for a vertex it duplicated).
  std::vector<std::size_t> copy_begin;
  std::vector<Vertex_index> copies;
  // Not direct: the inverse, the file vertex of each mesh vertex (see file_vertex_of()).
  std::vector<std::size_t> file_vertex_of_copy;
  // Not direct: the points and polygons of the file, as read (for outputs that give the mesh back).
  std::vector<Point_3> file_points;
  std::vector<std::vector<std::size_t> > file_polygons;
  Soup_repair_report repairs;                  // what was done (nothing when direct)
  std::string reader;                          // "fast OFF reader" or "CGAL::IO::read_polygon_soup"
  double read_seconds = 0.;                    // reading the file
  double repair_seconds = 0.;                  // checking, repairing and building the mesh

  // The mesh vertices standing for file vertex `i`.
  std::vector<Vertex_index> mesh_vertices_of(std::size_t i) const
  {
    if(direct)
      return std::vector<Vertex_index>(1, Vertex_index(static_cast<Mesh::size_type>(i)));
    return std::vector<Vertex_index>(copies.begin() + std::ptrdiff_t(copy_begin[i]),
                                     copies.begin() + std::ptrdiff_t(copy_begin[i + 1]));
  }

  // Values of the mesh vertices reported on the vertices of the file, into `r` (resized to file_vertices): the
  // minimum of value(v) over the copies v of a vertex, `+infinity` for a vertex without copy.
  template <class Value_of_mesh_vertex>
  void on_file_vertices(const Value_of_mesh_vertex& value, std::vector<double>& r) const
  {
    r.resize(file_vertices);
    if(direct)
    {
      for(std::size_t i = 0; i < file_vertices; ++i)
        r[i] = value(Vertex_index(static_cast<Mesh::size_type>(i)));
      return;
    }
    for(std::size_t i = 0; i < file_vertices; ++i)
    {
      double m = std::numeric_limits<double>::infinity();
      for(std::size_t k = copy_begin[i]; k < copy_begin[i + 1]; ++k)
        m = (std::min)(m, static_cast<double>(value(copies[k])));
      r[i] = m;
    }
  }

  // The same from values indexed by vertex index; moves from `per_mesh_vertex` if direct.
  std::vector<double> on_file_vertices(std::vector<double>&& per_mesh_vertex) const
  {
    if(direct)
      return std::move(per_mesh_vertex);
    std::vector<double> r;
    on_file_vertices([&per_mesh_vertex](Vertex_index v) { return per_mesh_vertex[std::size_t(v)]; }, r);
    return r;
  }

  // Per-vertex labels of the mesh (e.g. the nearest source) reported on the vertices of the file: the label of
  // the copy with the smallest distance in `per_mesh_distance` (the first such copy), `missing` without copy.
  template <class Label>
  std::vector<Label> labels_on_file_vertices(const std::vector<Label>& per_mesh_vertex,
                                             const std::vector<double>& per_mesh_distance, Label missing) const
  {
    if(direct)
      return per_mesh_vertex;
    std::vector<Label> r(file_vertices, missing);
    for(std::size_t i = 0; i < file_vertices; ++i)
      if(copy_begin[i] < copy_begin[i + 1])
      {
        std::size_t best = std::size_t(copies[copy_begin[i]]);
        for(std::size_t k = copy_begin[i] + 1; k < copy_begin[i + 1]; ++k)
          if(per_mesh_distance[std::size_t(copies[k])] < per_mesh_distance[best])
            best = std::size_t(copies[k]);
        r[i] = per_mesh_vertex[best];
      }
    return r;
  }

  // The file vertex that mesh vertex `v` stands for (of file vertices that the repair merged, the last one).
  std::size_t file_vertex_of(Vertex_index v) const
  {
    return direct ? std::size_t(v) : file_vertex_of_copy[std::size_t(v)];
  }

  // The point of file vertex `i`.
  const Point_3& file_point(std::size_t i) const
  {
    return direct ? mesh.point(Vertex_index(static_cast<Mesh::size_type>(i))) : file_points[i];
  }
};

// Reads `file` into `input` (see the top of this file); a valid triangle mesh is built by `threads` OpenMP
// threads (0: OpenMP's default), with the same result whatever their number. Throws `Input_error`.
void read_input_mesh(const std::string& file, Input_mesh& input, int threads = 1);

} // namespace vtp_support

#endif // VTP_SUPPORT_READ_MESH_H
