// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Every call of vtp_geodesics into the VTP_geodesics library is in this file.

#include "run.h"
#include "arguments.h"

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/options_and_statistics.h>

#include <vtp_tools/shortest_path_reference.h>

#include <algorithm>
#include <chrono>
#include <limits>

namespace vtp_geodesics_app {

namespace {

typedef CGAL::VTP_geodesics::Geodesic_distance_solver<vtp_tools::Mesh> Solver;

const CGAL::VTP_geodesics::Propagation_statistics&
run_method(const vtp_tools::Method_info& method, Solver& solver, vtp_tools::Vertex_index source,
           const CGAL::VTP_geodesics::Propagation_options& options)
{
  if(!method.parallel)
    return solver.compute_dense<CGAL::Sequential_tag>(source, options);
#ifdef _OPENMP
  return solver.compute_dense<CGAL::Parallel_tag>(source, options);
#else
  throw Tool_error(std::string("method ") + method.name + " needs OpenMP, and this program was built without it");
#endif
}

} // namespace

double recommended_lambda() { return CGAL::VTP_geodesics::Propagation_options::recommended_lambda; }

Run_result run_propagation(const vtp_tools::Mesh& mesh, const Run_request& request)
{
  const vtp_tools::Method_info& method = *request.method;
  CGAL::VTP_geodesics::Propagation_options options;
  options.number_of_threads = request.threads;
  if(method.approximate)
  {
    options.lambda = request.has_lambda ? request.lambda : recommended_lambda();
    options.lambda_g = request.lambda_g;
  }

  Solver solver(mesh);
  Run_result r;
  r.method = method.name;
  r.mesh_vertices = solver.number_of_vertices();
  r.mesh_faces = solver.number_of_faces();
  r.preprocessing_seconds = solver.preprocessing_seconds();
  r.mean_edge_length = solver.mean_edge_length();
  r.anisotropy = solver.anisotropy();

  // The solver numbers the vertices in the order of vertices(mesh), which is the index order of a
  // Surface_mesh without removed elements. Several sources: the minimum over one run per source.
  const double infinity = std::numeric_limits<double>::infinity();
  for(std::size_t k = 0; k < request.sources.size(); ++k)
  {
    const CGAL::VTP_geodesics::Propagation_statistics& st = run_method(method, solver, request.sources[k], options);
    r.threads = st.threads;
    r.propagation_seconds += st.seconds;
    r.windows_created += st.windows_created;
    r.windows_propagated += st.windows_propagated;
    r.peak_live_windows = (std::max)(r.peak_live_windows, st.peak_live_windows);
    r.peak_window_bytes = (std::max)(r.peak_window_bytes, st.peak_window_bytes);
    r.vertices_processed += st.vertices_processed;
    r.pseudo_sources += st.pseudo_sources;
    r.resets += st.resets;
    const std::vector<double>& d = solver.distances();
    if(k == 0)
      r.distances = d;
    else
      for(std::size_t j = 0; j < r.distances.size(); ++j)
        r.distances[j] = (std::min)(r.distances[j], d[j]);
  }
  if(request.sources.empty())
    r.distances.assign(r.mesh_vertices, infinity);

  if(request.check_cgal)
  {
    const auto t0 = std::chrono::steady_clock::now();
    r.reference.assign(mesh.number_of_vertices(), infinity);
    for(vtp_tools::Vertex_index s : request.sources)
    {
      const std::vector<double> d = vtp_tools::shortest_path_reference_distances(mesh, s);
      for(std::size_t j = 0; j < r.reference.size(); ++j)
        r.reference[j] = (std::min)(r.reference[j], d[j]);
    }
    r.cgal_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return r;
}

} // namespace vtp_geodesics_app
