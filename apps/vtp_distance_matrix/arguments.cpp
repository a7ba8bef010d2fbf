// vtp_distance_matrix: command-line arguments (one table of options, vtp_support/command_line.h, from which
// the parser and the help are made).

#include "arguments.h"
#include "tool_error.h"

#include <vtp_support/methods.h>

#include <cmath>
#include <string>
#include <vector>

namespace vtp_matrix {

namespace {

using vtp_support::parse_double;

// The methods --method accepts: the sequential ones of the table, "vtp, avtp, vsp or vsp2".
std::string sequential_method_names()
{
  std::vector<std::string> names;
  for(const vtp_support::Method_info* m = vtp_support::methods_begin(); m != vtp_support::methods_end(); ++m)
    if(!m->parallel)
      names.push_back(m->name);
  std::string s;
  for(std::size_t i = 0; i < names.size(); ++i)
    s += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ")) + names[i];
  return s;
}

// The options, in the order of the help.
const vtp_support::Option_table<Arguments> options = {
    { "--sources", "S",
      "the source vertices, one row each, in this order:\n"
      "  all        every vertex of MESH\n"
      "  A:B        the vertices A, A+1, ..., B-1\n"
      "  V,V,...    a list of vertex indices\n"
      "  FILE       a text file of vertex indices (separated by blanks, commas\n"
      "             or new lines; '#' starts a comment); write a file name that\n"
      "             looks like a number as ./NAME",
      [](Arguments& a, const std::string&, const std::string& v) {
        a.sources = v;
        if(a.sources.empty())
          throw Tool_error("empty value for --sources");
      } },
    { "--output", "FILE.h5",
      "the HDF5 file to write:\n"
      "  /sources    int64 (rows): the source vertex of each row\n"
      "  /distances  (rows, vertices) float64, inf where unreachable",
      [](Arguments& a, const std::string&, const std::string& v) {
        a.output = v;
        if(a.output.empty() || a.output == "-")
          throw Tool_error("invalid file name '" + a.output + "' for --output");
      } },
    { "--float32", nullptr, "write the distances as float32 (the float64 values rounded)",
      [](Arguments& a, const std::string&, const std::string&) { a.float32 = true; } },
    { "--max-distance", "R",
      "only distances <= R, as sparse rows: group /distances in CSR form\n"
      "(data, indices int64, indptr int64, attribute shape), the arrays of\n"
      "scipy.sparse.csr_matrix((data, indices, indptr), shape); entries\n"
      "beyond R and unreachable vertices are absent",
      vtp_support::apply_distance_limit<Arguments, &Arguments::max_distance, &Arguments::has_max_distance> },
    { "--polar", nullptr,
      "with --max-distance R: the polar patches, geodesic polar coordinates\n"
      "around each source: group /distances holds rho (as without --polar),\n"
      "group /angles theta in [0, 2 pi) (data; its indices and indptr are\n"
      "those of /distances), the log map of the library from the source\n"
      "alone (method vtp)",
      [](Arguments& a, const std::string&, const std::string&) { a.polar = true; } },
    { "--method", "vtp|avtp|vsp|vsp2",
      "exact VTP (default), approximate AVTP, or virtual source propagation\n"
      "(vsp: approximate, an upper bound, the fastest; vsp2: two virtual\n"
      "sources per vertex, half the error of vsp, 1.3-2x its time)",
      [](Arguments& a, const std::string&, const std::string& m) {
        a.method = vtp_support::find_method(m);
        if(a.method == nullptr || a.method->parallel)
          throw Tool_error("unknown method '" + m + "' (expected " + sequential_method_names() + ")");
      } },
    { "--lambda", "L", "reset period of avtp, in mean edge lengths (default 8)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.lambda = parse_double(n, v);
        if(!(a.lambda > 0.) || std::isinf(a.lambda))
          throw Tool_error("--lambda must be finite and > 0");
        a.has_lambda = true;
      } },
    { "--threads", "T", "rows computed at once on T threads (default: OpenMP's default)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.threads = static_cast<int>(vtp_support::parse_integer(n, v, 1, 4096));
      } },
    { "--resume", nullptr,
      "continue an interrupted run with the same arguments: only the missing\n"
      "rows are computed; the file is the same as that of an uninterrupted run",
      [](Arguments& a, const std::string&, const std::string&) { a.resume = true; } },
    { "--force", nullptr,
      "overwrite an existing output (it is replaced only once the new one is\n"
      "complete) and discard a partial run",
      [](Arguments& a, const std::string&, const std::string&) { a.force = true; } },
    { "--progress", nullptr,
      "print progress (rows done, rows per second, time left) on stderr, at\n"
      "most twice a second (default on a terminal)",
      [](Arguments& a, const std::string&, const std::string&) { a.progress = 1; } },
    { "--quiet", nullptr, "no progress", [](Arguments& a, const std::string&, const std::string&) { a.progress = 0; } },
    { "--help", nullptr, "print this help", [](Arguments& a, const std::string&, const std::string&) { a.help = true; } },
};

} // namespace

void print_usage(std::ostream& os)
{
  os << "usage: vtp_distance_matrix MESH --sources all|A:B|V,V,...|FILE --output FILE.h5 [options]\n"
        "\n"
        "Computes the exact (or approximate) geodesic distances from many source vertices to every\n"
        "vertex of a triangle mesh, one row per source, and writes them to an HDF5 file.\n"
        "\n";
  const std::size_t column = 22;
  vtp_support::print_help_item(os, "MESH", "mesh in OFF, OBJ or PLY format; vertices are numbered in file order", column);
  vtp_support::print_options(os, options, column);
  os << "\n"
        "The output is written as FILE.h5.part (and FILE.h5.part.journal, the rows completed so far),\n"
        "renamed to FILE.h5 once complete. Under MPI (mpirun -np N vtp_distance_matrix ...), the ranks\n"
        "share the rows and write the one file; each rank uses --threads threads.\n"
        "On any error: one line \"vtp_distance_matrix: error: ...\" on stderr and exit code 2; an\n"
        "existing complete output is never changed.\n";
}

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  a.method = vtp_support::find_method("vtp");
  vtp_support::parse_command_line(argc, argv, options, a, [](Arguments& a, const std::string& arg) {
    if(arg.empty() || arg == "-")
      throw Tool_error("invalid mesh file name '" + arg + "'");
    if(!a.mesh.empty())
      throw Tool_error("more than one mesh file given ('" + a.mesh + "' and '" + arg + "')");
    a.mesh = arg;
  });
  if(a.help)
    return a;
  if(a.mesh.empty())
    throw Tool_error("no mesh file given (see --help)");
  if(a.sources.empty())
    throw Tool_error("no --sources given (all, A:B, V,V,... or a file)");
  if(a.output.empty())
    throw Tool_error("no --output file given");
  if(a.has_lambda && !a.method->approximate)
    throw Tool_error("--lambda needs --method avtp");
  if(a.polar && !a.has_max_distance)
    throw Tool_error("--polar needs --max-distance R (the patches are sparse rows within R)");
  if(a.polar && std::string(a.method->name) != "vtp")
    throw Tool_error("--polar needs --method vtp (the log map needs the exact method)");
  if(a.resume && a.force)
    throw Tool_error("--resume and --force exclude each other");
  return a;
}

} // namespace vtp_matrix
