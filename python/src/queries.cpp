// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The queries of a solver: distances from several sources (with labels, a limit, targets), a geodesic path,
// one distance with early stop, and the nearest surface points (see core_solver.h).

#include "core_solver.h"

#include <vtp_support/join_copies.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>

namespace vtp_python {

// One propagation. Returns (distances (n,), labels (n,) int64 or None, target distances (len(targets),)). With
// keep_field (exact methods, no targets), the solver keeps the field of the run for field_query() (field.cpp).
py::tuple Core_solver::distances(const Index_array& sources, const Index_array& point_faces,
                                 const Double_array& point_bary, double max_distance, const Index_array& targets,
                                 const std::string& method_name, double lam, int threads, bool want_labels,
                                 bool keep_field)
{
  const vtp_support::Method_info& method = method_named(method_name, lam);
  check_limit(max_distance);
  const Caller_sources caller = sources_of(sources, point_faces, point_bary);
  const std::vector<std::size_t>& source_vertices = caller.vertices;
  const std::vector<Face_location>& source_points = caller.points;
  const std::vector<std::size_t> target_vertices = vertices_of(targets, "targets");
  if(keep_field)
  {
    if(method.approximate || method.virtual_sources)
      value_error(std::string("keep_field=True needs an exact method (\"vtp\" or \"pvtp\"), got method=\"")
                  + method.name + "\": the field of the approximate methods is not the distance inside the faces");
    if(!target_vertices.empty())
      value_error("keep_field=True cannot be used with targets (the run stops once the targets are known: the "
                  "field would be partial)");
    if(m_through_pinches && !m_repairs.empty())
      value_error("keep_field=True: the field is not kept through the vertices that the repair split (the solver "
                  "was made with through_pinches=True)");
  }
  const std::size_t n = number_of_vertices();
  py::array_t<double> out(static_cast<py::ssize_t>(n));
  py::array_t<std::int64_t> labels_out(static_cast<py::ssize_t>(want_labels ? n : 0));
  py::array_t<double> target_out(static_cast<py::ssize_t>(target_vertices.size()));
  double* d = out.mutable_data();
  std::int64_t* lab = labels_out.mutable_data();
  double* td = target_out.mutable_data();
  if(!m_repairs.empty())
  {
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      field_on_caller(source_vertices, source_points, target_vertices, max_distance, method, lam, threads, d,
                      want_labels ? lab : nullptr, keep_field);
      for(std::size_t i = 0; i < target_vertices.size(); ++i)
        td[i] = d[target_vertices[i]];
    }
    return py::make_tuple(out, want_labels ? py::object(labels_out) : py::object(py::none()), target_out);
  }
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    // isolated vertices are never reached: not targets of the stop rule (their distance is +inf)
    std::vector<Vertex_index> live_targets;
    for(std::size_t t : target_vertices)
      if(!m_mesh.is_isolated(Vertex_index(static_cast<Mesh::size_type>(t))))
        live_targets.push_back(Vertex_index(static_cast<Mesh::size_type>(t)));
    std::vector<Vertex_index> mesh_sources;
    for(std::size_t s : source_vertices)
      mesh_sources.push_back(Vertex_index(static_cast<Mesh::size_type>(s)));
    set_sources(mesh_sources, source_points);
    const auto vdm = boost::make_iterator_property_map(d, get(boost::vertex_index, m_mesh));
    std::vector<std::size_t> labels;
    vtp_support::with_method(method, lam, threads_or_default(threads), [&](auto tag, const auto& method_np) {
      typedef decltype(tag) Tag;
      const auto np = method_np.maximum_distance(max_distance)
                        .targets(live_targets)
                        .stop_at_targets(!live_targets.empty())
                        .statistics(m_statistics)
                        .keep_field(keep_field);
      if(want_labels)
      {
        labels.assign(n, VTP::no_source);
        m_solver->template compute<Tag>(
          vdm, np.nearest_source_map(boost::make_iterator_property_map(labels.begin(),
                                                                       get(boost::vertex_index, m_mesh))));
      }
      else
        m_solver->template compute<Tag>(vdm, np);
    });
    if(keep_field)
    {
      // the library's source i is the caller's source i (one mesh vertex per vertex of V, then the points)
      m_field_labels.resize(source_vertices.size() + source_points.size());
      for(std::size_t i = 0; i < m_field_labels.size(); ++i)
        m_field_labels[i] = static_cast<std::int64_t>(i);
      m_field_sources = m_field_labels.size();
      m_field_kept = true;
    }
    if(want_labels)
      for(std::size_t i = 0; i < n; ++i)
        lab[i] = (labels[i] == VTP::no_source || !(d[i] < infinity)) ? -1 : static_cast<std::int64_t>(labels[i]);
    std::size_t k = 0;
    for(std::size_t i = 0; i < target_vertices.size(); ++i)
      td[i] = m_mesh.is_isolated(Vertex_index(static_cast<Mesh::size_type>(target_vertices[i])))
                ? infinity
                : m_solver->target_distance(k++);
  }
  return py::make_tuple(out, want_labels ? py::object(labels_out) : py::object(py::none()), target_out);
}

