// vtp_benchmark: time, peak memory and accuracy of VTP against CGAL's exact and approximate
// geodesic distance methods.
//
//   vtp_benchmark [--remesh R] [--loop N] [--subdivide N] [--sources K] [--methods vtp,cgal,heat,heat_idt]
//                 [--external NAME=COMMAND] [--csv FILE] [--repeat R] [--save-meshes DIR] MESH...
//
// Realistic large inputs are made with CGAL: isotropic remeshing (--remesh) and Loop subdivision
// (--loop) give saddle vertices almost everywhere, like scans; midpoint subdivision (--subdivide)
// only adds flat vertices and is the easy case for VTP.
//
// Every (mesh, source, method) run happens in a forked child process, so that the peak resident
// memory of each method (ru_maxrss of the child, from wait4) is measured on its own; the child
// sends its timings and its distances back through a pipe. Errors are measured against VTP.
// See readme.txt.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/assertions_behaviour.h>
#include <CGAL/property_map.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <vtp_tools/methods.h>
#include <vtp_tools/midpoint_subdivision.h>
#include <vtp_tools/shortest_path_reference.h>

#ifdef CGAL_EIGEN3_ENABLED
#define VTP_BENCHMARK_WITH_HEAT_METHOD 1
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#endif

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h> // getrusage, struct rusage
#include <time.h>         // clock_gettime
#include <sys/types.h>
#include <sys/wait.h>     // wait4
#include <unistd.h>       // fork, pipe, read, write, _exit, sysconf

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;

