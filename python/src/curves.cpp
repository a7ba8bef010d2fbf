// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python bindings of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Isolines and cell borders as curves, and the areas of the cells (geodesic_curves.h): Solver.isolines(),
// Solver.cell_borders(), Solver.cell_areas() (one run each), and the same on the kept field
// (Solver.field_isolines(), field_cell_borders(), field_cell_areas()).

#include "core_solver.h"

#include <CGAL/VTP_geodesics/geodesic_curves.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace vtp_python {

// The sources of a run for curves (the GIL held): every copy of each vertex of `sources`, then the points; the
// caller's label of each library source (the index of the caller's source: copies of a vertex share it).
std::vector<std::int64_t> Core_solver::curve_sources(const Index_array& sources, const Index_array& point_faces,
                                                     const Double_array& point_bary,
                                                     std::vector<Vertex_index>& mesh_sources,
                                                     std::vector<Face_location>& points) const
{
  Caller_sources caller = sources_of(sources, point_faces, point_bary);
  const std::vector<std::size_t>& source_vertices = caller.vertices;
  points = std::move(caller.points);
  if(m_through_pinches && !m_repairs.empty())
    value_error("no curves through the vertices that the repair split (the solver was made with through_pinches=True)");
  std::vector<std::int64_t> label_of;
  mesh_sources.clear();
  for(std::size_t i = 0; i < source_vertices.size(); ++i)
  {
    append_copies(source_vertices[i], mesh_sources);
    label_of.resize(mesh_sources.size(), static_cast<std::int64_t>(i));
  }
  for(std::size_t i = 0; i < points.size(); ++i)
    label_of.push_back(static_cast<std::int64_t>(source_vertices.size() + i));
  if(mesh_sources.empty() && points.empty())
    value_error("no curves: the source vertices are in no face of the mesh (the repair removed them)");
  return label_of;
}

void Core_solver::run_keeping_field(const std::vector<Vertex_index>& mesh_sources,
                                    const std::vector<Face_location>& points)
{
  set_sources(mesh_sources, points);
  const CGAL::Constant_property_map<Vertex_index, double> no_map;
  m_solver->compute<CGAL::Sequential_tag>(no_map, VTP::parameters::keep_field(true).statistics(m_statistics));
}

// The isolines at `levels` (borders: false) or the borders of the cells (borders: true), on the kept field: that
// of one run from the sources (VTP), or (from_field) that of the last distances(..., keep_field=True), the sources
// then ignored. Each curve: (xyz (k, 3), faces (k,), barycentric (k, 3), closed, level, i, j) with i, j the
// caller's source indices of a border (the vertices of `sources`, then the points), -1 for an isoline.
py::list Core_solver::curves(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                             const Double_array& levels, bool borders, double chord_tolerance, int exact_refinement,
                             bool from_field)
{
  std::vector<Vertex_index> mesh_sources;
  std::vector<Face_location> source_points;
  std::vector<std::int64_t> label_of;
  if(!from_field)
    label_of = curve_sources(sources, point_faces, point_bary, mesh_sources, source_points);
  std::vector<double> level_list(levels.data(), levels.data() + levels.size());
  typedef VTP::Geodesic_curve<Face_index, Point_3> Curve;
  std::vector<Curve> curves;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    if(from_field)
    {
      require_kept_field();
      label_of = m_field_labels;
    }
    else
      run_keeping_field(mesh_sources, source_points);
    // isolines and borders on the kept field (every window that crossed a face: exact curves)
    const double tolerance = chord_tolerance > 0. ? chord_tolerance : 1e-3 * m_solver->mean_edge_length();
    const auto np = VTP::parameters::chord_tolerance(tolerance).exact_refinement(exact_refinement);
    curves = borders ? VTP::geodesic_cell_borders(*m_solver, np) : VTP::geodesic_isolines(*m_solver, level_list, np);
  }
  py::list out;
  for(const Curve& c : curves)
  {
    std::int64_t a = -1, b = -1;
    if(borders)
    {
      a = label_of[c.cells[0]];
      b = label_of[c.cells[1]];
      if(a == b)
        continue;  // (copies of one vertex)
      if(b < a)
        std::swap(a, b);
    }
    const std::size_t k = c.points.size();
    py::array_t<double> P({ static_cast<py::ssize_t>(k), py::ssize_t(3) });
    py::array_t<std::int64_t> PF(static_cast<py::ssize_t>(k));
    py::array_t<double> PB({ static_cast<py::ssize_t>(k), py::ssize_t(3) });
    double* p = P.mutable_data();
    std::int64_t* pf = PF.mutable_data();
    double* pb = PB.mutable_data();
    for(std::size_t i = 0; i < k; ++i)
    {
      for(int j = 0; j < 3; ++j)
        p[3 * i + std::size_t(j)] = c.points[i][j];
      pf[i] = to_user_face(c.locations[i].first);
      const std::array<double, 3> bary = to_user_barycentric(c.locations[i]);
      for(int j = 0; j < 3; ++j)
        pb[3 * i + std::size_t(j)] = bary[std::size_t(j)];
    }
    out.append(py::make_tuple(P, PF, PB, c.closed, borders ? std::nan("") : c.level, a, b));
  }
  return out;
}

// The areas of the geodesic Voronoi cells of the sources, cut along their exact borders (geodesic_curves.h), on
// the field of one run from the sources or (from_field) on the kept field. Returns (areas (s,), uncertainty (s,))
// per caller source (the copies of a vertex summed): s = the number of sources.
py::tuple Core_solver::cell_areas(const Index_array& sources, const Index_array& point_faces,
                                  const Double_array& point_bary, double chord_tolerance, bool from_field)
{
  std::vector<Vertex_index> mesh_sources;
  std::vector<Face_location> source_points;
  std::vector<std::int64_t> label_of;
  std::size_t s = 0;
  if(!from_field)
  {
    label_of = curve_sources(sources, point_faces, point_bary, mesh_sources, source_points);
    s = static_cast<std::size_t>(sources.size()) + source_points.size();
  }
  VTP::Voronoi_cell_areas cells;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    if(from_field)
    {
      require_kept_field();
      label_of = m_field_labels;
      s = m_field_sources;
    }
    else
      run_keeping_field(mesh_sources, source_points);
    const double tolerance = chord_tolerance > 0. ? chord_tolerance : 1e-3 * m_solver->mean_edge_length();
    cells = VTP::geodesic_voronoi_cell_areas(*m_solver, VTP::parameters::chord_tolerance(tolerance));
  }
  py::array_t<double> areas(static_cast<py::ssize_t>(s)), uncertainty(static_cast<py::ssize_t>(s));
  double* a = areas.mutable_data();
  double* u = uncertainty.mutable_data();
  std::fill(a, a + s, 0.);
  std::fill(u, u + s, 0.);
  for(std::size_t i = 0; i < cells.areas.size() && i < label_of.size(); ++i)
  {
    const std::size_t l = static_cast<std::size_t>(label_of[i]);
    a[l] += cells.areas[i];
    u[l] += cells.uncertainty[i];
  }
  return py::make_tuple(areas, uncertainty);
}

void define_curves(py::class_<Core_solver>& c)
{
  c.def("curves", &Core_solver::curves).def("cell_areas", &Core_solver::cell_areas);
}

} // namespace vtp_python
