// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_FILE_RESULTS_H
#define VTP_GEODESICS_APP_FILE_RESULTS_H

// The results of the run in the file's terms: per vertex of the file, in its order; the samples as vertices of
// the file; the paths in the order of the command line. The vertices go from the mesh back to the file through
// the correspondence that the reading keeps (vtp_support::Input_mesh: on_file_vertices(), file_vertex_of()).

#include "arguments.h"
#include "log_map_output.h"
#include "request.h"
#include "run.h"

#include <vtp_support/read_mesh.h>
#include <vtp_support/shortest_path_reference.h>

#include <array>
#include <cstddef>
#include <vector>

namespace vtp_geodesics_app {

struct File_results
{
  // Per vertex of the file: the distance (the smallest of its copies, with --signed the one of least absolute
  // value; 0 at a source vertex; +inf if unreachable), and the label of its nearest source (the request wanted
  // labels: -1 where none).
  std::vector<double> distances;
  std::vector<int> labels;
  // Per vertex of the mesh of the computation, when it is not the file's (a repaired mesh) and a picture is
  // drawn: the distances (else empty: the picture draws `distances`).
  std::vector<double> mesh_distances;
  std::vector<double> target_distances;      // the --target vertices, then the --target-point points
  std::vector<std::size_t> samples;          // farthest-point sampling: the samples, in order
  std::vector<std::vector<std::array<double, 3> > > paths; // of --path-output, in its order
  std::size_t reached_vertices = 0;          // vertices of the file at a finite distance
  double max_distance = 0.;                  // the largest finite distance
  bool checked = false;                      // --check-cgal: the distances against CGAL's
  vtp_support::Distance_comparison comparison;
  Log_map_results log_map;                   // --log-map-output, --picture-colour angle (else empty)
};

// Puts the results of `request` back in the file's terms (moves from `result`'s distances and paths).
File_results file_results(const Arguments& args, const vtp_support::Input_mesh& input, Request& request,
                          Run_result& result);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_FILE_RESULTS_H
