// A distance limit: only the vertices within a radius of the source get their (exact) distance, the
// others +infinity, and the work done is that of the region within the radius (the statistics show it).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                 Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;

namespace VG = CGAL::VTP_geodesics;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;

  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  VG::Geodesic_distance_solver<Triangle_mesh> solver(tm);
  const vertex_descriptor source = *vertices(tm).begin();

  // A full run first, to choose a radius: a tenth of the largest distance.
  solver.compute(distance, source);
  const VG::Propagation_statistics full = solver.statistics();
  const double radius = 0.1 * full.max_distance;

  // The same source with the limit: vertices beyond the radius get +infinity.
  solver.compute(distance, source, VG::parameters::maximum_distance(radius));
  const VG::Propagation_statistics limited = solver.statistics();

  std::size_t inside = 0;
  for(vertex_descriptor v : vertices(tm))
    if(std::isfinite(distance[v]))
      ++inside;
  std::cout << "radius " << radius << ": " << inside << " of " << num_vertices(tm) << " vertices within it"
            << std::endl;
  std::cout << "windows propagated: " << limited.windows_propagated << " (full run: " << full.windows_propagated
            << ")" << std::endl;
  std::cout << "vertices processed: " << limited.vertices_processed << " (full run: " << full.vertices_processed
            << ")" << std::endl;
  return EXIT_SUCCESS;
}
