// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Farthest-point sampling with geodesic distances, and the areas of the geodesic Voronoi cells of the samples
// (see core_solver.h).

#include "core_solver.h"

#include <CGAL/VTP_geodesics/geodesic_voronoi_cells.h>

namespace vtp_python {

// Up to k samples from `first` (-1: the vertex farthest from vertex 0) until the covering radius is <= radius.
// Returns (samples (s,), radii (s,), distances (n,), labels (n,) with -1 for none, cell areas (s,), cell
// uncertainty (s,)).
py::tuple Core_solver::farthest_point_sampling(std::int64_t k, std::int64_t first, double radius,
                                               const std::string& method_name, double lam, int threads)
{
  const vtp_support::Method_info& method = method_named(method_name, lam);
  if(k < 0)
    value_error("k must be >= 0, got " + std::to_string(k));
  if(!(radius >= 0.))
    value_error("radius must be >= 0, got " + std::to_string(radius));
  const bool has_first = first >= 0;
  Vertex_index first_vertex;
  if(has_first)
    first_vertex = vertex_of(first, "first");
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
    cells = VTP::geodesic_voronoi_cell_areas(m_mesh, r.samples.size(), r.labels, r.distances);
  }
  const std::size_t n = number_of_vertices(), s = r.samples.size();
  py::array_t<std::int64_t> samples(static_cast<py::ssize_t>(s)), labels(static_cast<py::ssize_t>(n));
  py::array_t<double> radii(static_cast<py::ssize_t>(s)), distances(static_cast<py::ssize_t>(n)),
    areas(static_cast<py::ssize_t>(s)), uncertainty(static_cast<py::ssize_t>(s));
  for(std::size_t i = 0; i < s; ++i)
  {
    samples.mutable_data()[i] = static_cast<std::int64_t>(std::size_t(r.samples[i]));
    radii.mutable_data()[i] = r.radii[i];
    areas.mutable_data()[i] = cells.areas[i];
    uncertainty.mutable_data()[i] = cells.uncertainty[i];
  }
  for(std::size_t i = 0; i < n; ++i)
  {
    distances.mutable_data()[i] = r.distances[i];
    labels.mutable_data()[i] = r.labels[i] == VTP::no_source ? -1 : static_cast<std::int64_t>(r.labels[i]);
  }
  return py::make_tuple(samples, radii, distances, labels, areas, uncertainty);
}

void define_sampling(py::class_<Core_solver>& c)
{
  c.def("farthest_point_sampling", &Core_solver::farthest_point_sampling);
}

} // namespace vtp_python
