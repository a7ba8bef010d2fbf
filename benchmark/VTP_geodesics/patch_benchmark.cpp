// patch_benchmark: polar patches around every vertex (issue 36, part 2) against the per-vertex time of one full
// run, in one program: the mesh read (and repaired, as the tools do) once, one solver, then
//   1. the full log map from vertex 0 on one core (and the distance run alone), REPEATS times interleaved:
//      the median time divided by the vertices reached is the per-vertex time of a full run;
//   2. the largest distance D of the mesh, by a double sweep (the vertex farthest from vertex 0, then the
//      largest distance from it; a lower bound of the diameter, within a factor 2);
//   3. for each radius fraction f: the patches of radius f * D around every vertex (polar_patches(), the default
//      log map), on 1 thread and on THREADS threads, REPEATS times interleaved, the median; their number of
//      (patch, vertex) entries P; the ratio  time / (P * per-vertex time of the full log map)  (the bar of the
//      issue: at most 2 with 2 threads on a 17K scan), and the same ratio against the distance run.
//
//   patch_benchmark MESH [--fractions F,F,...] [--threads T] [--repeats R]
//
// Defaults: --fractions 0.05, --threads 2, --repeats 3. One line per measure, "name value".

#include <vtp_support/read_mesh.h>

#include <CGAL/VTP_geodesics.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace VP = CGAL::VTP_geodesics::parameters;
typedef vtp_support::Mesh Mesh;
typedef vtp_support::Vertex_index Vertex;

namespace {

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class F>
double seconds(const F& f)
{
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<double> parse_list(const std::string& text)
{
  std::vector<double> out;
  std::stringstream s(text);
  std::string item;
  while(std::getline(s, item, ','))
    out.push_back(std::stod(item));
  return out;
}

} // namespace

int main(int argc, char** argv)
{
  const char* usage =
    "usage: patch_benchmark MESH [--fractions F,F,...] [--threads T] [--repeats R]\n"
    "Polar patches around every vertex of MESH, of radius F times the largest distance, on 1 and T threads,\n"
    "against the per-vertex time of one full run (log map and distance) from vertex 0 on one thread; the\n"
    "medians of R interleaved runs, one line per measure. Defaults: --fractions 0.05 --threads 2 --repeats 3.\n";
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h")
    {
      std::cout << usage;
      return 0;
    }
  if(argc < 2 || argc % 2 != 0)
  {
    std::cerr << usage;
    return 2;
  }
  std::vector<double> fractions(1, 0.05);
  int threads = 2, repeats = 3;
  for(int i = 2; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i];
    if(a == "--fractions")
      fractions = parse_list(argv[i + 1]);
    else if(a == "--threads")
      threads = std::atoi(argv[i + 1]);
    else if(a == "--repeats")
      repeats = std::atoi(argv[i + 1]);
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  try
  {
    vtp_support::Input_mesh input;
    vtp_support::read_input_mesh(argv[1], input, 1);
    const Mesh& mesh = input.mesh;
    CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> solver(mesh);
    const std::size_t n = solver.number_of_vertices();
    std::cout << "mesh " << argv[1] << "\nvertices " << n << "\nfaces " << solver.number_of_faces()
              << "\npseudo_source_vertices " << solver.number_of_pseudo_source_vertices() << "\n";
    if(!input.direct)
      std::cout << "repaired 1\n";

    // 1. the full runs from vertex 0, one core
    std::vector<std::array<double, 2> > x(num_vertices(mesh));
    std::vector<double> d(num_vertices(mesh));
    auto xm = boost::make_iterator_property_map(x.begin(), get(boost::vertex_index, mesh));
    auto dm = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
    const Vertex v0 = solver.vertex_list()[0];
    std::vector<double> t_distance, t_log;
    std::size_t reached = 0;
    for(int r = 0; r < repeats; ++r)
    {
      t_distance.push_back(seconds([&] { solver.compute(dm, v0); }));
      t_log.push_back(seconds([&] { solver.compute(dm, v0, VP::log_map(xm)); }));
      reached = solver.statistics().reached_vertices;
    }
    const double per_vertex_log = median(t_log) / static_cast<double>(reached);
    const double per_vertex_distance = median(t_distance) / static_cast<double>(reached);
    std::printf("full_run_reached %zu\nfull_distance_seconds %.4f\nfull_log_map_seconds %.4f\n", reached,
                median(t_distance), median(t_log));
    std::printf("per_vertex_log_map_microseconds %.4f\nper_vertex_distance_microseconds %.4f\n", per_vertex_log * 1e6,
                per_vertex_distance * 1e6);

    // 2. the largest distance (double sweep)
    solver.compute(dm, v0);
    const std::vector<double>& d0 = solver.distances();
    std::size_t far = 0;
    for(std::size_t i = 0; i < n; ++i)
      if(d0[i] < std::numeric_limits<double>::infinity() && d0[i] > d0[far])
        far = i;
    solver.compute(dm, solver.vertex_list()[far]);
    double largest = 0.;
    for(double e : solver.distances())
      if(e < std::numeric_limits<double>::infinity())
        largest = (std::max)(largest, e);
    std::printf("largest_distance %.9g\n", largest);

    // 3. the patches around every vertex
    const std::vector<Vertex>& centres = solver.vertex_list();
    for(double f : fractions)
    {
      const double radius = f * largest;
      std::vector<double> t1, tt;
      std::size_t entries = 0;
      for(int r = 0; r < repeats; ++r)
      {
        t1.push_back(seconds([&] { entries = solver.polar_patches(centres, radius).number_of_entries(); }));
        tt.push_back(seconds([&] {
          entries = solver.polar_patches<CGAL::Parallel_tag>(centres, radius, VP::number_of_threads(threads))
                      .number_of_entries();
        }));
      }
      const double pairs = static_cast<double>(entries);
      std::printf("fraction %.4g\nradius %.9g\nentries %zu\nentries_per_patch %.1f\n", f, radius, entries,
                  pairs / static_cast<double>(n));
      std::printf("patches_seconds_1_thread %.4f\npatches_seconds_%d_threads %.4f\n", median(t1), threads, median(tt));
      std::printf("ratio_1_thread_vs_log_map %.3f\nratio_%d_threads_vs_log_map %.3f\n",
                  median(t1) / (pairs * per_vertex_log), threads, median(tt) / (pairs * per_vertex_log));
      std::printf("ratio_1_thread_vs_distance %.3f\nratio_%d_threads_vs_distance %.3f\n",
                  median(t1) / (pairs * per_vertex_distance), threads, median(tt) / (pairs * per_vertex_distance));
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "patch_benchmark: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
