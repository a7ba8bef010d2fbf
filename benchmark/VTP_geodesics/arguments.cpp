// vtp_benchmark: the command line.

#include "vtp_benchmark.h"

#include <cerrno>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

namespace vtp_benchmark {

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

namespace {

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

} // namespace

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

} // namespace vtp_benchmark
