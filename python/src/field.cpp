// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The kept field: after distances(..., keep_field=True) (queries.cpp), the exact distance and the nearest source
// at any vertex or point of the surface, from the windows that the run kept (the library's
// Geodesic_distance_solver::field_distance() and field_nearest_source()); see core_solver.h.

#include "core_solver.h"

#include <CGAL/VTP_geodesics/Invalid_input_error.h>

namespace vtp_python {

// Whether the last computation of the solver is a distances(..., keep_field=True) whose field is kept.
bool Core_solver::has_kept_field() const
{
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_field_kept && m_solver->has_kept_field();
}

void Core_solver::require_kept_field() const
{
  if(!m_field_kept || !m_solver->has_kept_field())
    throw VTP::Invalid_input_error("the solver holds no kept field (a field is kept until the next computation of "
                                   "the solver): compute with distances(..., keep_field=True) first");
}

// The bytes of that field (0 without it).
std::size_t Core_solver::field_bytes() const
{
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_field_kept ? m_solver->field_bytes() : 0;
}

// The kept field at k points: the vertices of V `vertices` (each the least over its copies, that copy's label),
// or, if `vertices` is empty, the points (faces (k,), barycentric (k, 3) on F). Returns (distances (k,), labels
// (k,) int64 or None): +inf and -1 where no source reaches or beyond the limit of the run; the labels are the
// caller's source indices (the vertices of `sources`, then the points), as distances(..., return_labels=True).
py::tuple Core_solver::field_query(const Index_array& vertices, const Index_array& faces, const Double_array& bary,
                                   bool want_labels)
{
  const bool at_vertices = vertices.size() > 0;
  // the vertices of V checked, and their copies in the mesh; or the points as locations of the mesh's faces
  std::vector<std::size_t> copy_begin(1, 0);
  std::vector<Vertex_index> copies;
  std::vector<Face_location> points;
  if(at_vertices)
  {
    const std::int64_t* v = vertices.data();
    for(py::ssize_t i = 0; i < vertices.size(); ++i)
    {
      append_copies(vertex_of(v[i], "points"), copies);
      copy_begin.push_back(copies.size());
    }
  }
  else
    points = locations_of(faces, bary, "points");
  const std::size_t k = at_vertices ? copy_begin.size() - 1 : points.size();
  py::array_t<double> out(static_cast<py::ssize_t>(k));
  py::array_t<std::int64_t> labels_out(static_cast<py::ssize_t>(want_labels ? k : 0));
  double* d = out.mutable_data();
  std::int64_t* lab = labels_out.mutable_data();
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    require_kept_field();
    const auto caller_label = [&](std::size_t l) {
      return (l == VTP::no_source || l >= m_field_labels.size()) ? std::int64_t(-1) : m_field_labels[l];
    };
    // a label is looked up only where the distance is finite (a second search of the face's candidates)
    const auto query = [&](const auto& p, double& distance, std::int64_t* label) {
      distance = m_solver->field_distance(p);
      if(label != nullptr)
        *label = distance < infinity ? caller_label(m_solver->field_nearest_source(p)) : std::int64_t(-1);
    };
    for(std::size_t i = 0; i < k; ++i)
    {
      std::int64_t* label = want_labels ? lab + i : nullptr;
      if(!at_vertices)
      {
        query(points[i], d[i], label);
        continue;
      }
      // a vertex of V: the least over its copies (+inf, -1 without copy), that copy's label
      d[i] = infinity;
      if(label != nullptr)
        *label = -1;
      for(std::size_t c = copy_begin[i]; c < copy_begin[i + 1]; ++c)
      {
        double dc;
        std::int64_t lc = -1;
        query(copies[c], dc, label != nullptr ? &lc : nullptr);
        if(dc < d[i])
        {
          d[i] = dc;
          if(label != nullptr)
            *label = lc;
        }
      }
    }
  }
  return py::make_tuple(out, want_labels ? py::object(labels_out) : py::object(py::none()));
}

void define_field(py::class_<Core_solver>& c)
{
  c.def("field_query", &Core_solver::field_query)
    .def_property_readonly("has_kept_field", &Core_solver::has_kept_field)
    .def_property_readonly("field_bytes", &Core_solver::field_bytes);
}

} // namespace vtp_python
