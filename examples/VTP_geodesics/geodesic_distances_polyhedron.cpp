// Geodesic distances on a Polyhedron_3 without vertex ids: the output is an std::unordered_map
// seen as a property map through boost::make_assoc_property_map.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/geodesic_distances.h>

#include <boost/property_map/property_map.hpp>

#include <cstdlib>
#include <iostream>
#include <string>
#include <unordered_map>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel            Kernel;
typedef CGAL::Polyhedron_3<Kernel>                                     Triangle_mesh;
typedef boost::graph_traits<Triangle_mesh>::vertex_descriptor          vertex_descriptor;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;

  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // Polyhedron_3 has no vertex index: the package numbers the vertices internally,
  // and the distances go into an associative container.
  std::unordered_map<vertex_descriptor, double> distances;
  auto distance_map = boost::make_assoc_property_map(distances);

  const vertex_descriptor source = *(vertices(tm).first);
  CGAL::VTP_geodesics::compute_geodesic_distances(tm, distance_map, source);

  // The farthest vertex from the source.
  vertex_descriptor farthest = source;
  for(vertex_descriptor v : vertices(tm))
    if(distances[v] > distances[farthest])
      farthest = v;

  std::cout << "source at (" << source->point() << ")" << std::endl;
  std::cout << "farthest vertex at (" << farthest->point() << "), distance " << distances[farthest] << std::endl;
  return EXIT_SUCCESS;
}
