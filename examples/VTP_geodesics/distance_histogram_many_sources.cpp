// Many sources in parallel: the rows of 100 source vertices, computed on all cores, summarized as a
// histogram of geodesic distances (a shape descriptor), the mean distance and the farthest pair found.
//
// Geodesic_distance_solver::compute_each() computes one row per source, in parallel over the sources with
// CGAL::Parallel_tag (one workspace per thread; the per-mesh data is shared), and hands each finished row to
// a "sink", one row at a time, in any order. The sink here folds the row into the summary: only the summary
// is kept, never the rows.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#ifndef VTP_GEODESICS_DEFAULT_MESH
#define VTP_GEODESICS_DEFAULT_MESH "data/elephant.off"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel   Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                   Triangle_mesh;
typedef Triangle_mesh::Vertex_index                           vertex_descriptor;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Triangle_mesh> Solver;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : VTP_GEODESICS_DEFAULT_MESH;
  Triangle_mesh tm;
  if(!CGAL::IO::read_polygon_mesh(filename, tm) || !CGAL::is_triangle_mesh(tm) || tm.is_empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
#else
  const int threads = 1;
#endif

  // 100 sources, spread over the vertex list
  std::vector<vertex_descriptor> sources;
  const std::size_t nv = num_vertices(tm), count = (std::min)(nv, std::size_t(100));
  for(std::size_t i = 0; i < count; ++i)
    sources.push_back(*std::next(vertices(tm).begin(), static_cast<std::ptrdiff_t>(i * nv / count)));

  // The summary: a histogram of the distances in bins of half a mean edge length (grown as needed),
  // their sum, and the farthest pair.
  Solver solver(tm);
  const double bin_width = 0.5 * solver.mean_edge_length();
  std::vector<std::size_t> bins;
  double sum = 0., farthest = -1.;
  std::size_t reached = 0;
  vertex_descriptor far_source, far_target;

  // One call of the sink per row: `row` is indexed by solver.vertex_id(v).
  auto sink = [&](std::size_t, vertex_descriptor s, const std::vector<double>& row) {
    for(vertex_descriptor v : vertices(tm))
    {
      const double d = row[solver.vertex_id(v)];
      if(!(d < std::numeric_limits<double>::infinity()))
        continue;  // unreachable (another connected component)
      const std::size_t b = static_cast<std::size_t>(d / bin_width);
      if(b >= bins.size())
        bins.resize(b + 1, 0);
      ++bins[b];
      sum += d;
      ++reached;
      if(d > farthest)
      {
        farthest = d;
        far_source = s;
        far_target = v;
      }
    }
  };
  const auto t0 = std::chrono::steady_clock::now();
#ifdef _OPENMP
  solver.compute_each<CGAL::Parallel_tag>(sources, sink, CGAL::VTP_geodesics::parameters::number_of_threads(threads));
#else
  solver.compute_each<CGAL::Sequential_tag>(sources, sink);
#endif
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::cout << sources.size() << " rows of " << nv << " distances on " << threads << " thread(s) in " << seconds
            << " s (" << sources.size() / seconds << " rows/s)\n"
            << "mean geodesic distance " << sum / static_cast<double>(reached) << ", farthest pair found: "
            << far_source << " - " << far_target << " at " << farthest << "\n"
            << "histogram of the distances (10 bins from 0 to " << farthest << "):\n";
  // the fine bins grouped into 10 bars
  std::vector<std::size_t> bars(10, 0);
  for(std::size_t b = 0; b < bins.size(); ++b)
    bars[(std::min)(std::size_t(9), static_cast<std::size_t>((b + 0.5) * bin_width / farthest * 10.))] += bins[b];
  const std::size_t tallest = *std::max_element(bars.begin(), bars.end());
  for(std::size_t k = 0; k < bars.size(); ++k)
  {
    std::printf("  %8.4f - %8.4f %8zu ", k * farthest / 10., (k + 1) * farthest / 10., bars[k]);
    std::cout << std::string(tallest > 0 ? 50 * bars[k] / tallest : 0, '#') << "\n";
  }
  return EXIT_SUCCESS;
}
