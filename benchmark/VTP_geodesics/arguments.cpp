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
        "Inputs (applied in this order; the mesh label gets /rR, /LN, /sN, /morton):\n"
        "  --remesh R       isotropic remeshing (CGAL::Polygon_mesh_processing::isotropic_remeshing) at a\n"
        "                   target edge length of R times the mean edge length of the input (e.g. 0.25\n"
        "                   gives about 16x more vertices)\n"
        "  --remesh-iterations K  iterations of the remeshing (default 3)\n"
        "  --loop N         Loop subdivision (CGAL::Subdivision_method_3::Loop_subdivision), N steps (x4 each)\n"
        "  --subdivide N    1-to-4 midpoint subdivision, N times: every new vertex is flat (angle sum\n"
        "                   360 degrees), so few vertices are saddles: the easy case for VTP\n"
        "  --morton         renumber the vertices along a Morton (Z-order) curve of their positions and\n"
        "                   the faces by their least vertex, vertex 0 staying vertex 0: neighbours close\n"
        "                   in memory, as in many scans (CGAL's subdivisions and remeshings number new\n"
        "                   vertices far from their neighbours)\n"
        "  --save-meshes DIR  write each (generated) mesh as DIR/<label>.off, vertices in index order\n"
        "\n"
        "Methods and output:\n"
        "  --sources K      number of source vertices per mesh: vertex 0 and evenly spaced ids (default 1)\n"
        "  --methods LIST   comma-separated methods (default vtp,cgal):\n"
        "                     vtp       exact VTP (this package)\n"
        "                     cgal      CGAL::Surface_mesh_shortest_path (exact)\n"
        "                     heat      CGAL::Heat_method_3, Direct (approximate, needs Eigen)\n"
        "                     heat_idt  CGAL::Heat_method_3, Intrinsic_Delaunay (approximate, needs Eigen)\n"
        "                     pvtp:T    exact VTP on T threads\n"
        "                     avtp:lambda, pavtp:T:lambda  AVTP (approximate, resets every lambda mean edges)\n"
        "                     vsp, pvsp:T  one virtual source per vertex (approximate, an upper bound)\n"
        "                     vsp2, pvsp2:T  two virtual sources per vertex (about half the error of vsp)\n"
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

using vtp_support::parse_integer;

// What the options set: the arguments, and the method lists checked once the whole line is read.
struct Parsed
{
  Arguments a;
  std::string methods = "vtp,cgal";
  std::vector<Method> externals;
};

// The help is print_usage() above (it has sections), so the entries have none.
const vtp_support::Option_table<Parsed>& option_table()
{
  typedef const std::string& S;
  static const vtp_support::Option_table<Parsed> table = {
    { "--help", nullptr, nullptr, [](Parsed& p, S, S) { p.a.help = true; } },
    { "--morton", nullptr, nullptr, [](Parsed& p, S, S) { p.a.morton = true; } },
    { "--subdivide", "N", nullptr, [](Parsed& p, S n, S v) { p.a.subdivide = static_cast<int>(parse_integer(n, v, 0, 6)); } },
    { "--loop", "N", nullptr, [](Parsed& p, S n, S v) { p.a.loop = static_cast<int>(parse_integer(n, v, 0, 6)); } },
    { "--remesh", "R", nullptr,
      [](Parsed& p, S, S v) {
        char* end = nullptr;
        p.a.remesh = std::strtod(v.c_str(), &end);
        if(v.empty() || *end != '\0' || !(p.a.remesh >= 0.01) || !(p.a.remesh <= 100.))
          throw Tool_error("invalid value '" + v + "' for --remesh (expected a number in [0.01, 100])");
      } },
    { "--remesh-iterations", "K", nullptr,
      [](Parsed& p, S n, S v) { p.a.remesh_iterations = static_cast<int>(parse_integer(n, v, 1, 100)); } },
    { "--save-meshes", "DIR", nullptr,
      [](Parsed& p, S, S v) {
        p.a.save_meshes = v;
        if(p.a.save_meshes.empty())
          throw Tool_error("empty folder name for --save-meshes");
      } },
    { "--external", "NAME=COMMAND", nullptr,
      [](Parsed& p, S, S v) {
        const std::string::size_type eq = v.find('=');
        if(eq == std::string::npos || eq == 0 || eq + 1 == v.size())
          throw Tool_error("invalid --external '" + v + "' (expected NAME=COMMAND)");
        Method m;
        m.label = v.substr(0, eq);
        m.kind = Method_kind::EXTERNAL;
        m.command = v.substr(eq + 1);
        if(m.label.find_first_of(",: ") != std::string::npos)
          throw Tool_error("invalid external method name '" + m.label + "'");
        p.externals.push_back(m);
      } },
    { "--sources", "K", nullptr, [](Parsed& p, S n, S v) { p.a.sources = parse_integer(n, v, 1, 1000000); } },
    { "--methods", "LIST", nullptr, [](Parsed& p, S, S v) { p.methods = v; } },
    { "--csv", "FILE", nullptr,
      [](Parsed& p, S, S v) {
        p.a.csv = v;
        if(p.a.csv.empty())
          throw Tool_error("empty file name for --csv");
      } },
    { "--repeat", "R", nullptr, [](Parsed& p, S n, S v) { p.a.repeat = static_cast<int>(parse_integer(n, v, 1, 1000)); } },
  };
  return table;
}

} // namespace

Arguments parse_arguments(int argc, char** argv)
{
  Parsed p;
  vtp_support::parse_command_line(argc, argv, option_table(), p,
                                  [](Parsed& p, const std::string& mesh) { p.a.meshes.push_back(mesh); });
  Arguments& a = p.a;
  const std::string& methods = p.methods;
  const std::vector<Method>& externals = p.externals;
  if(a.help)
    return a;
  if(a.meshes.empty())
    throw Tool_error("no mesh given (see --help)");
  for(const std::string& spec : split(methods, ','))
  {
    if(spec.empty())
      throw Tool_error("empty method name in --methods '" + methods + "'");
    Method m = parse_method(spec);
    for(const Method& other : a.methods)
      if(other.label == m.label)
        throw Tool_error("method '" + spec + "' given twice");
    a.methods.push_back(m);
  }
  for(const Method& m : externals)
  {
    for(const Method& other : a.methods)
      if(other.label == m.label)
        throw Tool_error("method '" + m.label + "' given twice");
    a.methods.push_back(m);
  }
  return a;
}

} // namespace vtp_benchmark
