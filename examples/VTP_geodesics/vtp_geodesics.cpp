// vtp_geodesics: command-line front end of the VTP_geodesics package.
//
//   vtp_geodesics [MESH] [--source V] [--output FILE] [--stats-json FILE|-] [--check-cgal]
//                 [--method vtp|pvtp|avtp|pavtp] [--threads T] [--lambda L] [--lambda-g G]
//
// Computes the exact geodesic distances from one source vertex to all vertices of a triangle mesh
// (OFF, OBJ or PLY) by vertex-oriented triangle propagation. Run `vtp_geodesics --help` for details.
// Polygon meshes are triangulated and invalid polygon soups repaired (one line "vtp_geodesics: note: ..."
// on stderr says what was done); the distances are always reported in the vertex order of the file.
// On any error, it prints one line "vtp_geodesics: error: ..." on stderr, creates no output file
// and exits with code 2.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/assertions_behaviour.h>
#include <CGAL/property_map.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/tools/shortest_path_reference.h>
#include <CGAL/VTP_geodesics/internal/tools/triangle_mesh_from_soup.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/stat.h> // fchmod, umask
#include <unistd.h>   // mkstemp, close

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;

namespace {

const char* const program_name = "vtp_geodesics";

// Every error of the program: reported as one line, exit code 2.
struct Usage_error : std::runtime_error
{
  explicit Usage_error(const std::string& what) : std::runtime_error(what) {}
};

void print_usage(std::ostream& os)
{
  os << "usage: vtp_geodesics [MESH] [options]\n"
        "\n"
        "Computes exact geodesic distances from one source vertex to all vertices of a triangle mesh\n"
        "by vertex-oriented triangle propagation (VTP).\n"
        "\n"
        "  MESH                 mesh in OFF, OBJ or PLY format (.off, .obj, .ply)\n"
        "                       (default: " VTP_GEODESICS_DEFAULT_MESH ")\n"
        "  --source V           index of the source vertex, in file order (default: 0)\n"
        "  --output FILE        write one distance per line, one line per vertex of MESH, in\n"
        "                       the vertex order of MESH (\"%.17g\", \"inf\" for unreachable vertices)\n"
        "  --stats-json FILE|-  write statistics as one JSON object to FILE, or to stdout with \"-\"\n"
        "  --check-cgal         also run CGAL::Surface_mesh_shortest_path from the same source and\n"
        "                       report the largest absolute and relative differences\n"
        "  --method M           vtp (exact, default), pvtp (exact, parallel), avtp (approximate),\n"
        "                       pavtp (approximate, parallel)\n"
        "  --threads T          number of threads of the parallel methods (0: OpenMP default);\n"
        "                       ignored by the sequential methods\n"
        "  --lambda L           window-reset period of avtp / pavtp, in mean edge lengths (> 0,\n"
        "                       default 8)\n"
        "  --lambda-g G         guard band of avtp / pavtp, in mean edge lengths (>= 0, default 1)\n"
        "  --help               print this help and exit\n"
        "\n"
        "Input that is not a triangle mesh is repaired, and one line \"vtp_geodesics: note: ...\"\n"
        "on stderr says what was done:\n"
        "  - faces with more than three vertices (quads, polygons) are triangulated, without\n"
        "    adding vertices;\n"
        "  - a polygon soup that is not a valid mesh (non-manifold vertices or edges, faces with\n"
        "    repeated or coincident points, duplicate faces, inconsistent orientation) is repaired\n"
        "    with CGAL::Polygon_mesh_processing::repair_polygon_soup and orient_polygon_soup:\n"
        "    coincident points are merged, degenerate and duplicate faces removed, and the surface\n"
        "    is cut at non-manifold vertices and edges, which duplicates their vertices.\n"
        "The distances are then computed on the repaired surface (a shortest path does not go from\n"
        "one side of a cut to the other) and mapped back to the vertices of the file: a duplicated\n"
        "vertex gets the smallest distance over its copies (and, as the source, all its copies are\n"
        "sources), merged points share their distance, and a vertex left in no face is unreachable\n"
        "(\"inf\"). --output always has one line per vertex of the file, in file order.\n"
        "Input that cannot be repaired (no face left, faces that cannot be triangulated, bad\n"
        "indices, non-finite coordinates) is refused.\n"
        "\n"
        "Without --output and --stats-json, a short summary is printed. On error, one line\n"
        "\"vtp_geodesics: error: ...\" is printed on stderr, no output file is written, and the\n"
        "exit code is 2.\n";
}

// ------------------------------------------------------------------------------------------------
// Methods. Each entry says how the method runs; the lead wires pvtp / avtp / pavtp later.
// ------------------------------------------------------------------------------------------------
struct Method_info
{
  const char* name;
  bool parallel;     // CGAL::Parallel_tag scheduling (uses --threads)
  bool approximate;  // window resets (uses --lambda / --lambda-g)
  bool available;
};

#ifdef _OPENMP
const bool parallel_available = true;
#else
const bool parallel_available = false; // built without OpenMP
#endif

const Method_info methods[] = {
  { "vtp",   false, false, true  },
  { "pvtp",  true,  false, parallel_available },
  { "avtp",  false, true,  true  },
  { "pavtp", true,  true,  parallel_available },
};

const Method_info& find_method(const std::string& name)
{
  for(const Method_info& m : methods)
    if(name == m.name)
      return m;
  throw Usage_error("unknown method '" + name + "' (expected vtp, pvtp, avtp or pavtp)");
}

// Runs `method` from `sources` and returns its statistics; the distances stay in the solver.
template <class NamedParameters>
const CGAL::VTP_geodesics::Propagation_statistics&
run_method(const Method_info& method, Solver& solver, const std::vector<Vertex_index>& sources,
           const NamedParameters& np)
{
  if(!method.parallel)
  {
    solver.compute<CGAL::Sequential_tag>(CGAL::Constant_property_map<Vertex_index, double>(), sources, np);
    return solver.statistics();
  }
#ifdef _OPENMP
  solver.compute<CGAL::Parallel_tag>(CGAL::Constant_property_map<Vertex_index, double>(), sources, np);
  return solver.statistics();
#else
  throw Usage_error(std::string("method ") + method.name + " needs OpenMP, and this program was built without it");
#endif
}

// ------------------------------------------------------------------------------------------------
// Command line
// ------------------------------------------------------------------------------------------------
struct Arguments
{
  std::string mesh = VTP_GEODESICS_DEFAULT_MESH;
  std::size_t source = 0;
  std::string output;       // empty: none
  std::string stats_json;   // empty: none; "-": stdout
  bool check_cgal = false;
  std::string method = "vtp";
  int threads = 0;
  bool has_threads = false;
  double lambda = std::numeric_limits<double>::infinity();
  bool has_lambda = false;
  double lambda_g = 1.0;
  bool has_lambda_g = false;
  bool help = false;
};

std::size_t parse_index(const std::string& option, const std::string& s)
{
  if(s.empty() || !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; }))
    throw Usage_error("invalid value '" + s + "' for " + option + " (expected a non-negative integer)");
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if(errno == ERANGE || v > static_cast<unsigned long long>(std::numeric_limits<std::size_t>::max()))
    throw Usage_error("value '" + s + "' for " + option + " is too large");
  return static_cast<std::size_t>(v);
}

