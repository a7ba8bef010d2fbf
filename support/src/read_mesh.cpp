// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Reading a mesh file into the triangle mesh of a computation (see read_mesh.h).

#include <vtp_support/read_mesh.h>

#include <vtp_support/fast_off_reader.h>
#include <vtp_support/mesh_formats.h>
#include <vtp_support/triangle_mesh_from_soup.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/VTP_geodesics/Invalid_input_error.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <errno.h>
#include <sys/stat.h>

namespace vtp_support {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// When CGAL's reader refuses a text file, looks for the reason a person can fix: a coordinate that is not a
// finite number (CGAL's text readers stop there). Returns an empty string if none is found.
std::string diagnose_text_file(const std::string& file, const std::string& ext)
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

// When CGAL's reader refuses an ASCII OFF file, looks for a vertex line it cannot read, as it reads them: the lines
// with content after the counts (a '#' starts a comment), one per vertex, each needing 3 numbers (4 with the
// homogeneous coordinate of 4OFF) before anything else. Returns "line L: vertex i ...", L the line of the file
// (from 1), i the vertex (from 0); or an empty string if none is found (or the header is one this does not follow).
std::string diagnose_off_file(const std::string& file)
{
  std::ifstream in(file);
  std::string line;
  std::size_t number = 0;
  std::vector<std::string> words;
  auto next_content = [&]() {  // the words of the next line with content, before any '#'
    while(std::getline(in, line))
    {
      ++number;
      std::istringstream text(line.substr(0, line.find('#')));
      words.clear();
      for(std::string w; text >> w;)
        words.push_back(w);
      if(!words.empty())
        return true;
    }
    return false;
  };
  if(!next_content())
    return std::string();
  // The keyword: [ST][C][N][4]OFF (not nOFF, not BINARY), then the counts: vertices, faces, edges.
  std::string keyword = words[0];
  std::size_t j = 0;
  for(const char* prefix : { "ST", "C", "N", "4" })
    if(keyword.compare(j, std::strlen(prefix), prefix) == 0)
      j += std::strlen(prefix);
  if(keyword.compare(j, std::string::npos, "OFF") != 0)
    return std::string();
  const std::size_t needed = (keyword.find('4') != std::string::npos) ? 4 : 3;
  std::vector<std::string> counts(words.begin() + 1, words.end());
  while(counts.size() < 3 && next_content())
    counts.insert(counts.end(), words.begin(), words.end());
  if(counts.size() != 3)
    return std::string();
  for(char c : counts[0])
    if(c < '0' || c > '9')
      return std::string();
  const std::size_t vertices = static_cast<std::size_t>(std::strtoull(counts[0].c_str(), nullptr, 10));
  for(std::size_t i = 0; i < vertices && next_content(); ++i)
    for(std::size_t k = 0; k < needed; ++k)
    {
      if(k == words.size())
        return "line " + std::to_string(number) + ": vertex " + std::to_string(i) + " has " + std::to_string(k)
               + (k == 1 ? " coordinate" : " coordinates") + " (expected " + std::to_string(needed) + ")";
      char* end = nullptr;
      const double x = std::strtod(words[k].c_str(), &end);
      if(end != words[k].c_str() + words[k].size() || !std::isfinite(x))
        return "line " + std::to_string(number) + ": vertex " + std::to_string(i) + " has an invalid coordinate '"
               + words[k] + "'";
    }
  return std::string();
}

// Reads `file` with CGAL's polygon soup readers, with their diagnostics on std::cerr kept out of the one-line
// errors.
void read_soup(const std::string& file, std::vector<Point_3>& points,
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
    const std::string ext = lower_extension(file);
    const std::string reason = (ext == "off") ? diagnose_off_file(file) : diagnose_text_file(file, ext);
    throw Input_error("cannot read '" + file + "': " + (reason.empty() ? "invalid or unsupported mesh data" : reason));
  }
}

} // namespace

void read_input_mesh(const std::string& file, Input_mesh& input, int threads)
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
  read_soup(file, points, polygons);
  input.reader = "CGAL::IO::read_polygon_soup";
  input.read_seconds = seconds_since(t0);
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
      input.repair_seconds = seconds_since(t1);
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
  else
  {
    input.file_vertex_of_copy.assign(input.mesh.number_of_vertices(), 0);
    for(std::size_t i = 0; i < input.file_vertices; ++i)
      for(std::size_t k = input.copy_begin[i]; k < input.copy_begin[i + 1]; ++k)
        input.file_vertex_of_copy[std::size_t(input.copies[k])] = i;
  }
  input.repair_seconds = seconds_since(t1);
}

} // namespace vtp_support
