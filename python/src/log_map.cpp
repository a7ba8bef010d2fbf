// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The log map (geodesic polar coordinates): Solver.log_map() of the package, one run of VTP or PVTP with the
// library's named parameters log_map, log_map_via, log_map_strict and reference_direction (see core_solver.h).

#include "core_solver.h"

#include <CGAL/VTP_geodesics/parameters.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <string>

namespace vtp_python {

namespace log_map_detail {

typedef std::array<double, 3> Vec3;

Vec3 difference(const Point_3& a, const Point_3& b) { return { { a.x() - b.x(), a.y() - b.y(), a.z() - b.z() } }; }
double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 unit3(const Vec3& a)
{
  const double n = std::sqrt(dot3(a, a));
  return n > 0. ? Vec3{ { a[0] / n, a[1] / n, a[2] / n } } : a;
}
// the unit axes of the frame of the corners (a, b, c): x along a -> b, y towards c, in their plane
void face_axes(const Point_3& a, const Point_3& b, const Point_3& c, Vec3& x, Vec3& y)
{
  x = unit3(difference(b, a));
  const Vec3 ac = difference(c, a);
  const double t = dot3(ac, x);
  y = unit3(Vec3{ { ac[0] - t * x[0], ac[1] - t * x[1], ac[2] - t * x[2] } });
}

} // namespace log_map_detail

// The 2 x 2 map (row major) from the library's frame of face f (x along halfedge(f)) to the caller's (x along
// F[face][0] -> F[face][1], y towards F[face][2]), the frame of trace() at a point of a face.
std::array<double, 4> Core_solver::caller_face_frame(Face_index f) const
{
  using namespace log_map_detail;
  const Halfedge_index h = m_mesh.halfedge(f);
  const Point_3 lib[3] = { m_mesh.point(m_mesh.source(h)), m_mesh.point(m_mesh.target(h)),
                           m_mesh.point(m_mesh.target(m_mesh.next(h))) };
  const std::array<int, 3> pos = corner_order(f);
  Point_3 user[3];
  for(int k = 0; k < 3; ++k)
    user[pos[std::size_t(k)]] = lib[k];
  Vec3 ux, uy, lx, ly;
  face_axes(user[0], user[1], user[2], ux, uy);
  face_axes(lib[0], lib[1], lib[2], lx, ly);
  return { { dot3(lx, ux), dot3(ly, ux), dot3(lx, uy), dot3(ly, uy) } };
}

// One run from the sources (vertices of V: all their copies; face locations), VTP or PVTP, with the log map.
// Returns (coordinates (n, 2): rho (cos theta, sin theta), +inf where unreached; via (n,) int64: the last vertex
// of V the geodesic passes through, -1 for none). `reference`: empty, or a 3D direction.
py::tuple Core_solver::log_map(const Index_array& sources, const Index_array& point_faces,
                               const Double_array& point_bary, double max_distance, const Double_array& reference,
                               bool strict, const std::string& method_name, int threads)
{
  const vtp_support::Method_info& method = method_named(method_name, 1.);
  if(method.approximate || method.virtual_sources)
    value_error("log_map: method must be \"vtp\" or \"pvtp\", got \"" + method_name
                + "\" (the approximate methods and the virtual sources carry no direction)");
  check_limit(max_distance);
  const Caller_sources caller = sources_of(sources, point_faces, point_bary);
  const std::vector<std::size_t>& source_vertices = caller.vertices;
  const std::vector<Face_location>& source_points = caller.points;
  const bool has_reference = reference.size() != 0;
  if(has_reference && reference.size() != 3)
    value_error("reference must be a 3D direction (3,)");
  const std::array<double, 3> ref = has_reference ? std::array<double, 3>{ { reference.data()[0], reference.data()[1],
                                                                            reference.data()[2] } }
                                                  : std::array<double, 3>{ { 1., 0., 0. } };
  if(has_reference && (!std::isfinite(ref[0] + ref[1] + ref[2]) || (ref[0] == 0. && ref[1] == 0. && ref[2] == 0.)))
    value_error("reference must be a finite, non-zero 3D direction");
  if(m_through_pinches && !m_split.empty())
    value_error("log_map: the log map is not joined through the vertices that the repair split (the solver was "
                "made with through_pinches=True)");
  // the sources on the mesh (a vertex in no face: at 0 below, no propagation from it)
  std::vector<Vertex_index> mesh_sources;
  for(std::size_t s : source_vertices)
  {
    std::vector<Vertex_index> copies;
    append_copies(s, copies);
    for(Vertex_index c : copies)
      if(!m_mesh.is_isolated(c))
        mesh_sources.push_back(c);
  }
  // a point's coordinates in the caller's frame of its face (without a reference direction)
  std::vector<std::array<double, 4> > frames;
  if(!has_reference)
    for(const Face_location& l : source_points)
      frames.push_back(caller_face_frame(l.first));

  const std::size_t n = number_of_vertices(), nm = m_mesh.number_of_vertices();
  std::vector<double> d(nm, infinity);
  std::vector<std::array<double, 2> > x(nm, std::array<double, 2>{ { infinity, infinity } });
  std::vector<Vertex_index> via(nm);
  std::vector<std::size_t> labels(nm, VTP::no_source);
  if(!mesh_sources.empty() || !source_points.empty())
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    set_sources(mesh_sources, source_points);
    const auto index = get(boost::vertex_index, m_mesh);
    vtp_support::with_method(method, 1., threads_or_default(threads), [&](auto tag, const auto& method_np) {
      typedef decltype(tag) Tag;
      const auto np = method_np.maximum_distance(max_distance)
                        .statistics(m_statistics)
                        .nearest_source_map(boost::make_iterator_property_map(labels.begin(), index))
                        .log_map(boost::make_iterator_property_map(x.begin(), index))
                        .log_map_via(boost::make_iterator_property_map(via.begin(), index))
                        .log_map_strict(strict);
      const auto dm = boost::make_iterator_property_map(d.begin(), index);
      if(has_reference)
        m_solver->template compute<Tag>(dm, np.reference_direction(ref));
      else
        m_solver->template compute<Tag>(dm, np);
    });
    if(!has_reference)
      for(std::size_t i = 0; i < nm; ++i)
        if(labels[i] != VTP::no_source && labels[i] >= mesh_sources.size() && d[i] < infinity)
        {
          const std::array<double, 4>& m = frames[labels[i] - mesh_sources.size()];
          const double a = x[i][0], b = x[i][1];
          x[i] = { { m[0] * a + m[1] * b, m[2] * a + m[3] * b } };
        }
  }

