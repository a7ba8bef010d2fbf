// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python bindings of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Isolines and cell borders as curves (geodesic_curves.h): Solver.isolines() and Solver.cell_borders().

#include "core_solver.h"

#include <CGAL/VTP_geodesics/geodesic_curves.h>

#include <cmath>

namespace vtp_python {

// One run from the sources with the record of the paths, then the isolines at `levels` (borders: false) or the
// borders of the cells (borders: true). Each curve: (xyz (k, 3), faces (k,), barycentric (k, 3), closed, level,
// i, j) with i, j the source indices of a border (in the order: vertices of `sources`, then the points), -1 for
// an isoline.
py::list Core_solver::curves(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                             const Double_array& levels, bool borders, double chord_tolerance, int exact_refinement)
{
  const std::vector<std::size_t> source_vertices = vertices_of(sources, "sources");
  const std::vector<Face_location> source_points = locations_of(point_faces, point_bary, "points");
  if(source_vertices.empty() && source_points.empty())
    value_error("no source: give at least one vertex in sources or one point in points");
  if(m_through_pinches && !m_repairs.empty())
    value_error("no curves through the vertices that the repair split (the solver was made with through_pinches=True)");
  std::vector<double> level_list(levels.data(), levels.data() + levels.size());
  // the label of each library source: the index of the caller's source (copies of a vertex share it)
  std::vector<Vertex_index> mesh_sources;
  std::vector<std::int64_t> label_of;
  for(std::size_t i = 0; i < source_vertices.size(); ++i)
  {
    const std::size_t before = mesh_sources.size();
    append_copies(source_vertices[i], mesh_sources);
    label_of.resize(mesh_sources.size(), static_cast<std::int64_t>(i));
    (void)before;
  }
  for(std::size_t i = 0; i < source_points.size(); ++i)
    label_of.push_back(static_cast<std::int64_t>(source_vertices.size() + i));
  if(mesh_sources.empty() && source_points.empty())
    value_error("no curves: the source vertices are in no face of the mesh (the repair removed them)");
  typedef VTP::Geodesic_curve<Face_index, Point_3> Curve;
  std::vector<Curve> curves;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    set_sources(mesh_sources, source_points);
    const CGAL::Constant_property_map<Vertex_index, double> no_map;
    // isolines and borders on the kept field (every window that crossed a face: exact curves)
    m_solver->compute<CGAL::Sequential_tag>(no_map, VTP::parameters::keep_field(true).statistics(m_statistics));
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

void define_curves(py::class_<Core_solver>& c)
{
  c.def("curves", &Core_solver::curves);
}

} // namespace vtp_python
