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

#include <vtp_support/mesh_formats.h>
#include <vtp_support/number_format.h>
#include <vtp_support/statistics.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <sstream>

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

void write_paths(std::ostream& os, Path_format format, const std::vector<std::vector<std::array<double, 3> > >& paths)
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
    text += "# vtp_geodesics: " + std::to_string(paths.size())
            + " geodesic paths, one 'l' element each, from the target to the source\n";
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
  const vtp_support::Mesh::size_type nv = mesh.number_of_vertices();
  picture.set_mesh(
    static_cast<std::size_t>(nv),
    [&mesh](std::size_t i) {
      const vtp_support::Point_3& p = mesh.point(vtp_support::Vertex_index(static_cast<vtp_support::Mesh::size_type>(i)));
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

using vtp_support::json_value;

std::string json_value_or_null(bool has_value, double x) { return has_value ? json_value(x) : std::string("null"); }

} // namespace

std::string stats_json(const Report& r)
{
  const Run_result& s = *r.run;
  std::ostringstream os;
  os << "{"
     << "\"mesh\": " << json_value(r.mesh)
     << ", \"vertices\": " << r.vertices
     << ", \"faces\": " << r.faces
     << ", \"mesh_vertices\": " << s.mesh_vertices
     << ", \"mesh_faces\": " << s.mesh_faces
     << ", \"reader\": " << json_value(r.reader)
     << ", \"repairs\": " << json_value(r.repairs)
     << ", \"sources\": " << r.sources
     << ", \"source\": " << (r.single_vertex_source ? std::to_string(r.source) : std::string("null"))
     << ", \"max_distance_limit\": " << json_value_or_null(r.has_max_distance, r.max_distance_limit)
     << ", \"targets\": " << r.targets
     << ", \"paths\": " << r.paths
     << ", \"method\": " << json_value(r.method)
     << ", \"preprocessing_threads\": " << s.preprocessing_threads
     << ", \"read_seconds\": " << json_value(r.read_seconds)
     << ", \"repair_seconds\": " << json_value(r.repair_seconds)
     << ", \"preprocessing_seconds\": " << json_value(s.preprocessing_seconds)
     << ", \"propagation_seconds\": " << json_value(s.statistics.seconds)
     << ", \"write_seconds\": " << json_value(r.write_seconds)
     << ", \"total_seconds\": " << json_value(r.total_seconds)
     << ", \"peak_rss_mb\": " << json_value(r.peak_rss_mb)
     << ", \"reached_vertices\": " << r.reached_vertices
     << ", \"max_distance\": " << json_value(r.max_distance)
     << ", \"mean_edge_length\": " << json_value(s.mean_edge_length)
     << ", \"anisotropy\": " << json_value(s.anisotropy);
  if(!s.samples.empty())
  {
    const auto areas = std::minmax_element(s.cell_areas.begin(), s.cell_areas.end());
    os << ", \"samples\": " << s.samples.size()
       << ", \"covering_radius\": " << json_value(s.radii.back())
       << ", \"min_cell_area\": " << json_value(*areas.first)
       << ", \"max_cell_area\": " << json_value(*areas.second);
  }
  if(r.checked)
    os << ", \"cgal_seconds\": " << json_value(s.cgal_seconds)
       << ", \"max_abs_diff\": " << json_value(r.comparison.max_abs_diff)
       << ", \"max_rel_diff\": " << json_value(r.comparison.max_rel_diff)
       << ", \"mean_rel_diff\": " << json_value(r.comparison.mean_rel_diff)
       << ", \"mismatched_infinities\": " << r.comparison.mismatched_infinities;
  // Then the library's statistics, from their description (vtp_support/statistics.h): threads, seconds (the same
  // as propagation_seconds), the window counts, stopped_early, ... Six of its names are members above, with the
  // tool's meaning, and are not written again: vertices, faces, sources, reached_vertices and max_distance are
  // those of the file (the description's: of the mesh of the computation, counting the copies that a repair
  // made), and method is the method asked for (the description's: the one that ran, "vtp" when none did).
  vtp_support::write_statistics_json(os, s.statistics, ", ",
                                     { "vertices", "faces", "sources", "reached_vertices", "max_distance", "method" });
  os << "}\n";
  return os.str();
}

void print_summary(std::ostream& os, const Report& r)
{
  const Run_result& s = *r.run;
  const CGAL::VTP_geodesics::Propagation_statistics& st = s.statistics;
  os << "mesh: " << r.mesh << "\n"
     << "vertices: " << r.vertices << ", faces: " << r.faces << (r.sources == 1 ? ", source: " : ", sources: ")
     << r.sources_text << "\n"
     << "method: " << r.method << ", propagation: " << st.seconds
     << " s, preprocessing: " << s.preprocessing_seconds << " s, reading: " << r.read_seconds + r.repair_seconds
     << " s\n"
     << "max distance: " << r.max_distance << " (" << r.reached_vertices << " of " << r.vertices
     << " vertices reached" << (st.stopped_early ? "; stopped early" : "") << ")\n"
     << "windows: " << st.windows_created << " created, " << st.windows_propagated << " propagated, peak "
     << st.peak_live_windows << " alive (" << st.peak_window_bytes << " bytes)\n";
  if(!s.samples.empty())
  {
    const auto areas = std::minmax_element(s.cell_areas.begin(), s.cell_areas.end());
    double total = 0.;
    for(double a : s.cell_areas)
      total += a;
    os << "farthest points: " << s.samples.size() << (s.samples.size() == 1 ? " sample" : " samples") << ", covering radius " << s.radii.back() << "\n"
       << "Voronoi cells: area " << *areas.first << " to " << *areas.second << " (total " << total << ")\n";
  }
  if(!r.repairs.empty())
    os << "triangle mesh: " << s.mesh_vertices << " vertices, " << s.mesh_faces << " faces\n";
}

void print_check(std::ostream& os, const Report& r)
{
  os << "CGAL Surface_mesh_shortest_path: " << r.run->cgal_seconds << " s, max abs diff "
     << r.comparison.max_abs_diff << ", max rel diff " << r.comparison.max_rel_diff;
  if(r.comparison.mismatched_infinities != 0)
    os << ", " << r.comparison.mismatched_infinities << " reachability mismatches";
  os << "\n";
}

} // namespace vtp_geodesics_app
