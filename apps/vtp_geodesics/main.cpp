// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// vtp_geodesics: command-line front end of the VTP_geodesics package.
//
//   vtp_geodesics [MESH] [--source V[,V...]] [--source-point X,Y,Z] [--output FILE] [--picture FILE.png] ...
//
// Computes the geodesic distances from sources (vertices, points of the surface) to all vertices of a triangle
// mesh, and writes them in the vertex order of the file; optionally the nearest source of each vertex, a
// distance limit, distances at targets, geodesic paths. Run `vtp_geodesics --help` for details. The program is
// split by role:
//   arguments.cpp     the command line: the parser and the help; its table of options in arguments_table.cpp,
//                     the checks of combinations of options in arguments_checks.cpp
//   vtp_support/read_mesh.h (support/)   reading and repair, and the correspondence of file and mesh vertices
//   request.cpp       the request made from the arguments: file vertices and points to the mesh
//   locate.cpp        points of the command line located on the mesh (vtp_support/surface_locator.h)
//   query_points.cpp  the points of --query-points (a file) and their answers (--query-output)
//   run.cpp           the computation: every call into the library
//   file_results.cpp  the results back in the file's terms: mesh vertices to file vertices
//   outputs.cpp       the files: text, PLY (distance_ply.cpp), picture (picture*.cpp), samples, paths
//   report.cpp        the JSON statistics, the summary for people
//   main.cpp          the stages, their timing, the output files (output_file.h) and the errors
// On any error it prints one line "vtp_geodesics: error: ..." on stderr, leaves no partial output file and
// exits with code 2. On success it leaves as soon as its outputs are closed, without freeing its memory (but in
// builds with a sanitizer).

#include "arguments.h"
#include "file_results.h"
#include "output_file.h"
#include "outputs.h"
#include "report.h"
#include "request.h"
#include "run.h"

#include <vtp_support/read_mesh.h>

#include <CGAL/assertions_behaviour.h>
#include <CGAL/VTP_geodesics/Invalid_input_error.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <limits.h>
#include <sys/resource.h>
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

// Builds with a sanitizer free everything at exit, so that their leak checks see the whole teardown (CMake defines
// VTP_GEODESICS_APP_FREE_AT_EXIT with VTP_GEODESICS_SANITIZE; GCC and Clang say when AddressSanitizer is on).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#ifndef VTP_GEODESICS_APP_FREE_AT_EXIT
#define VTP_GEODESICS_APP_FREE_AT_EXIT
#endif
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer) || __has_feature(thread_sanitizer) \
    || __has_feature(memory_sanitizer)
#ifndef VTP_GEODESICS_APP_FREE_AT_EXIT
#define VTP_GEODESICS_APP_FREE_AT_EXIT
#endif
#endif
#endif

#ifndef VTP_GEODESICS_DEFAULT_MESH_RELATIVE
// The default mesh, relative to the folder of the executable (installed layout, mirrored in the build tree).
#define VTP_GEODESICS_DEFAULT_MESH_RELATIVE "../share/VTP_geodesics/elephant.off"
#endif

