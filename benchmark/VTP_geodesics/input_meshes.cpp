// vtp_benchmark: the input meshes (read, remeshed, subdivided) and their OFF files for external methods.

#include "vtp_benchmark.h"

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/subdivision_method_3.h>

#include <vtp_support/midpoint_subdivision.h>

#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

namespace vtp_benchmark {

void write_off(const Mesh& mesh, const std::string& file)
{
  FILE* out = std::fopen(file.c_str(), "w");
  if(out == nullptr)
    throw std::runtime_error("cannot write '" + file + "'");
  std::fprintf(out, "OFF\n%zu %zu 0\n", static_cast<std::size_t>(mesh.number_of_vertices()),
               static_cast<std::size_t>(mesh.number_of_faces()));
  for(Vertex_index v : mesh.vertices())
  {
    const Kernel::Point_3& p = mesh.point(v);
    std::fprintf(out, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  }
  for(Mesh::Face_index f : mesh.faces())
  {
    std::fprintf(out, "3");
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      std::fprintf(out, " %zu", static_cast<std::size_t>(v));
    std::fprintf(out, "\n");
  }
  if(std::fclose(out) != 0)
    throw std::runtime_error("cannot write '" + file + "'");
}

namespace {

std::string base_name(const std::string& path)
{
  const std::string::size_type slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

} // namespace

// Reads a mesh and makes the requested input from it: isotropic remeshing, then Loop subdivision,
// then midpoint subdivision. The vertices are numbered 0..n-1 in the end (garbage collected).
std::string load_mesh(const std::string& file, const Arguments& args, Mesh& mesh)
{
  std::ostringstream diagnostics;
  std::streambuf* const cerr_buffer = std::cerr.rdbuf(diagnostics.rdbuf());
  bool ok = false;
  try { ok = CGAL::IO::read_polygon_mesh(file, mesh); } catch(...) { ok = false; }
  std::cerr.rdbuf(cerr_buffer);
  if(!ok)
    throw Usage_error("cannot read mesh '" + file + "'");
  if(mesh.is_empty() || mesh.number_of_faces() == 0)
    throw Usage_error("the mesh '" + file + "' is empty");
  if(!CGAL::is_triangle_mesh(mesh))
    throw Usage_error("the mesh '" + file + "' is not a triangle mesh");
  std::string label = base_name(file);
  if(args.remesh > 0.)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    double sum = 0.;
    for(Mesh::Edge_index e : mesh.edges())
      sum += PMP::edge_length(e, mesh);
    const double target = args.remesh * sum / double(mesh.number_of_edges());
    PMP::isotropic_remeshing(faces(mesh), target, mesh,
                             CGAL::parameters::number_of_iterations(args.remesh_iterations));
    mesh.collect_garbage();
    label += "/r" + number(args.remesh, 4);
  }
  if(args.loop > 0)
  {
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(args.loop));
    label += "/L" + std::to_string(args.loop);
  }
  if(args.subdivide > 0)
  {
    vtp_support::midpoint_subdivide(mesh, args.subdivide);
    label += "/s" + std::to_string(args.subdivide);
  }
  if(mesh.has_garbage())
    mesh.collect_garbage();
  return label;
}

} // namespace vtp_benchmark
