// vtp_benchmark, child side: runs one method on one source, R times, in the forked process, and sends its
// timings and distances back to the parent through a pipe.

#include "vtp_benchmark.h"

#include <CGAL/property_map.h>
#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <vtp_support/shortest_path_reference.h>
#include <vtp_support/statistics.h>

#ifdef VTP_BENCHMARK_WITH_HEAT_METHOD
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#endif

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <time.h>         // clock_gettime
#include <unistd.h>       // write, close, _exit, sysconf

namespace vtp_benchmark {

// Processor time of the process (all its threads), in seconds.
double cpu_now_seconds()
{
  struct timespec t;
  if(::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) != 0)
    return nan_value;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double now_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double current_rss_kb()
{
  std::ifstream statm("/proc/self/statm");
  unsigned long size = 0, resident = 0;
  if(!(statm >> size >> resident))
    return 0.;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1024.;
}

namespace {

void run_vtp(const Mesh& mesh, Vertex_index source, const Method& method, int repeat, Child_header& h,
             std::vector<double>& d, CGAL::VTP_geodesics::Propagation_statistics& statistics)
{
  typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
  Solver solver(mesh);
  h.preprocessing_seconds = solver.preprocessing_seconds();
  h.pseudo_source_vertices = solver.number_of_pseudo_source_vertices();
  // the distances are read from the solver: nothing to write through a map
  for(int r = 0; r < repeat; ++r)
  {
    const double c0 = cpu_now_seconds();
    vtp_support::with_method(*method.info, method.lambda, method.threads, [&](auto tag, const auto& np) {
      solver.compute<decltype(tag)>(CGAL::Constant_property_map<Vertex_index, double>(), source, np);
    });
    const double cpu = cpu_now_seconds() - c0;
    if(r == 0 || solver.statistics().seconds < h.seconds)
    {
      statistics = solver.statistics();
      h.seconds = statistics.seconds;
    }
    if(r == 0 || cpu < h.cpu_seconds)
      h.cpu_seconds = cpu;
  }
  d = solver.distances();
}

void run_cgal(const Mesh& mesh, Vertex_index source, int repeat, Child_header& h, std::vector<double>& d)
{
  // Sequence tree from the source, and a query for every vertex of its component.
  h.preprocessing_seconds = 0.;
  for(int r = 0; r < repeat; ++r)
  {
    const double t0 = now_seconds();
    d = vtp_support::shortest_path_reference_distances(mesh, source);
    const double t = now_seconds() - t0;
    if(r == 0 || t < h.seconds)
      h.seconds = t;
  }
}

#ifdef VTP_BENCHMARK_WITH_HEAT_METHOD
template <class Mode>
void run_heat(Mesh& mesh, Vertex_index source, int repeat, Child_header& h, std::vector<double>& d)
{
  typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mesh, Mode> Heat_method;
  Mesh::Property_map<Vertex_index, double> distance =
    mesh.add_property_map<Vertex_index, double>("v:benchmark_heat_distance", 0.).first;
  for(int r = 0; r < repeat; ++r)
  {
    const double t0 = now_seconds();
    Heat_method heat(mesh);           // precomputation: matrices and factorizations
    const double t1 = now_seconds();
    heat.add_source(source);
    heat.estimate_geodesic_distances(distance);
    const double t2 = now_seconds();
    if(r == 0 || (t2 - t1) < h.seconds)
      h.seconds = t2 - t1;
    if(r == 0 || (t1 - t0) < h.preprocessing_seconds)
      h.preprocessing_seconds = t1 - t0;
  }
  d.resize(mesh.number_of_vertices());
  for(Vertex_index v : mesh.vertices())
    d[static_cast<std::size_t>(v)] = distance[v];
}
#endif

void write_all(int fd, const void* data, std::size_t size)
{
  const char* p = static_cast<const char*>(data);
  while(size > 0)
  {
    const ssize_t w = ::write(fd, p, size);
    if(w < 0)
    {
      if(errno == EINTR)
        continue;
      _exit(3);
    }
    p += w;
    size -= static_cast<std::size_t>(w);
  }
}

} // namespace

[[noreturn]] void run_in_child(int fd, Mesh& mesh, Vertex_index source, const Method& method, int repeat)
{
  Child_header h;
  std::vector<double> d;
  std::string error;
  CGAL::VTP_geodesics::Propagation_statistics statistics;
  bool has_statistics = false;
  h.rss_at_start_kb = current_rss_kb();
  try
  {
    switch(method.kind)
    {
      case Method_kind::VTP_FAMILY:
        run_vtp(mesh, source, method, repeat, h, d, statistics);
        has_statistics = true;
        break;
      case Method_kind::CGAL_SMSP:
        run_cgal(mesh, source, repeat, h, d);
        break;
#ifdef VTP_BENCHMARK_WITH_HEAT_METHOD
      case Method_kind::HEAT_DIRECT:
        run_heat<CGAL::Heat_method_3::Direct>(mesh, source, repeat, h, d);
        break;
      case Method_kind::HEAT_IDT:
        run_heat<CGAL::Heat_method_3::Intrinsic_Delaunay>(mesh, source, repeat, h, d);
        break;
#endif
      default:
        throw std::runtime_error("method " + method.label + " is not available");
    }
  }
  catch(const std::exception& e) { error = e.what(); }
  catch(...) { error = "unknown exception"; }
  if(error.empty() && d.size() != mesh.number_of_vertices())
    error = "wrong number of distances";
  if(!error.empty())
    d.clear();
  std::replace(error.begin(), error.end(), '\n', ' ');

  std::ostringstream statistics_json;
  if(has_statistics && error.empty())
    vtp_support::write_statistics_json(statistics_json, statistics);
  const std::string statistics_text = statistics_json.str();

  h.number_of_distances = d.size();
  h.error_length = error.size();
  h.statistics_length = statistics_text.size();
  write_all(fd, &h, sizeof(h));
  if(!d.empty())
    write_all(fd, d.data(), d.size() * sizeof(double));
  if(!error.empty())
    write_all(fd, error.data(), error.size());
  if(!statistics_text.empty())
    write_all(fd, statistics_text.data(), statistics_text.size());
  ::close(fd);
  _exit(0);
}

} // namespace vtp_benchmark
