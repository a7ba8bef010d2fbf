// Several sources at once: the distance of each vertex to the nearest source, and which source that is
// (a geodesic Voronoi partition of the vertices).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/geodesic_distances.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                 Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;

namespace VTP = CGAL::VTP_geodesics;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;

  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // Four sources spread over the vertex list.
  const std::size_t n = num_vertices(tm);
  std::vector<vertex_descriptor> sources;
  for(std::size_t i = 0; i < 4; ++i)
    sources.push_back(vertex_descriptor(static_cast<Triangle_mesh::size_type>(i * n / 4)));

  // Outputs: the distance to the nearest source, and its index in `sources`.
  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  auto nearest = tm.add_property_map<vertex_descriptor, std::size_t>("v:nearest_source", 0).first;

  VTP::compute_geodesic_distances(tm, distance, sources, VTP::parameters::nearest_source_map(nearest));

  // The size of each region, and its farthest vertex.
  std::vector<std::size_t> size(sources.size(), 0);
  std::vector<double> radius(sources.size(), 0.);
  for(vertex_descriptor v : vertices(tm))
  {
    if(nearest[v] == VTP::no_source) // not reached by any source (another connected component)
      continue;
    ++size[nearest[v]];
    radius[nearest[v]] = (std::max)(radius[nearest[v]], distance[v]);
  }
  for(std::size_t i = 0; i < sources.size(); ++i)
    std::cout << "source " << i << " (vertex " << sources[i] << "): " << size[i] << " vertices, within "
              << radius[i] << std::endl;
  return EXIT_SUCCESS;
}
