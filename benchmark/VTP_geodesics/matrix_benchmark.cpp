// matrix_benchmark: the row computation of vtp_distance_matrix, timed side by side (no file output).
//
//   matrix_benchmark [--rows K] [--repeat R] [--threads T] MESH
//
// For K sources spread over the vertices of MESH, R times in turn (interleaved, so that a change of
// the machine's load hits every variant alike):
//   single    one Geodesic_distance_solver, compute() from each source in turn (no output map; the row
//             read with distances()): the library's single-source call;
//   batch 1   compute_rows() of vtp_distance_matrix (vtp_support/distance_rows.h) on one
//             thread: the library's batch call compute_each() on a new solver, each row copied to file
//             order and handed to a sink (here: converted to float32, as a dense float32 output does);
//   batch T   the same on T threads (default 2).
// Prints the median time per source of each, rows per second, and the ratios. Writing the HDF5 file
// is measured with the tool itself (see README.md, "Many sources").

#include <vtp_support/command_line.h>
#include <vtp_support/distance_rows.h>
#include <vtp_support/read_mesh.h>

#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using vtp_support::Mesh;
using vtp_support::Tool_error;
using vtp_support::Vertex_index;

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0. : v[v.size() / 2];
}

struct Arguments
{
  std::size_t rows = 100;
  int repeat = 3, threads = 2;
  std::string file;
  bool help = false;
};

const char* const usage = "usage: matrix_benchmark [--rows K] [--repeat R] [--threads T] MESH\n";

Arguments parse_arguments(int argc, char** argv)
{
  typedef const std::string& S;
  using vtp_support::parse_integer;
  static const vtp_support::Option_table<Arguments> table = {
    { "--rows", "K", nullptr, [](Arguments& a, S n, S v) { a.rows = parse_integer(n, v, 1, 1u << 31); } },
    { "--repeat", "R", nullptr, [](Arguments& a, S n, S v) { a.repeat = static_cast<int>(parse_integer(n, v, 1, 1000)); } },
    { "--threads", "T", nullptr, [](Arguments& a, S n, S v) { a.threads = static_cast<int>(parse_integer(n, v, 1, 4096)); } },
    { "--help", nullptr, nullptr, [](Arguments& a, S, S) { a.help = true; } },
  };
  Arguments a;
  vtp_support::parse_command_line(argc, argv, table, a, [](Arguments& a, const std::string& file) {
    if(!a.file.empty())
      throw Tool_error("more than one mesh given ('" + a.file + "' and '" + file + "')");
    a.file = file;
  });
  if(!a.help && a.file.empty())
    throw Tool_error("no mesh given");
  return a;
}

} // namespace

int main(int argc, char** argv)
{
  Arguments args;
  try
  {
    args = parse_arguments(argc, argv);
  }
  catch(const Tool_error& e)
  {
    std::fprintf(stderr, "matrix_benchmark: error: %s\n%s", e.what(), usage);
    return 2;
  }
  if(args.help)
  {
    std::fputs(usage, stdout);
    return 0;
  }
  std::size_t rows = args.rows;
  const int repeat = args.repeat, threads = args.threads;
  const std::string& file = args.file;
  vtp_support::Input_mesh input;
  try
  {
    vtp_support::read_input_mesh(file, input);
  }
  catch(const vtp_support::Input_error& e)
  {
    std::fprintf(stderr, "matrix_benchmark: %s\n", e.what());
    return 2;
  }
  const std::size_t nv = input.file_vertices;
  rows = (std::min)(rows, nv);
  std::vector<std::int64_t> sources, all_rows;
  for(std::size_t i = 0; i < rows; ++i)
  {
    sources.push_back(static_cast<std::int64_t>(i * nv / rows));
    all_rows.push_back(static_cast<std::int64_t>(i));
  }
  std::printf("# %s: %zu vertices, %zu rows, %d repeats, batch threads 1 and %d\n", file.c_str(), nv, rows,
              repeat, threads);

  std::vector<double> single, batch1, batchT;
  double checksum = 0.;  // keeps the sinks' work alive
  CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> solver(input.mesh);
  const CGAL::Constant_property_map<Vertex_index, double> no_map;
  std::vector<float> row32(nv);
  auto sink = [&](std::int64_t, std::int64_t, const std::vector<double>& d) {
    for(std::size_t j = 0; j < nv; ++j)
      row32[j] = static_cast<float>(d[j]);
    checksum += row32[nv / 2];
  };
  for(int r = 0; r < repeat; ++r)
  {
    auto t0 = std::chrono::steady_clock::now();
    for(std::int64_t s : sources)
    {
      solver.compute<CGAL::Sequential_tag>(no_map, input.mesh_vertices_of(static_cast<std::size_t>(s)));
      checksum += solver.distances()[nv / 2];
    }
    single.push_back(seconds_since(t0) / static_cast<double>(rows));

    t0 = std::chrono::steady_clock::now();
    vtp_support::compute_rows(input, sources, all_rows, vtp_support::Row_method(), 1, sink);
    batch1.push_back(seconds_since(t0) / static_cast<double>(rows));

    t0 = std::chrono::steady_clock::now();
    vtp_support::compute_rows(input, sources, all_rows, vtp_support::Row_method(), threads, sink);
    batchT.push_back(seconds_since(t0) / static_cast<double>(rows));
    std::printf("# repeat %d: single %.6f s, batch 1 %.6f s, batch %d %.6f s per source\n", r + 1, single.back(),
                batch1.back(), threads, batchT.back());
  }
  const double s = median(single), b1 = median(batch1), bT = median(batchT);
  std::printf("variant   seconds/source  rows/s\n");
  std::printf("single    %.6f        %.1f\n", s, 1. / s);
  std::printf("batch 1   %.6f        %.1f\n", b1, 1. / b1);
  std::printf("batch %-2d  %.6f        %.1f\n", threads, bT, 1. / bT);
  std::printf("batch 1 / single: %.3f (time per source)\n", b1 / s);
  std::printf("batch %d / batch 1: %.2fx (rows per second)\n", threads, b1 / bT);
  std::printf("# checksum %g\n", checksum);
  return 0;
}
