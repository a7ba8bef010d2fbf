// A source anywhere on the surface: a 3D point (say, where the user clicked) is located on the mesh with
// CGAL::Polygon_mesh_processing::locate (an AABB tree finds the nearest face), and the resulting face
// location is the source.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/geodesic_distances.h>

#include <cstdlib>
#include <iostream>
#include <string>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3                                     Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;

namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;

  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The "clicked" point: here, a point just off the surface, near the middle of the first face.
  const Triangle_mesh::Halfedge_index h = halfedge(*faces(tm).begin(), tm);
  const Point_3 clicked = CGAL::centroid(tm.point(source(h, tm)), tm.point(target(h, tm)),
                                         tm.point(target(next(h, tm), tm))) + Kernel::Vector_3(0, 0, 1e-3);

  // Locate it: the nearest point of the surface, as a face and barycentric coordinates.
  typedef CGAL::AABB_face_graph_triangle_primitive<Triangle_mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > Tree;
  Tree tree;
  PMP::build_AABB_tree(tm, tree);
  const PMP::Face_location<Triangle_mesh, double> source = PMP::locate_with_AABB_tree(clicked, tree, tm);

  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  CGAL::VTP_geodesics::compute_geodesic_distances(tm, distance, source);

  vertex_descriptor farthest = *vertices(tm).begin();
  for(vertex_descriptor v : vertices(tm))
    if(distance[v] > distance[farthest])
      farthest = v;
  std::cout << "source: face " << source.first << ", barycentric coordinates " << source.second[0] << " "
            << source.second[1] << " " << source.second[2] << std::endl;
  std::cout << "farthest vertex: " << farthest << " at distance " << distance[farthest] << std::endl;
  return EXIT_SUCCESS;
}
