// One Geodesic_distance_solver reused for several sources: the per-mesh preprocessing is done once.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel   Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                   Triangle_mesh;
typedef Triangle_mesh::Vertex_index                           vertex_descriptor;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Triangle_mesh> Solver;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;

  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // Preprocessing (half-edge arrays, edge lengths, angles, saddle vertices), done once.
  Solver solver(tm);
  std::cout << num_vertices(tm) << " vertices, mean edge length " << solver.mean_edge_length()
            << ", preprocessing " << solver.preprocessing_seconds() << " s" << std::endl;

  Triangle_mesh::Property_map<vertex_descriptor, double> distance =
    tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;

  // Three sources, spread over the vertex list.
  const std::size_t n = num_vertices(tm);
  const std::vector<vertex_descriptor> sources = {
    vertex_descriptor(0), vertex_descriptor(static_cast<Triangle_mesh::size_type>(n / 2)),
    vertex_descriptor(static_cast<Triangle_mesh::size_type>(n - 1)) };

  for(vertex_descriptor s : sources)
  {
    solver.compute(distance, s);
    const CGAL::VTP_geodesics::Propagation_statistics& stats = solver.statistics();
    // The distance between the first and the last source, seen from each source.
    std::cout << "source " << s << ": distance to " << sources.front() << " = " << distance[sources.front()]
              << ", to " << sources.back() << " = " << distance[sources.back()]
              << " (" << stats.seconds << " s)" << std::endl;
  }
  return EXIT_SUCCESS;
}
