// Straightest geodesics (the exponential map): a walk from a point of the surface in a direction of its tangent
// plane for a length, straight across the faces. Here it undoes the log map: from the centroid of a face, the log
// map gives each nearby vertex v its distance rho and direction theta; the walk from the centroid in the direction
// theta for the length rho ends at v, when the geodesic to v passes through no vertex (via: none).
// Checks: every such walk goes its whole length (the polyline is that long), and every walk that meets no other
// vertex on its way ends at its vertex. (A walk that meets a vertex goes on from it by the straightest rule: where
// the geodesic to v grazes a vertex, the log map can take the path beside it, and the walk misses v; these walks
// are counted, not checked: issue 46.)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3                                     Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;
typedef Triangle_mesh::Face_index                           face_descriptor;
typedef std::pair<face_descriptor, std::array<double, 3> >  Face_location;

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

  // the log map around the centroid of a face, within a few edge lengths
  const Face_location start(*faces(tm).begin(), { { 1. / 3., 1. / 3., 1. / 3. } });
  const double radius = 4. * solver.mean_edge_length();
  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  auto log = tm.add_property_map<vertex_descriptor, std::array<double, 2> >("v:log_map").first;
  auto via = tm.add_property_map<vertex_descriptor, vertex_descriptor>("v:via").first;
  solver.compute(distance, start, VG::parameters::log_map(log).log_map_via(via).maximum_distance(radius));

  // one walk per vertex whose geodesic turns at no vertex: direction theta (the log map's frame), length rho
  std::size_t walks = 0, through_vertex = 0;
  double worst_miss = 0., worst_length = 0., worst_through = 0.;
  for(vertex_descriptor v : vertices(tm))
  {
    const double rho = distance[v];
    if(!(rho > 0. && rho <= radius) || via[v] != Triangle_mesh::null_vertex())
      continue;
    const std::array<double, 2> direction = { { log[v][0] / rho, log[v][1] / rho } };
    const VG::Straightest_geodesic<face_descriptor, Point_3> walk = solver.straightest_geodesic(start, direction, rho);
    double polyline = 0.;
    for(std::size_t i = 1; i < walk.points.size(); ++i)
      polyline += std::sqrt(CGAL::squared_distance(walk.points[i - 1], walk.points[i]));
    worst_length = (std::max)(worst_length, std::abs(polyline - rho) + std::abs(walk.length - rho));
    const double miss = std::sqrt(CGAL::squared_distance(walk.end_point, tm.point(v)));
    bool meets_vertex = false;  // a point of the walk at another vertex: a barycentric coordinate 1
    for(std::size_t i = 0; i < walk.locations.size(); ++i)
      for(double b : walk.locations[i].second)
        meets_vertex = meets_vertex || (b == 1. && walk.points[i] != tm.point(v));
    if(meets_vertex)
    {
      ++through_vertex;
      worst_through = (std::max)(worst_through, miss);
    }
    else
      worst_miss = (std::max)(worst_miss, miss);
    ++walks;
    if(walks <= 3)
      std::cout << "  to vertex " << std::size_t(v) << ": direction (" << direction[0] << ", " << direction[1]
                << "), length " << rho << ", " << walk.points.size() << " points, ends at " << walk.end_point
                << std::endl;
  }
  std::cout << walks << " walks from the centroid of face " << std::size_t(start.first) << ": largest miss of the "
            << "vertex " << worst_miss << ", largest length error " << worst_length << "; " << through_vertex
            << " walk(s) meeting another vertex on the way (largest miss " << worst_through << ")" << std::endl;
  const bool ok = walks > through_vertex && worst_miss <= 1e-9 * radius && worst_length <= 1e-9 * radius;
  if(!ok)
    std::cerr << "a walk did not reach its vertex" << std::endl;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
