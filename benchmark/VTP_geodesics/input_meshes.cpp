// vtp_benchmark: the input meshes (read, remeshed, subdivided) and their OFF files for external methods.

#include "vtp_benchmark.h"

#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/subdivision_method_3.h>

#include <vtp_support/midpoint_subdivision.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <utility>
#include <vector>
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

// Renumbers the vertices of `mesh` (no garbage) in the order in which the solver stores them (along a Morton
// curve of their positions: Geodesic_distance_solver::vertices_in_storage_order()), vertex 0 first, and orders
// the faces by their least new vertex index.
void reorder_morton(Mesh& mesh)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<std::size_t> new_index(n);
  std::vector<Mesh::Point> points(n);
  {
    const CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> solver(mesh);
    std::size_t next = 1;
    for(Mesh::Vertex_index v : solver.vertices_in_storage_order())
    {
      const std::size_t i = std::size_t(v) == 0 ? 0 : next++;
      new_index[std::size_t(v)] = i;
      points[i] = mesh.point(v);
    }
    if(next != n)
      throw Tool_error("--morton: the solver stores " + std::to_string(next) + " of " + std::to_string(n) + " vertices");
  }
  std::vector<std::array<std::size_t, 3> > triangles;
  triangles.reserve(mesh.number_of_faces());
  for(Mesh::Face_index f : mesh.faces())
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(Mesh::Vertex_index v : mesh.vertices_around_face(mesh.halfedge(f)))
      t[k++] = new_index[std::size_t(v)];
    triangles.push_back(t);
  }
  std::stable_sort(triangles.begin(), triangles.end(), [](const std::array<std::size_t, 3>& a, const std::array<std::size_t, 3>& b) {
    return (std::min)({ a[0], a[1], a[2] }) < (std::min)({ b[0], b[1], b[2] });
  });
  Mesh reordered;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, reordered);
  bool same = reordered.number_of_vertices() == n && reordered.number_of_faces() == mesh.number_of_faces();
  for(std::size_t i = 0; same && i < n; ++i)
    same = reordered.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(i))) == points[i];
  if(!same)
    throw Tool_error("--morton: the renumbered mesh is not the mesh in the new order");
  mesh = std::move(reordered);
}

} // namespace

// Reads a mesh and makes the requested input from it: isotropic remeshing, then Loop subdivision,
// then midpoint subdivision, then (--morton) the renumbering along a Morton curve. The vertices are numbered
// 0..n-1 in the end (garbage collected).
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
  if(args.morton)
  {
    reorder_morton(mesh);
    label += "/morton";
  }
  return label;
}

} // namespace vtp_benchmark