double parse_double(const std::string& option, const std::string& s)
{
  const char* begin = s.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if(s.empty() || end != begin + s.size() || std::isspace(static_cast<unsigned char>(s[0])) || std::isnan(v)
     || (errno == ERANGE && std::isinf(v)))
    throw Usage_error("invalid value '" + s + "' for " + option + " (expected a number)");
  return v;
}

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  bool has_mesh = false;
  for(int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    if(arg.size() > 1 && arg[0] == '-')
    {
      // "--name=value" or "--name value"
      std::string name = arg, value;
      bool has_inline_value = false;
      const std::string::size_type eq = arg.find('=');
      if(arg.compare(0, 2, "--") == 0 && eq != std::string::npos)
      {
        name = arg.substr(0, eq);
        value = arg.substr(eq + 1);
        has_inline_value = true;
      }
      auto next_value = [&]() -> std::string {
        if(has_inline_value)
          return value;
        if(i + 1 >= argc)
          throw Usage_error("missing value for " + name);
        return argv[++i];
      };
      auto no_value = [&]() {
        if(has_inline_value)
          throw Usage_error("option " + name + " takes no value");
      };

      if(name == "--help" || name == "-h") { no_value(); a.help = true; }
      else if(name == "--source") a.source = parse_index(name, next_value());
      else if(name == "--output")
      {
        a.output = next_value();
        if(a.output.empty() || a.output == "-")
          throw Usage_error("invalid file name '" + a.output + "' for --output");
      }
      else if(name == "--stats-json")
      {
        a.stats_json = next_value();
        if(a.stats_json.empty())
          throw Usage_error("empty file name for --stats-json");
      }
      else if(name == "--check-cgal") { no_value(); a.check_cgal = true; }
      else if(name == "--method") a.method = next_value();
      else if(name == "--threads")
      {
        const std::size_t t = parse_index(name, next_value());
        if(t > 4096)
          throw Usage_error("too many threads for --threads");
        a.threads = static_cast<int>(t);
        a.has_threads = true;
      }
      else if(name == "--lambda")
      {
        a.lambda = parse_double(name, next_value());
        if(!(a.lambda > 0.))
          throw Usage_error("--lambda must be > 0");
        a.has_lambda = true;
      }
      else if(name == "--lambda-g")
      {
        a.lambda_g = parse_double(name, next_value());
        if(!(a.lambda_g >= 0.) || std::isinf(a.lambda_g))
          throw Usage_error("--lambda-g must be finite and >= 0");
        a.has_lambda_g = true;
      }
      else
        throw Usage_error("unknown option '" + arg + "' (see --help)");
    }
    else
    {
      if(arg.empty() || arg == "-")
        throw Usage_error("invalid mesh file name '" + arg + "'");
      if(has_mesh)
        throw Usage_error("more than one mesh file given ('" + a.mesh + "' and '" + arg + "')");
      a.mesh = arg;
      has_mesh = true;
    }
  }

  if(a.help)
    return a;
  const Method_info& m = find_method(a.method);
  if((a.has_lambda || a.has_lambda_g) && !m.approximate)
    throw Usage_error("--lambda and --lambda-g need --method avtp or pavtp");
  if(!a.output.empty() && a.output == a.stats_json)
    throw Usage_error("--output and --stats-json must name different files");
  return a;
}

