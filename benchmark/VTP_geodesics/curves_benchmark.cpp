// vtp_curves_benchmark: the cost and the exactness of the isolines and cell borders of geodesic_curves.h on a
// mesh (doc/VTP_geodesics/curves.txt).
//
//   vtp_curves_benchmark MESH [--levels N] [--samples K] [--sources S] [--refine R] [--record paths|field]
//
// A distance run from vertex 0 without record gives the largest distance and the N levels (default 20: the
// largest distance times i / (N + 1)); then the same run with the record of the curves (--record: `field`, the
// default: keep_field(true), every window that crosses a face; `paths`: record_paths(true) only, the field from
// the per-vertex record), timed beside the run without record, with the memory of the record, and the
// isolines at the N levels, timed: the cost is (recorded run - plain run + extraction) / plain run. Then K points
// (default 1,000) taken evenly from all the isoline points, each checked by one exact run that has them all as
// targets: |exact distance - level| / largest distance; beside it, for the same points, what the linear
// interpolation of the vertex distances gives: |interpolated - exact| / largest distance. With S > 1, the
// borders of the cells of S sources (vertices spread over the index range) are checked the same way (the
// two cells' sources, one run each): |d_i - d_j| / largest distance; the borders' run keeps the field
// (keep_field(true)) unless --record paths. With R > 0, the isolines are refined by R exact runs (named
// parameter exact_refinement).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/VTP_geodesics.h>
#include <vtp_support/read_mesh.h>

