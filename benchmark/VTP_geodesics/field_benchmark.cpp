// vtp_field_benchmark: what keeping the field costs (keep_field(true): time beside the run without it, bytes,
// pieces per face) and whether what it answers is exact (doc/VTP_geodesics/curves.txt, issue 45).
//
//   vtp_field_benchmark MESH [--sources A,B,...] [--points P] [--levels N] [--samples K] [--repeat R]
//
// One run from the sources (mesh vertex indices, default 0 and the middle index) without the field and one with
// it, in turn, R times (default 3): the least processor time of each, the cost (kept - plain) / plain, the bytes
// of the field per vertex, its pieces per face (mean, 99th percentile, largest). Then, from that one run with the
// field:
//  - P (default 400) random points of random faces (seed 1): the field's distance against an exact run that has
//    them all as targets (|difference| / largest distance), and its nearest source against the nearer of one
//    targeted run per source, where those two differ by more than 1e-9 of the largest distance;
//  - the isolines at N levels (default 9: the largest distance times i / (N + 1)) and the cell borders, timed;
//    K points (default 1,000) taken evenly along them, each checked by exact targeted runs: |distance - level|,
//    and for a border point |d_i - d_j| of its two cells' sources (relative to the largest distance);
//  - the areas of the Voronoi cells from the borders against the area of the reached faces.
// Exit status 3 if the field's distance at a random point is off by more than 1e-9 of the largest distance or its
// nearest source is wrong. Processor time, one thread (robust to other jobs on the machine).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/VTP_geodesics.h>
#include <vtp_support/read_mesh.h>

#include "error_report.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <random>
#include <sstream>
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

