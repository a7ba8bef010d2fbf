// vtp_benchmark: the input meshes (read, remeshed, subdivided) and their OFF files for external methods.

#include "vtp_benchmark.h"

#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/subdivision_method_3.h>

#include <vtp_support/midpoint_subdivision.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

namespace vtp_benchmark {

void write_off(const Mesh& mesh, const std::string& file)
{
  // 17 significant digits: the coordinates read back exactly. The mesh has no garbage (see load_mesh), so the
  // vertices are written in index order.
  if(!CGAL::IO::write_OFF(file, mesh, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write '" + file + "'");
}

namespace {

std::string base_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

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
    throw Tool_error("cannot read mesh '" + file + "'");
  if(mesh.is_empty() || mesh.number_of_faces() == 0)
    throw Tool_error("the mesh '" + file + "' is empty");
  if(!CGAL::is_triangle_mesh(mesh))
    throw Tool_error("the mesh '" + file + "' is not a triangle mesh");
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
