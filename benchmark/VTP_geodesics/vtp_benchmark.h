// vtp_benchmark: what its parts share (see vtp_benchmark.cpp for the program and readme.txt for its use).
//
// The program is split along its roles, one file each:
//   methods.cpp        the methods (the VTP family from vtp_support/methods.h, cgal, heat, heat_idt, external)
//   arguments.cpp      the command line
//   child_run.cpp      the child side: one method on one source, R times, in a forked process (the only file
//                      with the solver, CGAL's exact shortest paths and the heat method)
//   parent_run.cpp     the parent side: fork, read the child's report through a pipe, wait4 for its peak memory
//   external_run.cpp   external methods (--external NAME=COMMAND)
//   report.cpp         the table on standard output and the CSV file
//   input_meshes.cpp   reading and making the input meshes (remeshing, Loop and midpoint subdivision), OFF output
//   vtp_benchmark.cpp  main(): the loop over meshes, sources and methods, the comparison with VTP

#ifndef VTP_BENCHMARK_H
#define VTP_BENCHMARK_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <vtp_support/command_line.h>
#include <vtp_support/methods.h>
#include <vtp_support/statistics.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/types.h> // pid_t

#ifdef CGAL_EIGEN3_ENABLED
#define VTP_BENCHMARK_WITH_HEAT_METHOD 1
#endif

