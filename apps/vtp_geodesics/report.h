// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_REPORT_H
#define VTP_GEODESICS_APP_REPORT_H

// What vtp_geodesics says about a run: the JSON statistics (--stats-json), the summary for people, and the
// comparison with CGAL's Surface_mesh_shortest_path (--check-cgal).

#include "arguments.h"
#include "file_results.h"
#include "run.h"

#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>
#include <vtp_support/statistics.h>

#include <cstddef>
#include <ostream>
#include <string>

namespace vtp_geodesics_app {

struct Report
{
  std::string mesh;                        // file name
  std::string reader;                      // which reader read it
  std::string method;                      // the method asked for (--method)
  std::string repairs;                     // what the repair did; empty if nothing
  std::size_t vertices = 0, faces = 0;     // of the file
  std::size_t sources = 0;                 // number of sources (vertices, points, curves, the border)
  bool single_vertex_source = false;       // one source, a vertex:
  std::size_t source = 0;                  // that vertex (file order)
  std::string sources_text;                // for people: "0, 17, 42 and 1 surface point"
  bool log_map_strict = false;             // --log-map-strict
  bool has_max_distance = false;
  double max_distance_limit = 0.;
  const Run_result* run = nullptr;         // the computation
  const File_results* results = nullptr;   // its results in the file's terms
  vtp_support::Stage_seconds stages;      // from the file to the answer (write and total: set by main.cpp)
  double peak_rss_mb = 0.;
};

// The report of a run (but the stages of writing and in all, and the peak memory).
Report make_report(const std::string& mesh_file, const Arguments& args, const vtp_support::Method_info& method,
                   const vtp_support::Input_mesh& input, const Run_result& run, const File_results& results);

std::string stats_json(const Report& r);
void print_summary(std::ostream& os, const Report& r);
void print_check(std::ostream& os, const Report& r);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_REPORT_H