// A repaired mesh (the mutex held, the GIL released): the field of the sources (vertices of V: all their copies;
// face locations) on the vertices of V, into d (n) and lab (n, if not null): the least over the copies of a
// vertex, its copy's label; 0 (and the first label) at a source vertex; +inf (-1) at a vertex in no face. The
// propagation stops at the targets (vertices of V: all their copies) and at the limit; with through_pinches, the
// copies of the split vertices are joined (paths through them), and targets and limit then bound the result,
// not the work.
void Core_solver::field_on_caller(const std::vector<std::size_t>& source_vertices,
                                  const std::vector<Face_location>& source_points,
                                  const std::vector<std::size_t>& target_vertices, double max_distance,
                                  const vtp_support::Method_info& method, double lam, int threads, double* d,
                                  std::int64_t* lab, bool keep_field)
{
  const std::size_t n = number_of_vertices(), nm = m_mesh.number_of_vertices();
  std::vector<Vertex_index> mesh_sources;
  std::vector<std::size_t> label_of_source;
  for(std::size_t i = 0; i < source_vertices.size(); ++i)
  {
    append_copies(source_vertices[i], mesh_sources);
    label_of_source.resize(mesh_sources.size(), i);
  }
  for(std::size_t j = 0; j < source_points.size(); ++j)
    label_of_source.push_back(source_vertices.size() + j);
  const bool join = m_through_pinches;
  std::vector<Vertex_index> live_targets;
  if(!join)
    for(std::size_t t : target_vertices)
    {
      std::vector<Vertex_index> copies;
      append_copies(t, copies);
      for(Vertex_index c : copies)
        if(!m_mesh.is_isolated(c))
          live_targets.push_back(c);
    }
  const double limit = join ? infinity : max_distance;
  std::vector<double> mesh_d(nm, infinity);
  std::vector<std::size_t> labels;
  if(lab != nullptr)
    labels.assign(nm, VTP::no_source);
  const auto index = get(boost::vertex_index, m_mesh);
  const int t = threads_or_default(threads);
  if(keep_field && label_of_source.empty())
    throw VTP::Invalid_input_error("keep_field=True: the source vertices are in no face of the mesh (the repair "
                                   "removed them), there is no field to keep");
  if(!label_of_source.empty())
  {
    set_sources(mesh_sources, source_points);
    vtp_support::with_method(method, lam, t, [&](auto tag, const auto& method_np) {
      typedef decltype(tag) Tag;
      const auto vdm = boost::make_iterator_property_map(mesh_d.begin(), index);
      const auto np = method_np.maximum_distance(limit)
                        .targets(live_targets)
                        .stop_at_targets(!live_targets.empty())
                        .statistics(m_statistics)
                        .keep_field(keep_field);
      if(lab != nullptr)
        m_solver->template compute<Tag>(vdm, np.nearest_source_map(boost::make_iterator_property_map(
                                               labels.begin(), index)));
      else
        m_solver->template compute<Tag>(vdm, np);
    });
    if(keep_field)
    {
      m_field_labels.assign(label_of_source.begin(), label_of_source.end());
      m_field_sources = source_vertices.size() + source_points.size();
      m_field_kept = true;
    }
    if(lab != nullptr)
      for(std::size_t& l : labels)
        if(l != VTP::no_source)
          l = label_of_source[l];
    if(join)
    {
      m_join_runs = vtp_support::join_copies(m_split, mesh_d, lab != nullptr ? &labels : nullptr,
                                [&](const std::vector<Vertex_index>& copies, std::vector<double>& field) {
                                  set_sources(copies, std::vector<Face_location>());
                                  vtp_support::with_method(method, lam, t, [&](auto tag, const auto& method_np) {
                                    typedef decltype(tag) Tag;
                                    const auto fm = boost::make_iterator_property_map(field.begin(), index);
                                    m_solver->template compute<Tag>(fm, method_np.initial_distances(fm));
                                  });
                                });
      if(max_distance < infinity)
        for(double& x : mesh_d)
          if(x > max_distance)
            x = infinity;
    }
  }
  to_caller(mesh_d, lab != nullptr ? &labels : nullptr, d, lab);
  for(std::size_t i = source_vertices.size(); i-- > 0;)
  {
    d[source_vertices[i]] = 0.;
    if(lab != nullptr)
      lab[source_vertices[i]] = static_cast<std::int64_t>(i);
  }
  (void)n;
}

