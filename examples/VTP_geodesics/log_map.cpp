// The log map (geodesic polar coordinates): one exact run gives, with the distances, for every vertex the
// angle theta at which its geodesic leaves the source, written as rho (cos theta, sin theta) in the tangent
// frame of the source (rho: the distance). Around a vertex, then around a point inside a face.
// Checks: rho is the distance of the same run at every vertex; the source is at (0, 0).

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
#include <sstream>
#include <string>
#include <utility>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                 Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;
typedef Triangle_mesh::Face_index                           face_descriptor;
typedef std::pair<face_descriptor, std::array<double, 3> >  Face_location;

namespace VG = CGAL::VTP_geodesics;

// Prints the log map of the last run and checks that its radius is the distance; returns the number of errors.
template <class DistanceMap, class LogMap, class ViaMap>
int report(const std::string& around, const Triangle_mesh& tm, DistanceMap distance, LogMap log, ViaMap via)
{
  const double pi = std::acos(-1.);
  int errors = 0;
  std::size_t reached = 0, behind = 0, shown = 0;
  double largest = 0.;
  std::ostringstream samples;  // a few vertices, printed after the summary
  for(vertex_descriptor v : vertices(tm))
  {
    if(!std::isfinite(distance[v]))
      continue;
    ++reached;
    largest = (std::max)(largest, distance[v]);
    const double rho = std::hypot(log[v][0], log[v][1]);
    if(!(std::abs(rho - distance[v]) <= 1e-12 * (1. + distance[v])))
    {
      std::cerr << "vertex " << v << ": log map radius " << rho << ", distance " << distance[v] << std::endl;
      ++errors;
    }
    if(via[v] != Triangle_mesh::null_vertex())  // its geodesic turns at a saddle or border vertex
      ++behind;
    if(shown < 4 && rho > 0.)
    {
      samples << "  vertex " << std::size_t(v) << ": rho " << rho << ", theta "
              << std::atan2(log[v][1], log[v][0]) * 180. / pi << " degrees" << std::endl;
      ++shown;
    }
  }
  std::cout << around << ": " << reached << " vertices, largest rho " << largest << ", " << behind
            << " behind a saddle or border vertex" << std::endl << samples.str();
  return errors;
}

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
  auto log = tm.add_property_map<vertex_descriptor, std::array<double, 2> >("v:log_map").first;
  auto via = tm.add_property_map<vertex_descriptor, vertex_descriptor>("v:via").first;
  VG::Geodesic_distance_solver<Triangle_mesh> solver(tm);

  // around a vertex: theta = 0 along the edge to source(halfedge(c)), angles scaled by 2 pi / the angle sum at c
  const vertex_descriptor centre = *vertices(tm).begin();
  solver.compute(distance, centre, VG::parameters::log_map(log).log_map_via(via));
  int errors = report("around vertex " + std::to_string(std::size_t(centre)), tm, distance, log, via);
  if(log[centre][0] != 0. || log[centre][1] != 0.)
    ++errors;

  // around a point inside a face (its centroid), within a radius: theta = 0 along halfedge(f), unscaled
  const Face_location point(*faces(tm).begin(), { { 1. / 3., 1. / 3., 1. / 3. } });
  const double radius = 20. * solver.mean_edge_length();
  solver.compute(distance, point, VG::parameters::log_map(log).log_map_via(via).maximum_distance(radius));
  errors += report("around the centroid of face " + std::to_string(std::size_t(point.first)) + " (radius "
                   + std::to_string(radius) + ")", tm, distance, log, via);

  if(errors != 0)
    std::cerr << errors << " error(s)" << std::endl;
  return errors == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
