// Ask the field: one exact run from two sources keeps its field (keep_field(true)); then the distance and the
// nearest source at any point of the surface (here located from positions with PMP::locate), and isolines at
// levels chosen after the run, are queries on it, without a new propagation.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics.h>

#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                 Triangle_mesh;
typedef Triangle_mesh::Vertex_index                         vertex_descriptor;

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

  // one run from two vertices, keeping the field
  VG::Geodesic_distance_solver<Triangle_mesh> solver(tm);
  const std::vector<vertex_descriptor> sources = { *vertices(tm).begin(),
                                                   vertex_descriptor(static_cast<Triangle_mesh::size_type>(num_vertices(tm) / 2)) };
  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  solver.compute(distance, sources, VG::parameters::keep_field(true));
  std::cout << "kept field: " << solver.statistics().field_pieces << " pieces, " << solver.field_bytes() << " bytes"
            << std::endl;

  // the exact distance and the nearest source at points of the surface
  CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(tm);
  for(int i = 0; i < 3; ++i)
  {
    const double t = (i + 1) / 4.;
    const Kernel::Point_3 near(box.xmin() + t * (box.xmax() - box.xmin()), box.ymin() + t * (box.ymax() - box.ymin()),
                               box.zmin() + t * (box.zmax() - box.zmin()));
    const Face_location p = PMP::locate(near, tm);
    std::cout << "at " << PMP::construct_point(p, tm) << ": distance " << solver.field_distance(p)
              << ", nearest source " << solver.field_nearest_source(p) << std::endl;
  }

  // isolines at levels chosen now, from the same run (exact: on the distance inside the faces)
  double largest = 0.;
  for(double d : solver.distances())
    if(d < std::numeric_limits<double>::infinity() && d > largest)
      largest = d;
  const std::vector<double> levels = { 0.25 * largest, 0.5 * largest };
  const auto isolines = VG::geodesic_isolines(solver, levels);
  const auto borders = VG::geodesic_cell_borders(solver);
  std::cout << isolines.size() << " isolines at " << levels[0] << " and " << levels[1] << ", " << borders.size()
            << " border(s) between the two cells" << std::endl;
  for(const auto& c : isolines)
    std::cout << "  level " << c.level << ": " << c.points.size() << " points, " << (c.closed ? "closed" : "open")
              << std::endl;
  return EXIT_SUCCESS;
}
