// vtp_path_check: the paths of every method on mesh files. For each mesh, each method and each source vertex, one
// run that records the paths, then the path of every reached vertex (or of an evenly spaced sample of them):
// the query must not throw, the path must start at the vertex and end at the source, and its length must be
// the vertex's distance within --tolerance of it (relative). This is the promise that every distance is the
// length of a path that can be returned, checked on real meshes (vtp_stress and the fuzzer check it on random
// ones).
//
//   vtp_path_check MESH... [--methods M,...] [--sources V,...] [--paths N] [--threads T] [--lambda L]
//                  [--tolerance E]
//
// The meshes are read as the tool vtp_geodesics reads them (repaired if needed; the sources are file vertices,
// taken at their first copy). It prints one line per mesh and method (runs, paths, queries that threw, paths of
// another length, the largest relative difference |length - d| / d and where) and exits with 1 if any path
// failed, 2 on a usage error or a mesh that cannot be read (the other meshes are checked).

#include <CGAL/VTP_geodesics.h>
#include <CGAL/property_map.h>
#include <vtp_support/command_line.h>
#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <iostream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using vtp_support::Mesh;
using vtp_support::Point_3;
using vtp_support::Vertex_index;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
// a distance map that discards what is written (the distances are read from the solver)
typedef CGAL::Constant_property_map<Vertex_index, double> Discard_map;

struct Settings
{
  std::vector<std::string> meshes;
  std::vector<const vtp_support::Method_info*> methods;
  std::vector<std::size_t> sources;  // empty: the first, middle and last vertices of each file
  std::size_t paths = 0;  // 0: every reached vertex
  int threads = 2;
  double lambda = vtp_support::default_lambda;
  double tolerance = 1e-9;
  bool help = false;
};

struct Counts
{
  std::size_t runs = 0, paths = 0, throwing = 0, wrong = 0;
  double worst = 0.;  // the largest |length - d| / d
  std::string worst_where, first_failure;
  double seconds = 0.;  // the runs and the queries
};

// The paths of the run just made by `solver` from s, into `counts`.
void check_paths(const Settings& settings, const Mesh& mesh, Solver& solver, Vertex_index s, std::size_t file_source,
                 Counts& counts)
{
  const std::vector<double>& d = solver.distances();
  const std::size_t n = d.size();
  const std::size_t step = settings.paths == 0 || settings.paths >= n ? 1 : (n + settings.paths - 1) / settings.paths;
  std::vector<Point_3> path;
  for(std::size_t i = 0; i < n; i += step)
  {
    if(!std::isfinite(d[i]))
      continue;
    const Vertex_index v(static_cast<Mesh::size_type>(i));
    ++counts.paths;
    std::ostringstream where;
    where.precision(17);
    where << "source " << file_source << ", mesh vertex " << i << " (distance " << d[i] << ")";
    path.clear();
    try
    {
      solver.shortest_path_points(v, std::back_inserter(path));
    }
    catch(const std::exception& e)
    {
      ++counts.throwing;
      if(counts.first_failure.empty())
        counts.first_failure = where.str() + ": " + e.what();
      continue;
    }
    double length = 0.;
    for(std::size_t k = 1; k < path.size(); ++k)
      length += std::sqrt(CGAL::squared_distance(path[k - 1], path[k]));
    const double error = std::abs(length - d[i]);
    const double relative = d[i] > 0. ? error / d[i] : error;
    if(relative > counts.worst)
    {
      counts.worst = relative;
      counts.worst_where = where.str();
    }
    if(path.empty() || path.front() != mesh.point(v) || path.back() != mesh.point(s)
       || !(relative <= settings.tolerance))
    {
      ++counts.wrong;
      if(counts.first_failure.empty())
      {
        std::ostringstream f;
        f.precision(17);
        f << where.str() << ": " << path.size() << " points, length " << length << " (relative difference "
          << relative << ")";
        counts.first_failure = f.str();
      }
    }
  }
}

bool check_mesh(const Settings& settings, const std::string& file)
{
  vtp_support::Input_mesh input;
  vtp_support::read_input_mesh(file, input, settings.threads);
  const Mesh& mesh = input.mesh;
  // the default sources: the first, middle and last file vertices, or the next (else the previous) one the mesh
  // has (a repair can remove a vertex)
  std::vector<std::size_t> file_sources = settings.sources;
  if(file_sources.empty())
    for(std::size_t f : { std::size_t(0), input.file_vertices / 2, input.file_vertices - 1 })
    {
      std::size_t g = f;
      while(g < input.file_vertices && input.mesh_vertices_of(g).empty())
        ++g;
      while(g == input.file_vertices && f > 0 && input.mesh_vertices_of(f).empty())
        --f;
      g = g < input.file_vertices ? g : f;
      if(std::find(file_sources.begin(), file_sources.end(), g) == file_sources.end())
        file_sources.push_back(g);
    }
  std::vector<Vertex_index> sources;
  for(std::size_t f : file_sources)
  {
    if(f >= input.file_vertices || input.mesh_vertices_of(f).empty())
      throw vtp_support::Input_error(file + ": no source vertex " + std::to_string(f) + " in the mesh");
    sources.push_back(input.mesh_vertices_of(f).front());
  }
  Solver solver(mesh, CGAL::VTP_geodesics::parameters::number_of_threads(settings.threads));
  std::cout << "vtp_path_check: " << file << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces" << (input.direct ? "" : " (repaired)") << std::endl;
  bool ok = true;
  for(const vtp_support::Method_info* m : settings.methods)
  {
    Counts counts;
    const auto t0 = std::chrono::steady_clock::now();
    for(std::size_t k = 0; k < sources.size(); ++k)
    {
      vtp_support::with_method(*m, settings.lambda, settings.threads, [&](auto tag, const auto& np) {
        solver.compute<decltype(tag)>(Discard_map(), sources[k], np.record_paths(true));
      });
      ++counts.runs;
      check_paths(settings, mesh, solver, sources[k], file_sources[k], counts);
    }
    counts.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const bool failed = counts.throwing != 0 || counts.wrong != 0;
    ok = ok && !failed;
    std::cout << "vtp_path_check: " << file << ": " << m->name << ": " << counts.runs << " runs, " << counts.paths
              << " paths, " << counts.throwing << " throwing, " << counts.wrong << " not of the length of the distance"
              << " (within " << settings.tolerance << "), largest |length - d| / d " << counts.worst;
    if(!counts.worst_where.empty())
      std::cout << " (" << counts.worst_where << ")";
    std::cout << ", " << counts.seconds << " s" << std::endl;
    if(failed)
      std::cout << "vtp_path_check: FAILED " << file << ": " << m->name << ": first failure: " << counts.first_failure
                << std::endl;
  }
  return ok;
}

