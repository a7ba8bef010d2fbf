// Polar patches: the log map around each of many centres, cut at a radius, in compressed sparse rows (each row:
// the vertices within the radius of its centre, with their geodesic polar coordinates rho and theta), as a
// geodesic convolutional network takes them. A run costs its patch, not the mesh.
// Checks: each row holds its centre (rho 0), its vertices in ascending order, each with rho <= radius and theta
// in [0, 2 pi); and rho is the distance of compute() from the centre alone with the same radius, bit for bit.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics.h>

#include <algorithm>
#include <cmath>
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
  VG::Geodesic_distance_solver<Triangle_mesh> solver(tm);

  // ten centres spread over the vertices, a radius of five mean edge lengths
  std::vector<vertex_descriptor> centres;
  for(std::size_t i = 0; i < 10; ++i)
    centres.push_back(solver.vertex_list()[i * solver.number_of_vertices() / 10]);
  const double radius = 5. * solver.mean_edge_length();
  const VG::Polar_patches patches = solver.polar_patches(centres, radius);
  std::cout << patches.number_of_patches() << " patches of radius " << radius << ": " << patches.number_of_entries()
            << " entries" << std::endl;

  const double two_pi = 2. * std::acos(-1.);
  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  int errors = 0;
  for(std::size_t i = 0; i < patches.number_of_patches(); ++i)
  {
    solver.compute(distance, centres[i], VG::parameters::maximum_distance(radius));
    std::size_t within = 0;
    for(vertex_descriptor v : vertices(tm))
      within += (distance[v] <= radius) ? 1 : 0;
    bool has_centre = false;
    double farthest = 0.;
    for(std::size_t e = patches.offsets[i]; e < patches.offsets[i + 1]; ++e)
    {
      const vertex_descriptor v = solver.vertex_list()[patches.vertices[e]];
      has_centre = has_centre || (v == centres[i] && patches.rho[e] == 0.);
      if(e > patches.offsets[i] && patches.vertices[e] <= patches.vertices[e - 1])
        ++errors;                                              // not ascending
      if(!(patches.rho[e] <= radius) || patches.rho[e] != distance[v])
        ++errors;                                              // not the distance of the same run
      if(!(patches.theta[e] >= 0. && patches.theta[e] < two_pi))
        ++errors;
      farthest = (std::max)(farthest, patches.rho[e]);
    }
    const std::size_t size = patches.offsets[i + 1] - patches.offsets[i];
    if(!has_centre || size != within)
      ++errors;                                                // the centre missing, or a vertex of the disk
    std::cout << "  centre " << std::size_t(centres[i]) << ": " << size << " vertices, the farthest at " << farthest
              << std::endl;
  }
  if(errors != 0)
    std::cerr << errors << " error(s)" << std::endl;
  return errors == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
