// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Sources that are curves (see core_solver.h): distances(curves=..., source_border=..., signed=...), the distances
// from vertices, points, curves and the border of the mesh, in that order (the labels), as the tool's
// --source, --source-point, --source-curve and --source-border.

#include "core_solver.h"

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>

namespace vtp_python {

// Returns (distances (n,), labels (n,) int64 or None). The curves: their points (curve_faces (K,), curve_bary
// (K, 3), with respect to F's corners), curve k being points curve_offsets[k] .. curve_offsets[k + 1]; curve_xyz
// (K, 3): the position each point was located from (NaN for a point given as (face, barycentric)).
py::tuple Core_solver::curve_distances(const Index_array& sources, const Index_array& point_faces,
                                       const Double_array& point_bary, const Index_array& curve_faces,
                                       const Double_array& curve_bary, const Double_array& curve_xyz,
                                       const Index_array& curve_offsets, bool border, bool signed_distance,
                                       double max_distance, const Index_array& targets, const std::string& method_name,
                                       double lam, int threads, bool want_labels, bool keep_field)
{
  const vtp_support::Method_info& method = method_named(method_name, lam);
  check_limit(max_distance);
  const std::vector<std::size_t> source_vertices = vertices_of(sources, "sources");
  const std::vector<Face_location> source_points = locations_of(point_faces, point_bary, "points");
  const std::vector<Face_location> curve_points = locations_of(curve_faces, curve_bary, "curves");
  const std::vector<std::size_t> target_vertices = vertices_of(targets, "targets");
  // the curves, each at least one point (Python checks the offsets; read within the arrays' sizes)
  std::vector<std::vector<Face_location> > curves;
  const std::int64_t* off = curve_offsets.data();
  for(py::ssize_t k = 0; k + 1 < curve_offsets.size(); ++k)
  {
    if(off[k] < 0 || off[k + 1] < off[k] || off[k + 1] > static_cast<std::int64_t>(curve_points.size()))
      value_error("curves: bad offsets");
    curves.push_back(std::vector<Face_location>(curve_points.begin() + off[k], curve_points.begin() + off[k + 1]));
  }
  if(source_vertices.empty() && source_points.empty() && curves.empty() && !border)
    value_error("no source: give a vertex in sources, a point in points, a curve in curves or source_border=True");
  if(signed_distance && curves.empty() && !border)
    value_error("signed=True needs a source that is a curve (curves or source_border=True)");
  if(m_through_pinches && !m_repairs.empty())
    value_error("curves and source_border: the curves are not joined through the vertices that the repair split "
                "(the solver was made with through_pinches=True)");
  if(keep_field)
  {
    if(method.approximate || method.virtual_sources)
      value_error(std::string("keep_field=True needs an exact method (\"vtp\" or \"pvtp\"), got method=\"")
                  + method.name + "\": the field of the approximate methods is not the distance inside the faces");
    if(targets.size() > 0)
      value_error("keep_field=True cannot be used with targets (the run stops once the targets are known: the "
                  "field would be partial)");
  }
  // the points given as xyz: on the surface, within the tolerance
  const double* xyz = curve_xyz.data();
  const std::size_t located = (std::min)(curve_points.size(), static_cast<std::size_t>(curve_xyz.size()) / 3);
  if(located > 0)
  {
    const double tolerance = vtp_support::curve_point_tolerance * vtp_support::bounding_box_diagonal(m_mesh);
    std::size_t curve = 0;
    for(std::size_t i = 0; i < located; ++i)
    {
      while(curve + 1 < static_cast<std::size_t>(curve_offsets.size()) && static_cast<std::int64_t>(i) >= off[curve + 1])
        ++curve;
      const double* p = xyz + 3 * i;
      if(std::isnan(p[0]))
        continue;
      const Face_location& l = curve_points[i];
      const Halfedge_index h = m_mesh.halfedge(l.first);
      const Point_3 c[3] = { m_mesh.point(m_mesh.source(h)), m_mesh.point(m_mesh.target(h)),
                             m_mesh.point(m_mesh.target(m_mesh.next(h))) };
      double q[3];
      for(int k = 0; k < 3; ++k)
        q[k] = l.second[0] * c[0][k] + l.second[1] * c[1][k] + l.second[2] * c[2][k];
      const double d = std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1])
                                 + (q[2] - p[2]) * (q[2] - p[2]));
      if(!(d <= tolerance))
        value_error("curves[" + std::to_string(curve) + "]: point " + std::to_string(i - std::size_t(off[curve]))
                    + " is off the surface (at " + std::to_string(d) + " from it; at most 1e-6 of the diagonal of "
                    "the mesh's bounding box)");
    }
  }

  const std::size_t n = number_of_vertices(), nm = m_mesh.number_of_vertices();
  py::array_t<double> out(static_cast<py::ssize_t>(n));
  py::array_t<std::int64_t> labels_out(static_cast<py::ssize_t>(want_labels ? n : 0));
  double* d = out.mutable_data();
  std::int64_t* lab = labels_out.mutable_data();
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    // the library's sources: every copy of each source vertex, the points, the curves, the border; the caller's
    // label of each
    std::vector<Vertex_index> mesh_sources;
    std::vector<std::size_t> label_of_source;
    for(std::size_t i = 0; i < source_vertices.size(); ++i)
    {
      append_copies(source_vertices[i], mesh_sources);
      label_of_source.resize(mesh_sources.size(), i);
    }
    set_sources(mesh_sources, source_points);
    for(std::size_t j = 0; j < source_points.size(); ++j)
      label_of_source.push_back(source_vertices.size() + j);
    for(std::size_t k = 0; k < curves.size(); ++k)
    {
      try
      {
        m_solver->add_source_curve(curves[k]);
      }
      catch(const VTP::Invalid_input_error& e)
      {
        throw VTP::Invalid_input_error("curves[" + std::to_string(k) + "]: " + e.what());
      }
      label_of_source.push_back(source_vertices.size() + source_points.size() + k);
    }
    if(border)
    {
      try
      {
        m_solver->add_source_border();
      }
      catch(const VTP::Invalid_input_error& e)
      {
        throw VTP::Invalid_input_error(std::string("source_border=True: ") + e.what());
      }
      label_of_source.push_back(source_vertices.size() + source_points.size() + curves.size());
    }
    std::vector<Vertex_index> live_targets;
    for(std::size_t t : target_vertices)
    {
      std::vector<Vertex_index> copies;
      append_copies(t, copies);
      for(Vertex_index c : copies)
        if(!m_mesh.is_isolated(c))
          live_targets.push_back(c);
    }
    std::vector<double> mesh_d(nm, infinity);
    std::vector<std::size_t> labels;
    if(want_labels)
      labels.assign(nm, VTP::no_source);
    const auto index = get(boost::vertex_index, m_mesh);
    if(!label_of_source.empty())
      vtp_support::with_method(method, lam, threads_or_default(threads), [&](auto tag, const auto& method_np) {
        typedef decltype(tag) Tag;
        const auto vdm = boost::make_iterator_property_map(mesh_d.begin(), index);
        const auto np = method_np.maximum_distance(max_distance)
                          .targets(live_targets)
                          .stop_at_targets(!live_targets.empty())
                          .statistics(m_statistics)
                          .signed_distance(signed_distance)
                          .keep_field(keep_field);
        if(want_labels)
          m_solver->template compute<Tag>(vdm, np.nearest_source_map(boost::make_iterator_property_map(
                                                 labels.begin(), index)));
        else
          m_solver->template compute<Tag>(vdm, np);
      });
    if(keep_field)
    {
      // (the field is the distance's magnitude: field queries and curves are unsigned)
      m_field_labels.assign(label_of_source.begin(), label_of_source.end());
      m_field_sources = source_vertices.size() + source_points.size() + curves.size() + (border ? 1 : 0);
      m_field_kept = true;
    }
    if(want_labels)
      for(std::size_t& l : labels)
        if(l != VTP::no_source)
          l = label_of_source[l];
    if(!signed_distance)
      to_caller(mesh_d, want_labels ? &labels : nullptr, d, want_labels ? lab : nullptr);
    else
    {
      // signed: each vertex of V gets the value of its copy of the least absolute value (the first such), and
      // that copy's label (as the tool does)
      std::vector<double> magnitude(nm);
      for(std::size_t i = 0; i < nm; ++i)
        magnitude[i] = std::abs(mesh_d[i]);
      std::vector<double> m(n);
      std::vector<std::int64_t> ml(want_labels ? n : 0);
      to_caller(magnitude, want_labels ? &labels : nullptr, m.data(), want_labels ? ml.data() : nullptr);
      for(std::size_t i = 0; i < n; ++i)
      {
        d[i] = infinity;
        std::vector<Vertex_index> copies;
        append_copies(i, copies);
        for(Vertex_index c : copies)
          if(magnitude[std::size_t(c)] < std::abs(d[i]))
            d[i] = mesh_d[std::size_t(c)];
        if(want_labels)
          lab[i] = ml[i];
      }
    }
    for(std::size_t i = source_vertices.size(); i-- > 0;)
    {
      d[source_vertices[i]] = 0.;
      if(want_labels)
        lab[source_vertices[i]] = static_cast<std::int64_t>(i);
    }
  }
  return py::make_tuple(out, want_labels ? py::object(labels_out) : py::object(py::none()));
}

void define_source_curves(py::class_<Core_solver>& c) { c.def("curve_distances", &Core_solver::curve_distances); }

} // namespace vtp_python
