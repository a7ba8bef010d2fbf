// vtp_distance_matrix: reading the mesh.
//
// With the reading and repair code shared by the tools (support/, vtp_support::read_input_mesh): a valid
// triangle mesh is read as is, vertex i of the mesh being vertex i of the file; other input is triangulated
// or repaired, and a file vertex may then stand for several mesh vertices (copies) or none. Rows and columns
// are always in the vertex order of the file. What this file adds: a hash of the mesh, part of the run's
// signature (a partial output is resumed only with the same mesh).

#ifndef VTP_DISTANCE_MATRIX_MESH_INPUT_H
#define VTP_DISTANCE_MATRIX_MESH_INPUT_H

#include "hashing.h"
#include "tool_error.h"

#include <vtp_support/read_mesh.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>

#include <string>
#include <vector>

namespace vtp_matrix {

typedef vtp_support::Mesh Mesh;
typedef vtp_support::Vertex_index Vertex_index;

struct Mesh_input : vtp_support::Input_mesh
{
  // a hash of the mesh of the computation (points, faces) and of how it stands for the file's vertices
  std::string hash;
  // what was done to make a triangle mesh of the file ("" if nothing)
  std::string repair_note;
};

// Throws Tool_error if the file cannot be read or made a triangle mesh.
inline void read_mesh_input(const std::string& file, Mesh_input& input, int threads = 1)
{
  try
  {
    vtp_support::read_input_mesh(file, static_cast<vtp_support::Input_mesh&>(input), threads);
  }
  catch(const vtp_support::Input_error& e)
  {
    throw Tool_error(e.what());
  }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e)
  {
    throw Tool_error("cannot use '" + file + "': " + e.what());
  }
  input.repair_note = input.direct ? std::string() : input.repairs.summary();

  const Mesh& m = input.mesh;
  Hash64 h;
  h.add(input.file_vertices);
  h.add(m.number_of_vertices());
  for(Vertex_index v : m.vertices())
  {
    h.add_double(m.point(v).x());
    h.add_double(m.point(v).y());
    h.add_double(m.point(v).z());
  }
  h.add(m.number_of_faces());
  for(Mesh::Face_index f : m.faces())
    for(Vertex_index v : m.vertices_around_face(m.halfedge(f)))
      h.add(static_cast<std::uint64_t>(v));
  h.add(input.direct ? 1 : 0);
  if(!input.direct)
  {
    for(std::size_t b : input.copy_begin)
      h.add(b);
    for(Vertex_index v : input.copies)
      h.add(static_cast<std::uint64_t>(v));
  }
  input.hash = h.hex();
}

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_MESH_INPUT_H
