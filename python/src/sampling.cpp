// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Farthest-point sampling with geodesic distances, and the areas of the geodesic Voronoi cells of the samples
// (see core_solver.h): exact for the exact methods (from a kept field), estimated from the vertices otherwise.

#include "core_solver.h"

#include <CGAL/VTP_geodesics/geodesic_curves.h>
#include <CGAL/VTP_geodesics/geodesic_voronoi_cells.h>

#include <CGAL/property_map.h>

namespace vtp_python {

// Up to k samples from `first` (-1: the vertex farthest from vertex 0) until the covering radius is <= radius.
// Returns (samples (s,), radii (s,), distances (n,), labels (n,) with -1 for none, cell areas (s,), cell
// uncertainty (s,)). The cell areas of the exact methods come from the exact borders of the cells (one more run
// from the samples that keeps its field) if exact_cell_areas; otherwise, and for the approximate methods, from
// the vertex values.
py::tuple Core_solver::farthest_point_sampling(std::int64_t k, std::int64_t first, double radius,
                                               const std::string& method_name, double lam, int threads,
                                               bool exact_cell_areas)
{
  const vtp_support::Method_info& method = method_named(method_name, lam);
  if(k < 0)
    value_error("k must be >= 0, got " + std::to_string(k));
  if(!(radius >= 0.))
    value_error("radius must be >= 0, got " + std::to_string(radius));
  if(m_through_pinches && !m_repairs.empty())
    value_error("farthest-point sampling does not go through the vertices that the repair split (the solver was "
                "made with through_pinches=True)");
  const bool has_first = first >= 0;
  Vertex_index first_vertex;
  if(has_first)
  {
    // a vertex of V: its first copy
    std::vector<Vertex_index> copies;
    append_copies(vertex_of(first, "first"), copies);
    if(copies.empty())
      value_error("first: vertex " + std::to_string(first) + " is in no face of the mesh (the repair removed it)");
    first_vertex = copies.front();
  }
  VTP::Farthest_point_samples<Vertex_index> r;
  VTP::Voronoi_cell_areas cells;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    vtp_support::with_method(method, lam, threads_or_default(threads), [&](auto tag, const auto& method_np) {
      typedef decltype(tag) Tag;
      const auto np = method_np.sampling_radius(radius);
      r = has_first ? m_solver->template farthest_point_sampling<Tag>(static_cast<std::size_t>(k),
                                                                        np.first_sample(first_vertex))
                    : m_solver->template farthest_point_sampling<Tag>(static_cast<std::size_t>(k), np);
    });
    m_statistics = r.statistics;
    if(exact_cell_areas && !method.approximate && !method.virtual_sources && !r.samples.empty())
    {
      // exact methods: the cells cut along their exact borders, from the field of one more run from the samples
      // that keeps every window (geodesic_curves.h); its statistics are not those of the sampling (kept above)
      set_sources(r.samples, std::vector<Face_location>());
      const CGAL::Constant_property_map<Vertex_index, double> no_map;
      vtp_support::with_method(method, lam, threads_or_default(threads), [&](auto tag, const auto& method_np) {
        typedef decltype(tag) Tag;
        m_solver->template compute<Tag>(no_map, method_np.keep_field(true));
      });
      cells = VTP::geodesic_voronoi_cell_areas(*m_solver);
    }
    else
      // approximate methods (or exact_cell_areas false): from the labels and distances of the vertices, each
      // face split where the two distances extended straight along its edges are equal (geodesic_voronoi_cells.h)
      cells = VTP::geodesic_voronoi_cell_areas(m_mesh, r.samples.size(), r.labels, r.distances);
  }
  const std::size_t n = number_of_vertices(), s = r.samples.size();
  py::array_t<std::int64_t> samples(static_cast<py::ssize_t>(s)), labels(static_cast<py::ssize_t>(n));
  py::array_t<double> radii(static_cast<py::ssize_t>(s)), distances(static_cast<py::ssize_t>(n)),
    areas(static_cast<py::ssize_t>(s)), uncertainty(static_cast<py::ssize_t>(s));
  for(std::size_t i = 0; i < s; ++i)
  {
    samples.mutable_data()[i] = static_cast<std::int64_t>(caller_of(r.samples[i]));
    radii.mutable_data()[i] = r.radii[i];
    areas.mutable_data()[i] = cells.areas[i];
    uncertainty.mutable_data()[i] = cells.uncertainty[i];
  }
  // on the vertices of V (the least over the copies of a vertex, and that copy's label)
  to_caller(r.distances, &r.labels, distances.mutable_data(), labels.mutable_data());
  return py::make_tuple(samples, radii, distances, labels, areas, uncertainty);
}

void define_sampling(py::class_<Core_solver>& c)
{
  c.def("farthest_point_sampling", &Core_solver::farthest_point_sampling);
}

} // namespace vtp_python
