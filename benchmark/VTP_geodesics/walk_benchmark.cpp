// vtp_walk_benchmark: straightest geodesics (the exp map), walks per second on 1 and T threads side by side.
//
//   vtp_walk_benchmark [--walks N] [--repeat R] [--threads T] [--length K] MESH...
//
// For each mesh: N walks (default 100000) from vertices spread over the mesh (every V/N-th vertex, in the order
// of vertices(tm)), each in a direction of its own (the golden angle times its number, in the tangent frame of
// its start) for K mean edge lengths (default 20); Geodesic_distance_solver::straightest_geodesics() with
// CGAL::Sequential_tag, then with CGAL::Parallel_tag on 1 and on T threads (default 2), interleaved R times
// (default 3), the fastest of each (wall-clock, and processor seconds of the process). It prints walks per second, the mean number of points of a walk (faces
// crossed and vertices passed), the walks that stopped on the border, and checks that the walks of the threads
// are bitwise those of the sequential run. For scale, the time of one full distance run (exact VTP from vertex 0).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <vtp_support/command_line.h>
#include <vtp_support/methods.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
typedef CGAL::VTP_geodesics::Straightest_geodesic<Mesh::Face_index, Kernel::Point_3> Walk;
namespace VP = CGAL::VTP_geodesics::parameters;
using vtp_support::parse_double;
using vtp_support::parse_integer;

struct Arguments
{
  std::size_t walks = 100000;
  int repeat = 3, threads = 2;
  double length = 20.;
  std::vector<std::string> files;
  bool help = false;
};

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  typedef const std::string& S;
  const vtp_support::Option_table<Arguments> table = {
    { "--walks", "N", nullptr, [](Arguments& a, S n, S v) { a.walks = static_cast<std::size_t>(parse_integer(n, v, 1, 100000000)); } },
    { "--repeat", "R", nullptr, [](Arguments& a, S n, S v) { a.repeat = static_cast<int>(parse_integer(n, v, 1, 1000)); } },
    { "--threads", "T", nullptr, [](Arguments& a, S n, S v) { a.threads = static_cast<int>(parse_integer(n, v, 1, 4096)); } },
    { "--length", "K", nullptr,
      [](Arguments& a, S n, S v) {
        a.length = parse_double(n, v);
        if(!(a.length >= 0.) || !std::isfinite(a.length))
          throw vtp_support::Tool_error(n + " must be finite and >= 0");
      } },
    { "--help", nullptr, nullptr, [](Arguments& a, S, S) { a.help = true; } },
  };
  vtp_support::parse_command_line(argc, argv, table, a, [](Arguments& a, const std::string& f) { a.files.push_back(f); });
  if(!a.help && a.files.empty())
    throw vtp_support::Tool_error("give at least one mesh");
  return a;
}

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// processor seconds of the process (all its threads): on a shared machine, compare these
double cpu_now()
{
  timespec t;
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

bool same(const std::vector<Walk>& a, const std::vector<Walk>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].points != b[i].points || a[i].end_direction != b[i].end_direction || a[i].length != b[i].length)
      return false;
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Arguments args = parse_arguments(argc, argv);
    if(args.help)
    {
      std::cout << "usage: vtp_walk_benchmark [--walks N] [--repeat R] [--threads T] [--length K] MESH...\n";
      return 0;
    }
    std::cout << "| Mesh | #V | Walks | Length (mean edges) | Points per walk | On the border | Run | Time (s) | Walks/s "
                 "| vs sequential | Processor s |\n|---|--:|--:|--:|--:|--:|---|--:|--:|--:|--:|\n";
    for(const std::string& file : args.files)
    {
      Mesh mesh;
      if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh) || mesh.is_empty())
        throw std::runtime_error("cannot read " + file);
      Solver solver(mesh);
      solver.compute(CGAL::Constant_property_map<Vertex_index, double>(), Vertex_index(0));
      const double full_run = solver.statistics().seconds;
      const std::vector<Vertex_index>& all = solver.vertex_list();
      std::vector<Vertex_index> starts;
      std::vector<std::array<double, 2> > directions;
      const double golden = 3.14159265358979323846 * (3. - std::sqrt(5.));
      for(std::size_t i = 0; i < args.walks; ++i)
      {
        const Vertex_index v = all[(i * all.size()) / args.walks];
        if(mesh.is_isolated(v))
          continue;
        starts.push_back(v);
        directions.push_back({ { std::cos(golden * double(i)), std::sin(golden * double(i)) } });
      }
      const std::vector<double> lengths(starts.size(), args.length * solver.mean_edge_length());
      const char* names[] = { "sequential", "parallel, 1 thread", "parallel, T threads" };
      std::vector<double> best(3, std::numeric_limits<double>::infinity()), best_cpu = best;
      std::vector<Walk> reference, walks;
      bool identical = true;
      for(int r = 0; r < args.repeat; ++r)
        for(int c = 0; c < 3; ++c)
        {
          const double t0 = now(), c0 = cpu_now();
          if(c == 0)
            walks = solver.straightest_geodesics(starts, directions, lengths);
          else if(!vtp_support::rows_on_threads)
            continue;
          else
            walks = solver.straightest_geodesics<vtp_support::Rows_tag>(
              starts, directions, lengths, VP::number_of_threads(c == 1 ? 1 : args.threads));
          best[std::size_t(c)] = (std::min)(best[std::size_t(c)], now() - t0);
          best_cpu[std::size_t(c)] = (std::min)(best_cpu[std::size_t(c)], cpu_now() - c0);
          if(c == 0 && r == 0)
            reference = walks;
          else
            identical = identical && same(walks, reference);
        }
      std::size_t points = 0, border = 0;
      for(const Walk& w : reference)
      {
        points += w.points.size();
        border += w.reached_border ? 1 : 0;
      }
      for(int c = 0; c < 3; ++c)
      {
        if(!(best[std::size_t(c)] < std::numeric_limits<double>::infinity()))
          continue;
        std::string name = names[c];
        if(c == 2)
          name = "parallel, " + std::to_string(args.threads) + " threads";
        char line[512];
        std::snprintf(line, sizeof(line), "| %s | %zu | %zu | %.0f | %.1f | %zu | %s | %.3f | %.0f | %.2f | %.3f |\n",
                      file.substr(file.find_last_of('/') + 1).c_str(), static_cast<std::size_t>(mesh.number_of_vertices()), starts.size(),
                      args.length, double(points) / double(reference.size()), border, name.c_str(),
                      best[std::size_t(c)], double(starts.size()) / best[std::size_t(c)],
                      best[0] / best[std::size_t(c)], best_cpu[std::size_t(c)]);
        std::cout << line;
      }
      std::cout << "\n" << file << ": the walks on threads are " << (identical ? "" : "NOT ")
                << "bitwise those of the sequential run; one full distance run (VTP, vertex 0): " << full_run
                << " s\n\n";
      if(!identical)
        return 1;
    }
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "vtp_walk_benchmark: error: " << e.what() << std::endl;
    return 2;
  }
}
