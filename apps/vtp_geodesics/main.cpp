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
//   vtp_geodesics [MESH] [--source V] [--output FILE] [--picture FILE.png] [--stats-json FILE|-] ...
//
// Computes the geodesic distances from one source vertex to all vertices of a triangle mesh, and writes them
// in the vertex order of the file. Run `vtp_geodesics --help` for details. The program is split by role:
//   arguments.cpp   the command line (one table of options)
//   vtp_tools/read_mesh.h (apps/common)   reading and repair
//   run.cpp         the computation: every call into the library
//   outputs.cpp     text, PLY, picture, JSON, summary
//   main.cpp        the stages, their timing, the output files (vtp_tools/output_file.h) and the errors
// On any error it prints one line "vtp_geodesics: error: ..." on stderr, leaves no partial output file and
// exits with code 2.

#include "arguments.h"
#include "outputs.h"
#include "run.h"

#include <vtp_tools/output_file.h>
#include <vtp_tools/read_mesh.h>
#include <vtp_tools/shortest_path_reference.h>

#include <CGAL/assertions_behaviour.h>
#include <CGAL/VTP_geodesics/Invalid_input_error.h>

#include <algorithm>
#include <cstdlib>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <limits.h>
#include <sys/resource.h>
#include <unistd.h>

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
  const std::string path(buffer.data(), static_cast<std::size_t>(n));
  const std::string::size_type slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash);
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

int run(int argc, char** argv)
{
  const Clock::time_point start = Clock::now();
  const Arguments args = parse_arguments(argc, argv);
  if(args.help)
  {
    print_usage(std::cout, default_mesh());
    return 0;
  }
  const vtp_tools::Method_info& method = *vtp_tools::find_method(args.method);
  if(!vtp_tools::method_available(method))
    throw Tool_error(std::string("method ") + method.name + " needs OpenMP, and this program was built without it");

  // Reading and repair.
  std::string mesh_file = args.mesh;
  if(mesh_file.empty())
  {
    mesh_file = default_mesh();
    if(::access(mesh_file.c_str(), R_OK) != 0)
      throw Tool_error("no mesh given, and the default mesh " + mesh_file + " is missing (give a mesh file)");
  }
  vtp_tools::Input_mesh input;
  vtp_tools::read_input_mesh(mesh_file, input);
  if(args.source >= input.file_vertices)
    throw Tool_error("source vertex " + std::to_string(args.source) + " is out of range (the mesh has "
                     + std::to_string(input.file_vertices) + " vertices)");

  // The computation. The mesh vertices standing for the source: one, several if the repair duplicated it (then
  // all are sources), none if the repair removed it (a vertex in no face: only itself is reachable).
  Run_request request;
  request.method = &method;
  request.threads = args.threads;
  request.has_lambda = args.has_lambda;
  request.lambda = args.lambda;
  request.lambda_g = args.lambda_g;
  request.sources = input.mesh_vertices_of(args.source);
  request.check_cgal = args.check_cgal;
  Run_result result = run_propagation(input.mesh, request);

  // Results per vertex of the file.
  const bool picture = !args.picture.empty();
  std::vector<double> mesh_distances;
  if(picture && !input.direct)
    mesh_distances = result.distances;
  std::vector<double> distances = input.on_file_vertices(std::move(result.distances));
  distances[args.source] = 0.;
  Report report;
  report.mesh = mesh_file;
  report.reader = input.reader;
  report.repairs = input.repairs.summary();
  report.vertices = input.file_vertices;
  report.faces = input.file_faces;
  report.source = args.source;
  report.run = &result;
  report.read_seconds = input.read_seconds;
  report.repair_seconds = input.repair_seconds;
  for(double d : distances)
    if(std::isfinite(d))
    {
      ++report.reached_vertices;
      report.max_distance = (std::max)(report.max_distance, d);
    }
  if(args.check_cgal)
  {
    const std::vector<double> reference = input.on_file_vertices(std::move(result.reference));
    std::vector<double> reference_on_file = reference;
    reference_on_file[args.source] = 0.;
    report.comparison = vtp_tools::compare_distances(distances, reference_on_file);
    report.checked = true;
  }

  // Outputs: every file is written completely (regular files to a temporary file), and only then are they
  // renamed over their targets.
  const Clock::time_point write_start = Clock::now();
  std::unique_ptr<vtp_tools::Output_file> output_file, picture_file, json_file;
  if(!args.output.empty())
  {
    output_file.reset(new vtp_tools::Output_file(args.output));
    write_distances(output_file->stream(), distance_format(args.output), input, distances, nullptr,
                    report.max_distance);
    output_file->close();
  }
  if(picture)
  {
    picture_file.reset(new vtp_tools::Output_file(args.picture));
    Picture_request p;
    p.isolines = args.isolines;
    p.has_view = args.has_view;
    p.view = args.view;
    for(vtp_tools::Vertex_index v : request.sources)
      p.source_vertices.push_back(static_cast<std::size_t>(v));
    write_picture(picture_file->stream(), input.mesh, input.direct ? distances : mesh_distances, report.max_distance,
                  p);
    picture_file->close();
  }
  report.write_seconds = seconds_since(write_start);
  report.total_seconds = seconds_since(start);
  report.peak_rss_mb = peak_rss_mb();
  if(!args.stats_json.empty())
  {
    json_file.reset(new vtp_tools::Output_file(args.stats_json));
    json_file->stream() << stats_json(report);
    json_file->close();
  }
  for(vtp_tools::Output_file* f : { output_file.get(), picture_file.get(), json_file.get() })
    if(f != nullptr)
      f->commit();

  // Text for people, on standard output unless it carries data.
  bool stdout_has_data = false;
  for(vtp_tools::Output_file* f : { output_file.get(), picture_file.get(), json_file.get() })
    stdout_has_data = stdout_has_data || (f != nullptr && f->writes_to_stdout());
  if(args.output.empty() && args.stats_json.empty() && !stdout_has_data)
    print_summary(std::cout, report);
  if(report.checked)
    print_check(stdout_has_data ? std::cerr : std::cout, report);
  std::cout.flush();
  if(!std::cout)
    throw Tool_error("cannot write to stdout");
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

} // namespace vtp_geodesics_app

int main(int argc, char** argv)
{
  using namespace vtp_geodesics_app;
  // CGAL's default handlers print several lines on std::cerr before throwing; the exceptions are caught below
  // and reported on one line instead.
  CGAL::set_error_handler(silent_cgal_handler);
  CGAL::set_warning_handler(silent_cgal_handler);
  try
  {
    return run(argc, argv);
  }
  catch(const Tool_error& e) { return fail(e.what()); }
  catch(const vtp_tools::Input_error& e) { return fail(e.what()); }
  catch(const vtp_tools::Output_error& e) { return fail(e.what()); }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e) { return fail(e.what()); }
  catch(const std::bad_alloc&) { return fail("out of memory"); }
  catch(const std::exception& e) { return fail(e.what()); }
  catch(...) { return fail("unknown error"); }
}