#include "error_report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
namespace VG = CGAL::VTP_geodesics;
using vtp_benchmark_report::cpu_seconds;
using vtp_benchmark_report::print_errors;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: vtp_curves_benchmark MESH [--levels N] [--samples K] [--sources S]\n";
    return 2;
  }
  int number_of_levels = 20, sources_count = 1, refine = 0, repeat = 1;
  std::string record = "field";
  std::size_t samples = 1000;
  for(int i = 2; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i];
    if(a == "--levels")
      number_of_levels = std::atoi(argv[i + 1]);
    else if(a == "--samples")
      samples = static_cast<std::size_t>(std::atol(argv[i + 1]));
    else if(a == "--repeat")
      repeat = (std::max)(1, std::atoi(argv[i + 1]));
    else if(a == "--refine")
      refine = std::atoi(argv[i + 1]);
    else if(a == "--sources")
      sources_count = std::atoi(argv[i + 1]);
    else if(a == "--record" && (std::string(argv[i + 1]) == "paths" || std::string(argv[i + 1]) == "field"))
      record = argv[i + 1];
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  // (the reader of the tools: OFF, OBJ, PLY, STL; a scan's soup repaired into a valid triangle mesh)
  vtp_support::Input_mesh input;
  try
  {
    vtp_support::read_input_mesh(argv[1], input);
  }
  catch(const vtp_support::Input_error& e)
  {
    std::cerr << "cannot read " << argv[1] << ": " << e.what() << "\n";
    return 1;
  }
  const Mesh& mesh = input.mesh;
  if(mesh.is_empty())
  {
    std::cerr << "cannot read " << argv[1] << ": no face\n";
    return 1;
  }
  Solver solver(mesh);
  const Vertex source = *mesh.vertices().begin();
  CGAL::Constant_property_map<Vertex, double> discard;
  auto t0 = std::chrono::steady_clock::now();
  VG::Propagation_statistics st;
  solver.compute(discard, source, VG::parameters::statistics(st));
  double plain = seconds_since(t0);
  double largest = 0.;
  for(double d : solver.distances())
    if(std::isfinite(d))
      largest = (std::max)(largest, d);
  std::vector<double> levels;
  for(int i = 1; i <= number_of_levels; ++i)
    levels.push_back(largest * i / (number_of_levels + 1));
  // processor times, the least of `repeat` runs of each (plain and recorded in turn)
  double plain_cpu = 1e300, recorded_cpu = 1e300, recorded = 1e300;
  for(int r = 0; r < repeat; ++r)
  {
    double c0 = cpu_seconds();
    t0 = std::chrono::steady_clock::now();
    solver.compute(discard, source);
    plain = (std::min)(plain, seconds_since(t0));
    plain_cpu = (std::min)(plain_cpu, cpu_seconds() - c0);
    c0 = cpu_seconds();
    t0 = std::chrono::steady_clock::now();
    if(record == "paths")
      solver.compute(discard, source, VG::parameters::record_paths(true));
    else
      solver.compute(discard, source, VG::parameters::keep_field(true));
    recorded = (std::min)(recorded, seconds_since(t0));
    recorded_cpu = (std::min)(recorded_cpu, cpu_seconds() - c0);
  }
  const VG::Propagation_statistics kept = solver.statistics();
  VG::Geodesic_curves_report report;
  t0 = std::chrono::steady_clock::now();
  const double c0 = cpu_seconds();
  const auto curves = VG::geodesic_isolines(solver, levels, VG::parameters::exact_refinement(refine).curves_report(report));
  const double extraction = seconds_since(t0), extraction_cpu = cpu_seconds() - c0;
  std::cout << argv[1] << ": " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces\n"
            << "distance run " << plain << " s, with the record (" << record << ") " << recorded << " s: "
            << kept.field_pieces << " pieces kept of " << st.windows_propagated << " windows propagated, "
            << kept.field_bytes / 1e6 << " MB (" << static_cast<double>(kept.field_bytes) / mesh.number_of_vertices()
            << " bytes per vertex, " << static_cast<double>(kept.field_pieces) / mesh.number_of_faces() << " pieces per face); "
            << number_of_levels
            << " levels: " << curves.size() << " curves, " << report.points << " points in " << extraction
            << " s; cost (recorded run - plain run + extraction) / plain run = "
            << 100. * (recorded - plain + extraction) / plain << "% (extraction alone " << 100. * extraction / plain
            << "%)\n"
            << "processor time (least of " << repeat << "): plain run " << plain_cpu << " s, recorded run " << recorded_cpu
            << " s, extraction " << extraction_cpu << " s; cost " << 100. * (recorded_cpu - plain_cpu + extraction_cpu) / plain_cpu
            << "% (record " << 100. * (recorded_cpu - plain_cpu) / plain_cpu << "%, extraction "
            << 100. * extraction_cpu / plain_cpu << "%)\n"
            << "exact refinement runs: " << refine << " (residual before the last moves: " << report.residual / largest
            << " of the largest distance)\n"
            << "left on the chord: " << report.undecided << ", edge points interpolated: " << report.edge_fallbacks << "\n";
  // the sample
  std::vector<Solver::Face_location> points;
  std::vector<double> at_level;
  std::size_t total = report.points, index = 0;
  const std::size_t stride = (std::max)(std::size_t(1), total / (samples ? samples : 1));
  for(const auto& c : curves)
    for(const auto& l : c.locations)
    {
      if(index++ % stride == 0 && points.size() < samples)
      {
        points.push_back(l);
        at_level.push_back(c.level);
      }
    }
  Solver exact(mesh);
  exact.compute(discard, source, VG::parameters::targets(points));
  std::vector<double> curve_error, linear_error;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const double d = exact.target_distance(i);
    curve_error.push_back(std::abs(d - at_level[i]) / largest);
    const auto h = mesh.halfedge(points[i].first);
    const Vertex v[3] = { mesh.source(h), mesh.target(h), mesh.target(mesh.next(h)) };
    double interpolated = 0.;
    for(int k = 0; k < 3; ++k)
      interpolated += points[i].second[static_cast<std::size_t>(k)] * solver.distance(v[k]);
    linear_error.push_back(std::abs(interpolated - d) / largest);
  }
  print_errors("isoline points at their level (exact run)", curve_error, 1e-9);
  print_errors("linear interpolation of the vertex distances at the same points", linear_error, 1e-9);
  if(sources_count > 1)
  {
    std::vector<Vertex> sources;
    const std::size_t nv = mesh.number_of_vertices();
    for(int i = 0; i < sources_count; ++i)
      sources.push_back(Vertex(static_cast<Mesh::size_type>(nv * static_cast<std::size_t>(i) / static_cast<std::size_t>(sources_count))));
    t0 = std::chrono::steady_clock::now();
    solver.compute(discard, sources, VG::parameters::record_paths(true));
    const double border_plain = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    solver.compute(discard, sources, VG::parameters::record_paths(record == "paths").keep_field(record != "paths"));
    const double border_recorded = seconds_since(t0);
    std::cout << sources_count << " sources: run with record_paths " << border_plain << " s, with keep_field("
              << (record != "paths") << ") " << border_recorded << " s: " << solver.statistics().field_pieces
              << " pieces, " << solver.statistics().field_bytes / 1e6 << " MB\n";
    VG::Geodesic_curves_report border_report;
    t0 = std::chrono::steady_clock::now();
    const auto borders = VG::geodesic_cell_borders(solver, VG::parameters::curves_report(border_report));
    const double border_time = seconds_since(t0);
    std::size_t border_points = 0;
    for(const auto& b : borders)
      border_points += b.points.size();
    std::cout << sources_count << " sources: " << borders.size() << " borders, " << border_points << " points in "
              << border_time << " s\n";
    std::vector<double> border_error;
    const std::size_t border_stride = (std::max)(std::size_t(1), border_points / (samples ? samples : 1));
    std::size_t q = 0;
    for(const auto& b : borders)
    {
      std::vector<Solver::Face_location> chosen;
      for(const auto& l : b.locations)
        if(q++ % border_stride == 0)
          chosen.push_back(l);
      if(chosen.empty())
        continue;
      std::vector<double> d[2];
      for(int j = 0; j < 2; ++j)
      {
        exact.compute(discard, sources[b.cells[static_cast<std::size_t>(j)]], VG::parameters::targets(chosen));
        for(std::size_t i = 0; i < chosen.size(); ++i)
          d[j].push_back(exact.target_distance(i));
      }
      for(std::size_t i = 0; i < chosen.size(); ++i)
        border_error.push_back(std::abs(d[0][i] - d[1][i]) / largest);
    }
    print_errors("border points equidistant (exact runs)", border_error, 1e-9);
    // the cells' areas from the borders against the area of the mesh
    const VG::Voronoi_cell_areas cells = VG::geodesic_voronoi_cell_areas(solver);
    double sum = 0., bound = 0., area = 0.;
    for(std::size_t i = 0; i < cells.areas.size(); ++i)
    {
      sum += cells.areas[i];
      bound += cells.uncertainty[i];
    }
    for(auto f : mesh.faces())
    {
      const auto h = mesh.halfedge(f);
      area += std::sqrt(CGAL::squared_area(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                           mesh.point(mesh.target(mesh.next(h)))));
    }
    std::cout << "cell areas from the borders: sum " << sum << ", mesh area " << area << ", relative difference "
              << std::abs(sum - area) / area << ", chord bound (sum of uncertainty) " << bound << "\n";
  }
  return 0;
}
