// vtp_query_benchmark: the cost of the queries beyond a full distance field, side by side in one run:
// a distance limit, one near target, and path recording, against the full run from the same source.
//
//   vtp_query_benchmark [--repeat R] [--threads T] [--limit F] [--fps K1,K2,...] [--naive K] [--vsp] MESH...
//
// For each mesh (source: vertex 0), in this order and R times, interleaved, each run in a forked child (so
// that its peak resident memory, ru_maxrss from wait4, is its own; the mesh is read by the parent):
//   full      exact VTP to every vertex
//   limit     maximum_distance(F * the largest distance of the full run) (default F = 0.1)
//   target    targets(v), v the vertex whose distance is nearest F times the largest one
//   record    the full run with record_paths(true)
//   pvtp-*    the same three first runs with CGAL::Parallel_tag on T threads (if built with OpenMP)
//   fps k     with --fps K1,K2,...: farthest-point sampling of k samples (exact VTP, first sample vertex 0)
//   naive k   with --naive K: the naive sampling of the same first K samples, a full run from all the
//             samples so far at every step (the samples come from an untimed sampling in the same child)
//   vsp full, vsp fps k   with --vsp: a full run and the samplings of --fps with one virtual source per
//             vertex (virtual_sources(true))
// After the table, for each sampling: its covering radius (by its own distances) and the exact covering
// radius of its samples (an untimed exact run from them in the same child).
// It prints the fastest time of each (wall-clock seconds of the computation, and processor seconds of the
// process during it: on a shared machine, compare the latter), its ratio to the full run of the same
// scheduling, the vertices processed and windows propagated, and the peak RSS and its ratio to the full run.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <vtp_support/command_line.h>
#include <vtp_support/methods.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;

