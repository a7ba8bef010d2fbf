// Farthest-point sampling with exact geodesic distances: 50 samples spread evenly over the surface, the
// covering radius after each, and the geodesic Voronoi cells of the samples with their areas. The free function
// writes into property maps; the solver member returns everything at once and reuses the preprocessing.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/farthest_point_sampling.h>
#include <CGAL/VTP_geodesics/geodesic_voronoi_cells.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <iterator>
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

  // The free function: the samples in order, the covering radius after each, and the Voronoi cell (the index
  // of the nearest sample) of every vertex.
  std::vector<vertex_descriptor> samples;
  std::vector<double> radii;
  auto cell = tm.add_property_map<vertex_descriptor, std::size_t>("v:cell", 0).first;
  VTP::farthest_point_sampling(tm, 50, std::back_inserter(samples),
                               VTP::parameters::covering_radii(std::back_inserter(radii)).nearest_source_map(cell));
  // (fewer than 50 on a mesh of fewer vertices: the sampling stops once every vertex is a sample)
  std::cout << samples.size() << " samples (vertex, covering radius once it is taken):\n";
  for(std::size_t i = 0; i < samples.size(); ++i)
  {
    if(i < 5 || i + 1 == samples.size())
      std::cout << "  " << std::size_t(samples[i]) << " " << radii[i] << "\n";
    else if(i == 5)
      std::cout << "  ...\n";
  }

  // The solver member: the same samples from a given first vertex, until every vertex is within half of the
  // radius above; then the area of each cell.
  VTP::Geodesic_distance_solver<Triangle_mesh> solver(tm);
  const auto r = solver.farthest_point_sampling(1000, VTP::parameters::first_sample(samples[0])
                                                        .sampling_radius(0.5 * radii.back()));
  const VTP::Voronoi_cell_areas cells =
    VTP::geodesic_voronoi_cell_areas(tm, r.samples.size(), r.labels, r.distances);
  const auto extremes = std::minmax_element(cells.areas.begin(), cells.areas.end());
  std::cout << r.samples.size() << " samples for a radius of " << r.radii.back() << " (" << r.statistics.windows_created
            << " windows); cell areas from " << *extremes.first << " to " << *extremes.second << std::endl;
  return EXIT_SUCCESS;
}
