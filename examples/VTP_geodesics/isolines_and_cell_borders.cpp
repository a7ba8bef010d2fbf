// Isolines and cell borders from exact runs that keep their field (keep_field(true)): the borders between the
// geodesic Voronoi cells of three sources and the cells' areas, then isolines at levels chosen after a run, all
// from the distance inside the faces, with no new propagation.
// Checks: the cells' areas add up to the area of the mesh; every border point is as far from the two sources of
// its cells (from a run from each source alone); every isoline point is at its level (field_distance() there).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
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

// The isolines of the last run of `solver` (which kept its field) at a quarter and at half of its largest distance;
// checks that every point is at its level; returns the number of failed checks.
int check_isolines(const VG::Geodesic_distance_solver<Triangle_mesh>& solver)
{
  double largest = 0.;
  for(double d : solver.distances())
    if(std::isfinite(d))
      largest = (std::max)(largest, d);
  const std::vector<double> levels = { 0.25 * largest, 0.5 * largest };
  VG::Geodesic_curves_report report;
  const auto isolines = VG::geodesic_isolines(solver, levels, VG::parameters::curves_report(report));
  double worst = 0.;
  for(const auto& curve : isolines)
  {
    for(const auto& location : curve.locations)
      worst = (std::max)(worst, std::abs(solver.field_distance(location) - curve.level));
    std::cout << "  isoline at " << curve.level << ": " << curve.points.size() << " points, "
              << (curve.closed ? "closed" : "open") << std::endl;
  }
  std::cout << isolines.size() << " isolines, " << report.points << " points, largest "
            << "|distance - level| " << worst << std::endl;
  return (isolines.empty() || !(worst <= 1e-9 * largest)) ? 1 : 0;
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

  // one exact run from three vertices, keeping the field
  VG::Geodesic_distance_solver<Triangle_mesh> solver(tm);
  const std::size_t n = solver.number_of_vertices();
  const std::vector<vertex_descriptor> sources = { solver.vertex_list()[0], solver.vertex_list()[n / 3],
                                                   solver.vertex_list()[2 * n / 3] };
  auto distance = tm.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  solver.compute(distance, sources, VG::parameters::keep_field(true));
  double largest = 0.;
  for(double d : solver.distances())
    if(std::isfinite(d))
      largest = (std::max)(largest, d);
  int errors = 0;
  const double tolerance = 1e-9 * largest;

  // the areas of the cells add up to the area of the mesh
  const VG::Voronoi_cell_areas cells = VG::geodesic_voronoi_cell_areas(solver);
  double sum = 0.;
  for(std::size_t i = 0; i < cells.areas.size(); ++i)
  {
    std::cout << "  cell of vertex " << std::size_t(sources[i]) << ": area " << cells.areas[i] << " (uncertainty "
              << cells.uncertainty[i] << ")" << std::endl;
    sum += cells.areas[i];
  }
  const double area = CGAL::Polygon_mesh_processing::area(tm);
  std::cout << "cell areas sum to " << sum << ", the mesh's area is " << area << std::endl;
  if(cells.areas.size() != sources.size() || !(std::abs(sum - area) <= 1e-9 * area))
    ++errors;

  // the isolines of the three sources, at levels chosen now, from the same run
  errors += check_isolines(solver);

  // the borders between the three cells; then, from each source alone, the distance at the border points: at each
  // point, the two sources of its cells are as far (from the kept field of each run)
  const auto borders = VG::geodesic_cell_borders(solver);
  std::vector<std::vector<double> > to_source(sources.size());
  for(std::size_t s = 0; s < sources.size(); ++s)
  {
    solver.compute(distance, sources[s], VG::parameters::keep_field(true));
    for(const auto& curve : borders)
      for(const auto& location : curve.locations)
        to_source[s].push_back(solver.field_distance(location));
  }
  double worst_border = 0.;
  std::size_t k = 0;
  for(const auto& curve : borders)
    for(std::size_t i = 0; i < curve.locations.size(); ++i, ++k)
      worst_border = (std::max)(worst_border, std::abs(to_source[curve.cells[0]][k] - to_source[curve.cells[1]][k]));
  std::cout << borders.size() << " borders, " << k << " points, largest difference of the distances to the two "
            << "sources " << worst_border << std::endl;
  if(borders.empty() || !(worst_border <= tolerance))
    ++errors;

  if(errors != 0)
    std::cerr << errors << " check(s) failed" << std::endl;
  return errors == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