// The geodesic path to a target (a vertex if target_vertex >= 0, else the face location), from the sources.
// Returns (points (k, 3), faces (k,), barycentric (k, 3), distance), from the source to the target.
py::tuple Core_solver::path(std::int64_t target_vertex, std::int64_t target_face, const Double_array& target_bary,
                            const Index_array& sources, const Index_array& point_faces,
                            const Double_array& point_bary, double max_distance)
{
  check_limit(max_distance);
  const Caller_sources caller = sources_of(sources, point_faces, point_bary);
  const std::vector<std::size_t>& source_vertices = caller.vertices;
  const std::vector<Face_location>& source_points = caller.points;
  if(m_through_pinches && !m_repairs.empty())
    value_error("no path: paths are not traced through the vertices that the repair split (the solver was made "
                "with through_pinches=True)");
  const bool at_vertex = target_vertex >= 0;
  std::vector<Vertex_index> tv, mesh_sources;
  Face_location tl;
  if(at_vertex)
  {
    append_copies(vertex_of(target_vertex, "target"), tv);
    if(tv.empty())
      value_error("no path: target vertex " + std::to_string(target_vertex)
                  + " is in no face of the mesh (the repair removed it), no source reaches it");
  }
  else
    tl = location_of(target_face, target_bary, "target");
  for(std::size_t s : source_vertices)
    append_copies(s, mesh_sources);
  if(mesh_sources.empty() && source_points.empty())
    value_error("no path: the source vertices are in no face of the mesh (the repair removed them)");
  Solver::Polyline path;
  double distance = infinity;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    set_sources(mesh_sources, source_points);
    const CGAL::Constant_property_map<Vertex_index, double> no_map;
    const auto np = VTP::parameters::maximum_distance(max_distance).record_paths(true).stop_at_targets(true)
                      .statistics(m_statistics);
    if(at_vertex)
    {
      // every copy of the target (a copy in no face: the target is isolated), the path from the nearest
      std::vector<Vertex_index> live;
      for(Vertex_index c : tv)
        if(!m_mesh.is_isolated(c))
          live.push_back(c);
      if(live.empty())
        throw VTP::Invalid_input_error("no path: the target is an isolated vertex, which no source reaches");
      m_solver->compute<CGAL::Sequential_tag>(no_map, np.targets(live));
      Vertex_index best = live.front();
      for(std::size_t k = 0; k < live.size(); ++k)
        if(m_solver->target_distance(k) < distance)
        {
          distance = m_solver->target_distance(k);
          best = live[k];
        }
      path = m_solver->shortest_path(best);
    }
    else
    {
      m_solver->compute<CGAL::Sequential_tag>(no_map, np.targets(tl));
      distance = m_solver->target_distance(0);
      path = m_solver->shortest_path(tl);
    }
  }
  const std::vector<Point_3>& points = path.points;
  const std::vector<Face_location>& locations = path.locations;
  const std::size_t k = points.size();
  py::array_t<double> P({ static_cast<py::ssize_t>(k), py::ssize_t(3) });
  py::array_t<std::int64_t> PF(static_cast<py::ssize_t>(locations.size()));
  py::array_t<double> PB({ static_cast<py::ssize_t>(locations.size()), py::ssize_t(3) });
  double* p = P.mutable_data();
  for(std::size_t i = 0; i < k; ++i) // the library gives the target first: reversed, source first
    for(int j = 0; j < 3; ++j)
      p[3 * i + std::size_t(j)] = points[k - 1 - i][j];
  std::int64_t* pf = PF.mutable_data();
  double* pb = PB.mutable_data();
  for(std::size_t i = 0; i < locations.size(); ++i)
  {
    const Face_location& l = locations[locations.size() - 1 - i];
    pf[i] = to_user_face(l.first);
    const std::array<double, 3> b = to_user_barycentric(l);
    for(int j = 0; j < 3; ++j)
      pb[3 * i + std::size_t(j)] = b[std::size_t(j)];
  }
  return py::make_tuple(P, PF, PB, distance);
}

