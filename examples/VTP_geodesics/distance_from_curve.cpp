// The distance from a curve drawn on the surface, unsigned and signed (negative on the left of the curve: inside
// a counter-clockwise loop seen from the side of the faces' normals).
//
// 1. A flat jittered grid of the unit square, built here, and a closed polygon of points located on it: the
//    geodesic distance is the Euclidean distance to the polygon, negative inside with signed_distance(true).
// 2. The mesh of the command line (default: the elephant) and a curve through three of its vertices, which share
//    no face (joined by the shortest geodesics between them): the distance to the curve is 0 at its points and
//    never more than the distance to any of them.
// The program checks both and fails otherwise.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3                                     Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;

namespace PMP = CGAL::Polygon_mesh_processing;
namespace VTP = CGAL::VTP_geodesics;

// An n x n grid of the unit square (z = 0), interior vertices moved by less than a quarter of the spacing,
// counter-clockwise triangles (normal +z).
Triangle_mesh jittered_square(int n)
{
  Triangle_mesh tm;
  std::mt19937 random(47);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  const double h = 1. / (n - 1);
  std::vector<vertex_descriptor> v;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const bool inner = i > 0 && i < n - 1 && j > 0 && j < n - 1;
      const double dx = jitter(random) * h, dy = jitter(random) * h;
      v.push_back(tm.add_vertex(Point_3(i * h + (inner ? dx : 0.), j * h + (inner ? dy : 0.), 0.)));
    }
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i)
    {
      const vertex_descriptor a = v[j * n + i], b = v[j * n + i + 1], c = v[(j + 1) * n + i + 1],
                              d = v[(j + 1) * n + i];
      tm.add_face(a, b, c);
      tm.add_face(a, c, d);
    }
  return tm;
}

// The Euclidean distance from (x, y) to the closed polygon `p`, and whether (x, y) is inside it.
double distance_to_polygon(const std::vector<std::array<double, 2> >& p, double x, double y, bool& inside)
{
  double best = std::numeric_limits<double>::infinity();
  inside = false;
  for(std::size_t k = 0; k < p.size(); ++k)
  {
    const std::array<double, 2>& a = p[k];
    const std::array<double, 2>& b = p[(k + 1) % p.size()];
    const double ux = b[0] - a[0], uy = b[1] - a[1];
    const double t = (std::max)(0., (std::min)(1., ((x - a[0]) * ux + (y - a[1]) * uy) / (ux * ux + uy * uy)));
    best = (std::min)(best, std::hypot(x - a[0] - t * ux, y - a[1] - t * uy));
    if((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * ux / uy)
      inside = !inside;
  }
  return best;
}

int main(int argc, char* argv[])
{
  // 1. The plane: a counter-clockwise polygon, its points located on the surface (the last one repeats the
  //    first: the curve is closed).
  {
    const Triangle_mesh tm = jittered_square(41);
    typedef CGAL::AABB_face_graph_triangle_primitive<Triangle_mesh> Primitive;
    typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > Tree;
    Tree tree;
    PMP::build_AABB_tree(tm, tree);
    const std::vector<std::array<double, 2> > polygon = { { { 0.31, 0.29 } }, { { 0.72, 0.33 } },
                                                          { { 0.69, 0.71 } }, { { 0.27, 0.66 } } };
    std::vector<PMP::Face_location<Triangle_mesh, double> > curve;
    for(std::size_t k = 0; k <= polygon.size(); ++k)
    {
      const std::array<double, 2>& p = polygon[k % polygon.size()];
      curve.push_back(PMP::locate_with_AABB_tree(Point_3(p[0], p[1], 0.), tree, tm));
    }

    VTP::Geodesic_distance_solver<Triangle_mesh> solver(tm);
    solver.add_source_curve(curve);  // one source
    std::vector<double> unsigned_d, signed_d;
    const CGAL::Constant_property_map<vertex_descriptor, double> no_map;
    solver.compute(no_map);
    unsigned_d = solver.distances();  // indexed by vertex_id(): the order of vertices(tm)
    solver.compute(no_map, VTP::parameters::signed_distance(true));
    signed_d = solver.distances();

    double worst = 0.;
    std::size_t inside_count = 0;
    for(vertex_descriptor v : vertices(tm))
    {
      bool inside = false;
      const double e = distance_to_polygon(polygon, tm.point(v).x(), tm.point(v).y(), inside);
      const std::size_t i = solver.vertex_id(v);
      worst = (std::max)(worst, std::abs(unsigned_d[i] - e));
      worst = (std::max)(worst, std::abs(signed_d[i] - (inside ? -e : e)));
      inside_count += inside ? 1 : 0;
    }
    std::cout << "plane: " << num_vertices(tm) << " vertices (" << inside_count << " inside the polygon); largest "
              << "difference from the Euclidean distance to the polygon, unsigned and signed: " << worst << std::endl;
    if(!(worst <= 1e-12) || inside_count == 0)
    {
      std::cerr << "FAILED: the distance from the polygon is not the Euclidean one" << std::endl;
      return EXIT_FAILURE;
    }
  }

  // 2. A curve through three vertices of a real mesh.
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;
  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }
  const std::size_t n = num_vertices(tm);
  const std::vector<vertex_descriptor> through = { vertex_descriptor(0), vertex_descriptor(Triangle_mesh::size_type(n / 3)),
                                                   vertex_descriptor(Triangle_mesh::size_type(2 * n / 3)) };
  VTP::Geodesic_distance_solver<Triangle_mesh> solver(tm);
  const CGAL::Constant_property_map<vertex_descriptor, double> no_map;
  // the distances from each of the three points alone
  std::vector<std::vector<double> > from_point;
  for(vertex_descriptor v : through)
  {
    solver.compute(no_map, v);
    from_point.push_back(solver.distances());
  }
  solver.clear_sources();
  solver.add_source_curve(through);
  solver.compute(no_map);
  const std::vector<double>& d = solver.distances();
  double above = 0., largest = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!std::isfinite(d[i]))
      continue;
    largest = (std::max)(largest, d[i]);
    for(const std::vector<double>& p : from_point)
      above = (std::max)(above, d[i] - p[i]);
  }
  double at_points = 0.;
  for(vertex_descriptor v : through)
    at_points = (std::max)(at_points, std::abs(d[solver.vertex_id(v)]));
  std::cout << filename << ": the curve through vertices " << through[0] << ", " << through[1] << ", " << through[2]
            << ": largest distance " << largest << ", distance at its points " << at_points
            << ", largest excess over the distance to one of its points " << above << std::endl;
  if(!(at_points == 0.) || !(above <= 1e-12 * largest) || !(largest > 0.))
  {
    std::cerr << "FAILED: the distance to the curve is not 0 at its points, or exceeds the distance to one of them"
              << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "done" << std::endl;
  return EXIT_SUCCESS;
}