namespace {

enum class Query { FULL, LIMIT, TARGET, RECORD, FPS, NAIVE, FULL_VSP, FPS_VSP };
const char* const query_names[] = { "full", "limit", "target", "record", "fps", "naive", "vsp full", "vsp fps" };

struct Result
{
  double seconds = 0.;
  double cpu_seconds = 0.;  // processor time of this process (all its threads) during the computation
  double max_distance = 0.;
  unsigned long long processed = 0, propagated = 0;
  double target_distance = 0.;  // (a sampling: the exact covering radius of its samples)
  int ok = 0;
};

double cpu_now()
{
  timespec t;
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Farthest-point sampling of k samples from vertex 0 (Query::FPS, Query::FPS_VSP), or the naive method for
// the same samples (Query::NAIVE): the seconds of the propagations.
Result run_sampling(const Mesh& mesh, Query q, std::size_t k)
{
  Solver solver(mesh);
  const double c0 = cpu_now();
  const vtp_support::Method_info& method = *vtp_support::find_method(q == Query::FPS_VSP ? "vsp" : "vtp");
  const auto samples = vtp_support::with_method(method, vtp_support::default_lambda, 0, [&](auto tag, const auto& np) {
    return solver.farthest_point_sampling<decltype(tag)>(k, np.first_sample(Vertex_index(0)));
  });
  Result r;
  r.cpu_seconds = cpu_now() - c0;
  r.seconds = samples.statistics.seconds;
  r.max_distance = samples.radii.back();
  r.processed = samples.statistics.vertices_processed;
  r.propagated = samples.statistics.windows_propagated;
  if(q != Query::NAIVE)
  {
    // untimed: the exact covering radius of the samples
    solver.compute(CGAL::Constant_property_map<Vertex_index, double>(), samples.samples);
    r.target_distance = solver.statistics().max_distance;
  }
  if(q == Query::NAIVE)
  {
    r.seconds = r.cpu_seconds = 0.;
    r.processed = r.propagated = 0;
    const CGAL::Constant_property_map<Vertex_index, double> no_map;
    for(std::size_t i = 1; i <= samples.samples.size(); ++i)
    {
      const double c1 = cpu_now();
      solver.compute(no_map, std::vector<Vertex_index>(samples.samples.begin(), samples.samples.begin() + i));
      r.cpu_seconds += cpu_now() - c1;
      r.seconds += solver.statistics().seconds;
      r.processed += solver.statistics().vertices_processed;
      r.propagated += solver.statistics().windows_propagated;
    }
  }
  r.ok = 1;
  return r;
}

// Runs one query in this process.
Result run_query(const Mesh& mesh, Query q, bool parallel, int threads, double limit, Vertex_index target,
                 std::size_t k)
{
  if(q == Query::FPS || q == Query::NAIVE || q == Query::FPS_VSP)
    return run_sampling(mesh, q, k);
  Solver solver(mesh);
  const CGAL::Constant_property_map<Vertex_index, double> no_map;
  const Vertex_index source(0);
  const vtp_support::Method_info& method =
    *vtp_support::find_method(q == Query::FULL_VSP ? (parallel ? "pvsp" : "vsp") : (parallel ? "pvtp" : "vtp"));
  std::vector<Vertex_index> targets;
  if(q == Query::TARGET)
    targets.push_back(target);
  const double c0 = cpu_now();
  vtp_support::with_method(method, vtp_support::default_lambda, threads, [&](auto tag, const auto& np) {
    const double max_distance = q == Query::LIMIT ? limit : std::numeric_limits<double>::infinity();
    solver.compute<decltype(tag)>(
      no_map, source, np.maximum_distance(max_distance).record_paths(q == Query::RECORD).targets(targets));
  });
  Result r;
  r.cpu_seconds = cpu_now() - c0;
  r.seconds = solver.statistics().seconds;
  r.max_distance = solver.statistics().max_distance;
  r.processed = solver.statistics().vertices_processed;
  r.propagated = solver.statistics().windows_propagated;
  r.target_distance = q == Query::TARGET ? solver.target_distance(0) : 0.;
  r.ok = 1;
  return r;
}

// Runs one query in a child process; returns its result and its peak RSS (MB).
Result run_forked(const Mesh& mesh, Query q, bool parallel, int threads, double limit, Vertex_index target,
                  std::size_t k, double& peak_rss_mb)
{
  int fds[2];
  if(::pipe(fds) != 0)
    throw std::runtime_error("pipe() failed");
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if(pid < 0)
    throw std::runtime_error("fork() failed");
  if(pid == 0)
  {
    ::close(fds[0]);
    Result r;
    try { r = run_query(mesh, q, parallel, threads, limit, target, k); }
    catch(...) { r.ok = 0; }
    const char* p = reinterpret_cast<const char*>(&r);
    std::size_t left = sizeof(r);
    while(left > 0)
    {
      const ssize_t w = ::write(fds[1], p, left);
      if(w <= 0)
        _exit(3);
      p += w;
      left -= static_cast<std::size_t>(w);
    }
    _exit(0);
  }
  ::close(fds[1]);
  Result r;
  char* p = reinterpret_cast<char*>(&r);
  std::size_t got = 0;
  while(got < sizeof(r))
  {
    const ssize_t n = ::read(fds[0], p + got, sizeof(r) - got);
    if(n < 0 && errno == EINTR)
      continue;
    if(n <= 0)
      break;
    got += static_cast<std::size_t>(n);
  }
  ::close(fds[0]);
  int status = 0;
  struct rusage usage;
  while(::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {}
  peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.;
  if(got != sizeof(r) || !r.ok || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("a child run failed");
  return r;
}

struct Arguments
{
  int repeat = 3, threads = 2;
  double fraction = 0.1;
  std::vector<std::size_t> fps;
  std::size_t naive = 0;
  bool vsp = false;
  std::vector<std::string> files;
  bool help = false;
};

Arguments parse_arguments(int argc, char** argv)
{
  typedef const std::string& S;
  using vtp_support::parse_integer;
  static const vtp_support::Option_table<Arguments> table = {
    { "--repeat", "R", nullptr, [](Arguments& a, S n, S v) { a.repeat = static_cast<int>(parse_integer(n, v, 1, 1000)); } },
    { "--threads", "T", nullptr, [](Arguments& a, S n, S v) { a.threads = static_cast<int>(parse_integer(n, v, 1, 4096)); } },
    { "--limit", "F", nullptr,
      [](Arguments& a, S n, S v) {
        a.fraction = vtp_support::parse_double(n, v);
        if(!(a.fraction > 0.))
          throw vtp_support::Tool_error("the limit fraction of " + n + " must be > 0");
      } },
    { "--fps", "K1,K2,...", nullptr,
      [](Arguments& a, S n, S v) {
        for(std::size_t i : vtp_support::parse_index_list(n, v))
          a.fps.push_back(i);
      } },
    { "--naive", "K", nullptr, [](Arguments& a, S n, S v) { a.naive = static_cast<std::size_t>(parse_integer(n, v, 1, 100000)); } },
    { "--vsp", nullptr, nullptr, [](Arguments& a, S, S) { a.vsp = true; } },
    { "--help", nullptr, nullptr, [](Arguments& a, S, S) { a.help = true; } },
  };
  Arguments a;
  vtp_support::parse_command_line(argc, argv, table, a, [](Arguments& a, const std::string& f) { a.files.push_back(f); });
  if(!a.help && a.files.empty())
    throw vtp_support::Tool_error("give at least one mesh");
  return a;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Arguments args = parse_arguments(argc, argv);
    if(args.help)
    {
      std::cout << "usage: vtp_query_benchmark [--repeat R] [--threads T] [--limit F] [--fps K1,K2,...] [--naive K] "
                   "[--vsp] MESH...\n";
      return 0;
    }
    const int repeat = args.repeat, threads = args.threads;
    const double fraction = args.fraction;
    const std::vector<std::string>& files = args.files;
    std::cout << "| Mesh | #V | Run | Time (s) | vs full | Processor s | vs full | Vertices processed | Windows propagated "
                 "| Peak RSS (MB) | vs full |\n"
              << "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for(const std::string& file : files)
    {
      Mesh mesh;
      if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh) || mesh.is_empty())
        throw std::runtime_error("cannot read " + file);
      // the largest distance and the target, from one full run in this process
      Vertex_index target(0);
      double limit = 0.;
      {
        Solver solver(mesh);
        solver.compute(CGAL::Constant_property_map<Vertex_index, double>(), Vertex_index(0));
        const std::vector<double>& d = solver.distances();
        const double max_d = solver.statistics().max_distance;
        limit = fraction * max_d;
        double best = std::numeric_limits<double>::infinity();
        for(Vertex_index v : vertices(mesh))
          if(std::abs(d[solver.vertex_id(v)] - limit) < best)
          {
            best = std::abs(d[solver.vertex_id(v)] - limit);
            target = v;
          }
      }
      struct Case { Query q; bool parallel; std::size_t k; };
      std::vector<Case> cases = { { Query::FULL, false, 0 }, { Query::LIMIT, false, 0 }, { Query::TARGET, false, 0 },
                                  { Query::RECORD, false, 0 } };
#ifdef _OPENMP
      cases.push_back({ Query::FULL, true, 0 });
      cases.push_back({ Query::LIMIT, true, 0 });
      cases.push_back({ Query::TARGET, true, 0 });
#endif
      for(std::size_t k : args.fps)
        cases.push_back({ Query::FPS, false, k });
      if(args.naive > 0)
        cases.push_back({ Query::NAIVE, false, args.naive });
      if(args.vsp)
      {
        cases.push_back({ Query::FULL_VSP, false, 0 });
        for(std::size_t k : args.fps)
          cases.push_back({ Query::FPS_VSP, false, k });
      }
      std::vector<Result> best(cases.size());
      std::vector<double> rss(cases.size(), 0.);
      for(int r = 0; r < repeat; ++r)
        for(std::size_t c = 0; c < cases.size(); ++c)
        {
          double peak = 0.;
          const Result x = run_forked(mesh, cases[c].q, cases[c].parallel, threads, limit, target, cases[c].k, peak);
          if(r == 0 || x.seconds < best[c].seconds)
            best[c] = x;
          rss[c] = std::max(rss[c], peak);
        }
      const std::string name = std::filesystem::path(file).filename().string();
      for(std::size_t c = 0; c < cases.size(); ++c)
      {
        const std::size_t full = cases[c].parallel ? 4 : 0;
        char line[512];
        const std::string k = cases[c].k > 0 ? " k=" + std::to_string(cases[c].k) : std::string();
        std::snprintf(line, sizeof(line), "| %s | %zu | %s%s%s | %.3g | %.3f | %.3g | %.3f | %llu | %llu | %.0f | %.3f |\n", name.c_str(),
                      static_cast<std::size_t>(num_vertices(mesh)),
                      cases[c].parallel ? ("pvtp:" + std::to_string(threads) + " ").c_str() : "",
                      query_names[static_cast<int>(cases[c].q)], k.c_str(), best[c].seconds, best[c].seconds / best[full].seconds,
                      best[c].cpu_seconds, best[c].cpu_seconds / best[full].cpu_seconds,
                      best[c].processed, best[c].propagated, rss[c], rss[c] / rss[full]);
        std::cout << line;
      }
      std::cout << "| | | (limit " << limit << " = " << fraction << " x max distance " << best[0].max_distance
                << "; target at distance " << best[2].target_distance << ") | | | | | | |" << std::endl;
      for(std::size_t c = 0; c < cases.size(); ++c)
        if(cases[c].q == Query::FPS || cases[c].q == Query::FPS_VSP)
          std::cout << "| | | (" << query_names[static_cast<int>(cases[c].q)] << " k=" << cases[c].k
                    << ": covering radius " << best[c].max_distance << ", exact covering radius of its samples "
                    << best[c].target_distance << ") | | | | | | |" << std::endl;
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "vtp_query_benchmark: error: " << e.what() << std::endl;
    return 2;
  }
  return 0;
}
