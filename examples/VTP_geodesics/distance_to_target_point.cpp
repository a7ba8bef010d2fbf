// The distance between two points of the surface: the target is a point inside a face (a face location,
// as CGAL::Polygon_mesh_processing::locate returns it); the propagation stops as soon as its distance is
// final, and the distance is exact at the point itself (not interpolated from the corners of its face).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <array>
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
typedef Triangle_mesh::Face_index                           face_descriptor;

namespace PMP = CGAL::Polygon_mesh_processing;
namespace VG = CGAL::VTP_geodesics;
typedef PMP::Face_location<Triangle_mesh, double> Face_location;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;

  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // Two points of the surface: the source in the first face, the target in the middle face (by index).
  const face_descriptor first = *faces(tm).begin();
  const face_descriptor middle(static_cast<Triangle_mesh::size_type>(num_faces(tm) / 2));
  const Face_location source(first, CGAL::make_array(0.2, 0.3, 0.5));
  const Face_location target(middle, CGAL::make_array(1. / 3, 1. / 3, 1. / 3));

  VG::Geodesic_distance_solver<Triangle_mesh> solver(tm);
  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  const std::vector<Face_location> targets(1, target);
  solver.compute(distance, source, VG::parameters::targets(targets));   // stops once the target is final

  const VG::Propagation_statistics& stats = solver.statistics();
  std::cout << "source " << PMP::construct_point(source, tm) << " -> target "
            << PMP::construct_point(target, tm) << std::endl;
  std::cout << "geodesic distance: " << solver.target_distance(0) << std::endl;
  std::cout << "vertices processed: " << stats.vertices_processed << " of " << num_vertices(tm)
            << (stats.stopped_early ? " (stopped early)" : "") << std::endl;

  // The straight-line distance is a lower bound of the geodesic one.
  const double chord = std::sqrt(CGAL::squared_distance(PMP::construct_point(source, tm),
                                                        PMP::construct_point(target, tm)));
  std::cout << "straight-line distance: " << chord << std::endl;
  return solver.target_distance(0) >= chord * (1. - 1e-12) ? EXIT_SUCCESS : EXIT_FAILURE;
}
