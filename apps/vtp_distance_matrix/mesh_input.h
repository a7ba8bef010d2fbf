// vtp_distance_matrix: reading the mesh.
//
// The mesh file is read as a polygon soup and made a triangle mesh by the same code as vtp_geodesics
// (triangle_mesh_from_soup: a valid triangle mesh is taken as is, vertex i of the file being vertex i
// of the mesh; other input is triangulated or repaired, and a file vertex may then stand for several
// mesh vertices or none). Rows and columns are always in the vertex order of the file.
// (To be replaced by the reading code shared with vtp_geodesics once it moves to apps/.)

#ifndef VTP_DISTANCE_MATRIX_MESH_INPUT_H
#define VTP_DISTANCE_MATRIX_MESH_INPUT_H

#include "hashing.h"
#include "tool_error.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>

#include <CGAL/VTP_geodesics/options_and_statistics.h>
#include <CGAL/VTP_geodesics/internal/tools/triangle_mesh_from_soup.h>

#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace vtp_matrix {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;

struct Mesh_input
{
  Mesh mesh;
  std::size_t file_vertices = 0, file_faces = 0;
  // copies of file vertex i: copies[copy_begin[i] .. copy_begin[i+1])
  std::vector<std::size_t> copy_begin;
  std::vector<Vertex_index> copies;
  // true when mesh vertex i is file vertex i, for every i (no repair changed the vertices)
  bool same_vertices = false;
  // a hash of the points and faces of the file (bit patterns of the coordinates)
  std::string hash;
  // what was done to make a triangle mesh of the file ("" if nothing)
  std::string repairs;
};

inline std::string lower_extension(const std::string& file)
{
  const std::string::size_type dot = file.find_last_of('.');
  const std::string::size_type slash = file.find_last_of('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = file.substr(dot + 1);
  for(char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Throws Tool_error if the file cannot be read or made a triangle mesh.
inline void read_mesh_input(const std::string& file, Mesh_input& input)
{
  const std::string ext = lower_extension(file);
  if(ext != "off" && ext != "obj" && ext != "ply")
    throw Tool_error("cannot read '" + file + "': unsupported file extension (expected .off, .obj or .ply)");
  {
    std::ifstream probe(file, std::ios::binary);
    char c;
    if(!probe)
      throw Tool_error("cannot open '" + file + "'");
    if(!probe.get(c))
      throw Tool_error("cannot read '" + file + "': empty or unreadable file");
  }
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  // CGAL's readers may print diagnostics on std::cerr: keep them out of the one-line error.
  std::ostringstream diagnostics;
  std::streambuf* const cerr_buffer = std::cerr.rdbuf(diagnostics.rdbuf());
  bool ok = false;
  try
  {
    if(ext == "off")
      ok = CGAL::IO::read_OFF(file, points, polygons);
    else if(ext == "obj")
      ok = CGAL::IO::read_OBJ(file, points, polygons);
    else
      ok = CGAL::IO::read_PLY(file, points, polygons);
  }
  catch(...)
  {
    ok = false;
  }
  std::cerr.rdbuf(cerr_buffer);
  if(!ok)
    throw Tool_error("cannot read '" + file + "': invalid or unsupported mesh data");

  Hash64 h;
  h.add(points.size());
  for(const Point_3& p : points)
  {
    h.add_double(p.x());
    h.add_double(p.y());
    h.add_double(p.z());
  }
  h.add(polygons.size());
  for(const std::vector<std::size_t>& f : polygons)
  {
    h.add(f.size());
    for(std::size_t i : f)
      h.add(i);
  }
  input.hash = h.hex();
  input.file_vertices = points.size();
  input.file_faces = polygons.size();
  try
  {
    input.repairs = CGAL::VTP_geodesics::internal::triangle_mesh_from_soup(
      std::move(points), std::move(polygons), input.mesh, input.copy_begin, input.copies).summary();
  }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e)
  {
    throw Tool_error("cannot use '" + file + "': " + e.what());
  }
  input.same_vertices = input.mesh.number_of_vertices() == input.file_vertices;
  for(std::size_t i = 0; input.same_vertices && i < input.file_vertices; ++i)
    input.same_vertices = input.copy_begin[i + 1] == i + 1 && input.copies[i] == Vertex_index(static_cast<Mesh::size_type>(i));
}

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_MESH_INPUT_H
