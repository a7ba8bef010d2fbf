// log_map_benchmark: the cost of the log map (issue 36) against the distance run it rides on, side by side
// in one program, on one core: the same solver, the same source, runs interleaved (distance, log map, strict
// log map), the median of each. Also the peak of live windows (each carries 8 bytes for the log map) and the
// bytes per vertex of the log map's record.
//
//   log_map_benchmark MESH [SOURCE_VERTEX [REPEATS]]
//
// With LOG_MAP_BENCHMARK_ONLY=distance|default|strict in the environment it runs only that one, REPEATS
// times, and prints nothing: for counting instructions (valgrind --tool=callgrind), which a loaded machine
// does not distort.
//
// Built without the log map (-DLOG_MAP_BENCHMARK_DISTANCE_ONLY), it times the distance run alone: compiled
// against another version of the headers, it compares the distance runs of the two versions.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/VTP_geodesics.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace VP = CGAL::VTP_geodesics::parameters;

namespace {

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// wall seconds of f(); `cpu`: the processor seconds of the process meanwhile (std::clock: on a shared machine,
// where another process may hold the core, the time the run was given, not the time it waited)
template <class F>
double seconds(const F& f, double& cpu)
{
  const std::clock_t c0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  f();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  return wall;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: log_map_benchmark MESH [SOURCE_VERTEX [REPEATS]]\n";
    return 2;
  }
  Mesh mesh;
  std::ifstream in(argv[1]);
  if(!(in >> mesh) || num_faces(mesh) == 0)
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  const Vertex centre(argc > 2 ? static_cast<Mesh::size_type>(std::atoi(argv[2])) : 0);
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 5;
  CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> solver(mesh);
  const std::size_t n = num_vertices(mesh);
  std::vector<double> d(n);
  auto dm = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  std::vector<double> t_distance, t_log, t_strict, c_distance, c_log, c_strict;
  double cpu = 0.;
  CGAL::VTP_geodesics::Propagation_statistics st;
#ifndef LOG_MAP_BENCHMARK_DISTANCE_ONLY
  std::vector<std::array<double, 2> > x(n);
  auto xm = boost::make_iterator_property_map(x.begin(), get(boost::vertex_index, mesh));
#endif
  const char* only = std::getenv("LOG_MAP_BENCHMARK_ONLY");
  const std::string mode = only ? only : "";
  if(!mode.empty())
  {
    for(int r = 0; r < repeats; ++r)
    {
      if(mode == "distance")
        solver.compute(dm, centre);
#ifndef LOG_MAP_BENCHMARK_DISTANCE_ONLY
      else
        solver.compute(dm, centre, VP::log_map(xm).log_map_strict(mode == "strict"));
#endif
    }
    return 0;
  }
  for(int r = 0; r < repeats; ++r)
  {
    t_distance.push_back(seconds([&] { solver.compute(dm, centre, VP::statistics(st)); }, cpu));
    c_distance.push_back(cpu);
#ifndef LOG_MAP_BENCHMARK_DISTANCE_ONLY
    t_log.push_back(seconds([&] { solver.compute(dm, centre, VP::log_map(xm).statistics(st)); }, cpu));
    c_log.push_back(cpu);
    t_strict.push_back(seconds([&] { solver.compute(dm, centre, VP::log_map(xm).log_map_strict(true)); }, cpu));
    c_strict.push_back(cpu);
#endif
  }
  std::cout << "mesh " << argv[1] << ": " << n << " vertices, source " << std::size_t(centre) << ", " << repeats
            << " runs each, median seconds (compute() with the output maps)\n";
  std::cout << "distance run:        " << median(t_distance) << " s   (processor " << median(c_distance) << " s)\n";
#ifndef LOG_MAP_BENCHMARK_DISTANCE_ONLY
  std::cout << "log map (default):   " << median(t_log) << " s   ratio " << median(t_log) / median(t_distance)
            << "   (processor " << median(c_log) << " s, ratio " << median(c_log) / median(c_distance) << ")\n";
  std::cout << "log map (strict):    " << median(t_strict) << " s   ratio " << median(t_strict) / median(t_distance)
            << "   (processor " << median(c_strict) << " s, ratio " << median(c_strict) / median(c_distance) << ")\n";
  std::cout << "log map record: 17 bytes per vertex (theta double, turn float, cut int8, via int32), " << 17. * double(n) / 1e6
            << " MB\n";
  // continuity: the jump of theta across each edge whose two ends are farther from the source than 10 mean edge
  // lengths (near the source theta turns fast), percentiles over the edges; the cut locus is not excluded
  const double far = 10. * solver.mean_edge_length();
  for(const bool strict : {false, true})
  {
    solver.compute(dm, centre, VP::log_map(xm).log_map_strict(strict));
    std::vector<double> jumps;
    for(auto e : edges(mesh))
    {
      const Vertex a = mesh.source(mesh.halfedge(e)), b = mesh.target(mesh.halfedge(e));
      if(!(d[a] > far && d[b] > far && d[a] < 1e300 && d[b] < 1e300))
        continue;
      const double ta = std::atan2(x[a][1], x[a][0]), tb = std::atan2(x[b][1], x[b][0]);
      jumps.push_back(std::abs(std::remainder(ta - tb, 2. * 3.14159265358979323846)));
    }
    std::sort(jumps.begin(), jumps.end());
    const auto at = [&](double q) { return jumps.empty() ? 0. : jumps[static_cast<std::size_t>(q * double(jumps.size() - 1))]; };
    std::cout << "theta jump across an edge (" << (strict ? "strict" : "default") << ", " << jumps.size()
              << " edges beyond 10 mean edge lengths): median " << at(0.5) << ", 99% " << at(0.99) << ", 99.9% "
              << at(0.999) << ", max " << at(1.) << " rad\n";
  }
#endif
  std::cout << "peak live windows " << st.peak_live_windows << " (" << double(st.peak_live_windows) / double(n)
            << " per vertex), window pool peak " << st.peak_window_bytes << " bytes ("
            << double(st.peak_window_bytes) / double(n) << " per vertex, "
            << double(st.peak_window_bytes) / double((std::max)(st.peak_live_windows, std::size_t(1)))
            << " per live window at the peak)\n";
  return 0;
}
