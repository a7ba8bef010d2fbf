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

#include "curves_output.h"
#include "locate.h"

#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace vtp_geodesics_app {

struct Run_request
{
  const vtp_support::Method_info* method = nullptr;
  int threads = 0;                        // parallel methods and preprocessing; 0: OpenMP's default
  bool has_lambda = false;                // approximate methods: reset period (default: the recommended one)
  double lambda = 0.;
  double lambda_g = 1.;                   // approximate methods: guard band
  // --curves-output: the isolines at curve_levels (empty: about `curve_isolines` round levels), and the
  // borders of the cells with several sources (curves_output.h)
  bool want_curves = false;
  std::vector<double> curve_levels;
  int curve_isolines = 10;
  // --picture: it draws the library's curves (from the same extraction as --curves-output): the isolines at its
  // levels (about `curve_isolines` round values), or with the label colouring the borders of the cells
  bool picture_isolines = false;
  bool picture_borders = false;
  bool wants_curves() const { return want_curves || picture_isolines || picture_borders; }
  // --keep-field (--query-points): the run keeps its field (exact methods), which answers at the query points
  // (located as the target points). With an exact method the curves come from the kept field too (else from the
  // run's trace-back record, per vertex).
  bool keep_field = false;
  std::vector<Face_location> query_locations;
  // The sources: mesh vertices, then points of the surface, each with the index of the source of the command
  // line it stands for (its label; the copies of a vertex share one). None: nothing is computed (all +inf).
  std::vector<vtp_support::Vertex_index> source_vertices;
  std::vector<std::size_t> source_vertex_labels;
  std::vector<Face_location> source_locations;
  std::vector<std::size_t> source_location_labels;
  // then the curves (each one source: its points, joined by the library), and the border of the mesh
  struct Curve
  {
    std::string name;                     // for the errors: "curve 1 of --source-curve file 'f' (lines 1-5)"
    std::vector<Face_location> points;
  };
  std::vector<Curve> source_curves;
  std::vector<std::size_t> source_curve_labels;
  bool source_border = false;
  std::size_t source_border_label = 0;
  bool signed_distance = false;           // --signed: negative on the left of the curves
  bool has_curve_sources() const { return !source_curves.empty() || source_border; }
  bool want_labels = false;               // fill Run_result::labels
  double max_distance = std::numeric_limits<double>::infinity();
  // Targets: mesh vertices and points of the surface whose distance must be final when the run stops (with
  // stop_at_targets; else the run goes on to the end).
  std::vector<vtp_support::Vertex_index> target_vertices;
  std::vector<Face_location> target_locations;
  bool stop_at_targets = true;
  // Paths to trace after the run; their end points must be among the targets (so that the run records
  // them). A vertex path starts at its copy nearest to a source.
  struct Path
  {
    std::string name;                     // for the errors: "vertex 12 (--path-to)"
    std::vector<vtp_support::Vertex_index> copies; // a vertex: the mesh vertices standing for it (not empty)
    bool is_point = false;                // else a point of the surface:
    Face_location location;
  };
  std::vector<Path> paths;
  // Straightest geodesics to walk (--trace): from a mesh vertex, a 3D direction (projected), a length.
  struct Trace
  {
    std::string name;                     // for the errors: "--trace 2"
    vtp_support::Vertex_index start;
    std::array<double, 3> direction = { { 1., 0., 0. } };
    double length = 0.;
  };
  std::vector<Trace> traces;
  bool check_cgal = false;                // also run CGAL::Surface_mesh_shortest_path
  // --through-pinches: the copies of each vertex that the repair split, joined after the run (which then goes
  // to the end: max_distance and the targets bound the result, not the work)
  std::vector<std::vector<vtp_support::Vertex_index> > joined_copies;
  // Farthest-point sampling (instead of the sources above): up to farthest_points samples, from `first` (or
  // the vertex farthest from vertex 0), until the covering radius is <= radius.
  std::size_t farthest_points = 0;
  bool has_first = false;
  vtp_support::Vertex_index first;
  double radius = 0.;
  // The log map (vtp, pvtp; see log_map_output.h): the run also gives each vertex its tangent coordinates
  bool log_map = false;
  bool log_map_strict = false;
  bool has_reference_direction = false;
  std::array<double, 3> reference_direction = { { 1., 0., 0. } };
};

struct Run_result
{
  std::vector<double> distances;          // per mesh vertex (index order); +inf if unreachable
  std::vector<int> labels;                // want_labels: per mesh vertex, the nearest source's label or -1
  std::vector<double> target_location_distances; // per target location
  std::vector<std::vector<std::array<double, 3> > > paths; // per path: its points, target first, source last
  std::vector<std::vector<std::array<double, 3> > > traces; // per trace: its points, start first
  std::vector<std::vector<std::array<double, 3> > > source_curves; // per source curve: its points as joined
  std::vector<double> reference;          // CGAL::Surface_mesh_shortest_path's, if check_cgal
  double cgal_seconds = 0.;
  std::size_t join_runs = 0;              // --through-pinches: the runs that joined the copies
  // The library's statistics of the propagation (with farthest-point sampling, those it gives for the whole
  // sampling); default values when nothing ran (no source).
  CGAL::VTP_geodesics::Propagation_statistics statistics;
  int preprocessing_threads = 1;          // reading the mesh and building the solver's arrays
  std::size_t mesh_vertices = 0, mesh_faces = 0;
  double preprocessing_seconds = 0.;      // solver construction
  double mean_edge_length = 0., anisotropy = 0.;
  // farthest-point sampling: the samples (mesh vertices) in order, the covering radius after each, and the
  // area of the geodesic Voronoi cell of each with the area of its faces shared with other cells
  std::vector<vtp_support::Vertex_index> samples;
  std::vector<double> radii;
  std::vector<double> cell_areas, cell_uncertainty;
  // log_map: per mesh vertex, rho (cos theta, sin theta) ({inf, inf} if unreached) and the last mesh vertex its
  // geodesic passes through (-1: none)
  std::vector<std::array<double, 2> > log_map;
  std::vector<long long> log_map_via;
  std::vector<Curve_set> curves;          // --curves-output and --picture (Curve_set::in_output, in_picture)
  // per query location: its distance (+inf if unreached) and its nearest source's label (-1: none)
  std::vector<double> query_distances;
  std::vector<int> query_labels;
  // The solver of the run, with its kept field: freed with the result, or never (main.cpp leaves the process
  // without freeing what the OS takes back anyway).
  std::shared_ptr<const void> solver;
};

// Runs `request` on `mesh`; throws Tool_error (e.g. a path to a vertex that no source reaches) or the
// library's exceptions.
Run_result run_propagation(const vtp_support::Mesh& mesh, const Run_request& request);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_RUN_H