// The distance from one source (vertex or location) to one target (vertex or location), stopping once the
// target's distance is final.
double Core_solver::distance(std::int64_t a_vertex, std::int64_t a_face, const Double_array& a_bary,
                             std::int64_t b_vertex, std::int64_t b_face, const Double_array& b_bary,
                             const std::string& method_name, double lam)
{
  const vtp_support::Method_info& method = method_named(method_name, lam);
  std::vector<Vertex_index> av, bv;
  Face_location al, bl;
  if(a_vertex >= 0)
    append_copies(vertex_of(a_vertex, "a"), av);
  else
    al = location_of(a_face, a_bary, "a");
  if(b_vertex >= 0)
    append_copies(vertex_of(b_vertex, "b"), bv);
  else
    bl = location_of(b_face, b_bary, "b");
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(m_mutex);
  if(a_vertex >= 0 && a_vertex == b_vertex)
    return 0.;
  if(!m_repairs.empty() && m_through_pinches && b_vertex < 0)
    throw VTP::Invalid_input_error("the distance to a point of a face is not joined through the vertices that the "
                                   "repair split (the solver was made with through_pinches=True): give a vertex");
  if(!m_repairs.empty() && m_through_pinches)
  {
    // the whole field, its copies joined
    std::vector<double> d(number_of_vertices());
    std::vector<Face_location> points;
    std::vector<std::size_t> sources;
    if(a_vertex >= 0)
      sources.push_back(static_cast<std::size_t>(a_vertex));
    else
      points.push_back(al);
    field_on_caller(sources, points, std::vector<std::size_t>(), infinity, method, lam, 0, d.data(), nullptr, false);
    return d[static_cast<std::size_t>(b_vertex)];
  }
  std::vector<Vertex_index> live;
  for(Vertex_index c : bv)
    if(!m_mesh.is_isolated(c))
      live.push_back(c);
  if((b_vertex >= 0 && live.empty()) || (a_vertex >= 0 && av.empty()))
    return infinity;
  if(a_vertex >= 0)
    set_sources(av, std::vector<Face_location>());
  else
    set_sources(std::vector<Vertex_index>(), std::vector<Face_location>(1, al));
  const CGAL::Constant_property_map<Vertex_index, double> no_map;
  vtp_support::with_method(method, lam, threads_or_default(0), [&](auto tag, const auto& method_np) {
    typedef decltype(tag) Tag;
    const auto np = method_np.stop_at_targets(true).statistics(m_statistics);
    if(b_vertex >= 0)
      m_solver->template compute<Tag>(no_map, np.targets(live));
    else
      m_solver->template compute<Tag>(no_map, np.targets(bl));
  });
  double r = infinity;
  for(std::size_t k = 0; k < m_solver->number_of_targets(); ++k)
    r = (std::min)(r, m_solver->target_distance(k));
  return r;
}

// Nearest points of the surface to the rows of P (k, 3): (faces (k,), barycentric (k, 3)).
py::tuple Core_solver::locate(const Double_array& P)
{
  const std::size_t k = static_cast<std::size_t>(P.size()) / 3;
  const double* p = P.data();
  for(std::size_t i = 0; i < 3 * k; ++i)
    if(!std::isfinite(p[i]))
      value_error("point " + std::to_string(i / 3) + " has a non-finite coordinate");
  py::array_t<std::int64_t> faces(static_cast<py::ssize_t>(k));
  py::array_t<double> bary({ static_cast<py::ssize_t>(k), py::ssize_t(3) });
  std::int64_t* fo = faces.mutable_data();
  double* bo = bary.mutable_data();
  std::string error;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    if(!m_locator)
      m_locator.reset(new vtp_support::Surface_locator(m_mesh));
    for(std::size_t i = 0; i < k; ++i)
    {
      Face_location l;
      if(!m_locator->locate(Point_3(p[3 * i], p[3 * i + 1], p[3 * i + 2]), l))
      {
        error = "cannot locate point " + std::to_string(i) + " on the surface (its nearest face is degenerate)";
        break;
      }
      const std::array<double, 3> u = to_user_barycentric(l);
      fo[i] = to_user_face(l.first);
      for(int j = 0; j < 3; ++j)
        bo[3 * i + std::size_t(j)] = u[std::size_t(j)];
    }
  }
  if(!error.empty())
    value_error(error);
  return py::make_tuple(faces, bary);
}

void define_queries(py::class_<Core_solver>& c)
{
  c.def("distances", &Core_solver::distances)
    .def("path", &Core_solver::path)
    .def("distance", &Core_solver::distance)
    .def("locate", &Core_solver::locate);
}

} // namespace vtp_python