  // on the vertices of V: the copy nearest to a source (the first of least distance)
  py::array_t<double> out({ static_cast<py::ssize_t>(n), py::ssize_t(2) });
  py::array_t<std::int64_t> via_out(static_cast<py::ssize_t>(n));
  double* o = out.mutable_data();
  std::int64_t* w = via_out.mutable_data();
  for(std::size_t j = 0; j < n; ++j)
  {
    std::size_t best = nm;
    if(m_repairs.empty())
      best = j;
    else
      for(std::size_t k = m_copy_begin[j]; k < m_copy_begin[j + 1]; ++k)
        if(best == nm || d[std::size_t(m_copies[k])] < d[best])
          best = std::size_t(m_copies[k]);
    const bool reached = best < nm && d[best] < infinity;
    o[2 * j] = reached ? x[best][0] : infinity;
    o[2 * j + 1] = reached ? x[best][1] : infinity;
    w[j] = reached && via[best] != Vertex_index() ? static_cast<std::int64_t>(caller_of(via[best])) : -1;
  }
  for(std::size_t s : source_vertices)
  {
    o[2 * s] = o[2 * s + 1] = 0.;
    w[s] = -1;
  }
  return py::make_tuple(out, via_out);
}

void define_log_map(py::class_<Core_solver>& c) { c.def("log_map", &Core_solver::log_map); }

} // namespace vtp_python
