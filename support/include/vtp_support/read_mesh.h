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

// Reading a mesh file into the triangle mesh of a computation, for the command-line tools.
//
// `read_input_mesh(file, input)` reads every format that CGAL reads as a polygon soup (OFF, OBJ, PLY, STL, GOCAD
// TS; the format comes from the file extension) and makes a triangle `Surface_mesh` of it:
// - a valid triangle mesh in plain ASCII OFF (the common case for large meshes) is read straight into the mesh
//   by a fast reader (`fast_off_reader.h`), with vertex i of the mesh being vertex i of the file;
// - everything else goes through CGAL's readers and `triangle_mesh_from_soup()` (triangulation of polygons,
//   repair of soups that are not valid meshes), which tells which mesh vertices stand for each file vertex.
// Results are reported per vertex of the file with `Input_mesh::on_file_vertices()`.

#include <vtp_support/fast_off_reader.h>
#include <vtp_support/mesh_formats.h>
#include <vtp_support/triangle_mesh_from_soup.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <errno.h>
#include <sys/stat.h>

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

  // Per-vertex values of the mesh (indexed by vertex index) reported on the vertices of the file: the minimum
  // over the copies of a vertex, `+infinity` for a vertex without copy. Moves from `per_mesh_vertex` if direct.
  std::vector<double> on_file_vertices(std::vector<double>&& per_mesh_vertex) const
  {
    if(direct)
      return std::move(per_mesh_vertex);
    std::vector<double> r(file_vertices, std::numeric_limits<double>::infinity());
    for(std::size_t i = 0; i < file_vertices; ++i)
      for(std::size_t k = copy_begin[i]; k < copy_begin[i + 1]; ++k)
        r[i] = (std::min)(r[i], per_mesh_vertex[std::size_t(copies[k])]);
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

  // The point of file vertex `i`.
  const Point_3& file_point(std::size_t i) const
  {
    return direct ? mesh.point(Vertex_index(static_cast<Mesh::size_type>(i))) : file_points[i];
  }
};

namespace read_detail {

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// When CGAL's reader refuses a text file, looks for the reason a person can fix: a coordinate that is not a
// finite number (CGAL's text readers stop there). Returns an empty string if none is found.
inline std::string diagnose_text_file(const std::string& file, const std::string& ext)
{
  if(ext != "obj" && ext != "stl")
    return std::string();
  std::ifstream in(file);
  std::string line;
  std::size_t vertex = 0;
  const std::string keyword = (ext == "obj") ? "v" : "vertex";
  while(std::getline(in, line))
  {
    std::istringstream words(line);
    std::string first;
    if(!(words >> first) || first != keyword)
      continue;
    for(int k = 0; k < 3; ++k)
    {
      std::string token;
      if(!(words >> token))
        break;
      char* end = nullptr;
      const double x = std::strtod(token.c_str(), &end);
      if(end != token.c_str() + token.size())
        return "vertex " + std::to_string(vertex) + " has an invalid coordinate '" + token + "'";
      if(!std::isfinite(x))
        return ext == "obj" ? "vertex " + std::to_string(vertex) + " has a non-finite coordinate"
                            : "facet " + std::to_string(vertex / 3) + " has a non-finite coordinate";
    }
    ++vertex;
  }
  return std::string();
}

// Reads `file` with CGAL's polygon soup readers, with their diagnostics on std::cerr kept out of the one-line
// errors.
inline void read_soup(const std::string& file, std::vector<Point_3>& points,
                      std::vector<std::vector<std::size_t> >& polygons)
{
  std::ostringstream diagnostics;
  std::streambuf* const cerr_buffer = std::cerr.rdbuf(diagnostics.rdbuf());
  bool ok = false;
  try
  {
    ok = CGAL::IO::read_polygon_soup(file, points, polygons, CGAL::parameters::verbose(false));
  }
  catch(...)
  {
    ok = false;
  }
  std::cerr.rdbuf(cerr_buffer);
  if(!ok)
  {
    const std::string reason = diagnose_text_file(file, lower_extension(file));
    throw Input_error("cannot read '" + file + "': " + (reason.empty() ? "invalid or unsupported mesh data" : reason));
  }
}

} // namespace read_detail

