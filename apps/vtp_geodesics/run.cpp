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
#include <CGAL/VTP_geodesics/geodesic_curves.h>
#include <CGAL/VTP_geodesics/geodesic_voronoi_cells.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <vtp_support/join_copies.h>
#include <vtp_support/methods.h>
#include <vtp_support/shortest_path_reference.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iterator>
#include <limits>
#include <memory>
#include <string>

namespace vtp_geodesics_app {

namespace {

typedef CGAL::VTP_geodesics::Geodesic_distance_solver<vtp_support::Mesh> Solver;
namespace VTP = CGAL::VTP_geodesics;

// A vertex as a face location: a corner of one of its faces (the library takes such a location as the vertex).
Face_location location_of_vertex(const vtp_support::Mesh& mesh, vtp_support::Vertex_index v)
{
  const vtp_support::Mesh::Halfedge_index h = mesh.halfedge(v); // a half-edge whose target is v
  const vtp_support::Mesh::Halfedge_index g = mesh.is_border(h) ? mesh.opposite(h) : h;
  const vtp_support::Mesh::Face_index f = mesh.face(g);
  const vtp_support::Mesh::Halfedge_index first = mesh.halfedge(f);
  std::array<double, 3> b = { { 0., 0., 0. } };
  if(mesh.source(first) == v)
    b[0] = 1.;
  else if(mesh.target(first) == v)
    b[1] = 1.;
  else
    b[2] = 1.;
  return Face_location(f, b);
}

std::vector<std::array<double, 3> > to_arrays(const std::vector<vtp_support::Point_3>& points)
{
  std::vector<std::array<double, 3> > r;
  r.reserve(points.size());
  for(const vtp_support::Point_3& p : points)
    r.push_back({ { p.x(), p.y(), p.z() } });
  return r;
}

// The curves that --curves-output and the picture ask for, after the solver's last run.
Curve_request curve_request(const Solver& solver, const Run_request& request, bool several_sources)
{
  Curve_request c;
  if(request.want_curves)
    c.output_levels = curve_levels(solver, request.curve_levels, request.curve_isolines);
  if(request.picture_isolines)
    c.picture_levels = picture_levels(solver, request.curve_isolines);
  // (no cell borders from sources that are curves: the library draws their isolines, their offset curves, only)
  c.output_borders = request.want_curves && several_sources && !request.has_curve_sources();
  c.picture_borders = request.picture_borders && several_sources && !request.has_curve_sources();
  return c;
}

// Whether `method` can keep its field (keep_field: the exact methods).
bool keeps_field(const vtp_support::Method_info& method) { return !method.approximate && !method.virtual_sources; }

// The answers at the query points from the field that the solver's last run kept (none if `kept` is false: no
// source, inf and -1 everywhere); its labels mapped by `label_of_source` (empty: the library's).
void answer_queries(const Solver& solver, bool kept, const std::vector<Face_location>& points,
                    const std::vector<std::size_t>& label_of_source, Run_result& r)
{
  const double infinity = std::numeric_limits<double>::infinity();
  r.query_distances.assign(points.size(), infinity);
  r.query_labels.assign(points.size(), -1);
  if(!kept)
    return;
  CGAL_assertion(solver.has_kept_field());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const double d = solver.field_distance(points[i]);
    if(!(d < infinity))
      continue;
    const std::size_t s = solver.field_nearest_source(points[i]);
    r.query_distances[i] = d;
    if(s != VTP::no_source)
      r.query_labels[i] = static_cast<int>(label_of_source.empty() ? s : label_of_source[s]);
  }
}

// Farthest-point sampling with `method` (any of the table), then the areas of the Voronoi cells (the exact methods:
// from the exact borders of one more run from the samples that keeps its field; the others: estimated from the
// vertex values).
void run_sampling(const vtp_support::Method_info& method, Solver& solver, const vtp_support::Mesh& mesh,
                  const Run_request& request, double lambda, Run_result& r)
{
  VTP::Farthest_point_samples<vtp_support::Vertex_index> fps =
    vtp_support::with_method(method, lambda, request.threads, [&](auto tag, const auto& method_np) {
      typedef decltype(tag) Tag;
      const auto np = method_np.lambda_g(request.lambda_g).sampling_radius(request.radius);
      return request.has_first ? solver.farthest_point_sampling<Tag>(request.farthest_points,
                                                                     np.first_sample(request.first))
                               : solver.farthest_point_sampling<Tag>(request.farthest_points, np);
    });
  const VTP::Voronoi_cell_areas cells =
    VTP::geodesic_voronoi_cell_areas(mesh, fps.samples.size(), fps.labels, fps.distances);
  r.samples = fps.samples;
  r.radii = fps.radii;
  r.cell_areas = cells.areas;
  r.cell_uncertainty = cells.uncertainty;
  r.distances = std::move(fps.distances);
  r.labels.resize(r.mesh_vertices);
  for(std::size_t i = 0; i < r.mesh_vertices; ++i)
    r.labels[i] = fps.labels[i] == VTP::no_source ? -1 : static_cast<int>(fps.labels[i]);
  r.statistics = fps.statistics;
  // the samples as sources (their labels: the sample numbers), for the cell areas, the curves of their field
  // and the query points (one more run): an exact method keeps the field (the cells' areas from their exact
  // borders, as the Python module's, and the curves exact), the others record their paths for the curves
  const bool keep = keeps_field(method);
  const bool more = !fps.samples.empty() && (request.wants_curves() || request.keep_field || keep);
  if(more)
  {
    vtp_support::with_method(method, lambda, request.threads, [&](auto tag, const auto& method_np) {
      typedef decltype(tag) Tag;
      const CGAL::Constant_property_map<vtp_support::Vertex_index, double> no_map;
      solver.compute<Tag>(no_map, fps.samples,
                          method_np.lambda_g(request.lambda_g).record_paths(!keep).keep_field(keep));
    });
    r.statistics.field_pieces = solver.statistics().field_pieces;
    r.statistics.field_bytes = solver.statistics().field_bytes;
    if(keep)
    {
      const VTP::Voronoi_cell_areas exact = VTP::geodesic_voronoi_cell_areas(solver);
      r.cell_areas = exact.areas;
      r.cell_uncertainty = exact.uncertainty;
      r.cell_areas.resize(fps.samples.size(), 0.);
      r.cell_uncertainty.resize(fps.samples.size(), 0.);
    }
  }
  if(more && request.wants_curves())
    r.curves = extract_curve_sets(solver, curve_request(solver, request, fps.samples.size() > 1),
                                  std::vector<std::size_t>());
  if(request.keep_field)
    answer_queries(solver, more, request.query_locations, std::vector<std::size_t>(), r);
}

// The run with the log map (vtp, pvtp): the named parameters `np` of the run, and the log map's, into r.log_map
// and r.log_map_via; the nearest sources into `labels` (sized to the mesh).
template <class Tag, class NamedParameters>
void compute_log_map(Solver& solver, const vtp_support::Mesh& mesh, const Run_request& request,
                     const NamedParameters& np, std::vector<std::size_t>& labels, Run_result& r)
{
  const std::size_t n = r.mesh_vertices;
  const double infinity = std::numeric_limits<double>::infinity();
  const auto index = get(boost::vertex_index, mesh);
  const CGAL::Constant_property_map<vtp_support::Vertex_index, double> no_map;
  r.log_map.assign(n, std::array<double, 2>{ { infinity, infinity } });
  std::vector<vtp_support::Vertex_index> via(n);
  const auto lm = np.nearest_source_map(boost::make_iterator_property_map(labels.begin(), index))
                    .log_map(boost::make_iterator_property_map(r.log_map.begin(), index))
                    .log_map_via(boost::make_iterator_property_map(via.begin(), index))
                    .log_map_strict(request.log_map_strict);
  if(request.has_reference_direction)
    solver.template compute<Tag>(no_map, lm.reference_direction(request.reference_direction));
  else
    solver.template compute<Tag>(no_map, lm);
  r.log_map_via.resize(n);
  for(std::size_t i = 0; i < n; ++i)
    r.log_map_via[i] = via[i] == vtp_support::Vertex_index() ? -1 : static_cast<long long>(std::size_t(via[i]));
}

} // namespace

