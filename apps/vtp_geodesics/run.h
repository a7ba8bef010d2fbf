// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_RUN_H
#define VTP_GEODESICS_APP_RUN_H

// The computation: the only part of vtp_geodesics that calls the VTP_geodesics library (run.cpp). Everything
// it returns is plain data.

#include <vtp_tools/methods.h>
#include <vtp_tools/read_mesh.h>

#include <cstddef>
#include <string>
#include <vector>

namespace vtp_geodesics_app {

struct Run_request
{
  const vtp_tools::Method_info* method = nullptr;
  int threads = 0;                        // parallel methods; 0: OpenMP's default
  bool has_lambda = false;                // approximate methods: reset period (default: the recommended one)
  double lambda = 0.;
  double lambda_g = 1.;                   // approximate methods: guard band
  std::vector<vtp_tools::Vertex_index> sources; // several: the distance to the nearest one
  bool check_cgal = false;                // also run CGAL::Surface_mesh_shortest_path
};

struct Run_result
{
  std::vector<double> distances;          // per mesh vertex (index order); +inf if unreachable
  std::vector<double> reference;          // CGAL::Surface_mesh_shortest_path's, if check_cgal
  double cgal_seconds = 0.;
  // statistics
  std::string method;
  int threads = 1;
  std::size_t mesh_vertices = 0, mesh_faces = 0;
  double preprocessing_seconds = 0.;      // solver construction
  double propagation_seconds = 0.;        // the propagations (all sources)
  double mean_edge_length = 0., anisotropy = 0.;
  std::size_t windows_created = 0, windows_propagated = 0, peak_live_windows = 0, peak_window_bytes = 0;
  std::size_t vertices_processed = 0, pseudo_sources = 0, resets = 0;
};

// Runs `request` on `mesh`; throws Tool_error or the library's exceptions.
Run_result run_propagation(const vtp_tools::Mesh& mesh, const Run_request& request);

// The lambda used by the approximate methods when none is given.
double recommended_lambda();

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_RUN_H