// Reads `file` into `input` (see the top of this file); a valid triangle mesh is built by `threads` OpenMP
// threads (0: OpenMP's default), with the same result whatever their number. Throws `Input_error`.
inline void read_input_mesh(const std::string& file, Input_mesh& input, int threads = 1)
{
  const std::string ext = lower_extension(file);
  bool known = false;
  for(const std::string& e : readable_extensions())
    known = known || (e == ext);
  if(!known)
    throw Input_error("cannot read '" + file + "': " + (ext.empty() ? std::string("no file extension")
                                                                     : "unsupported file extension '." + ext + "'")
                      + " (expected " + readable_extensions_text() + ")");
  {
    struct stat st;
    if(::stat(file.c_str(), &st) != 0)
      throw Input_error("cannot open '" + file + "': " + std::strerror(errno));
    if(S_ISDIR(st.st_mode))
      throw Input_error("cannot read '" + file + "': it is a folder");
    std::ifstream probe(file, std::ios::binary);
    if(!probe)
      throw Input_error("cannot open '" + file + "'");
    char c;
    if(!probe.get(c))
      throw Input_error("cannot read '" + file + "': the file is empty");
  }

  input = Input_mesh();
  const auto t0 = std::chrono::steady_clock::now();

  // Plain ASCII OFF, valid triangle mesh: straight into the mesh.
  if(ext == "off")
  {
    Fast_off_result r;
    try
    {
      r = read_off_triangle_mesh(file, input.mesh, threads);
    }
    catch(const Fast_off_error& e)
    {
      throw Input_error("cannot read '" + file + "': " + e.what());
    }
    if(r.status == Fast_off_result::MESH)
    {
      input.direct = true;
      input.file_vertices = input.mesh.number_of_vertices();
      input.file_faces = input.mesh.number_of_faces();
      input.reader = "fast OFF reader";
      input.read_seconds = r.read_seconds;
      input.repair_seconds = r.build_seconds;
      return;
    }
    input.mesh.clear();
  }

  // Everything else: CGAL's readers, then the checks and repairs of triangle_mesh_from_soup().
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  read_detail::read_soup(file, points, polygons);
  input.reader = "CGAL::IO::read_polygon_soup";
  input.read_seconds = read_detail::seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  input.file_vertices = points.size();
  input.file_faces = polygons.size();
  if(points.empty() && polygons.empty())
    throw Input_error("cannot read '" + file + "': the file has no vertices and no faces");
  try
  {
    check_soup_values(points, polygons);
  }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e)
  {
    throw Input_error("cannot use '" + file + "': " + e.what());
  }

  // A valid triangle mesh (the common case): checked and built directly, as by the fast OFF reader.
  if(points.size() < (std::size_t(1) << 31) && polygons.size() < (std::size_t(1) << 31) / 3
     && std::all_of(polygons.begin(), polygons.end(), [](const std::vector<std::size_t>& p) { return p.size() == 3; }))
  {
    std::vector<fast_off_detail::Triangle> triangles(polygons.size());
    for(std::size_t f = 0; f < polygons.size(); ++f)
      for(int k = 0; k < 3; ++k)
        triangles[f][k] = static_cast<std::uint32_t>(polygons[f][k]);
    input.mesh.reserve(static_cast<Mesh::size_type>(points.size()), 0, 0);
    for(const Point_3& p : points)
      input.mesh.add_vertex(p);
    std::string reason;
    if(fast_off_detail::build_triangle_mesh(triangles, input.mesh, reason, threads))
    {
      input.direct = true;
      input.repair_seconds = read_detail::seconds_since(t1);
      return;
    }
    input.mesh.clear();
  }

  input.file_points = points;
  input.file_polygons = polygons;
  try
  {
    input.repairs = triangle_mesh_from_soup(std::move(points), std::move(polygons), input.mesh, input.copy_begin,
                                            input.copies);
  }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e)
  {
    throw Input_error("cannot use '" + file + "': " + e.what());
  }
  if(!input.repairs.repaired && input.repairs.triangulated_faces == 0)
  {
    // A valid triangle mesh: mesh vertex i is point i, mesh face j is polygon j.
    input.direct = true;
    std::vector<std::size_t>().swap(input.copy_begin);
    std::vector<Vertex_index>().swap(input.copies);
    std::vector<Point_3>().swap(input.file_points);
    std::vector<std::vector<std::size_t> >().swap(input.file_polygons);
  }
  input.repair_seconds = read_detail::seconds_since(t1);
}

} // namespace vtp_support

#endif // VTP_SUPPORT_READ_MESH_H
