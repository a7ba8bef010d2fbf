// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_LOG_MAP_OUTPUT_H
#define VTP_GEODESICS_APP_LOG_MAP_OUTPUT_H

// The log map of vtp_geodesics (--log-map-output, --picture-colour angle): the run's tangent coordinates and
// via vertices (per mesh vertex, run.h) put back on the vertices of the file, and the text written.
//
// The file has one line per vertex of the file, in file order: "rho theta via". rho is the distance (as
// --output), theta the angle in [0, 2 pi) at which the vertex's geodesic leaves its nearest source, in that
// source's tangent frame (doc/VTP_geodesics/log_map.txt), via the last vertex of the file that the geodesic
// passes through (a saddle or border vertex it turns at), -1 if none. An unreached vertex (or one beyond
// --max-distance, or not final with --target) is "inf nan -1"; a source vertex "0 0 -1". Numbers are the
// shortest text that reads back as the same double.
//
// A vertex that the repair of the input split takes the values of its copy nearest to a source (the copy whose
// distance --output gives, as its label), a via vertex that is a copy is written as its vertex of the file.

#include "arguments.h"
#include "run.h"

#include <vtp_support/read_mesh.h>

#include <cstddef>
#include <ostream>
#include <vector>

namespace vtp_geodesics_app {

struct Log_map_results
{
  std::vector<double> rho, theta;     // per vertex of the file; theta in [0, 2 pi), NaN where rho is inf
  std::vector<long long> via;         // per vertex of the file: a vertex of the file, or -1
  std::size_t behind_vertices = 0;    // reached vertices whose geodesic passes through a vertex (via != -1)
};

// The log map of `run` (run.log_map, per mesh vertex) on the vertices of the file. Empty if the run has none.
Log_map_results log_map_on_file_vertices(const Arguments& args, const vtp_support::Input_mesh& input,
                                         const Run_result& run);

// Writes the lines "rho theta via", one per vertex of the file.
void write_log_map(std::ostream& os, const Log_map_results& log_map);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_LOG_MAP_OUTPUT_H
