// vtp_distance_matrix: geodesic distance matrices (many sources, every vertex) in HDF5.
//
//   vtp_distance_matrix MESH --sources all|A:B|V,V,...|FILE --output FILE.h5 [--float32]
//                       [--max-distance R [--polar]] [--method vtp|avtp] [--lambda L] [--threads T]
//                       [--resume|--force] [--progress|--quiet]
//
// One row per source: the distances from that source vertex to every vertex of the mesh, in the
// vertex order of the file; dense (float64 or float32, inf where unreachable) or, with a distance
// limit, sparse rows in CSR form. Rows are computed on T threads (and, under mpirun, on every rank),
// written to the output as they finish, and recorded in a journal, so that a run killed at any moment
// continues with --resume. With --polar, the rows are the polar patches (rho and theta) within the limit.
// See README.md, section "Many sources", and the files of this folder:
//   arguments.*      the command line            source_list.*   --sources
//   mesh_input.h     reading the mesh (support/) and its hash
//   vtp_support/distance_rows.h  computing the rows (the library's batch call, compute_each; shared with the
//                    benchmark's matrix_benchmark)
//   polar_rows.h     the rows of --polar (the library's compute_each_polar_patch)
//   matrix_store.*   output files, journal, resume, sparse assembly
//   hdf5_layout.*    the HDF5 file               raw_file.*      positioned writes (POSIX or MPI-IO)
//   job.*            MPI ranks, errors agreed by all ranks, progress counts   progress.*  the progress line

#include "arguments.h"
#include "hashing.h"
#include "job.h"
#include "matrix_store.h"
#include "mesh_input.h"
#include "polar_rows.h"
#include "progress.h"
#include "source_list.h"
#include "tool_error.h"

#include <vtp_support/distance_rows.h>
#include <vtp_support/methods.h>

#include <CGAL/assertions_behaviour.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <unistd.h> // isatty


#ifndef VTP_GEODESICS_VERSION
#define VTP_GEODESICS_VERSION "unknown"
#endif

using namespace vtp_matrix;

namespace {

std::string number_text(double v)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.17g", v);
  return text;
}

// Everything that determines the bytes of the output, one "key=value" per line. A partial output is
// resumed, and a complete one accepted by --resume, only with the same signature. The number of
// threads and of ranks is not part of it: it does not change the result.
std::string run_signature(const Arguments& a, const Mesh_input& input, const std::vector<std::int64_t>& sources)
{
  Hash64 h;
  for(std::int64_t s : sources)
    h.add(static_cast<std::uint64_t>(s));
  std::string s;
  s += "format=vtp_distance_matrix 1\n";
  s += std::string("version=") + VTP_GEODESICS_VERSION + "\n";
  s += "mesh=" + input.hash + "\n";
  s += "vertices=" + std::to_string(input.file_vertices) + "\n";
  s += "sources=" + std::to_string(sources.size()) + " " + h.hex() + "\n";
  s += std::string("layout=") + (a.has_max_distance ? "csr" : "dense") + "\n";
  s += std::string("values=") + (a.float32 ? "float32" : "float64") + "\n";
  s += std::string("method=") + a.method->name + "\n";
  s += "lambda=" + (a.method->approximate ? number_text(a.lambda) : std::string("-")) + "\n";
  s += "max_distance=" + (a.has_max_distance ? number_text(a.max_distance) : std::string("-")) + "\n";
  if(a.polar)
    s += "polar=rho,theta\n";  // (absent without --polar: the signatures of distance runs are unchanged)
  return s;
}

void print_error(const std::string& message)
{
  std::fprintf(stderr, "%s: error: %s\n", program_name, message.c_str());
}