namespace vtp_benchmark {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;

const double inf = std::numeric_limits<double>::infinity();
const double nan_value = std::numeric_limits<double>::quiet_NaN();

// Bad arguments and unreadable input: one line "vtp_benchmark: error: ...", exit code 2.
using vtp_support::Tool_error;
using vtp_support::split;

// ------------------------------------------------------------------------------------------------
// Methods (methods.cpp). To add one, add an enumerator, a parser in `method_parsers` (or, for a method of
// the package, an entry in vtp_support/methods.h), and a case in `run_in_child()` (child_run.cpp).
// ------------------------------------------------------------------------------------------------
enum class Method_kind { VTP_FAMILY, CGAL_SMSP, HEAT_DIRECT, HEAT_IDT, EXTERNAL };

struct Method
{
  std::string label;        // as printed and written in the CSV, e.g. "vtp", "pvtp:4"
  Method_kind kind = Method_kind::VTP_FAMILY;
  const vtp_support::Method_info* info = nullptr;  // VTP_FAMILY: the method of the table (vtp, pvtp, ..., pvsp2)
  int threads = 1;          // parallel methods of the table
  double lambda = inf;      // approximate methods of the table
  std::string command;      // EXTERNAL: shell command with {mesh}, {source}, {output}
};

// "vtp", "pvtp:4", "cgal", ...; throws Tool_error.
Method parse_method(const std::string& spec);

// ------------------------------------------------------------------------------------------------
// Command line (arguments.cpp)
// ------------------------------------------------------------------------------------------------
struct Arguments
{
  double remesh = 0.;       // target edge length / mean edge length; 0: no remeshing
  int remesh_iterations = 3;
  int loop = 0;
  int subdivide = 0;
  bool morton = false;      // renumber along a Morton curve (see reorder_morton())
  std::string save_meshes;
  std::size_t sources = 1;
  std::vector<Method> methods;
  std::string csv;
  int repeat = 1;
  std::vector<std::string> meshes;
  bool help = false;
};

void print_usage(std::ostream& os);
Arguments parse_arguments(int argc, char** argv);

// ------------------------------------------------------------------------------------------------
// Child side (child_run.cpp): run one method on one source, R times; the report sent to the parent.
// ------------------------------------------------------------------------------------------------
// The report of the child: this header, then the distances (number_of_distances doubles), the error text
// (error_length bytes) and the library's statistics of the fastest repeat (VTP family only: statistics_length
// bytes, the JSON members that vtp_support::write_statistics_json() writes).
struct Child_header
{
  double seconds = nan_value;                // per-source work, fastest of the repeats
  double cpu_seconds = nan_value;            // processor time of that work (all threads), fastest of the repeats
  double preprocessing_seconds = nan_value;  // per-mesh work (solver construction, factorization)
  double rss_at_start_kb = 0.;
  std::uint64_t pseudo_source_vertices = 0;
  std::uint64_t number_of_distances = 0;
  std::uint64_t error_length = 0;
  std::uint64_t statistics_length = 0;
};

// Processor time of the process (all its threads), in seconds.
double cpu_now_seconds();
double now_seconds();
double current_rss_kb();

// Runs `method` in this (child) process, writes a Child_header, the distances and the error text to `fd`,
// and exits.
[[noreturn]] void run_in_child(int fd, Mesh& mesh, Vertex_index source, const Method& method, int repeat);

// ------------------------------------------------------------------------------------------------
// Parent side (parent_run.cpp) and external methods (external_run.cpp)
// ------------------------------------------------------------------------------------------------
struct Run_result
{
  Method method;
  bool ok = false;
  std::string status = "ok";
  Child_header header;
  // The library's statistics (the VTP family), or the window counts that an external method printed; else the
  // defaults (1 thread).
  bool has_statistics = false;
  CGAL::VTP_geodesics::Propagation_statistics statistics;
  double peak_rss_mb = nan_value;
  std::vector<double> distances;
  // Filled after all methods of the source ran.
  double max_abs_err = nan_value, max_rel_err = nan_value, mean_rel_err = nan_value, speedup_vs_cgal = nan_value;
  double mean_pointwise_rel_err = nan_value, max_pointwise_rel_err = nan_value, speedup_vs_vtp = nan_value;
  double cpu_ratio_vs_vtp = nan_value;  // processor time of VTP / processor time of this method
  double max_below_vtp = nan_value;     // largest (vtp - d) / largest vtp distance (> 0: below the exact one)
  std::size_t mismatched_infinities = 0;
};

double ns_per_window(const Run_result& r);
double total_seconds(const Run_result& r);

// Reads everything the child `pid` writes to `fd` (before waiting: the child blocks when the pipe is full),
// closes `fd`, then waits for the child: its exit status and peak RSS (MB).
std::string read_all_and_wait(int fd, pid_t pid, int& status, double& peak_rss_mb);

// Forks with a pipe from the child to the parent (the output streams are flushed first). Returns the child's
// pid to the parent, which keeps the read end in `fd`, and 0 to the child, which keeps the write end in `fd`.
// Throws std::runtime_error.
pid_t fork_with_pipe(int& fd);

Run_result run_forked(Mesh& mesh, Vertex_index source, const Method& method, int repeat);

std::string replace_all(std::string s, const std::string& what, const std::string& with);

// Runs an external method (see --external) on the mesh written to `mesh_file`, in its own process
// (so its peak RSS is its own), and reads its time, window count and distances.
Run_result run_external(const std::string& mesh_file, std::size_t source, std::size_t number_of_vertices,
                        const Method& method, const std::string& output_file);

// ------------------------------------------------------------------------------------------------
// Table and CSV output (report.cpp)
// ------------------------------------------------------------------------------------------------
struct Mesh_info
{
  std::string label;
  std::size_t vertices = 0, faces = 0;
  double pseudo_source_share = nan_value;  // saddle or boundary vertices / vertices (from the VTP run)
};

std::string number(double x, int precision = 6);
extern const char* const csv_columns;
void write_csv_row(std::ostream& os, const Mesh_info& mesh, std::size_t source, const Run_result& r);
void print_table_header();
void print_table_row(const Mesh_info& mesh, std::size_t source, const Run_result& r);

// ------------------------------------------------------------------------------------------------
// Input meshes (input_meshes.cpp)
// ------------------------------------------------------------------------------------------------

// Reads a mesh and makes the requested input from it: isotropic remeshing, then Loop subdivision,
// then midpoint subdivision. The vertices are numbered 0..n-1 in the end (garbage collected).
// Returns the label of the mesh.
std::string load_mesh(const std::string& file, const Arguments& args, Mesh& mesh);

// file_to_answer.cpp: the stages from the OFF file `file` to the distances from `source` (exact VTP, the solver's
// preprocessing on `threads` threads), as the tool goes through them, in a fresh child process; false if it failed.
int default_threads();  // OpenMP's default, as the tool's
bool file_to_answer(const std::string& file, std::size_t source, int threads, vtp_support::Stage_seconds& stages);
void print_file_to_answer(const std::string& label, std::size_t source, int threads,
                          const vtp_support::Stage_seconds& stages);

// Writes `mesh` as an OFF file, vertices in index order; throws std::runtime_error.
void write_off(const Mesh& mesh, const std::string& file);

} // namespace vtp_benchmark

#endif // VTP_BENCHMARK_H
