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
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <CGAL/property_map.h>

#include <vtp_tools/shortest_path_reference.h>

#include <algorithm>
#include <chrono>
#include <limits>

namespace vtp_geodesics_app {

namespace {

typedef CGAL::VTP_geodesics::Geodesic_distance_solver<vtp_tools::Mesh> Solver;

// Runs `method` from `sources`; the distances stay in the solver (read with distances()).
template <class NamedParameters>
void run_method(const vtp_tools::Method_info& method, Solver& solver, const std::vector<vtp_tools::Vertex_index>& sources,
                const NamedParameters& np)
{
  const CGAL::Constant_property_map<vtp_tools::Vertex_index, double> no_map;
  if(!method.parallel)
  {
    solver.compute<CGAL::Sequential_tag>(no_map, sources, np);
    return;
  }
#ifdef _OPENMP
  solver.compute<CGAL::Parallel_tag>(no_map, sources, np);
#else
  throw Tool_error(std::string("method ") + method.name + " needs OpenMP, and this program was built without it");
#endif
}

} // namespace

double recommended_lambda() { return CGAL::VTP_geodesics::recommended_lambda; }

Run_result run_propagation(const vtp_tools::Mesh& mesh, const Run_request& request)
{
  const vtp_tools::Method_info& method = *request.method;
  const double lambda = !method.approximate ? std::numeric_limits<double>::infinity()
                       : (request.has_lambda ? request.lambda : recommended_lambda());
  const auto options = CGAL::VTP_geodesics::parameters::number_of_threads(request.threads)
                         .lambda(lambda).lambda_g(request.lambda_g);

  Solver solver(mesh);
  Run_result r;
  r.method = method.name;
  r.mesh_vertices = solver.number_of_vertices();
  r.mesh_faces = solver.number_of_faces();
  r.preprocessing_seconds = solver.preprocessing_seconds();
  r.mean_edge_length = solver.mean_edge_length();
  r.anisotropy = solver.anisotropy();

  // The solver numbers the vertices in the order of vertices(mesh), which is the index order of a
  // Surface_mesh without removed elements. Several sources: one run from all of them.
  const double infinity = std::numeric_limits<double>::infinity();
  if(request.sources.empty())
    r.distances.assign(r.mesh_vertices, infinity);
  else
  {
    run_method(method, solver, request.sources, options);
    const CGAL::VTP_geodesics::Propagation_statistics& st = solver.statistics();
    r.threads = st.threads;
    r.propagation_seconds = st.seconds;
    r.windows_created = st.windows_created;
    r.windows_propagated = st.windows_propagated;
    r.peak_live_windows = st.peak_live_windows;
    r.peak_window_bytes = st.peak_window_bytes;
    r.vertices_processed = st.vertices_processed;
    r.pseudo_sources = st.pseudo_sources;
    r.resets = st.resets;
    r.distances = solver.distances();
  }

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