int run(Job& job, int argc, char** argv)
{
  Arguments args;
  Mesh_input input;
  std::vector<std::int64_t> sources;
  std::string error;
  // 1. arguments, mesh and sources, on every rank
  try
  {
    args = parse_arguments(argc, argv);
    if(!args.help)
    {
      read_mesh_input(args.mesh, input, args.threads > 0 ? args.threads : vtp_support::default_threads());
      sources = parse_sources(args.sources, static_cast<std::int64_t>(input.file_vertices));
    }
  }
  catch(const Tool_error& e)
  {
    error = e.what();
  }
  catch(const std::bad_alloc&)
  {
    error = "out of memory while reading the input";
  }
  catch(const std::exception& e)
  {
    error = std::string("internal error: ") + e.what();
  }
  job.agree(error);
  if(args.help)
  {
    if(job.is_root())
      print_usage(std::cout);
    return 0;
  }
  const bool talk = job.is_root() && args.progress != 0;
  if(talk && !input.repair_note.empty())
    std::fprintf(stderr, "%s: note: %s\n", program_name, input.repair_note.c_str());

  // 2. the output: start, continue, or nothing to do
  Matrix_spec spec;
  spec.output = args.output;
  spec.sparse = args.has_max_distance;
  spec.max_distance = args.max_distance;
  spec.file.sources = sources;
  spec.file.columns = static_cast<std::int64_t>(input.file_vertices);
  spec.file.float32 = args.float32;
  spec.file.polar = args.polar;
  spec.file.signature = run_signature(args, input, sources);
  spec.file.text_attributes = { { "method", args.method->name },
                                { "format", args.has_max_distance ? "csr" : "dense" } };
  const double infinity = std::numeric_limits<double>::infinity();
  spec.file.number_attributes = { { "lambda", args.method->approximate ? args.lambda : infinity },
                                  { "max_distance", args.has_max_distance ? args.max_distance : infinity } };
  spec.file.integer_attributes = { { "mesh_vertices", static_cast<std::int64_t>(input.file_vertices) } };
  if(args.polar)
    spec.file.integer_attributes.push_back({ "polar", 1 });
  Matrix_store store(job, spec);
  store.open(args.resume, args.force);
  if(talk && !store.note().empty())
    std::fprintf(stderr, "%s: note: %s\n", program_name, store.note().c_str());
  if(store.complete())
    return 0;

  // 3. the rows
  const std::int64_t total = static_cast<std::int64_t>(sources.size());
  const std::int64_t before = store.rows_done_before();
  const bool show = job.is_root() && (args.progress == 1 || (args.progress == -1 && isatty(2)));
  Progress progress(show, total, before);
  vtp_support::Row_method method;
  method.method = args.method;
  method.lambda = args.lambda;
  method.max_distance = args.max_distance;  // +inf without --max-distance
  const int threads = args.threads > 0 ? args.threads : vtp_support::default_threads();
  try
  {
    auto count_row = [&]() {
      if(job.is_root())
        progress.update(before + store.rows_written() + job.other_rows());
      else
        job.send_rows(store.rows_written(), false);
    };
    if(args.polar)
      compute_polar_rows(input, sources, store.rows_to_compute(), args.max_distance, threads,
                         [&](std::int64_t row, const std::vector<std::int64_t>& indices, const std::vector<double>& rho,
                             const std::vector<double>& theta) {
                           store.write_polar_row(row, indices.data(), rho.data(), theta.data(), indices.size());
                           count_row();
                         });
    else
      vtp_support::compute_rows(input, sources, store.rows_to_compute(), method, threads,
                   [&](std::int64_t row, std::int64_t, const std::vector<double>& distances) {
                     store.write_row(row, distances.data());
                     count_row();
                   });
  }
  catch(const Tool_error& e)
  {
    error = e.what();
  }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e)
  {
    error = e.what();
  }
  catch(const std::bad_alloc&)
  {
    error = "out of memory";
  }
  catch(const std::exception& e)
  {
    error = std::string("internal error: ") + e.what();
  }
  // every rank sends its final count, also after an error; rank 0 waits for all of them
  if(job.is_root())
    job.wait_for_final_rows(
      [&](std::int64_t others) { progress.update(before + store.rows_written() + others); });
  else
    job.send_rows(store.rows_written(), true);
  if(!error.empty())
    store.abandon();
  job.agree(error);

  // 4. the complete file
  store.finish();
  progress.finish(total);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  // a failed CGAL check becomes an exception (reported as an error), not an abort
  CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION);
  std::unique_ptr<Job> job;
  try
  {
    job.reset(new Job(argc, argv));
  }
  catch(const Tool_error& e)
  {
    print_error(e.what());
    return 2;
  }
  int code = 2;
  try
  {
    code = run(*job, argc, argv);
  }
  catch(const Job_error& e)
  {
    if(job->is_root())
      print_error(e.message);
    code = 2;
  }
  catch(const std::exception& e)
  {
    // not agreed by the other ranks: end the whole job
    print_error(std::string("unexpected error: ") + e.what());
    if(job->uses_mpi())
      job->abort(2);
    code = 2;
  }
  job.reset();
  return code;
}