void usage(std::ostream& os)
{
  os << "usage: vtp_path_check MESH... [--methods M,...] [--sources V,...] [--paths N] [--threads T]\n"
        "                      [--lambda L] [--tolerance E]\n"
        "\n"
        "Checks the path of every reached vertex of runs that record the paths: no query throws, each path\n"
        "goes from the vertex to the source and has the length of the vertex's distance.\n"
        "  --methods M    comma-separated among "
     << vtp_support::method_names(", ")
     << " (default: all that this\n"
        "                 program can run)\n"
        "  --sources V    source vertices (file order), one run each (default: the first, middle and\n"
        "                 last vertices of each file)\n"
        "  --paths N      check about N paths per run, evenly spaced (default 0: every reached vertex)\n"
        "  --threads T    threads of the parallel methods and of the preprocessing (default 2)\n"
        "  --lambda L     reset period of avtp and pavtp (default: the library's recommendation)\n"
        "  --tolerance E  largest relative difference of a path's length and its distance (default 1e-9)\n";
}

const vtp_support::Option_table<Settings>& option_table()
{
  typedef const std::string& S;
  static const vtp_support::Option_table<Settings> table = {
    { "--methods", "M", nullptr,
      [](Settings& s, S, S v) {
        s.methods.clear();
        for(const std::string& name : vtp_support::split(v, ','))
        {
          const vtp_support::Method_info* m = vtp_support::find_method(name);
          if(m == nullptr)
            throw vtp_support::Tool_error("unknown method '" + name + "' (expected " + vtp_support::method_names() + ")");
          if(!vtp_support::method_available(*m))
            throw vtp_support::Tool_error(name + " needs OpenMP, and this program was built without it");
          s.methods.push_back(m);
        }
      } },
    { "--sources", "V", nullptr,
      [](Settings& s, S o, S v) {
        s.sources.clear();
        for(const std::string& x : vtp_support::split(v, ','))
          s.sources.push_back(vtp_support::parse_index(o, x));
      } },
    { "--paths", "N", nullptr, [](Settings& s, S o, S v) { s.paths = std::size_t(vtp_support::parse_integer(o, v, 0, 1u << 31)); } },
    { "--threads", "T", nullptr, [](Settings& s, S o, S v) { s.threads = int(vtp_support::parse_integer(o, v, 1, 1024)); } },
    { "--lambda", "L", nullptr, [](Settings& s, S o, S v) { s.lambda = vtp_support::parse_double(o, v); } },
    { "--tolerance", "E", nullptr, [](Settings& s, S o, S v) { s.tolerance = vtp_support::parse_double(o, v); } },
    { "--help", nullptr, nullptr, [](Settings& s, S, S) { s.help = true; } },
  };
  return table;
}

} // namespace

int main(int argc, char** argv)
{
  Settings settings;
  try
  {
    vtp_support::parse_command_line(argc, argv, option_table(), settings,
                                    [](Settings& s, const std::string& a) { s.meshes.push_back(a); });
    if(settings.help)
    {
      usage(std::cout);
      return 0;
    }
    if(settings.meshes.empty())
      throw vtp_support::Tool_error("no mesh given");
    if(settings.methods.empty())
      for(const vtp_support::Method_info* m = vtp_support::methods_begin(); m != vtp_support::methods_end(); ++m)
        if(vtp_support::method_available(*m))
          settings.methods.push_back(m);
  }
  catch(const std::exception& e)
  {
    std::cerr << "vtp_path_check: error: " << e.what() << std::endl;
    usage(std::cerr);
    return 2;
  }
  // each mesh, whatever happens to the others
  int status = 0;
  for(const std::string& file : settings.meshes)
    try
    {
      if(!check_mesh(settings, file))
        status = (std::max)(status, 1);
    }
    catch(const std::exception& e)
    {
      std::cout << "vtp_path_check: ERROR " << file << ": " << e.what() << std::endl;
      status = 2;
    }
  return status;
}