Run_result run_propagation(const vtp_support::Mesh& mesh, const Run_request& request)
{
  const vtp_support::Method_info& method = *request.method;
  // used by the approximate methods only (vtp_support::method_parameters())
  const double lambda = request.has_lambda ? request.lambda : vtp_support::default_lambda;

  // the preprocessing uses the threads of the parallel methods, whatever the method (same result)
  const std::shared_ptr<Solver> kept_solver =
    std::make_shared<Solver>(mesh, CGAL::VTP_geodesics::parameters::number_of_threads(request.threads));
  Solver& solver = *kept_solver;
  Run_result r;
  r.solver = kept_solver;
  r.mesh_vertices = solver.number_of_vertices();
  r.mesh_faces = solver.number_of_faces();
  r.preprocessing_seconds = solver.preprocessing_seconds();
  r.preprocessing_threads = !vtp_support::rows_on_threads ? 1
                            : request.threads > 0 ? request.threads : vtp_support::default_threads();
  r.mean_edge_length = solver.mean_edge_length();
  r.anisotropy = solver.anisotropy();
  if(request.farthest_points > 0)
  {
    run_sampling(method, solver, mesh, request, lambda, r);
    return r;
  }

  // The source set: the label of the library (the order of add_source()) maps to the label of the command line.
  std::vector<std::size_t> label_of_source;
  for(std::size_t i = 0; i < request.source_vertices.size(); ++i)
  {
    if(request.log_map && mesh.is_isolated(request.source_vertices[i]))
      continue;  // it reaches nothing, and has no tangent frame (file_results.cpp puts it at 0)
    solver.add_source(request.source_vertices[i]);
    label_of_source.push_back(request.source_vertex_labels[i]);
  }
  for(std::size_t i = 0; i < request.source_locations.size(); ++i)
  {
    solver.add_source(request.source_locations[i]);
    label_of_source.push_back(request.source_location_labels[i]);
  }
  for(std::size_t i = 0; i < request.source_curves.size(); ++i)
  {
    try
    {
      solver.add_source_curve(request.source_curves[i].points);
    }
    catch(const VTP::Invalid_input_error& e)
    {
      throw Tool_error(request.source_curves[i].name + ": " + e.what());
    }
    // the curve as the library joined it (the picture draws it)
    r.source_curves.push_back(to_arrays(solver.source_curve(label_of_source.size()).points));
    label_of_source.push_back(request.source_curve_labels[i]);
  }
  if(request.source_border)
  {
    try
    {
      solver.add_source_border();
    }
    catch(const VTP::Invalid_input_error& e)
    {
      throw Tool_error(std::string("--source-border: ") + e.what());
    }
    label_of_source.push_back(request.source_border_label);
  }

  // The targets, all as face locations: the target vertices (but isolated ones, which no propagation reaches),
  // the target points, then the end points of the paths (so that the run records their trace-back).
  std::vector<Face_location> targets;
  for(vtp_support::Vertex_index v : request.target_vertices)
    if(!mesh.is_isolated(v))
      targets.push_back(location_of_vertex(mesh, v));
  const std::size_t first_target_location = targets.size();
  targets.insert(targets.end(), request.target_locations.begin(), request.target_locations.end());
  for(const Run_request::Path& p : request.paths)
  {
    if(p.is_point)
      targets.push_back(p.location);
    else
      for(vtp_support::Vertex_index v : p.copies)
        if(!mesh.is_isolated(v))
          targets.push_back(location_of_vertex(mesh, v));
  }

  const double infinity = std::numeric_limits<double>::infinity();
  // One run gives the distances, the trace-back of the paths and what the curves and the query points need: with
  // an exact method its kept field (the curves exact at any level, found after the run), else its record (the
  // curves per vertex). (Not with runs through the split vertices, which start from known distances: the
  // arguments refuse --keep-field and --curves-output with them, and the picture then interpolates.)
  const bool keep = keeps_field(method) && request.joined_copies.empty()
                    && (request.keep_field || request.wants_curves());
  const bool record = !request.paths.empty() || (request.wants_curves() && !keep);
  std::vector<std::size_t> labels;
  if(label_of_source.empty())
  {
    r.distances.assign(r.mesh_vertices, infinity);
    r.target_location_distances.assign(request.target_locations.size(), infinity);
    if(request.want_labels)
      r.labels.assign(r.mesh_vertices, -1);
    if(request.log_map)
    {
      r.log_map.assign(r.mesh_vertices, std::array<double, 2>{ { infinity, infinity } });
      r.log_map_via.assign(r.mesh_vertices, -1);
    }
  }
  else
  {
    if(request.want_labels || request.log_map)
      labels.assign(r.mesh_vertices, VTP::no_source);
    vtp_support::with_method(method, lambda, request.threads, [&](auto tag, const auto& method_np) {
      typedef decltype(tag) Tag;
      // the distances stay in the solver (read with distances()): nothing to write through a map
      const CGAL::Constant_property_map<vtp_support::Vertex_index, double> no_map;
      const bool join = !request.joined_copies.empty();
      const auto np = method_np.lambda_g(request.lambda_g)
                        .maximum_distance(join ? infinity : request.max_distance)
                        .targets(targets)
                        .stop_at_targets(request.stop_at_targets && !join)
                        .record_paths(record)
                        .keep_field(keep)
                        .signed_distance(request.signed_distance);
      if(request.log_map)
        compute_log_map<Tag>(solver, mesh, request, np, labels, r);
      else if(request.want_labels)
        solver.compute<Tag>(no_map, np.nearest_source_map(boost::make_iterator_property_map(
                                      labels.begin(), get(boost::vertex_index, mesh))));
      else
        solver.compute<Tag>(no_map, np);
    });
    r.statistics = solver.statistics();
    r.distances = solver.distances();
    for(std::size_t i = 0; i < request.target_locations.size(); ++i)
      r.target_location_distances.push_back(solver.target_distance(first_target_location + i));
    if(request.want_labels)
    {
      r.labels.resize(r.mesh_vertices);
      for(std::size_t i = 0; i < r.mesh_vertices; ++i)
        r.labels[i] = labels[i] == VTP::no_source ? -1 : static_cast<int>(label_of_source[labels[i]]);
    }
    if(!request.joined_copies.empty())
    {
      // through the split vertices: runs from the known distances, then the limit
      r.join_runs = vtp_support::join_copies(
        request.joined_copies, r.distances, request.want_labels ? &r.labels : nullptr,
        [&](const std::vector<vtp_support::Vertex_index>& copies, std::vector<double>& field) {
          solver.clear_sources();
          for(vtp_support::Vertex_index c : copies)
            solver.add_source(c);
          vtp_support::with_method(method, lambda, request.threads, [&](auto tag, const auto& method_np) {
            typedef decltype(tag) Tag;
            const auto fm = boost::make_iterator_property_map(field.begin(), get(boost::vertex_index, mesh));
            solver.compute<Tag>(fm, method_np.lambda_g(request.lambda_g).initial_distances(fm));
          });
        });
      for(std::size_t i = 0; i < r.distances.size(); ++i)
        if(r.distances[i] > request.max_distance)
        {
          r.distances[i] = infinity;
          if(request.want_labels)
            r.labels[i] = -1;
        }
    }
  }

  // The curves and the query points, from the same run
  if(request.wants_curves() && !label_of_source.empty() && request.joined_copies.empty())
    r.curves = extract_curve_sets(solver, curve_request(solver, request, label_of_source.size() > 1),
                                  label_of_source);
  if(request.keep_field)
    answer_queries(solver, !label_of_source.empty(), request.query_locations, label_of_source, r);

  // The paths, from the trace-back recorded by the run; a vertex path from its copy nearest to a source.
  const std::string beyond = request.max_distance < infinity ? " (or it lies beyond --max-distance)" : "";
  for(const Run_request::Path& p : request.paths)
  {
    std::vector<vtp_support::Point_3> points;
    if(p.is_point)
    {
      if(label_of_source.empty())
        throw Tool_error("no path from " + p.name + ": no source reaches it" + beyond);
      try
      {
        solver.shortest_path_points(p.location, std::back_inserter(points));
      }
      catch(const VTP::Invalid_input_error& e)
      {
        throw Tool_error("no path from " + p.name + ": " + e.what());
      }
    }
    else
    {
      CGAL_assertion(!p.copies.empty());
      vtp_support::Vertex_index start = p.copies.front();
      for(vtp_support::Vertex_index v : p.copies)
        if(r.distances[std::size_t(v)] < r.distances[std::size_t(start)])
          start = v;
      if(!(r.distances[std::size_t(start)] < infinity))
        throw Tool_error("no path from " + p.name + ": no source reaches it" + beyond);
      solver.shortest_path_points(start, std::back_inserter(points));
    }
    if(points.empty())
      throw Tool_error("no path from " + p.name + ": the library returned an empty path");
    r.paths.push_back(to_arrays(points));
  }

  // The straightest geodesics (they need no distances)
  for(const Run_request::Trace& t : request.traces)
  {
    try
    {
      r.traces.push_back(to_arrays(solver.straightest_geodesic(t.start, t.direction, t.length).points));
    }
    catch(const VTP::Invalid_input_error& e)
    {
      throw Tool_error(t.name + ": " + e.what());
    }
  }

  if(request.check_cgal)
  {
    const auto t0 = std::chrono::steady_clock::now();
    r.reference = vtp_support::shortest_path_reference_distances(mesh, request.source_vertices, request.source_locations);
    r.cgal_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return r;
}

} // namespace vtp_geodesics_app