// `every`-th location of the curves, at most `samples`
std::vector<std::size_t> sample_indices(std::size_t total, std::size_t samples)
{
  std::vector<std::size_t> r;
  const std::size_t stride = (std::max)(std::size_t(1), total / (samples ? samples : 1));
  for(std::size_t i = 0; i < total && r.size() < samples; i += stride)
    r.push_back(i);
  return r;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: vtp_field_benchmark MESH [--sources A,B,...] [--points P] [--levels N] [--samples K] [--repeat R]\n";
    return 2;
  }
  std::vector<std::size_t> source_ids;
  std::size_t points_count = 400, samples = 1000;
  int number_of_levels = 9, repeat = 3;
  for(int i = 2; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i], v = argv[i + 1];
    if(a == "--sources")
    {
      std::stringstream ss(v);
      std::string item;
      while(std::getline(ss, item, ','))
        source_ids.push_back(static_cast<std::size_t>(std::atol(item.c_str())));
    }
    else if(a == "--points")
      points_count = static_cast<std::size_t>(std::atol(v.c_str()));
    else if(a == "--levels")
      number_of_levels = std::atoi(v.c_str());
    else if(a == "--samples")
      samples = static_cast<std::size_t>(std::atol(v.c_str()));
    else if(a == "--repeat")
      repeat = (std::max)(1, std::atoi(v.c_str()));
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
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
  if(source_ids.empty())
    source_ids = { 0, mesh.number_of_vertices() / 2 };
  std::vector<Vertex> sources;
  for(std::size_t id : source_ids)
  {
    if(id >= mesh.number_of_vertices())
    {
      std::cerr << "source " << id << " is not a vertex of the mesh\n";
      return 2;
    }
    sources.push_back(Vertex(static_cast<Mesh::size_type>(id)));
  }
  const CGAL::Constant_property_map<Vertex, double> discard;
  Solver solver(mesh);
  double plain = 1e300, kept = 1e300;
  for(int r = 0; r < repeat; ++r)
  {
    double c0 = cpu_seconds();
    solver.compute(discard, sources);
    plain = (std::min)(plain, cpu_seconds() - c0);
    c0 = cpu_seconds();
    solver.compute(discard, sources, VG::parameters::keep_field(true));
    kept = (std::min)(kept, cpu_seconds() - c0);
  }
  const VG::Propagation_statistics st = solver.statistics();
  double largest = 0.;
  for(double d : solver.distances())
    if(std::isfinite(d))
      largest = (std::max)(largest, d);
  std::vector<std::size_t> per_face;
  for(auto f : mesh.faces())
    per_face.push_back(solver.number_of_field_pieces(f));
  std::sort(per_face.begin(), per_face.end());
  const std::size_t nf = per_face.size(), nv = mesh.number_of_vertices();
  std::cout << argv[1] << ": " << nv << " vertices, " << nf << " faces, " << sources.size() << " sources\n"
            << "processor time (least of " << repeat << "): run " << plain << " s, with the field " << kept
            << " s: keeping the field costs " << 100. * (kept - plain) / plain << "% of the run\n"
            << "field: " << st.field_pieces << " pieces (of " << st.windows_propagated << " windows propagated), "
            << st.field_bytes << " bytes = " << static_cast<double>(st.field_bytes) / static_cast<double>(nv)
            << " bytes per vertex; pieces per face: mean " << static_cast<double>(st.field_pieces) / static_cast<double>(nf)
            << ", 99th percentile " << per_face[nf * 99 / 100] << ", largest " << per_face.back() << "\n";

  // random points of random faces against targeted runs
  std::mt19937 g(1);
  std::uniform_real_distribution<double> u(0., 1.);
  std::uniform_int_distribution<std::size_t> face(0, nf - 1);
  std::vector<Solver::Face_location> points;
  for(std::size_t i = 0; i < points_count; ++i)
  {
    double a = u(g), b = u(g);
    if(a + b > 1.)
    {
      a = 1. - a;
      b = 1. - b;
    }
    points.emplace_back(Mesh::Face_index(static_cast<Mesh::size_type>(face(g))), std::array<double, 3>{ { 1. - a - b, a, b } });
  }
  std::vector<double> field(points.size());
  std::vector<std::size_t> label(points.size());
  double c0 = cpu_seconds();
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    field[i] = solver.field_distance(points[i]);
    label[i] = solver.field_nearest_source(points[i]);
  }
  const double query_time = cpu_seconds() - c0;
  Solver exact(mesh);
  exact.compute(discard, sources, VG::parameters::targets(points));
  std::vector<std::vector<double> > single(sources.size());
  for(std::size_t s = 0; s < sources.size(); ++s)
  {
    exact.compute(discard, sources[s], VG::parameters::targets(points));
    for(std::size_t i = 0; i < points.size(); ++i)
      single[s].push_back(exact.target_distance(i));
  }
  exact.compute(discard, sources, VG::parameters::targets(points));
  std::vector<double> error;
  std::size_t decided = 0, right = 0, unreached = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const double d = exact.target_distance(i);
    if(!std::isfinite(d) || !std::isfinite(field[i]))
    {
      unreached += 1;
      if(std::isfinite(d) != std::isfinite(field[i]))
        error.push_back(1.);  // (one reached, the other not: counted as wrong)
      continue;
    }
    error.push_back(std::abs(field[i] - d) / largest);
    std::size_t best = 0;
    bool clear = true;
    for(std::size_t s = 1; s < sources.size(); ++s)
      if(single[s][i] < single[best][i])
        best = s;
    for(std::size_t s = 0; s < sources.size(); ++s)
      if(s != best && !(single[s][i] - single[best][i] > 1e-9 * largest))
        clear = false;
    if(clear)
    {
      ++decided;
      right += label[i] == best ? 1 : 0;
    }
  }
  std::cout << points.size() << " random surface points (" << unreached << " unreached), queried in " << query_time
            << " s\n";
  print_errors("field distance = targeted exact run", error, 1e-9);
  std::cout << "nearest source: " << right << " of " << decided
            << " points where one source is nearer by more than 1e-9 of the largest distance\n";
  const bool field_exact = right == decided
                           && std::all_of(error.begin(), error.end(), [](double e) { return e <= 1e-9; });

  // isolines and borders from the same run
  std::vector<double> levels;
  for(int i = 1; i <= number_of_levels; ++i)
    levels.push_back(largest * i / (number_of_levels + 1));
  c0 = cpu_seconds();
  const auto isolines = VG::geodesic_isolines(solver, levels);
  const double isoline_time = cpu_seconds() - c0;
  c0 = cpu_seconds();
  VG::Geodesic_curves_report border_report;
  const auto borders = VG::geodesic_cell_borders(solver, VG::parameters::curves_report(border_report));
  const double border_time = cpu_seconds() - c0;
  std::vector<Solver::Face_location> at;
  std::vector<double> level_of;
  std::size_t total = 0;
  for(const auto& c : isolines)
    total += c.locations.size();
  std::vector<std::size_t> chosen = sample_indices(total, samples);
  std::size_t k = 0, next = 0;
  for(const auto& c : isolines)
    for(const auto& l : c.locations)
    {
      if(next < chosen.size() && k == chosen[next])
      {
        at.push_back(l);
        level_of.push_back(c.level);
        ++next;
      }
      ++k;
    }
  exact.compute(discard, sources, VG::parameters::targets(at));
  error.clear();
  for(std::size_t i = 0; i < at.size(); ++i)
    error.push_back(std::abs(exact.target_distance(i) - level_of[i]) / largest);
  std::cout << number_of_levels << " levels: " << isolines.size() << " isolines, " << total << " points in "
            << isoline_time << " s (" << 100. * isoline_time / plain << "% of the run)\n";
  print_errors("isoline points at their level (targeted exact run)", error, 1e-9);
  total = 0;
  for(const auto& b : borders)
    total += b.locations.size();
  chosen = sample_indices(total, samples);
  error.clear();
  k = 0;
  next = 0;
  for(const auto& b : borders)
  {
    std::vector<Solver::Face_location> here;
    for(const auto& l : b.locations)
    {
      if(next < chosen.size() && k == chosen[next])
      {
        here.push_back(l);
        ++next;
      }
      ++k;
    }
    if(here.empty())
      continue;
    std::vector<double> d[2];
    for(int j = 0; j < 2; ++j)
    {
      exact.compute(discard, sources[b.cells[static_cast<std::size_t>(j)]], VG::parameters::targets(here));
      for(std::size_t i = 0; i < here.size(); ++i)
        d[j].push_back(exact.target_distance(i));
    }
    for(std::size_t i = 0; i < here.size(); ++i)
      error.push_back(std::abs(d[0][i] - d[1][i]) / largest);
  }
  std::cout << borders.size() << " cell borders, " << total << " points in " << border_time << " s (points left on "
            << "their chord " << border_report.undecided << ", edge fallbacks " << border_report.edge_fallbacks
            << ", junction fallbacks " << border_report.junction_fallbacks << ")\n";
  print_errors("border points equidistant from their two sources (targeted exact runs)", error, 1e-9);
  const VG::Voronoi_cell_areas cells = VG::geodesic_voronoi_cell_areas(solver);
  double sum = 0., area = 0.;
  for(double a : cells.areas)
    sum += a;
  for(auto f : mesh.faces())
  {
    const auto h = mesh.halfedge(f);
    const Vertex v[3] = { mesh.source(h), mesh.target(h), mesh.target(mesh.next(h)) };
    if(std::isfinite(solver.distance(v[0])) && std::isfinite(solver.distance(v[1])) && std::isfinite(solver.distance(v[2])))
      area += std::sqrt(CGAL::squared_area(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])));
  }
  std::cout << "cell areas: sum " << sum << ", area of the reached faces " << area << ", relative difference "
            << std::abs(sum - area) / area << "\n";
  // (exit status 3 if a point's field distance or nearest source was wrong: the smoke test checks it)
  return field_exact ? 0 : 3;
}
