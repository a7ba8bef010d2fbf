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
//   arguments.cpp   the command line (one table of options)
//   vtp_support/read_mesh.h (support/)   reading and repair
//   locate.cpp      points of the command line located on the mesh (AABB tree)
//   run.cpp         the computation: every call into the library
//   outputs.cpp     text, PLY, picture, JSON, summary
//   main.cpp        the stages, their timing, the output files (vtp_support/output_file.h) and the errors
// On any error it prints one line "vtp_geodesics: error: ..." on stderr, leaves no partial output file and
// exits with code 2.

#include "arguments.h"
#include "locate.h"
#include "output_file.h"
#include "outputs.h"
#include "run.h"

#include <vtp_support/number_format.h>
#include <vtp_support/read_mesh.h>
#include <vtp_support/shortest_path_reference.h>

#include <CGAL/assertions_behaviour.h>
#include <CGAL/VTP_geodesics/Invalid_input_error.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
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

  // Reading and repair.
  std::string mesh_file = args.mesh;
  if(mesh_file.empty())
  {
    mesh_file = default_mesh();
    if(::access(mesh_file.c_str(), R_OK) != 0)
      throw Tool_error("no mesh given, and the default mesh " + mesh_file + " is missing (give a mesh file)");
  }
  vtp_support::Input_mesh input;
  vtp_support::read_input_mesh(mesh_file, input, args.threads);
  auto check_vertex = [&input](std::size_t v, const char* what) {
    if(v >= input.file_vertices)
      throw Tool_error(std::string(what) + " vertex " + std::to_string(v) + " is out of range (the mesh has "
                       + std::to_string(input.file_vertices) + " vertices)");
  };
  for(std::size_t v : args.sources)
    check_vertex(v, "source");
  for(std::size_t v : args.targets)
    check_vertex(v, "target");
  for(std::size_t v : args.path_to)
    check_vertex(v, "path");
  if(args.has_first)
    check_vertex(args.first, "--first");

  // Points, located on the mesh of the computation (the repaired mesh, if the file needed a repair).
  std::unique_ptr<Point_locator> locator;
  if(!args.source_points.empty() || !args.target_points.empty() || !args.path_to_points.empty())
    locator.reset(new Point_locator(input.mesh));
  auto locate_all = [&locator](const std::vector<std::array<double, 3> >& points, const char* option) {
    std::vector<Located_point> r;
    for(const std::array<double, 3>& p : points)
      r.push_back(locator->locate(p, option));
    return r;
  };
  const std::vector<Located_point> source_points = locate_all(args.source_points, "--source-point");
  const std::vector<Located_point> target_points = locate_all(args.target_points, "--target-point");
  const std::vector<Located_point> path_points = locate_all(args.path_to_points, "--path-to-point");

  // The computation. The mesh vertices standing for a file vertex: one, several if the repair duplicated it (as
  // a source or a target, all are), none if the repair removed it (a vertex in no face: only itself is reachable).
  Run_request request;
  request.method = &method;
  request.threads = args.threads;
  request.has_lambda = args.has_lambda;
  request.lambda = args.lambda;
  request.lambda_g = args.lambda_g;
  for(std::size_t i = 0; i < args.sources.size(); ++i)
    for(vtp_support::Vertex_index v : input.mesh_vertices_of(args.sources[i]))
    {
      request.source_vertices.push_back(v);
      request.source_vertex_labels.push_back(i);
    }
  for(std::size_t j = 0; j < source_points.size(); ++j)
  {
    request.source_locations.push_back(source_points[j].location);
    request.source_location_labels.push_back(args.sources.size() + j);
  }
  const bool several_sources = args.number_of_sources() > 1 || args.farthest_points > 1;
  request.want_labels = several_sources || !args.labels.empty();
  request.max_distance = args.max_distance;
  for(std::size_t v : args.targets)
    for(vtp_support::Vertex_index c : input.mesh_vertices_of(v))
      request.target_vertices.push_back(c);
  for(const Located_point& p : target_points)
    request.target_locations.push_back(p.location);
  request.stop_at_targets = args.has_targets();
  // Paths: to a source vertex itself, the single point; from a vertex the repair removed (and not a source),
  // none; the others are traced after the run (`traced[k]`: the index of path k among them, or -1).
  std::vector<std::vector<std::array<double, 3> > > paths(args.path_to.size() + path_points.size());
  std::vector<long long> traced(paths.size(), -1);
  const std::string beyond = args.has_max_distance ? " (or it lies beyond --max-distance)" : "";
  for(std::size_t k = 0; k < args.path_to.size(); ++k)
  {
    const std::size_t v = args.path_to[k];
    if(std::find(args.sources.begin(), args.sources.end(), v) != args.sources.end())
    {
      const vtp_support::Point_3& p = input.file_point(v);
      paths[k].push_back({ { p.x(), p.y(), p.z() } });
      continue;
    }
    Run_request::Path path;
    path.name = "vertex " + std::to_string(v) + " (--path-to)";
    path.copies = input.mesh_vertices_of(v);
    if(path.copies.empty())
      throw Tool_error("no path from " + path.name + ": no source reaches it (it is in no face of the mesh)");
    traced[k] = static_cast<long long>(request.paths.size());
    request.paths.push_back(path);
  }
  for(std::size_t j = 0; j < path_points.size(); ++j)
  {
    Run_request::Path path;
    path.name = "point " + vtp_support::double_to_string(args.path_to_points[j][0]) + ","
                + vtp_support::double_to_string(args.path_to_points[j][1]) + ","
                + vtp_support::double_to_string(args.path_to_points[j][2]) + " (--path-to-point)";
    path.is_point = true;
    path.location = path_points[j].location;
    traced[args.path_to.size() + j] = static_cast<long long>(request.paths.size());
    request.paths.push_back(path);
  }
  request.check_cgal = args.check_cgal;
  const bool sampling = args.farthest_points > 0;
  if(sampling)
  {
    request.farthest_points = args.farthest_points;
    request.radius = args.radius;
    request.want_labels = true;
    if(args.has_first)
    {
      const std::vector<vtp_support::Vertex_index> copies = input.mesh_vertices_of(args.first);
      if(copies.empty())
        throw Tool_error("--first vertex " + std::to_string(args.first) + " is in no face of the mesh");
      request.has_first = true;
      request.first = copies.front();
    }
  }
  request.want_labels = request.want_labels || args.colour_labels;
  Run_result result = run_propagation(input.mesh, request);
  // the samples as vertices of the file
  std::vector<std::size_t> samples;
  if(sampling)
  {
    std::vector<std::size_t> file_vertex_of(result.mesh_vertices, 0);
    for(std::size_t i = 0; i < input.file_vertices; ++i)
      for(vtp_support::Vertex_index v : input.mesh_vertices_of(i))
        file_vertex_of[std::size_t(v)] = i;
    for(vtp_support::Vertex_index v : result.samples)
      samples.push_back(file_vertex_of[std::size_t(v)]);
  }
  for(std::size_t k = 0; k < paths.size(); ++k)
    if(traced[k] >= 0)
      paths[k] = std::move(result.paths[static_cast<std::size_t>(traced[k])]);

  // Results per vertex of the file.
  const bool picture = !args.picture.empty();
  std::vector<double> mesh_distances;
  if((picture || request.want_labels) && !input.direct)
    mesh_distances = result.distances;
  std::vector<int> labels;
  if(request.want_labels)
  {
    labels = input.labels_on_file_vertices(result.labels, input.direct ? result.distances : mesh_distances, -1);
  }
  std::vector<double> distances = input.on_file_vertices(std::move(result.distances));
  for(std::size_t i = args.sources.size(); i-- > 0;) // the first source at a vertex gives its label
  {
    distances[args.sources[i]] = 0.;
    if(request.want_labels)
      labels[args.sources[i]] = static_cast<int>(i);
  }
  std::vector<double> target_distances;
  for(std::size_t v : args.targets)
    target_distances.push_back(distances[v]);
  target_distances.insert(target_distances.end(), result.target_location_distances.begin(),
                          result.target_location_distances.end());

  Report report;
  report.mesh = mesh_file;
  report.reader = input.reader;
  report.method = method.name;
  report.repairs = input.repairs.summary();
  report.vertices = input.file_vertices;
  report.faces = input.file_faces;
  report.sources = sampling ? samples.size() : args.number_of_sources();
  report.single_vertex_source = args.number_of_sources() == 1 && args.sources.size() == 1;
  if(sampling)
    report.sources_text =
      std::to_string(samples.size()) + (samples.size() == 1 ? " farthest point" : " farthest points");
  report.source = args.sources.empty() ? 0 : args.sources.front();
  for(std::size_t i = 0; i < args.sources.size(); ++i)
    report.sources_text += (i == 0 ? "" : ", ") + std::to_string(args.sources[i]);
  if(!args.source_points.empty())
    report.sources_text += (args.sources.empty() ? "" : " and ") + std::to_string(args.source_points.size())
                           + (args.source_points.size() == 1 ? " surface point" : " surface points");
  report.has_max_distance = args.has_max_distance;
  report.max_distance_limit = args.max_distance;
  report.targets = target_distances.size();
  report.paths = paths.size();
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
    // Compared where the result is defined: within the distance limit, and (with targets) where it is final.
    std::vector<double> reference = input.on_file_vertices(std::move(result.reference));
    for(std::size_t v : args.sources)
      reference[v] = 0.;
    for(std::size_t i = 0; i < reference.size(); ++i)
      if(reference[i] > args.max_distance || (args.has_targets() && !std::isfinite(distances[i])))
        reference[i] = std::numeric_limits<double>::infinity();
    report.comparison = vtp_support::compare_distances(distances, reference);
    report.checked = true;
  }

  // Outputs: every file is written completely (regular files to a temporary file), and only then are they
  // renamed over their targets.
  const Clock::time_point write_start = Clock::now();
  std::vector<std::unique_ptr<Output_file> > files;
  auto open_output = [&files](const std::string& name) -> Output_file& {
    files.emplace_back(new Output_file(name));
    return *files.back();
  };
  if(!args.output.empty())
  {
    Output_file& f = open_output(args.output);
    write_distances(f.stream(), distance_format(args.output), input, distances, several_sources ? &labels : nullptr,
                    report.max_distance);
    f.close();
  }
  if(!args.labels.empty())
  {
    Output_file& f = open_output(args.labels);
    write_labels(f.stream(), labels);
    f.close();
  }
  if(!args.target_output.empty())
  {
    Output_file& f = open_output(args.target_output);
    vtp_support::write_values_text(f.stream(), target_distances);
    f.close();
  }
  if(!args.samples_output.empty())
  {
    Output_file& f = open_output(args.samples_output);
    write_samples(f.stream(), samples, result.radii);
    f.close();
  }
  if(!args.path_output.empty())
  {
    Output_file& f = open_output(args.path_output);
    write_paths(f.stream(), path_format(args.path_output), paths);
    f.close();
  }
  if(picture)
  {
    Output_file& f = open_output(args.picture);
    Picture_request p;
    p.isolines = args.isolines;
    p.has_view = args.has_view;
    p.view = args.view;
    for(std::size_t v : args.sources)
    {
      const vtp_support::Point_3& q = input.file_point(v);
      p.markers.push_back({ { q.x(), q.y(), q.z() } });
    }
    for(const Located_point& q : source_points)
      p.markers.push_back(q.point);
    for(std::size_t v : samples)
    {
      const vtp_support::Point_3& q = input.file_point(v);
      p.markers.push_back({ { q.x(), q.y(), q.z() } });
    }
    p.polylines = paths;
    if(args.colour_labels)
      p.labels = &result.labels;
    write_picture(f.stream(), input.mesh, input.direct ? distances : mesh_distances, report.max_distance, p);
    f.close();
  }
  report.write_seconds = seconds_since(write_start);
  report.total_seconds = seconds_since(start);
  report.peak_rss_mb = peak_rss_mb();
  if(!args.stats_json.empty())
  {
    Output_file& f = open_output(args.stats_json);
    f.stream() << stats_json(report);
    f.close();
  }
  for(const std::unique_ptr<Output_file>& f : files)
    f->commit();

  // Text for people, on standard output unless it carries data.
  bool stdout_has_data = false;
  for(const std::unique_ptr<Output_file>& f : files)
    stdout_has_data = stdout_has_data || f->writes_to_stdout();
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
  catch(const vtp_support::Input_error& e) { return fail(e.what()); }
  catch(const Output_error& e) { return fail(e.what()); }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e) { return fail(e.what()); }
  catch(const std::bad_alloc&) { return fail("out of memory"); }
  catch(const std::exception& e) { return fail(e.what()); }
  catch(...) { return fail("unknown error"); }
}
