// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#include "outputs.h"

#include "colour_map.h"
#include "distance_ply.h"
#include "picture.h"
#include "query_points.h"

#include <vtp_support/mesh_formats.h>
#include <vtp_support/number_format.h>

#include <algorithm>
#include <string>

namespace vtp_geodesics_app {

Distance_format distance_format(const std::string& file)
{
  return vtp_support::lower_extension(file) == "ply" ? Distance_format::PLY : Distance_format::TEXT;
}

void write_distances(std::ostream& os, Distance_format format, const vtp_support::Input_mesh& input,
                     const std::vector<double>& distances, const std::vector<int>* labels, double max_distance)
{
  if(format == Distance_format::TEXT)
  {
    vtp_support::write_values_text(os, distances);
    return;
  }
  std::string comment = "VTP_geodesics: geodesic distances (property distance; inf: unreachable)";
  if(labels != nullptr)
    comment += "\nsource: index of the nearest source (-1: none)";
  comment += "\ncolours: " + std::string(colour_map_name()) + " from 0 to "
             + vtp_support::double_to_string(max_distance) + "; grey: unreachable";
  write_distance_ply(os, input, distances, labels, max_distance, comment);
}

void write_labels(std::ostream& os, const std::vector<int>& labels)
{
  std::string text;
  text.reserve(labels.size() * 3);
  for(int l : labels)
  {
    text += std::to_string(l);
    text += '\n';
  }
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
}

Path_format path_format(const std::string& file)
{
  return vtp_support::lower_extension(file) == "obj" ? Path_format::OBJ : Path_format::POLYLINES;
}

void write_paths(std::ostream& os, Path_format format, const std::vector<std::vector<std::array<double, 3> > >& paths,
                 const std::vector<Arguments::Trace>& traces)
{
  std::string text;
  char buffer[vtp_support::max_double_chars];
  auto number = [&](double x) { text.append(buffer, vtp_support::format_double(buffer, x)); };
  if(format == Path_format::POLYLINES)
  {
    for(const std::vector<std::array<double, 3> >& path : paths)
    {
      text += std::to_string(path.size());
      for(const std::array<double, 3>& p : path)
        for(double x : p)
        {
          text += ' ';
          number(x);
        }
      text += '\n';
    }
  }
  else
  {
    const std::size_t geodesic_paths = paths.size() - (std::min)(traces.size(), paths.size());
    if(traces.empty())
      text += "# vtp_geodesics: " + std::to_string(paths.size())
              + " geodesic paths, one 'l' element each, from the target to the source\n";
    else
    {
      auto count = [](std::size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); };
      text += "# vtp_geodesics: ";
      if(geodesic_paths > 0)
        text += count(geodesic_paths, "geodesic path") + ", from the target to the source, then ";
      text += count(traces.size(), "straightest geodesic") + " (--straightest-geodesic), each from its start point, one"
              " 'l' element each\n";
      for(std::size_t k = 0; k < traces.size(); ++k)
      {
        text += "# 'l' element " + std::to_string(geodesic_paths + k + 1) + ": straightest geodesic from vertex "
                + std::to_string(traces[k].vertex) + ", direction (";
        for(int i = 0; i < 3; ++i)
        {
          if(i > 0)
            text += ", ";
          number(traces[k].direction[static_cast<std::size_t>(i)]);
        }
        text += ") projected onto the tangent plane, length ";
        number(traces[k].length);
        text += " (less if it reaches the border)\n";
      }
    }
    for(const std::vector<std::array<double, 3> >& path : paths)
      for(const std::array<double, 3>& p : path)
      {
        text += 'v';
        for(double x : p)
        {
          text += ' ';
          number(x);
        }
        text += '\n';
      }
    std::size_t next = 1; // OBJ numbers vertices from 1
    for(const std::vector<std::array<double, 3> >& path : paths)
    {
      text += 'l';
      for(std::size_t k = 0; k < path.size(); ++k)
        text += ' ' + std::to_string(next + k);
      if(path.size() == 1)
        text += ' ' + std::to_string(next);
      text += '\n';
      next += path.size();
    }
  }
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void write_picture(std::ostream& os, const vtp_support::Mesh& mesh, const std::vector<double>& mesh_distances,
                   double max_distance, const Picture_request& request)
{
  Picture_options options;
  options.isolines = request.isolines;
  if(request.has_view)
  {
    options.has_view = true;
    options.view = request.view;
  }
  Distance_picture picture(options);
  if(request.labels != nullptr)
    picture.set_labels(*request.labels);
  if(request.angles != nullptr)
    picture.set_angles(*request.angles);
  if(request.curves != nullptr)
  {
    std::vector<std::vector<std::array<double, 3> > > lines;
    for(const Curve_set& s : *request.curves)
      if(s.in_picture)
        for(std::size_t i = 0; i < s.curves.size(); ++i)
        {
          lines.push_back(s.curves[i]);
          if(s.closed[i] && !s.curves[i].empty())
            lines.back().push_back(s.curves[i].front());
        }
    picture.set_curves(std::move(lines));
  }
  const vtp_support::Mesh::size_type nv = mesh.number_of_vertices();
  picture.set_mesh(
    static_cast<std::size_t>(nv),
    [&mesh](std::size_t i) {
      const vtp_support::Point_3& p =
        mesh.point(vtp_support::Vertex_index(static_cast<vtp_support::Mesh::size_type>(i)));
      return std::array<double, 3>{ { p.x(), p.y(), p.z() } };
    },
    static_cast<std::size_t>(mesh.number_of_faces()),
    [&mesh](std::size_t f) {
      const vtp_support::Mesh::Halfedge_index h = mesh.halfedge(vtp_support::Mesh::Face_index(
        static_cast<vtp_support::Mesh::size_type>(f)));
      return std::array<std::uint32_t, 3>{ { static_cast<std::uint32_t>(mesh.source(h)),
                                             static_cast<std::uint32_t>(mesh.target(h)),
                                             static_cast<std::uint32_t>(mesh.target(mesh.next(h))) } };
    },
    mesh_distances, max_distance);
  for(const std::vector<std::array<double, 3> >& line : request.polylines)
    picture.add_polyline(line);
  for(const std::array<double, 3>& p : request.markers)
    picture.add_marker(p);
  picture.write_png(os);
}

void write_samples(std::ostream& os, const std::vector<std::size_t>& samples, const std::vector<double>& radii)
{
  std::string text = "# farthest-point samples: vertex (file order), covering radius once it is taken\n";
  for(std::size_t i = 0; i < samples.size(); ++i)
    text += std::to_string(samples[i]) + ' ' + vtp_support::double_to_string(radii[i]) + '\n';
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
}

namespace {

std::array<double, 3> point_of_file_vertex(const vtp_support::Input_mesh& input, std::size_t v)
{
  const vtp_support::Point_3& p = input.file_point(v);
  return std::array<double, 3>{ { p.x(), p.y(), p.z() } };
}

} // namespace

void write_outputs(Output_files& files, const Arguments& args, const vtp_support::Input_mesh& input,
                   const Request& request, const Run_result& run, const File_results& results)
{
  if(!args.output.empty())
    files.write(args.output, [&](std::ostream& os) {
      write_distances(os, distance_format(args.output), input, results.distances,
                      args.several_sources() ? &results.labels : nullptr, results.max_distance);
    });
  if(!args.labels.empty())
    files.write(args.labels, [&](std::ostream& os) { write_labels(os, results.labels); });
  if(!args.target_output.empty())
    files.write(args.target_output,
                [&](std::ostream& os) { vtp_support::write_values_text(os, results.target_distances); });
  if(!args.samples_output.empty())
    files.write(args.samples_output, [&](std::ostream& os) { write_samples(os, results.samples, run.radii); });
  if(!args.path_output.empty())
    files.write(args.path_output,
                [&](std::ostream& os) { write_paths(os, path_format(args.path_output), results.paths, args.traces); });
  if(!args.log_map_output.empty())
    files.write(args.log_map_output, [&](std::ostream& os) { write_log_map(os, results.log_map); });
  if(!args.curves_output.empty())
    files.write(args.curves_output, [&](std::ostream& os) { write_curves_obj(os, run.curves); });
  if(!args.query_output.empty())
    files.write(args.query_output,
                [&](std::ostream& os) { write_query_results(os, run.query_distances, run.query_labels); });
  if(!args.picture.empty())
    files.write(args.picture, [&](std::ostream& os) {
      // the mesh of the computation, with the sources (or the samples) and the paths
      Picture_request p;
      p.isolines = args.isolines;
      p.has_view = args.has_view;
      p.view = args.view;
      for(std::size_t v : args.sources)
        p.markers.push_back(point_of_file_vertex(input, v));
      for(const Located_point& q : request.source_points)
        p.markers.push_back(q.point);
      for(std::size_t v : results.samples)
        p.markers.push_back(point_of_file_vertex(input, v));
      p.polylines = results.paths;
      p.polylines.insert(p.polylines.end(), run.source_curves.begin(), run.source_curves.end());
      if(args.colour_labels)
        p.labels = &run.labels;
      if(args.colour_angle)
        p.angles = &run.log_map;
      if(request.run.picture_isolines || request.run.picture_borders)
        p.curves = &run.curves;
      write_picture(os, input.mesh, input.direct ? results.distances : results.mesh_distances, results.max_distance,
                    p);
    });
}

} // namespace vtp_geodesics_app
