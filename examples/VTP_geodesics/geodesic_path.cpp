// The geodesic path from the farthest vertex back to the source, written as a polyline (CGAL's polylines
// text format: the number of points, then their coordinates) next to a copy of the mesh, to open both in
// a viewer. With record_paths(true), the computation keeps what the trace-back needs (O(V) memory).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3                                     Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;

namespace VG = CGAL::VTP_geodesics;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;
  const std::string prefix = (argc > 2) ? argv[2] : "geodesic_path";

  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  VG::Geodesic_distance_solver<Triangle_mesh> solver(tm);
  const vertex_descriptor source = *vertices(tm).begin();
  solver.compute(distance, source, VG::parameters::record_paths(true));

  vertex_descriptor farthest = source;
  for(vertex_descriptor v : vertices(tm))
    if(std::isfinite(distance[v]) && distance[v] > distance[farthest])
      farthest = v;

  std::vector<Point_3> path;                       // from the farthest vertex to the source
  solver.shortest_path_points(farthest, std::back_inserter(path));

  double length = 0.;
  for(std::size_t i = 1; i < path.size(); ++i)
    length += std::sqrt(CGAL::squared_distance(path[i - 1], path[i]));
  std::cout << "path of " << path.size() << " points from vertex " << farthest << ": length " << length
            << ", geodesic distance " << distance[farthest] << std::endl;

  std::ofstream polylines(prefix + ".polylines.txt");
  polylines.precision(17);
  polylines << path.size();
  for(const Point_3& p : path)
    polylines << " " << p;
  polylines << "\n";
  if(!polylines || !CGAL::IO::write_polygon_mesh(prefix + ".off", tm, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "Cannot write " << prefix << ".polylines.txt or " << prefix << ".off" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << prefix << ".off and " << prefix << ".polylines.txt" << std::endl;
  return std::abs(length - distance[farthest]) <= 1e-9 * distance[farthest] ? EXIT_SUCCESS : EXIT_FAILURE;
}
