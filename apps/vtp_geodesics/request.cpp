// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The request made from the command line (see request.h).

#include "request.h"
#include "query_points.h"

#include <vtp_support/number_format.h>
#include <vtp_support/surface_locator.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace vtp_geodesics_app {

namespace {

// Throws unless every vertex of `vertices` is a vertex of the file.
void check_vertices(const std::vector<std::size_t>& vertices, const vtp_support::Input_mesh& input, const char* what)
{
  for(std::size_t v : vertices)
    if(v >= input.file_vertices)
      throw Tool_error(std::string(what) + " vertex " + std::to_string(v) + " is out of range (the mesh has "
                       + std::to_string(input.file_vertices) + " vertices)");
}

std::string point_text(const std::array<double, 3>& p)
{
  return vtp_support::double_to_string(p[0]) + "," + vtp_support::double_to_string(p[1]) + ","
         + vtp_support::double_to_string(p[2]);
}

// The paths (see Request): to a source vertex, its point; from another vertex, all its copies (the run starts
// the path at the copy nearest to a source); from a point, its location.
void add_paths(const Arguments& args, const vtp_support::Input_mesh& input,
               const std::vector<Located_point>& path_points, Request& r)
{
  r.paths.assign(args.path_to.size() + path_points.size(), std::vector<std::array<double, 3> >());
  r.traced.assign(r.paths.size(), -1);
  for(std::size_t k = 0; k < args.path_to.size(); ++k)
  {
    const std::size_t v = args.path_to[k];
    if(std::find(args.sources.begin(), args.sources.end(), v) != args.sources.end())
    {
      const vtp_support::Point_3& p = input.file_point(v);
      r.paths[k].push_back({ { p.x(), p.y(), p.z() } });
      continue;
    }
    Run_request::Path path;
    path.name = "vertex " + std::to_string(v) + " (--path-to)";
    path.copies = input.mesh_vertices_of(v);
    if(path.copies.empty())
      throw Tool_error("no path from " + path.name + ": no source reaches it (it is in no face of the mesh)");
    r.traced[k] = static_cast<long long>(r.run.paths.size());
    r.run.paths.push_back(path);
  }
  for(std::size_t j = 0; j < path_points.size(); ++j)
  {
    Run_request::Path path;
    path.name = "point " + point_text(args.path_to_points[j]) + " (--path-to-point)";
    path.is_point = true;
    path.location = path_points[j].location;
    r.traced[args.path_to.size() + j] = static_cast<long long>(r.run.paths.size());
    r.run.paths.push_back(path);
  }
}

} // namespace