namespace vtp_geodesics_app {

namespace {

const char* const program_name = "vtp_geodesics";

typedef std::chrono::steady_clock Clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The folder of this executable (from /proc/self/exe), or an empty string.
std::string executable_folder()
{
  std::vector<char> buffer(PATH_MAX + 1);
  const ssize_t n = ::readlink("/proc/self/exe", buffer.data(), PATH_MAX);
  if(n <= 0)
    return std::string();
  return std::filesystem::path(std::string(buffer.data(), static_cast<std::size_t>(n))).parent_path().string();
}

std::string default_mesh()
{
  const std::string folder = executable_folder();
  const std::string path = (folder.empty() ? std::string(".") : folder) + "/" + VTP_GEODESICS_DEFAULT_MESH_RELATIVE;
  char* resolved = ::realpath(path.c_str(), nullptr); // without the "bin/.." of the relative path
  if(resolved == nullptr)
    return path;
  const std::string r = resolved;
  std::free(resolved);
  return r;
}

double peak_rss_mb()
{
  struct rusage usage;
  if(::getrusage(RUSAGE_SELF, &usage) != 0)
    return 0.;
  return static_cast<double>(usage.ru_maxrss) / 1024.; // ru_maxrss is in KB on Linux
}

// After a successful run, once every output file is written, closed and renamed and stdout and stderr are
// flushed: leaves the process at once, without the destructors of the mesh, the solver and its kept field (memory
// that the OS takes back anyway, which they would walk block by block). Builds with a sanitizer return instead.
void leave_without_teardown()
{
#ifndef VTP_GEODESICS_APP_FREE_AT_EXIT
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  std::_Exit(0);
#endif
}

int run(int argc, char** argv)
{
  const Clock::time_point start = Clock::now();
  const Arguments args = parse_arguments(argc, argv);
  if(args.help)
  {
    print_usage(std::cout, default_mesh());
    return 0;
  }
  const vtp_support::Method_info& method = *vtp_support::find_method(args.method);
  if(!vtp_support::method_available(method))
    throw Tool_error(std::string("method ") + method.name + " needs OpenMP, and this program was built without it");

  // Reading and repair: the mesh of the computation, and the correspondence of its vertices with the file's.
  std::string mesh_file = args.mesh;
  if(mesh_file.empty())
  {
    mesh_file = default_mesh();
    if(::access(mesh_file.c_str(), R_OK) != 0)
      throw Tool_error("no mesh given, and the default mesh " + mesh_file + " is missing (give a mesh file)");
  }
  vtp_support::Input_mesh input;
  vtp_support::read_input_mesh(mesh_file, input, args.threads);

  // The computation, on the mesh; its results back on the vertices of the file.
  Request request = make_request(args, method, input);
  Run_result result = run_propagation(input.mesh, request.run);
  const File_results results = file_results(args, input, request, result);
  Report report = make_report(mesh_file, args, method, input, result, results);

  // Outputs: every file is written completely (regular files to a temporary file), and only then are they
  // renamed over their targets.
  const Clock::time_point write_start = Clock::now();
  Output_files files;
  write_outputs(files, args, input, request, result, results);
  report.stages.write = seconds_since(write_start);
  report.stages.total = seconds_since(start);
  report.peak_rss_mb = peak_rss_mb();
  if(!args.stats_json.empty())
    files.write(args.stats_json, [&report](std::ostream& os) { os << stats_json(report); });
  files.commit();

  // Text for people, on standard output unless it carries data.
  const bool stdout_has_data = files.writes_to_stdout();
  if(args.output.empty() && args.stats_json.empty() && !stdout_has_data)
    print_summary(std::cout, report);
  if(results.checked)
    print_check(stdout_has_data ? std::cerr : std::cout, report);
  std::cout.flush();
  if(!std::cout)
    throw Tool_error("cannot write to stdout");
  if(!report.repairs.empty())
    std::cerr << program_name << ": note: " << report.repairs << std::endl;
  leave_without_teardown();
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

} // namespace vtp_geodesics_app

int main(int argc, char** argv)
{
  using namespace vtp_geodesics_app;
#if defined(__GLIBC__)
  // The memory of freed blocks is kept for the next ones (blocks up to glibc's largest mmap() threshold, 32 MB,
  // from the heap, which is not trimmed) instead of being given back to the kernel: each stage from the file to
  // the answer frees its temporaries (the file's text, the check's tables, the import's numbering) just before
  // the next one asks as much, and memory asked again is faulted and zeroed again by the kernel
  // (doc/VTP_geodesics/performance.txt, "From file to answer").
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  // CGAL's default handlers print several lines on std::cerr before throwing; the exceptions are caught below
  // and reported on one line instead.
  CGAL::set_error_handler(silent_cgal_handler);
  CGAL::set_warning_handler(silent_cgal_handler);
  try
  {
    return run(argc, argv);
  }
  catch(const Tool_error& e) { return fail(e.what()); }
  catch(const vtp_support::Input_error& e) { return fail(e.what()); }
  catch(const Output_error& e) { return fail(e.what()); }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e) { return fail(e.what()); }
  catch(const std::bad_alloc&) { return fail("out of memory"); }
  catch(const std::exception& e) { return fail(e.what()); }
  catch(...) { return fail("unknown error"); }
}
