// vtp_distance_matrix: command-line arguments.

#include "arguments.h"
#include "tool_error.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace vtp_matrix {

void print_usage(std::ostream& os)
{
  os << "usage: vtp_distance_matrix MESH --sources all|A:B|V,V,...|FILE --output FILE.h5 [options]\n"
        "\n"
        "Computes the exact (or approximate) geodesic distances from many source vertices to every\n"
        "vertex of a triangle mesh, one row per source, and writes them to an HDF5 file.\n"
        "\n"
        "  MESH                mesh in OFF, OBJ or PLY format; vertices are numbered in file order\n"
        "  --sources S         the source vertices, one row each, in this order:\n"
        "                        all        every vertex of MESH\n"
        "                        A:B        the vertices A, A+1, ..., B-1\n"
        "                        V,V,...    a list of vertex indices\n"
        "                        FILE       a text file of vertex indices (separated by blanks, commas\n"
        "                                   or new lines; '#' starts a comment); write a file name that\n"
        "                                   looks like a number as ./NAME\n"
        "  --output FILE.h5    the HDF5 file to write:\n"
        "                        /sources    int64 (rows): the source vertex of each row\n"
        "                        /distances  (rows, vertices) float64, inf where unreachable\n"
        "  --float32           write the distances as float32 (the float64 values rounded)\n"
        "  --max-distance R    only distances <= R, as sparse rows: group /distances in CSR form\n"
        "                      (data, indices int64, indptr int64, attribute shape), the arrays of\n"
        "                      scipy.sparse.csr_matrix((data, indices, indptr), shape); entries\n"
        "                      beyond R and unreachable vertices are absent\n"
        "  --method vtp|avtp|vsp  exact VTP (default), approximate AVTP, or virtual source\n"
        "                      propagation (approximate, an upper bound, fastest)\n"
        "  --lambda L          reset period of avtp, in mean edge lengths (default 8)\n"
        "  --threads T         rows computed at once on T threads (default: OpenMP's default)\n"
        "  --resume            continue an interrupted run with the same arguments: only the missing\n"
        "                      rows are computed; the file is the same as that of an uninterrupted run\n"
        "  --force             overwrite an existing output (it is replaced only once the new one is\n"
        "                      complete) and discard a partial run\n"
        "  --progress          print progress (rows done, rows per second, time left) on stderr, at\n"
        "                      most twice a second (default on a terminal)\n"
        "  --quiet             no progress\n"
        "  --help              print this help\n"
        "\n"
        "The output is written as FILE.h5.part (and FILE.h5.part.journal, the rows completed so far),\n"
        "renamed to FILE.h5 once complete. Under MPI (mpirun -np N vtp_distance_matrix ...), the ranks\n"
        "share the rows and write the one file; each rank uses --threads threads.\n"
        "On any error: one line \"vtp_distance_matrix: error: ...\" on stderr and exit code 2; an\n"
        "existing complete output is never changed.\n";
}

namespace {

long long parse_integer(const std::string& option, const std::string& s, long long low, long long high)
{
  if(s.empty() || !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; }))
    throw Tool_error("invalid value '" + s + "' for " + option + " (expected an integer)");
  errno = 0;
  const long long v = std::strtoll(s.c_str(), nullptr, 10);
  if(errno == ERANGE || v < low || v > high)
    throw Tool_error("value '" + s + "' for " + option + " is out of range [" + std::to_string(low) + ", "
                     + std::to_string(high) + "]");
  return v;
}

double parse_double(const std::string& option, const std::string& s)
{
  const char* begin = s.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if(s.empty() || end != begin + s.size() || std::isspace(static_cast<unsigned char>(s[0])) || std::isnan(v)
     || (errno == ERANGE && std::isinf(v)))
    throw Tool_error("invalid value '" + s + "' for " + option + " (expected a number)");
  return v;
}

} // namespace

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  bool has_mesh = false, has_sources = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg.size() > 1 && arg[0] == '-')
    {
      std::string name = arg, value;
      bool inline_value = false;
      const std::string::size_type eq = arg.find('=');
      if(arg.compare(0, 2, "--") == 0 && eq != std::string::npos)
      {
        name = arg.substr(0, eq);
        value = arg.substr(eq + 1);
        inline_value = true;
      }
      auto next_value = [&]() -> std::string {
        if(inline_value)
          return value;
        if(i + 1 >= argc)
          throw Tool_error("missing value for " + name);
        return argv[++i];
      };
      auto no_value = [&]() {
        if(inline_value)
          throw Tool_error("option " + name + " takes no value");
      };

      if(name == "--help" || name == "-h") { no_value(); a.help = true; }
      else if(name == "--sources")
      {
        a.sources = next_value();
        if(a.sources.empty())
          throw Tool_error("empty value for --sources");
        has_sources = true;
      }
      else if(name == "--output")
      {
        a.output = next_value();
        if(a.output.empty() || a.output == "-")
          throw Tool_error("invalid file name '" + a.output + "' for --output");
      }
      else if(name == "--float32") { no_value(); a.float32 = true; }
      else if(name == "--max-distance")
      {
        a.max_distance = parse_double(name, next_value());
        if(!(a.max_distance >= 0.))
          throw Tool_error("--max-distance must be >= 0");
        a.has_max_distance = true;
      }
      else if(name == "--method")
      {
        const std::string m = next_value();
        a.approximate = m == "avtp";
        a.virtual_sources = m == "vsp";
        if(m != "vtp" && m != "avtp" && m != "vsp")
          throw Tool_error("unknown method '" + m + "' (expected vtp, avtp or vsp)");
      }
      else if(name == "--lambda")
      {
        a.lambda = parse_double(name, next_value());
        if(!(a.lambda > 0.) || std::isinf(a.lambda))
          throw Tool_error("--lambda must be finite and > 0");
        a.has_lambda = true;
      }
      else if(name == "--threads")
        a.threads = static_cast<int>(parse_integer(name, next_value(), 1, 4096));
      else if(name == "--resume") { no_value(); a.resume = true; }
      else if(name == "--force") { no_value(); a.force = true; }
      else if(name == "--progress") { no_value(); a.progress = 1; }
      else if(name == "--quiet") { no_value(); a.progress = 0; }
      else
        throw Tool_error("unknown option '" + arg + "' (see --help)");
    }
    else
    {
      if(arg.empty() || arg == "-")
        throw Tool_error("invalid mesh file name '" + arg + "'");
      if(has_mesh)
        throw Tool_error("more than one mesh file given ('" + a.mesh + "' and '" + arg + "')");
      a.mesh = arg;
      has_mesh = true;
    }
  }
  if(a.help)
    return a;
  if(!has_mesh)
    throw Tool_error("no mesh file given (see --help)");
  if(!has_sources)
    throw Tool_error("no --sources given (all, A:B, V,V,... or a file)");
  if(a.output.empty())
    throw Tool_error("no --output file given");
  if(a.has_lambda && !a.approximate)
    throw Tool_error("--lambda needs --method avtp");
  if(a.resume && a.force)
    throw Tool_error("--resume and --force exclude each other");
  return a;
}

} // namespace vtp_matrix