Request make_request(const Arguments& args, const vtp_support::Method_info& method,
                     const vtp_support::Input_mesh& input)
{
  check_vertices(args.sources, input, "source");
  check_vertices(args.targets, input, "target");
  check_vertices(args.path_to, input, "path");
  if(args.has_first)
    check_vertices(std::vector<std::size_t>(1, args.first), input, "--first");

  // Points, located on the mesh of the computation (the repaired mesh, if the file needed a repair).
  const std::vector<std::array<double, 3> > query_points =
    args.query_points.empty() ? std::vector<std::array<double, 3> >() : read_query_points(args.query_points);
  std::unique_ptr<Point_locator> locator;
  if(!args.source_points.empty() || !args.target_points.empty() || !args.path_to_points.empty()
     || !query_points.empty() || !args.source_curves.empty())
    locator.reset(new Point_locator(input.mesh));
  auto locate_all = [&locator](const std::vector<std::array<double, 3> >& points, const char* option) {
    std::vector<Located_point> located;
    for(const std::array<double, 3>& p : points)
      located.push_back(locator->locate(p, option));
    return located;
  };
  Request r;
  r.source_points = locate_all(args.source_points, "--source-point");
  const std::vector<Located_point> target_points = locate_all(args.target_points, "--target-point");
  const std::vector<Located_point> path_points = locate_all(args.path_to_points, "--path-to-point");
  if(!args.source_curves.empty())
  {
    const double tolerance = vtp_support::curve_point_tolerance * vtp_support::bounding_box_diagonal(input.mesh);
    for(const Arguments::Curve& c : args.source_curves)
    {
      Run_request::Curve curve;
      curve.name = c.name;
      r.source_curves.push_back(std::vector<Located_point>());
      for(std::size_t i = 0; i < c.points.size(); ++i)
      {
        const Located_point q = locator->locate(c.points[i], c.name);
        const double dx = q.point[0] - c.points[i][0], dy = q.point[1] - c.points[i][1],
                     dz = q.point[2] - c.points[i][2];
        const double off = std::sqrt(dx * dx + dy * dy + dz * dz);
        if(!(off <= tolerance))
          throw Tool_error(c.name + ": point " + std::to_string(i + 1) + " (" + point_text(c.points[i])
                           + ") is off the surface (at " + vtp_support::double_to_string(off)
                           + " from it; at most 1e-6 of the mesh's bounding box diagonal, "
                           + vtp_support::double_to_string(tolerance) + ")");
        curve.points.push_back(q.location);
        r.source_curves.back().push_back(q);
      }
      r.run.source_curves.push_back(curve);
    }
  }
  for(std::size_t i = 0; i < query_points.size(); ++i)
    r.run.query_locations.push_back(
      locator->locate(query_points[i], "--query-points (line " + std::to_string(i + 1) + ")").location);

  // The mesh vertices standing for a file vertex: one, several if the repair duplicated it (as a source or a
  // target, all are), none if the repair removed it (a vertex in no face: only itself is reachable).
  Run_request& run = r.run;
  run.method = &method;
  run.threads = args.threads;
  run.has_lambda = args.has_lambda;
  run.lambda = args.lambda;
  run.lambda_g = args.lambda_g;
  for(std::size_t i = 0; i < args.sources.size(); ++i)
    for(vtp_support::Vertex_index v : input.mesh_vertices_of(args.sources[i]))
    {
      run.source_vertices.push_back(v);
      run.source_vertex_labels.push_back(i);
    }
  for(std::size_t j = 0; j < r.source_points.size(); ++j)
  {
    run.source_locations.push_back(r.source_points[j].location);
    run.source_location_labels.push_back(args.sources.size() + j);
  }
  for(std::size_t k = 0; k < r.run.source_curves.size(); ++k)
    run.source_curve_labels.push_back(args.sources.size() + r.source_points.size() + k);
  run.source_border = args.source_border;
  run.source_border_label = args.sources.size() + r.source_points.size() + r.run.source_curves.size();
  run.signed_distance = args.signed_distance;
  run.want_curves = !args.curves_output.empty();
  // the picture draws the curves of the library but after runs through the split vertices (it interpolates then),
  // and the borders of cells of sources that are curves (the library draws their isolines only)
  const bool picture_curves = !args.picture.empty() && !args.through_pinches;
  run.picture_isolines = picture_curves && !args.colour_labels && args.isolines > 0;
  run.picture_borders = picture_curves && args.colour_labels && !args.has_curve_sources();
  run.curve_levels = args.levels;
  run.keep_field = args.wants_field();
  run.curve_isolines = args.isolines;
  run.want_labels = args.several_sources() || !args.labels.empty() || args.farthest_points > 0 || args.colour_labels;
  run.max_distance = args.max_distance;
  for(std::size_t v : args.targets)
    for(vtp_support::Vertex_index c : input.mesh_vertices_of(v))
      run.target_vertices.push_back(c);
  for(const Located_point& p : target_points)
    run.target_locations.push_back(p.location);
  run.stop_at_targets = args.has_targets();
  add_paths(args, input, path_points, r);
  for(std::size_t k = 0; k < args.traces.size(); ++k)
  {
    Run_request::Trace t;
    t.name = "--straightest-geodesic " + std::to_string(k) + " (from vertex " + std::to_string(args.traces[k].vertex) + ")";
    check_vertices(std::vector<std::size_t>(1, args.traces[k].vertex), input, "--straightest-geodesic");
    const std::vector<vtp_support::Vertex_index> copies = input.mesh_vertices_of(args.traces[k].vertex);
    if(copies.empty())
      throw Tool_error(t.name + ": the vertex is in no face of the mesh");
    t.start = copies.front();
    t.direction = args.traces[k].direction;
    t.length = args.traces[k].length;
    run.traces.push_back(t);
  }
  run.check_cgal = args.check_cgal;
  run.log_map = args.wants_log_map();
  run.log_map_strict = args.log_map_strict;
  run.has_reference_direction = args.has_reference_direction;
  run.reference_direction = args.reference_direction;
  if(args.through_pinches && !input.direct)
  {
    // the copies of each split vertex, once (coincident vertices of the file that the repair merged share them)
    std::vector<unsigned char> seen(input.mesh.number_of_vertices(), 0);
    for(std::size_t i = 0; i < input.file_vertices; ++i)
    {
      const std::vector<vtp_support::Vertex_index> copies = input.mesh_vertices_of(i);
      if(copies.size() > 1 && !seen[std::size_t(copies.front())])
      {
        seen[std::size_t(copies.front())] = 1;
        run.joined_copies.push_back(copies);
      }
    }
  }
  if(args.farthest_points > 0)
  {
    run.farthest_points = args.farthest_points;
    run.radius = args.radius;
    if(args.has_first)
    {
      const std::vector<vtp_support::Vertex_index> copies = input.mesh_vertices_of(args.first);
      if(copies.empty())
        throw Tool_error("--first vertex " + std::to_string(args.first) + " is in no face of the mesh");
      run.has_first = true;
      run.first = copies.front();
    }
  }
  return r;
}

} // namespace vtp_geodesics_app
