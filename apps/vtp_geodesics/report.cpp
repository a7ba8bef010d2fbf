// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// What vtp_geodesics says about a run (see report.h).

#include "report.h"

#include <vtp_support/statistics.h>

#include <algorithm>
#include <sstream>

namespace vtp_geodesics_app {

namespace {

using vtp_support::json_value;

std::string json_value_or_null(bool has_value, double x) { return has_value ? json_value(x) : std::string("null"); }

} // namespace

Report make_report(const std::string& mesh_file, const Arguments& args, const vtp_support::Method_info& method,
                   const vtp_support::Input_mesh& input, const Run_result& run, const File_results& results)
{
  Report report;
  report.mesh = mesh_file;
  report.reader = input.reader;
  report.method = method.name;
  report.repairs = input.repairs.summary();
  report.vertices = input.file_vertices;
  report.faces = input.file_faces;
  const bool sampling = args.farthest_points > 0;
  const std::size_t samples = results.samples.size();
  report.sources = sampling ? samples : args.number_of_sources();
  report.single_vertex_source = args.number_of_sources() == 1 && args.sources.size() == 1;
  if(sampling)
    report.sources_text = std::to_string(samples) + (samples == 1 ? " farthest point" : " farthest points");
  report.source = args.sources.empty() ? 0 : args.sources.front();
  for(std::size_t i = 0; i < args.sources.size(); ++i)
    report.sources_text += (i == 0 ? "" : ", ") + std::to_string(args.sources[i]);
  if(!args.source_points.empty())
    report.sources_text += (args.sources.empty() ? "" : " and ") + std::to_string(args.source_points.size())
                           + (args.source_points.size() == 1 ? " surface point" : " surface points");
  if(!args.source_curves.empty())
    report.sources_text += (report.sources_text.empty() ? "" : " and ") + std::to_string(args.source_curves.size())
                           + (args.source_curves.size() == 1 ? " curve" : " curves");
  if(args.source_border)
    report.sources_text += (report.sources_text.empty() ? "" : " and ") + std::string("the border");
  if(args.signed_distance)
    report.sources_text += " (signed)";
  report.log_map_strict = args.log_map_strict;
  report.has_max_distance = args.has_max_distance;
  report.max_distance_limit = args.max_distance;
  report.run = &run;
  report.results = &results;
  report.stages.read = input.read_seconds;
  report.stages.repair = input.repair_seconds;
  report.stages.preprocessing = run.preprocessing_seconds;
  report.stages.propagation = run.statistics.seconds;
  return report;
}

std::string stats_json(const Report& r)
{
  const Run_result& s = *r.run;
  const File_results& f = *r.results;
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
     << ", \"targets\": " << f.target_distances.size()
     << ", \"paths\": " << f.paths.size()
     << ", \"query_points\": " << s.query_distances.size()
     << ", \"method\": " << json_value(r.method)
     << ", \"preprocessing_threads\": " << s.preprocessing_threads;
  // the stages from the file to the answer, from their description (vtp_support/statistics.h): read_seconds,
  // repair_seconds, ..., total_seconds, outside_propagation_ratio
  vtp_support::write_stages_json(os, r.stages, ", ");
  os << ", \"peak_rss_mb\": " << json_value(r.peak_rss_mb)
     << ", \"reached_vertices\": " << f.reached_vertices
     << ", \"max_distance\": " << json_value(f.max_distance)
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
  if(!f.log_map.rho.empty())
    os << ", \"log_map\": " << json_value(std::string(r.log_map_strict ? "strict" : "default"))
       << ", \"log_map_behind_vertices\": " << f.log_map.behind_vertices;
  if(f.checked)
    os << ", \"cgal_seconds\": " << json_value(s.cgal_seconds)
       << ", \"max_abs_diff\": " << json_value(f.comparison.max_abs_diff)
       << ", \"max_rel_diff\": " << json_value(f.comparison.max_rel_diff)
       << ", \"mean_rel_diff\": " << json_value(f.comparison.mean_rel_diff)
       << ", \"mismatched_infinities\": " << f.comparison.mismatched_infinities;
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
  const File_results& f = *r.results;
  os << "mesh: " << r.mesh << "\n"
     << "vertices: " << r.vertices << ", faces: " << r.faces << (r.sources == 1 ? ", source: " : ", sources: ")
     << r.sources_text << "\n"
     << "method: " << r.method << ", propagation: " << st.seconds
     << " s, preprocessing: " << s.preprocessing_seconds << " s, reading: " << r.stages.read + r.stages.repair
     << " s\n"
     << "max distance: " << f.max_distance << " (" << f.reached_vertices << " of " << r.vertices
     << " vertices reached" << (st.stopped_early ? "; stopped early" : "") << ")\n"
     << "windows: " << st.windows_created << " created, " << st.windows_propagated << " propagated, peak "
     << st.peak_live_windows << " alive (" << st.peak_window_bytes << " bytes)\n";
  if(!s.samples.empty())
  {
    const auto areas = std::minmax_element(s.cell_areas.begin(), s.cell_areas.end());
    double total = 0.;
    for(double a : s.cell_areas)
      total += a;
    os << "farthest points: " << s.samples.size() << (s.samples.size() == 1 ? " sample" : " samples")
       << ", covering radius " << s.radii.back() << "\n"
       << "Voronoi cells: area " << *areas.first << " to " << *areas.second << " (total " << total << ")\n";
  }
  if(!r.repairs.empty())
    os << "triangle mesh: " << s.mesh_vertices << " vertices, " << s.mesh_faces << " faces\n";
}

void print_check(std::ostream& os, const Report& r)
{
  const vtp_support::Distance_comparison& c = r.results->comparison;
  os << "CGAL Surface_mesh_shortest_path: " << r.run->cgal_seconds << " s, max abs diff " << c.max_abs_diff
     << ", max rel diff " << c.max_rel_diff;
  if(c.mismatched_infinities != 0)
    os << ", " << c.mismatched_infinities << " reachability mismatches";
  os << "\n";
}

} // namespace vtp_geodesics_app
