// Geodesic distances from one source vertex on a Surface_mesh, with the free function.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/geodesic_distances.h>

#include <cstdlib>
#include <iostream>
#include <string>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                 Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;

  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The output: a property map attached to the mesh.
  Triangle_mesh::Property_map<vertex_descriptor, double> distance =
    tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;

  // Exact geodesic distances from the first vertex.
  const vertex_descriptor source = *(vertices(tm).first);
  CGAL::VTP_geodesics::Propagation_statistics stats;  // optional
  CGAL::VTP_geodesics::compute_geodesic_distances(tm, distance, source,
                                                  CGAL::VTP_geodesics::parameters::statistics(stats));

  std::cout << "source: " << source << ", " << num_vertices(tm) << " vertices, "
            << stats.windows_created << " windows created in " << stats.seconds << " s" << std::endl;

  // Print a few distances.
  int printed = 0;
  for(vertex_descriptor v : vertices(tm))
  {
    std::cout << "  distance(" << v << ") = " << distance[v] << std::endl;
    if(++printed == 5)
      break;
  }
  return EXIT_SUCCESS;
}