namespace {

const double inf = std::numeric_limits<double>::infinity();
const double nan_value = std::numeric_limits<double>::quiet_NaN();

struct Usage_error : std::runtime_error
{
  explicit Usage_error(const std::string& what) : std::runtime_error(what) {}
};

// ================================================================================================
// Methods. To add one, add an enumerator, a parser in `method_parsers` (or, for a method of the package, an
// entry in vtp_tools/methods.h), and a case in `run_in_child()`.
// ================================================================================================
enum class Method_kind { VTP, PVTP, AVTP, PAVTP, CGAL_SMSP, HEAT_DIRECT, HEAT_IDT, EXTERNAL };

struct Method
{
  std::string label;        // as printed and written in the CSV, e.g. "vtp", "pvtp:4"
  Method_kind kind = Method_kind::VTP;
  int threads = 1;
  double lambda = inf;      // approximate variants
  bool virtual_sources = false;  // vsp, pvsp:T (one virtual source per vertex)
  std::string command;      // EXTERNAL: shell command with {mesh}, {source}, {output}
};

int parse_int_field(const std::string& method, const std::string& s, int min_value)
{
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if(s.empty() || *end != '\0' || errno == ERANGE || v < min_value || v > 4096)
    throw Usage_error("invalid parameter '" + s + "' in method '" + method + "'");
  return static_cast<int>(v);
}

double parse_positive_field(const std::string& method, const std::string& s)
{
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if(s.empty() || *end != '\0' || !(v > 0.))
    throw Usage_error("invalid parameter '" + s + "' in method '" + method + "'");
  return v;
}

struct Method_parser
{
  const char* name;
  const char* syntax;
  bool available;
  // fields[0] is the name; the parser reads the parameters and fills `m`.
  void (*parse)(const std::vector<std::string>& fields, Method& m);
};

void expect_fields(const std::vector<std::string>& fields, std::size_t n, const char* syntax)
{
  if(fields.size() != n)
    throw Usage_error("invalid method '" + fields[0] + "...' (expected " + syntax + ")");
}

// The VTP family (vtp, pvtp:T, avtp:lambda, pavtp:T:lambda) comes from the table of methods shared with the
// command-line tools (vtp_tools/methods.h): the name, then ":T" for a parallel method and ":lambda" for an
// approximate one. Returns false if `fields[0]` is not one of them.
bool parse_vtp_method(const std::vector<std::string>& fields, Method& m)
{
  const vtp_tools::Method_info* info = vtp_tools::find_method(fields[0]);
  if(info == nullptr)
    return false;
  const std::string syntax = std::string(info->name) + (info->parallel ? ":T" : "") + (info->approximate ? ":lambda" : "");
  expect_fields(fields, 1 + (info->parallel ? 1 : 0) + (info->approximate ? 1 : 0), syntax.c_str());
  m.kind = info->parallel ? (info->approximate ? Method_kind::PAVTP : Method_kind::PVTP)
                          : (info->approximate ? Method_kind::AVTP : Method_kind::VTP);
  m.virtual_sources = info->virtual_sources;
  std::size_t k = 1;
  if(info->parallel)
    m.threads = parse_int_field(m.label, fields[k++], 1);
  if(info->approximate)
    m.lambda = parse_positive_field(m.label, fields[k++]);
  if(!vtp_tools::method_available(*info))
    throw Usage_error("method " + std::string(info->name) + " is not available (vtp_benchmark was built without OpenMP)");
  return true;
}

const Method_parser method_parsers[] = {
  { "cgal", "cgal", true,
    [](const std::vector<std::string>& f, Method& m) { expect_fields(f, 1, "cgal"); m.kind = Method_kind::CGAL_SMSP; } },
#ifdef VTP_BENCHMARK_WITH_HEAT_METHOD
  { "heat", "heat", true,
#else
  { "heat", "heat", false,
#endif
    [](const std::vector<std::string>& f, Method& m) { expect_fields(f, 1, "heat"); m.kind = Method_kind::HEAT_DIRECT; } },
#ifdef VTP_BENCHMARK_WITH_HEAT_METHOD
  { "heat_idt", "heat_idt", true,
#else
  { "heat_idt", "heat_idt", false,
#endif
    [](const std::vector<std::string>& f, Method& m) { expect_fields(f, 1, "heat_idt"); m.kind = Method_kind::HEAT_IDT; } },
};

std::vector<std::string> split(const std::string& s, char separator)
{
  std::vector<std::string> parts;
  std::string::size_type begin = 0;
  for(;;)
  {
    const std::string::size_type end = s.find(separator, begin);
    parts.push_back(s.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    if(end == std::string::npos)
      return parts;
    begin = end + 1;
  }
}

Method parse_method(const std::string& spec)
{
  const std::vector<std::string> fields = split(spec, ':');
  {
    Method m;
    m.label = spec;
    if(parse_vtp_method(fields, m))
      return m;
  }
  for(const Method_parser& p : method_parsers)
  {
    if(fields[0] != p.name)
      continue;
    Method m;
    m.label = spec;
    p.parse(fields, m);
    if(!p.available)
    {
#ifndef VTP_BENCHMARK_WITH_HEAT_METHOD
      if(m.kind == Method_kind::HEAT_DIRECT || m.kind == Method_kind::HEAT_IDT)
        throw Usage_error("method " + spec + " is not available (vtp_benchmark was built without Eigen)");
#endif
      throw Usage_error("method " + std::string(p.name) + " is not available (vtp_benchmark was built without OpenMP)");
    }
    return m;
  }
  std::string known = "vtp, pvtp:T, avtp:lambda, pavtp:T:lambda";
  for(const Method_parser& p : method_parsers)
    known += (known.empty() ? "" : ", ") + std::string(p.syntax);
  throw Usage_error("unknown method '" + spec + "' (known: " + known + ")");
}

// ================================================================================================
// Command line
// ================================================================================================
struct Arguments
{
  double remesh = 0.;       // target edge length / mean edge length; 0: no remeshing
  int remesh_iterations = 3;
  int loop = 0;
  int subdivide = 0;
  std::string save_meshes;
  std::size_t sources = 1;
  std::vector<Method> methods;
  std::string csv;
  int repeat = 1;
  std::vector<std::string> meshes;
  bool help = false;
};

void print_usage(std::ostream& os)
{
  os << "usage: vtp_benchmark [options] MESH...\n"
        "\n"
        "Inputs (applied in this order; the mesh label gets /rR, /LN, /sN):\n"
        "  --remesh R       isotropic remeshing (CGAL::Polygon_mesh_processing::isotropic_remeshing) at a\n"
        "                   target edge length of R times the mean edge length of the input (e.g. 0.25\n"
        "                   gives about 16x more vertices)\n"
        "  --remesh-iterations K  iterations of the remeshing (default 3)\n"
        "  --loop N         Loop subdivision (CGAL::Subdivision_method_3::Loop_subdivision), N steps (x4 each)\n"
        "  --subdivide N    1-to-4 midpoint subdivision, N times: every new vertex is flat (angle sum\n"
        "                   360 degrees), so few vertices are saddles: the easy case for VTP\n"
        "  --save-meshes DIR  write each (generated) mesh as DIR/<label>.off, vertices in index order\n"
        "\n"
        "Methods and output:\n"
        "  --sources K      number of source vertices per mesh: vertex 0 and evenly spaced ids (default 1)\n"
        "  --methods LIST   comma-separated methods (default vtp,cgal):\n"
        "                     vtp       exact VTP (this package)\n"
        "                     cgal      CGAL::Surface_mesh_shortest_path (exact)\n"
        "                     heat      CGAL::Heat_method_3, Direct (approximate, needs Eigen)\n"
        "                     heat_idt  CGAL::Heat_method_3, Intrinsic_Delaunay (approximate, needs Eigen)\n"
        "                     pvtp:T, avtp:lambda, pavtp:T:lambda\n"
        "  --external NAME=COMMAND  also run an external program as method NAME (may be repeated): the\n"
        "                   mesh is written as an OFF file (vertices in index order) and COMMAND runs in\n"
        "                   /bin/sh with {mesh}, {source} (vertex index) and {output} replaced; it must\n"
        "                   print seconds=<time of its propagation> (and may print cpu_seconds=<t> and\n"
        "                   windows_propagated=<n>)\n"
        "                   on standard output, and may write one distance per vertex into {output}\n"
        "  --csv FILE       also write the results as CSV\n"
        "  --repeat R       run each method R times per source and keep the fastest (default 1); the\n"
        "                   runs are interleaved (each method once, in turn, R times), so that every\n"
        "                   method meets the same changes of the machine's state\n"
        "  --help           print this help\n"
        "\n"
        "Each method runs in its own child process: peak_rss_mb is the peak resident memory of that\n"
        "process (mesh included). Errors are measured against VTP, which is always run.\n"
        "cpu_seconds is the processor time of the same work (all threads; for an external method, what it\n"
        "prints as cpu_seconds=<time>), and cpu_ratio_vs_vtp the processor time of vtp divided by the\n"
        "method's: on a machine busy with other work, it is steadier than the elapsed times.\n"
        "ns_per_window is the time divided by the number of windows the method propagated (for an\n"
        "external method, the count it prints). Before each mesh's rows, a line gives its share of\n"
        "pseudo-source vertices (saddle or boundary).\n"
        "With a parallel method, the round-trip time of a cache line between two threads is printed\n"
        "before and after the runs of each source: on a virtual machine it changes with where the host\n"
        "places the virtual processors (about 50 ns or about 330 ns on the 2-vCPU machine this package\n"
        "was developed on), and the parallel methods, which share data between cores, feel it.\n";
}

std::size_t parse_count(const std::string& option, const std::string& s, std::size_t min_value, std::size_t max_value)
{
  if(s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
    throw Usage_error("invalid value '" + s + "' for " + option + " (expected an integer)");
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if(errno == ERANGE || v < min_value || v > max_value)
    throw Usage_error("value '" + s + "' for " + option + " is out of range [" + std::to_string(min_value) + ", "
                      + std::to_string(max_value) + "]");
  return static_cast<std::size_t>(v);
}

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  std::string methods = "vtp,cgal";
  std::vector<Method> externals;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw Usage_error("missing value for " + arg);
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h") a.help = true;
    else if(arg == "--subdivide") a.subdivide = static_cast<int>(parse_count(arg, value(), 0, 6));
    else if(arg == "--loop") a.loop = static_cast<int>(parse_count(arg, value(), 0, 6));
    else if(arg == "--remesh")
    {
      const std::string v = value();
      char* end = nullptr;
      a.remesh = std::strtod(v.c_str(), &end);
      if(v.empty() || *end != '\0' || !(a.remesh >= 0.01) || !(a.remesh <= 100.))
        throw Usage_error("invalid value '" + v + "' for --remesh (expected a number in [0.01, 100])");
    }
    else if(arg == "--remesh-iterations") a.remesh_iterations = static_cast<int>(parse_count(arg, value(), 1, 100));
    else if(arg == "--save-meshes")
    {
      a.save_meshes = value();
      if(a.save_meshes.empty())
        throw Usage_error("empty folder name for --save-meshes");
    }
    else if(arg == "--external")
    {
      const std::string v = value();
      const std::string::size_type eq = v.find('=');
      if(eq == std::string::npos || eq == 0 || eq + 1 == v.size())
        throw Usage_error("invalid --external '" + v + "' (expected NAME=COMMAND)");
      Method m;
      m.label = v.substr(0, eq);
      m.kind = Method_kind::EXTERNAL;
      m.command = v.substr(eq + 1);
      if(m.label.find_first_of(",: ") != std::string::npos)
        throw Usage_error("invalid external method name '" + m.label + "'");
      externals.push_back(m);
    }
    else if(arg == "--sources") a.sources = parse_count(arg, value(), 1, 1000000);
    else if(arg == "--methods") methods = value();
    else if(arg == "--csv")
    {
      a.csv = value();
      if(a.csv.empty())
        throw Usage_error("empty file name for --csv");
    }
    else if(arg == "--repeat") a.repeat = static_cast<int>(parse_count(arg, value(), 1, 1000));
    else if(arg.size() > 1 && arg[0] == '-')
      throw Usage_error("unknown option '" + arg + "' (see --help)");
    else
      a.meshes.push_back(arg);
  }
  if(a.help)
    return a;
  if(a.meshes.empty())
    throw Usage_error("no mesh given (see --help)");
  for(const std::string& spec : split(methods, ','))
  {
    if(spec.empty())
      throw Usage_error("empty method name in --methods '" + methods + "'");
    Method m = parse_method(spec);
    for(const Method& other : a.methods)
      if(other.label == m.label)
        throw Usage_error("method '" + spec + "' given twice");
    a.methods.push_back(m);
  }
  for(const Method& m : externals)
  {
    for(const Method& other : a.methods)
      if(other.label == m.label)
        throw Usage_error("method '" + m.label + "' given twice");
    a.methods.push_back(m);
  }
  return a;
}

// ================================================================================================
// Child side: run one method on one source, R times.
// ================================================================================================
struct Child_header
{
  double seconds = nan_value;                // per-source work, fastest of the repeats
  double cpu_seconds = nan_value;            // processor time of that work (all threads), fastest of the repeats
  double preprocessing_seconds = nan_value;  // per-mesh work (solver construction, factorization)
  double rss_at_start_kb = 0.;
  std::uint64_t windows_created = 0, windows_propagated = 0, peak_window_bytes = 0, peak_live_windows = 0;
  std::uint64_t pseudo_source_vertices = 0;
  std::int32_t threads = 1;
  std::int32_t has_windows = 0;
  std::uint64_t number_of_distances = 0;
  std::uint64_t error_length = 0;
};

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

void run_vtp(const Mesh& mesh, Vertex_index source, const Method& method, int repeat,
             Child_header& h, std::vector<double>& d)
{
  typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
  Solver solver(mesh);
  h.preprocessing_seconds = solver.preprocessing_seconds();
  h.pseudo_source_vertices = solver.number_of_pseudo_source_vertices();
  const auto options = CGAL::VTP_geodesics::parameters::lambda(method.lambda).number_of_threads(method.threads)
                         .virtual_sources(method.virtual_sources);
  // the distances are read from the solver: nothing to write through a map
  for(int r = 0; r < repeat; ++r)
  {
    const double c0 = cpu_now_seconds();
    switch(method.kind)
    {
      case Method_kind::VTP:
      case Method_kind::AVTP:
        solver.compute<CGAL::Sequential_tag>(CGAL::Constant_property_map<Vertex_index, double>(), source, options);
        break;
      default:
#ifdef _OPENMP
        solver.compute<CGAL::Parallel_tag>(CGAL::Constant_property_map<Vertex_index, double>(), source, options);
#else
        throw std::runtime_error("method " + method.label + " needs OpenMP");
#endif
    }
    const double cpu = cpu_now_seconds() - c0;
    const CGAL::VTP_geodesics::Propagation_statistics& s = solver.statistics();
    if(r == 0 || s.seconds < h.seconds)
      h.seconds = s.seconds;
    if(r == 0 || cpu < h.cpu_seconds)
      h.cpu_seconds = cpu;
    h.windows_created = s.windows_created;
    h.windows_propagated = s.windows_propagated;
    h.peak_window_bytes = (std::max)(h.peak_window_bytes, static_cast<std::uint64_t>(s.peak_window_bytes));
    h.peak_live_windows = (std::max)(h.peak_live_windows, static_cast<std::uint64_t>(s.peak_live_windows));
    h.threads = s.threads;
  }
  h.has_windows = 1;
  d = solver.distances();
}

void run_cgal(const Mesh& mesh, Vertex_index source, int repeat, Child_header& h, std::vector<double>& d)
{
  // Sequence tree from the source, and a query for every vertex of its component.
  h.preprocessing_seconds = 0.;
  for(int r = 0; r < repeat; ++r)
  {
    const double t0 = now_seconds();
    d = vtp_tools::shortest_path_reference_distances(mesh, source);
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

[[noreturn]] void run_in_child(int fd, Mesh& mesh, Vertex_index source, const Method& method, int repeat)
{
  Child_header h;
  std::vector<double> d;
  std::string error;
  h.rss_at_start_kb = current_rss_kb();
  try
  {
    switch(method.kind)
    {
      case Method_kind::VTP:
      case Method_kind::PVTP:
      case Method_kind::AVTP:
      case Method_kind::PAVTP:
        run_vtp(mesh, source, method, repeat, h, d);
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

  h.number_of_distances = d.size();
  h.error_length = error.size();
  write_all(fd, &h, sizeof(h));
  if(!d.empty())
    write_all(fd, d.data(), d.size() * sizeof(double));
  if(!error.empty())
    write_all(fd, error.data(), error.size());
  ::close(fd);
  _exit(0);
}

// ================================================================================================
// Parent side
// ================================================================================================
struct Run_result
{
  Method method;
  bool ok = false;
  std::string status = "ok";
  Child_header header;
  double peak_rss_mb = nan_value;
  std::vector<double> distances;
  // Filled after all methods of the source ran.
  double max_abs_err = nan_value, max_rel_err = nan_value, mean_rel_err = nan_value, speedup_vs_cgal = nan_value;
  double mean_pointwise_rel_err = nan_value, max_pointwise_rel_err = nan_value, speedup_vs_vtp = nan_value;
  double cpu_ratio_vs_vtp = nan_value;  // processor time of VTP / processor time of this method
  double max_below_vtp = nan_value;     // largest (vtp - d) / largest vtp distance (> 0: below the exact one)
  std::size_t mismatched_infinities = 0;
};

double ns_per_window(const Run_result& r)
{
  if(!r.ok || !r.header.has_windows || r.header.windows_propagated == 0)
    return nan_value;
  return r.header.seconds * 1e9 / static_cast<double>(r.header.windows_propagated);
}

double total_seconds(const Run_result& r) { return r.header.seconds + r.header.preprocessing_seconds; }

// Reads everything the child `pid` writes to `fd` (before waiting: the child blocks when the pipe is full),
// closes `fd`, then waits for the child: its exit status and peak RSS (MB).
std::string read_all_and_wait(int fd, pid_t pid, int& status, double& peak_rss_mb)
{
  std::string text;
  char buffer[1 << 16];
  for(;;)
  {
    const ssize_t r = ::read(fd, buffer, sizeof(buffer));
    if(r < 0 && errno == EINTR)
      continue;
    if(r <= 0)
      break;
    text.append(buffer, static_cast<std::size_t>(r));
  }
  ::close(fd);
  status = 0;
  struct rusage usage;
  std::memset(&usage, 0, sizeof(usage));
  while(::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {}
  peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.; // ru_maxrss is in KB on Linux
  return text;
}

Run_result run_forked(Mesh& mesh, Vertex_index source, const Method& method, int repeat)
{
  Run_result result;
  result.method = method;
  int fds[2];
  if(::pipe(fds) != 0)
    throw std::runtime_error(std::string("pipe() failed: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork() failed: ") + std::strerror(errno));
  }
  if(pid == 0)
  {
    ::close(fds[0]);
    run_in_child(fds[1], mesh, source, method, repeat);
  }
  ::close(fds[1]);

  int status = 0;
  const std::string message = read_all_and_wait(fds[0], pid, status, result.peak_rss_mb);

  if(WIFSIGNALED(status))
  {
    result.status = "killed by signal " + std::to_string(WTERMSIG(status));
    return result;
  }
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0 || message.size() < sizeof(Child_header))
  {
    result.status = "child failed";
    return result;
  }
  std::memcpy(&result.header, message.data(), sizeof(Child_header));
  const Child_header& h = result.header;
  const std::size_t expected = sizeof(Child_header) + h.number_of_distances * sizeof(double) + h.error_length;
  if(message.size() != expected)
  {
    result.status = "truncated child report";
    return result;
  }
  result.distances.resize(h.number_of_distances);
  if(h.number_of_distances > 0)
    std::memcpy(result.distances.data(), message.data() + sizeof(Child_header), h.number_of_distances * sizeof(double));
  if(h.error_length > 0)
  {
    result.status = "error: " + message.substr(sizeof(Child_header) + h.number_of_distances * sizeof(double));
    return result;
  }
  result.ok = true;
  return result;
}

// External methods ---------------------------------------------------------------------------------
std::string replace_all(std::string s, const std::string& what, const std::string& with)
{
  for(std::string::size_type at = s.find(what); at != std::string::npos; at = s.find(what, at + with.size()))
    s.replace(at, what.size(), with);
  return s;
}

// Value of "key=<value>" in `text`, at the start of the text or after a space, tab or new line.
bool find_value(const std::string& text, const std::string& key, std::string& value)
{
  const std::string k = key + "=";
  for(std::string::size_type at = text.find(k); at != std::string::npos; at = text.find(k, at + 1))
  {
    if(at > 0 && text[at - 1] != ' ' && text[at - 1] != '\t' && text[at - 1] != '\n')
      continue;
    const std::string::size_type begin = at + k.size();
    const std::string::size_type end = text.find_first_of(" \t\r\n", begin);
    value = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    return true;
  }
  return false;
}

// Runs an external method (see --external) on the mesh written to `mesh_file`, in its own process
// (so its peak RSS is its own), and reads its time, window count and distances.
Run_result run_external(const std::string& mesh_file, std::size_t source, std::size_t number_of_vertices,
                        const Method& method, const std::string& output_file)
{
  Run_result result;
  result.method = method;
  std::string command = replace_all(method.command, "{mesh}", mesh_file);
  command = replace_all(command, "{source}", std::to_string(source));
  const bool wants_output = command.find("{output}") != std::string::npos;
  command = replace_all(command, "{output}", output_file);
  if(wants_output)
    std::remove(output_file.c_str());

  int fds[2];
  if(::pipe(fds) != 0)
    throw std::runtime_error(std::string("pipe() failed: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork() failed: ") + std::strerror(errno));
  }
  if(pid == 0)
  {
    ::close(fds[0]);
    ::dup2(fds[1], 1);
    ::close(fds[1]);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  ::close(fds[1]);
  int status = 0;
  const std::string text = read_all_and_wait(fds[0], pid, status, result.peak_rss_mb);
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    result.status = WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                        : "exit code " + std::to_string(WEXITSTATUS(status));
    return result;
  }
  std::string value;
  char* end = nullptr;
  if(!find_value(text, "seconds", value) || (result.header.seconds = std::strtod(value.c_str(), &end), *end != '\0'))
  {
    result.status = "no seconds=<time> in the output";
    return result;
  }
  result.header.preprocessing_seconds = nan_value;
  if(find_value(text, "cpu_seconds", value))
    result.header.cpu_seconds = std::strtod(value.c_str(), nullptr);
  if(find_value(text, "windows_propagated", value))
  {
    result.header.windows_propagated = std::strtoull(value.c_str(), nullptr, 10);
    result.header.has_windows = 1;
  }
  if(find_value(text, "windows_created", value))
    result.header.windows_created = std::strtoull(value.c_str(), nullptr, 10);
  if(wants_output)
  {
    std::ifstream in(output_file);
    std::string token;
    while(in >> token)
    {
      const double d = std::strtod(token.c_str(), &end);
      if(*end != '\0')
      {
        result.status = "unreadable distance '" + token + "' in " + output_file;
        return result;
      }
      result.distances.push_back(d);
    }
    if(result.distances.size() != number_of_vertices)
    {
      result.status = "wrong number of distances in " + output_file;
      return result;
    }
    std::remove(output_file.c_str());
  }
  result.ok = true;
  return result;
}

void write_off(const Mesh& mesh, const std::string& file)
{
  FILE* out = std::fopen(file.c_str(), "w");
  if(out == nullptr)
    throw std::runtime_error("cannot write '" + file + "'");
  std::fprintf(out, "OFF\n%zu %zu 0\n", static_cast<std::size_t>(mesh.number_of_vertices()),
               static_cast<std::size_t>(mesh.number_of_faces()));
  for(Vertex_index v : mesh.vertices())
  {
    const Kernel::Point_3& p = mesh.point(v);
    std::fprintf(out, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  }
  for(Mesh::Face_index f : mesh.faces())
  {
    std::fprintf(out, "3");
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      std::fprintf(out, " %zu", static_cast<std::size_t>(v));
    std::fprintf(out, "\n");
  }
  if(std::fclose(out) != 0)
    throw std::runtime_error("cannot write '" + file + "'");
}

// CSV and table output ---------------------------------------------------------------------------
std::string number(double x, int precision = 6)
{
  if(std::isnan(x))
    return std::string();
  if(std::isinf(x))
    return x > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", precision, x);
  return buffer;
}

std::string csv_field(const std::string& s)
{
  if(s.find_first_of(",\"\n") == std::string::npos)
    return s;
  std::string r = "\"";
  for(char c : s)
  {
    if(c == '"') r += '"';
    r += c;
  }
  return r + "\"";
}

const char* const csv_columns =
  "mesh,vertices,faces,source,method,threads,seconds,preprocessing_seconds,peak_rss_mb,windows_created,"
  "windows_propagated,peak_window_bytes,max_abs_err_vs_vtp,max_rel_err_vs_vtp,mean_rel_err_vs_vtp,speedup_vs_cgal,"
  "total_seconds,rss_at_start_mb,mean_pointwise_rel_err_vs_vtp,max_pointwise_rel_err_vs_vtp,speedup_vs_vtp,"
  "peak_live_windows,ns_per_window,pseudo_source_share,cpu_seconds,cpu_ratio_vs_vtp,status,max_below_vtp";

struct Mesh_info
{
  std::string label;
  std::size_t vertices = 0, faces = 0;
  double pseudo_source_share = nan_value;  // saddle or boundary vertices / vertices (from the VTP run)
};

void write_csv_row(std::ostream& os, const Mesh_info& mesh, std::size_t source, const Run_result& r)
{
  const Child_header& h = r.header;
  const bool w = r.ok && h.has_windows;
  os << csv_field(mesh.label) << ',' << mesh.vertices << ',' << mesh.faces << ',' << source << ','
     << csv_field(r.method.label) << ',' << (r.ok ? std::to_string(h.threads) : std::string()) << ','
     << (r.ok ? number(h.seconds, 9) : "") << ',' << (r.ok ? number(h.preprocessing_seconds, 9) : "") << ','
     << number(r.peak_rss_mb, 6) << ','
     << (w && r.method.kind != Method_kind::EXTERNAL ? std::to_string(h.windows_created) : "") << ','
     << (w ? std::to_string(h.windows_propagated) : "") << ','
     << (w && r.method.kind != Method_kind::EXTERNAL ? std::to_string(h.peak_window_bytes) : "") << ','
     << number(r.max_abs_err, 6) << ',' << number(r.max_rel_err, 6) << ',' << number(r.mean_rel_err, 6) << ','
     << number(r.speedup_vs_cgal, 6) << ','
     << (r.ok ? number(total_seconds(r), 9) : "") << ','
     << (r.ok ? number(h.rss_at_start_kb / 1024., 6) : "") << ','
     << number(r.mean_pointwise_rel_err, 6) << ',' << number(r.max_pointwise_rel_err, 6) << ','
     << number(r.speedup_vs_vtp, 6) << ','
     << (w && r.method.kind != Method_kind::EXTERNAL ? std::to_string(h.peak_live_windows) : "") << ','
     << number(ns_per_window(r), 6) << ',' << number(mesh.pseudo_source_share, 6) << ','
     << (r.ok ? number(h.cpu_seconds, 9) : "") << ',' << number(r.cpu_ratio_vs_vtp, 6) << ','
     << csv_field(r.status) << ',' << number(r.max_below_vtp, 6) << '\n';
}

void print_table_header()
{
  std::printf("%-22s %9s %9s  %-12s %11s %11s %9s %9s %11s %7s %10s %9s  %s\n", "mesh", "vertices", "source", "method",
              "seconds", "prep_s", "rss_MB", "+rss_MB", "windows", "ns/win", "max_rel", "speedup", "status");
}

void print_table_row(const Mesh_info& mesh, std::size_t source, const Run_result& r)
{
  const Child_header& h = r.header;
  const std::string windows = (r.ok && h.has_windows && r.method.kind != Method_kind::EXTERNAL)
                              ? std::to_string(h.windows_created) : "-";
  const double increase = (r.ok && r.method.kind != Method_kind::EXTERNAL) ? r.peak_rss_mb - h.rss_at_start_kb / 1024.
                                                                           : nan_value;
  auto cell = [](double x, int p) { const std::string s = number(x, p); return s.empty() ? std::string("-") : s; };
  std::printf("%-22s %9zu %9zu  %-12s %11s %11s %9s %9s %11s %7s %10s %9s  %s\n", mesh.label.c_str(), mesh.vertices, source,
              r.method.label.c_str(), cell(r.ok ? h.seconds : nan_value, 4).c_str(),
              cell(r.ok ? h.preprocessing_seconds : nan_value, 4).c_str(), cell(r.peak_rss_mb, 4).c_str(),
              cell(increase, 4).c_str(), windows.c_str(), cell(ns_per_window(r), 3).c_str(), cell(r.max_rel_err, 3).c_str(),
              cell(r.speedup_vs_cgal, 3).c_str(), r.status.c_str());
  std::fflush(stdout);
}

std::string base_name(const std::string& path)
{
  const std::string::size_type slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Reads a mesh and makes the requested input from it: isotropic remeshing, then Loop subdivision,
// then midpoint subdivision. The vertices are numbered 0..n-1 in the end (garbage collected).
std::string load_mesh(const std::string& file, const Arguments& args, Mesh& mesh)
{
  std::ostringstream diagnostics;
  std::streambuf* const cerr_buffer = std::cerr.rdbuf(diagnostics.rdbuf());
  bool ok = false;
  try { ok = CGAL::IO::read_polygon_mesh(file, mesh); } catch(...) { ok = false; }
  std::cerr.rdbuf(cerr_buffer);
  if(!ok)
    throw Usage_error("cannot read mesh '" + file + "'");
  if(mesh.is_empty() || mesh.number_of_faces() == 0)
    throw Usage_error("the mesh '" + file + "' is empty");
  if(!CGAL::is_triangle_mesh(mesh))
    throw Usage_error("the mesh '" + file + "' is not a triangle mesh");
  std::string label = base_name(file);
  if(args.remesh > 0.)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    double sum = 0.;
    for(Mesh::Edge_index e : mesh.edges())
      sum += PMP::edge_length(e, mesh);
    const double target = args.remesh * sum / double(mesh.number_of_edges());
    PMP::isotropic_remeshing(faces(mesh), target, mesh,
                             CGAL::parameters::number_of_iterations(args.remesh_iterations));
    mesh.collect_garbage();
    label += "/r" + number(args.remesh, 4);
  }
  if(args.loop > 0)
  {
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(args.loop));
    label += "/L" + std::to_string(args.loop);
  }
  if(args.subdivide > 0)
  {
    vtp_tools::midpoint_subdivide(mesh, args.subdivide);
    label += "/s" + std::to_string(args.subdivide);
  }
  if(mesh.has_garbage())
    mesh.collect_garbage();
  return label;
}

// Round-trip time of a cache line between two threads (they bounce a counter), in nanoseconds; 0 with
// fewer than 2 processors. On a virtual machine it tells where the host placed the virtual processors
// at that moment (seen on the 2-vCPU machine of this project: about 50 ns, or about 330 ns at times),
// which the parallel methods feel (they share data between cores) and the sequential ones do not.
double core_to_core_round_trip_ns()
{
  if(std::thread::hardware_concurrency() < 2)
    return 0.;
  struct alignas(64) Line
  {
    std::atomic<long> value{ 0 };
  } line;
  const long n = 100000;
  auto wait_for = [&line](long v) {
    for(int spins = 0; line.value.load(std::memory_order_acquire) != v;)
      if(++spins > 4096)
        std::this_thread::yield();
  };
  std::thread other([&] {
    for(long i = 0; i < n; ++i)
    {
      wait_for(2 * i + 1);
      line.value.store(2 * i + 2, std::memory_order_release);
    }
  });
  const double t0 = now_seconds();
  for(long i = 0; i < n; ++i)
  {
    line.value.store(2 * i + 1, std::memory_order_release);
    wait_for(2 * i + 2);
  }
  const double t = now_seconds() - t0;
  other.join();
  return t / double(n) * 1e9;
}

int run(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv);
  if(args.help)
  {
    print_usage(std::cout);
    return 0;
  }
  for(const std::string& file : args.meshes)
    if(!std::ifstream(file))
      throw Usage_error("cannot open '" + file + "'");

  std::ofstream csv;
  if(!args.csv.empty())
  {
    csv.open(args.csv);
    if(!csv)
      throw Usage_error("cannot write '" + args.csv + "'");
    csv << csv_columns << '\n';
  }

  // VTP is the reference: it runs first, even when not asked for (then it is not reported).
  std::vector<Method> runs;
  Method reference;
  reference.label = "vtp";
  reference.kind = Method_kind::VTP;
  const bool report_vtp =
    std::any_of(args.methods.begin(), args.methods.end(), [](const Method& m) { return m.label == "vtp"; });
  runs.push_back(reference);
  for(const Method& m : args.methods)
    if(m.label != "vtp")
      runs.push_back(m);

  bool header_printed = false;
  int failures = 0;
  const bool parallel = std::any_of(args.methods.begin(), args.methods.end(), [](const Method& m) {
    return m.label.compare(0, 4, "pvtp") == 0 || m.label.compare(0, 5, "pavtp") == 0;
  });
  const bool external = std::any_of(args.methods.begin(), args.methods.end(),
                                    [](const Method& m) { return m.kind == Method_kind::EXTERNAL; });
  std::string temporary_folder;
  if(external)
  {
    char name[] = "/tmp/vtp_benchmark_XXXXXX";
    if(::mkdtemp(name) == nullptr)
      throw std::runtime_error(std::string("mkdtemp() failed: ") + std::strerror(errno));
    temporary_folder = name;
  }
  for(const std::string& file : args.meshes)
  {
    Mesh mesh;
    Mesh_info info;
    info.label = load_mesh(file, args, mesh);
    info.vertices = mesh.number_of_vertices();
    info.faces = mesh.number_of_faces();
    std::string mesh_file;
    if(!args.save_meshes.empty())
    {
      mesh_file = args.save_meshes + "/" + replace_all(info.label, "/", "_") + ".off";
      write_off(mesh, mesh_file);
    }
    else if(external)
    {
      mesh_file = temporary_folder + "/mesh.off";
      write_off(mesh, mesh_file);
    }
    if(!header_printed)
    {
      print_table_header();
      header_printed = true;
    }

    const std::size_t k = (std::min)(args.sources, info.vertices);
    for(std::size_t i = 0; i < k; ++i)
    {
      // Vertex 0 and evenly spaced ids.
      const std::size_t source_id = static_cast<std::size_t>(
        (static_cast<unsigned long long>(i) * info.vertices) / k);
      const Vertex_index source(static_cast<Mesh::size_type>(source_id));
      auto run_method = [&](const Method& m) {
        if(m.kind == Method_kind::EXTERNAL)
          return run_external(mesh_file, source_id, info.vertices, m, temporary_folder + "/distances.txt");
        return run_forked(mesh, source, m, 1);
      };

      const double round_trip_before = parallel ? core_to_core_round_trip_ns() : 0.;
      std::vector<Run_result> results;
      for(const Method& m : runs)
        results.push_back(run_method(m));
      for(int r = 1; r < args.repeat; ++r)
        for(std::size_t j = 0; j < runs.size(); ++j)
        {
          if(!results[j].ok)
            continue;
          const Run_result again = run_method(runs[j]);
          if(!again.ok)
          {
            results[j] = again;
            continue;
          }
          Child_header& h = results[j].header;
          h.seconds = (std::min)(h.seconds, again.header.seconds);
          if(!(h.cpu_seconds <= again.header.cpu_seconds))
            h.cpu_seconds = again.header.cpu_seconds;
          h.preprocessing_seconds = (std::min)(h.preprocessing_seconds, again.header.preprocessing_seconds);
          results[j].peak_rss_mb = (std::max)(results[j].peak_rss_mb, again.peak_rss_mb);
        }
      if(parallel)
        std::printf("# core-to-core round trip: %.0f ns before these runs, %.0f ns after (see --help)\n",
                    round_trip_before, core_to_core_round_trip_ns());

      const Run_result& vtp = results.front();
      if(i == 0 && vtp.ok)
      {
        info.pseudo_source_share = double(vtp.header.pseudo_source_vertices) / double(info.vertices);
        std::printf("# %s: %zu vertices, %zu faces, %llu pseudo-source vertices (saddle or boundary): %.1f%%\n",
                    info.label.c_str(), info.vertices, info.faces,
                    static_cast<unsigned long long>(vtp.header.pseudo_source_vertices),
                    100. * info.pseudo_source_share);
      }
      const Run_result* cgal = nullptr;
      for(const Run_result& r : results)
        if(r.method.kind == Method_kind::CGAL_SMSP && r.ok)
          cgal = &r;
      for(Run_result& r : results)
      {
        if(!r.ok)
          continue;
        if(vtp.ok && (r.method.kind != Method_kind::EXTERNAL || !r.distances.empty()))
        {
          const vtp_tools::Distance_comparison c =
            vtp_tools::compare_distances(r.distances, vtp.distances);
          r.max_abs_err = c.max_abs_diff;
          r.max_rel_err = c.max_rel_diff;
          r.mean_rel_err = c.mean_rel_diff;
          r.mean_pointwise_rel_err = c.mean_pointwise_rel_diff;
          r.max_pointwise_rel_err = c.max_pointwise_rel_diff;
          r.mismatched_infinities = c.mismatched_infinities;
          double below = -inf, scale = 0.;
          for(double x : vtp.distances)
            if(std::isfinite(x))
              scale = (std::max)(scale, x);
          for(std::size_t i = 0; i < r.distances.size() && i < vtp.distances.size(); ++i)
            if(std::isfinite(r.distances[i]) && std::isfinite(vtp.distances[i]))
              below = (std::max)(below, vtp.distances[i] - r.distances[i]);
          r.max_below_vtp = scale > 0. ? below / scale : below;
          if(c.mismatched_infinities > 0 && r.status == "ok")
            r.status = "ok (" + std::to_string(c.mismatched_infinities) + " reachability mismatches)";
        }
        if(vtp.ok && r.header.seconds > 0.)
          r.speedup_vs_vtp = vtp.header.seconds / r.header.seconds;
        if(vtp.ok && r.header.cpu_seconds > 0.)
          r.cpu_ratio_vs_vtp = vtp.header.cpu_seconds / r.header.cpu_seconds;
        if(cgal != nullptr && total_seconds(r) > 0.)
          r.speedup_vs_cgal = total_seconds(*cgal) / total_seconds(r);
      }
      // Report in the order of --methods; the reference run is shown only if "vtp" was asked for
      // (or if it failed).
      std::vector<const Run_result*> shown;
      if(!report_vtp && !vtp.ok)
        shown.push_back(&vtp);
      for(const Method& m : args.methods)
        for(const Run_result& r : results)
          if(r.method.label == m.label)
            shown.push_back(&r);
      for(const Run_result* r : shown)
      {
        if(!r->ok)
          ++failures;
        print_table_row(info, source_id, *r);
        if(csv.is_open())
          write_csv_row(csv, info, source_id, *r);
      }
      if(csv.is_open())
      {
        csv.flush();
        if(!csv)
          throw Usage_error("cannot write '" + args.csv + "'");
      }
    }
  }
  if(!temporary_folder.empty())
  {
    std::remove((temporary_folder + "/mesh.off").c_str());
    ::rmdir(temporary_folder.c_str());
  }
  if(failures > 0)
  {
    std::cerr << "vtp_benchmark: " << failures << " run(s) failed (see the status column)" << std::endl;
    return 1;
  }
  return 0;
}

void silent_cgal_handler(const char*, const char*, const char*, int, const char*) {}

} // namespace

int main(int argc, char** argv)
{
  // CGAL failures become exceptions reported on one line (or in the status column).
  CGAL::set_error_handler(silent_cgal_handler);
  CGAL::set_warning_handler(silent_cgal_handler);
  try
  {
    return run(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::string message = e.what();
    std::replace(message.begin(), message.end(), '\n', ' ');
    std::cerr << "vtp_benchmark: error: " << message << std::endl;
    return 2;
  }
}