// ------------------------------------------------------------------------------------------------
// Input
// ------------------------------------------------------------------------------------------------
std::string lower_extension(const std::string& file)
{
  const std::string::size_type dot = file.find_last_of('.');
  const std::string::size_type slash = file.find_last_of('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = file.substr(dot + 1);
  for(char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The mesh of the computation, and which of its vertices stand for each vertex of the file.
struct Input_mesh
{
  Mesh mesh;
  std::size_t file_vertices = 0, file_faces = 0;
  std::vector<std::size_t> copy_begin;  // copies of file vertex i: copies[copy_begin[i] .. copy_begin[i+1])
  std::vector<Vertex_index> copies;
  CGAL::VTP_geodesics::internal::Soup_repair_report repairs;
};

// Reads `file` as a polygon soup and makes a triangle mesh of it (see triangle_mesh_from_soup.h).
void read_mesh(const std::string& file, Input_mesh& input)
{
  const std::string ext = lower_extension(file);
  if(ext != "off" && ext != "obj" && ext != "ply")
    throw Usage_error("cannot read '" + file + "': unsupported file extension (expected .off, .obj or .ply)");
  {
    std::ifstream probe(file, std::ios::binary);
    if(!probe)
      throw Usage_error("cannot open '" + file + "'");
    char c;
    if(!probe.get(c))
      throw Usage_error("cannot read '" + file + "': empty or unreadable file");
  }

  // CGAL's readers may print diagnostics on std::cerr: keep them out of the one-line error.
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::ostringstream diagnostics;
  std::streambuf* const cerr_buffer = std::cerr.rdbuf(diagnostics.rdbuf());
  bool ok = false;
  try
  {
    if(ext == "off")
      ok = CGAL::IO::read_OFF(file, points, polygons);
    else if(ext == "obj")
      ok = CGAL::IO::read_OBJ(file, points, polygons);
    else
      ok = CGAL::IO::read_PLY(file, points, polygons);
  }
  catch(...)
  {
    std::cerr.rdbuf(cerr_buffer);
    throw Usage_error("cannot read '" + file + "': invalid or unsupported mesh data");
  }
  std::cerr.rdbuf(cerr_buffer);
  if(!ok)
    throw Usage_error("cannot read '" + file + "': invalid or unsupported mesh data");

  input.file_vertices = points.size();
  input.file_faces = polygons.size();
  try
  {
    input.repairs = CGAL::VTP_geodesics::internal::triangle_mesh_from_soup(
      std::move(points), std::move(polygons), input.mesh, input.copy_begin, input.copies);
  }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e)
  {
    throw Usage_error("cannot use '" + file + "': " + e.what());
  }
}

// ------------------------------------------------------------------------------------------------
// Output: written to a temporary file next to the target, then renamed.
// ------------------------------------------------------------------------------------------------
class Temporary_file
{
public:
  explicit Temporary_file(const std::string& target) : m_target(target)
  {
    std::string pattern = target + ".tmp.XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = mkstemp(name.data());
    if(fd < 0)
      throw Usage_error("cannot create a file next to '" + target + "': " + std::strerror(errno));
    m_name = name.data();
    // mkstemp() creates the file with mode 0600: give it the usual mode of a new file.
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, static_cast<mode_t>(0666) & ~mask);
    m_file = fdopen(fd, "w");
    if(m_file == nullptr)
    {
      close(fd);
      std::remove(m_name.c_str());
      throw Usage_error("cannot write '" + target + "'");
    }
  }
  Temporary_file(const Temporary_file&) = delete;
  Temporary_file& operator=(const Temporary_file&) = delete;
  ~Temporary_file()
  {
    if(m_file != nullptr)
      std::fclose(m_file);
    if(!m_committed)
      std::remove(m_name.c_str());
  }

  std::FILE* stream() const { return m_file; }

  // Flushes and closes the temporary file; throws if anything failed.
  void close_file()
  {
    const bool failed = std::ferror(m_file) != 0;
    const bool close_failed = std::fclose(m_file) != 0;
    m_file = nullptr;
    if(failed || close_failed)
      throw Usage_error("cannot write '" + m_target + "'");
  }

  // Renames the temporary file to its target.
  void commit()
  {
    if(std::rename(m_name.c_str(), m_target.c_str()) != 0)
      throw Usage_error("cannot write '" + m_target + "': " + std::strerror(errno));
    m_committed = true;
  }

  const std::string& target() const { return m_target; }

private:
  std::string m_target;
  std::string m_name;
  std::FILE* m_file = nullptr;
  bool m_committed = false;
};

void write_distances(std::FILE* f, const std::vector<double>& d)
{
  for(double x : d)
  {
    if(std::isinf(x))
      std::fputs(x > 0 ? "inf\n" : "-inf\n", f);
    else
      std::fprintf(f, "%.17g\n", x);
  }
}

std::string json_string(const std::string& s)
{
  std::string r = "\"";
  for(unsigned char c : s)
  {
    if(c == '"') r += "\\\"";
    else if(c == '\\') r += "\\\\";
    else if(c < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\u%04x", static_cast<unsigned>(c));
      r += buffer;
    }
    else r += static_cast<char>(c);
  }
  return r + "\"";
}

std::string json_number(double x)
{
  if(!std::isfinite(x))
    return "null";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.17g", x);
  return buffer;
}

struct Report
{
  std::string mesh;
  std::size_t vertices = 0, faces = 0, source = 0, reached_vertices = 0; // vertices and faces of the file
  std::size_t mesh_vertices = 0, mesh_faces = 0;                         // of the (repaired) triangle mesh
  std::string repairs;                                                   // empty if none
  double max_distance = 0.;
  double preprocessing_seconds = 0., mean_edge_length = 0., anisotropy = 0.;
  CGAL::VTP_geodesics::Propagation_statistics stats;
  bool checked = false;
  double cgal_seconds = 0.;
  CGAL::VTP_geodesics::internal::Distance_comparison comparison;
};

std::string stats_json(const Report& r)
{
  std::ostringstream os;
  os << "{"
     << "\"mesh\": " << json_string(r.mesh)
     << ", \"vertices\": " << r.vertices
     << ", \"faces\": " << r.faces
     << ", \"mesh_vertices\": " << r.mesh_vertices
     << ", \"mesh_faces\": " << r.mesh_faces
     << ", \"repairs\": " << json_string(r.repairs)
     << ", \"source\": " << r.source
     << ", \"method\": " << json_string(r.stats.method)
     << ", \"threads\": " << r.stats.threads
     << ", \"seconds\": " << json_number(r.stats.seconds)
     << ", \"preprocessing_seconds\": " << json_number(r.preprocessing_seconds)
     << ", \"windows_created\": " << r.stats.windows_created
     << ", \"windows_propagated\": " << r.stats.windows_propagated
     << ", \"peak_live_windows\": " << r.stats.peak_live_windows
     << ", \"peak_window_bytes\": " << r.stats.peak_window_bytes
     << ", \"vertices_processed\": " << r.stats.vertices_processed
     << ", \"pseudo_sources\": " << r.stats.pseudo_sources
     << ", \"resets\": " << r.stats.resets
     << ", \"reached_vertices\": " << r.reached_vertices
     << ", \"max_distance\": " << json_number(r.max_distance)
     << ", \"mean_edge_length\": " << json_number(r.mean_edge_length)
     << ", \"anisotropy\": " << json_number(r.anisotropy);
  if(r.checked)
    os << ", \"cgal_seconds\": " << json_number(r.cgal_seconds)
       << ", \"max_abs_diff\": " << json_number(r.comparison.max_abs_diff)
       << ", \"max_rel_diff\": " << json_number(r.comparison.max_rel_diff)
       << ", \"mean_rel_diff\": " << json_number(r.comparison.mean_rel_diff)
       << ", \"mismatched_infinities\": " << r.comparison.mismatched_infinities;
  os << "}\n";
  return os.str();
}

int run(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv);
  if(args.help)
  {
    print_usage(std::cout);
    return 0;
  }
  const Method_info& method = find_method(args.method);
  if(!method.available)
    throw Usage_error(std::string("method ") + method.name + " needs OpenMP, and this program was built without it");

  Input_mesh input;
  read_mesh(args.mesh, input);
  const Mesh& mesh = input.mesh;
  if(args.source >= input.file_vertices)
    throw Usage_error("source vertex " + std::to_string(args.source) + " is out of range (the mesh has "
                      + std::to_string(input.file_vertices) + " vertices)");
  // The vertices of the mesh standing for the source: one, several if the repair duplicated it (then
  // all are sources: the distances are the minimum over them), none if the repair removed it (a vertex
  // in no face: only the source itself is reachable).
  const std::vector<Vertex_index> sources(input.copies.begin() + std::ptrdiff_t(input.copy_begin[args.source]),
                                          input.copies.begin() + std::ptrdiff_t(input.copy_begin[args.source + 1]));

  const double lambda = !method.approximate ? std::numeric_limits<double>::infinity()
                       : (args.has_lambda ? args.lambda : CGAL::VTP_geodesics::recommended_lambda);
  const auto options = CGAL::VTP_geodesics::parameters::number_of_threads(args.threads)
                         .lambda(lambda).lambda_g(args.lambda_g);

  Solver solver(mesh);
  Report report;
  report.mesh = args.mesh;
  report.vertices = input.file_vertices;
  report.faces = input.file_faces;
  report.mesh_vertices = solver.number_of_vertices();
  report.mesh_faces = solver.number_of_faces();
  report.repairs = input.repairs.summary();
  report.source = args.source;
  report.preprocessing_seconds = solver.preprocessing_seconds();
  report.mean_edge_length = solver.mean_edge_length();
  report.anisotropy = solver.anisotropy();
  report.stats.method = method.name;

  // Distances per mesh vertex (the solver numbers them in the order of vertices(mesh)), from all the copies
  // of the source at once; then per vertex of the file.
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> mesh_distances(solver.number_of_vertices(), infinity);
  if(!sources.empty())
  {
    report.stats = run_method(method, solver, sources, options);
    mesh_distances = solver.distances();
  }
  auto on_file_vertices = [&](const std::vector<double>& per_mesh_vertex) {
    std::vector<double> r = CGAL::VTP_geodesics::internal::values_on_soup_points(
      input.copy_begin, input.copies, [&](Vertex_index v) { return per_mesh_vertex[std::size_t(v)]; });
    r[args.source] = 0.;
    return r;
  };
  const std::vector<double> distances = on_file_vertices(mesh_distances);
  for(double d : distances)
    if(std::isfinite(d))
    {
      ++report.reached_vertices;
      report.max_distance = (std::max)(report.max_distance, d);
    }

  if(args.check_cgal)
  {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<double> reference(mesh.number_of_vertices(), infinity);
    for(Vertex_index s : sources)
    {
      const std::vector<double> r = CGAL::VTP_geodesics::internal::shortest_path_reference_distances(mesh, s);
      for(std::size_t j = 0; j < reference.size(); ++j)
        reference[j] = (std::min)(reference[j], r[j]);
    }
    report.cgal_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    report.comparison = CGAL::VTP_geodesics::internal::compare_distances(distances, on_file_vertices(reference));
    report.checked = true;
  }

  // Write everything to temporary files first, then rename: no partial output on error.
  std::unique_ptr<Temporary_file> output_file, json_file;
  if(!args.output.empty())
  {
    output_file.reset(new Temporary_file(args.output));
    write_distances(output_file->stream(), distances);
    output_file->close_file();
  }
  const std::string json = args.stats_json.empty() ? std::string() : stats_json(report);
  if(!args.stats_json.empty() && args.stats_json != "-")
  {
    json_file.reset(new Temporary_file(args.stats_json));
    std::fputs(json.c_str(), json_file->stream());
    json_file->close_file();
  }
  if(output_file)
    output_file->commit();
  if(json_file)
  {
    try { json_file->commit(); }
    catch(...)
    {
      if(output_file)
        std::remove(output_file->target().c_str());
      throw;
    }
  }

  const bool json_on_stdout = (args.stats_json == "-");
  if(json_on_stdout)
    std::cout << json << std::flush;
  if(args.output.empty() && args.stats_json.empty())
  {
    std::cout << "mesh: " << args.mesh << "\n"
              << "vertices: " << report.vertices << ", faces: " << report.faces << ", source: " << report.source
              << "\n"
              << "method: " << report.stats.method << ", propagation: " << report.stats.seconds
              << " s, preprocessing: " << report.preprocessing_seconds << " s\n"
              << "max distance: " << report.max_distance << " (" << report.reached_vertices << " of "
              << report.vertices << " vertices reached)\n"
              << "windows: " << report.stats.windows_created << " created, " << report.stats.windows_propagated
              << " propagated, peak " << report.stats.peak_live_windows << " alive ("
              << report.stats.peak_window_bytes << " bytes)\n";
    if(!report.repairs.empty())
      std::cout << "triangle mesh: " << report.mesh_vertices << " vertices, " << report.mesh_faces << " faces\n";
  }
  if(report.checked && !json_on_stdout)
  {
    std::cout << "CGAL Surface_mesh_shortest_path: " << report.cgal_seconds << " s, max abs diff "
              << report.comparison.max_abs_diff << ", max rel diff " << report.comparison.max_rel_diff;
    if(report.comparison.mismatched_infinities != 0)
      std::cout << ", " << report.comparison.mismatched_infinities << " reachability mismatches";
    std::cout << "\n";
  }
  std::cout.flush();
  if(!std::cout)
    throw Usage_error("cannot write to stdout");
  if(!report.repairs.empty())
    std::cerr << program_name << ": note: " << report.repairs << std::endl;
  return 0;
}

int fail(std::string message)
{
  // Keep the report on one line (CGAL's exception messages span several lines).
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::cerr << program_name << ": error: " << message << std::endl;
  return 2;
}

void silent_cgal_handler(const char*, const char*, const char*, int, const char*) {}

} // namespace

int main(int argc, char** argv)
{
  // CGAL's default handlers print several lines on std::cerr before throwing; the exceptions
  // are caught below and reported on one line instead.
  CGAL::set_error_handler(silent_cgal_handler);
  CGAL::set_warning_handler(silent_cgal_handler);
  try
  {
    return run(argc, argv);
  }
  catch(const Usage_error& e) { return fail(e.what()); }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e) { return fail(e.what()); }
  catch(const std::bad_alloc&) { return fail("out of memory"); }
  catch(const std::exception& e) { return fail(e.what()); }
  catch(...) { return fail("unknown error"); }
}
