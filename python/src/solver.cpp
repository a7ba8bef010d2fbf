// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The solver of one mesh: the Surface_mesh built from V and F (checked), the library's per-mesh preprocessing,
// and the statistics of the last computation (see core_solver.h).

#include "core_solver.h"

#include <vtp_support/statistics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <algorithm>
#include <chrono>
#include <cmath>


namespace vtp_python {

const vtp_support::Method_info& method_named(const std::string& name, double lam)
{
  const vtp_support::Method_info* m = vtp_support::find_method(name);
  if(m == nullptr)
    value_error("unknown method '" + name + "' (expected " + vtp_support::method_names() + ")");
  if(!vtp_support::method_available(*m))
    value_error("method '" + name + "' needs OpenMP, and this module was built without it");
  if(m->approximate && !(lam > 0.))
    value_error("lam must be > 0, got " + std::to_string(lam));
  return *m;
}

void check_limit(double max_distance)
{
  if(!(max_distance >= 0.))
    value_error("max_distance must be >= 0 (inf for none), got " + std::to_string(max_distance));
}

Core_solver::Core_solver(const Double_array& V, const Index_array& F, int threads, bool repair, bool through_pinches)
  : m_through_pinches(through_pinches), m_threads(threads)
{
  // V is (n, 3) and F is (m, 3) (checked in Python): their rows are read within their sizes
  const std::size_t n = static_cast<std::size_t>(V.size()) / 3, m = static_cast<std::size_t>(F.size()) / 3;
  if(n == 0)
    value_error("the mesh has no vertices");
  if(m == 0)
    value_error("the mesh has no faces");
  if(n >= (std::size_t(1) << 31) - 1 || m >= ((std::size_t(1) << 31) - 1) / 3)
    value_error("the mesh is too large (at most 2^31 - 2 vertices and (2^31 - 1) / 3 faces)");
  m_n = n;
  m_m = m;
  const double* v = V.data();
  const std::int64_t* f = F.data();
  std::string error;
  {
    py::gil_scoped_release release;
    const auto t0 = std::chrono::steady_clock::now();
    bool repairable = false;
    error = build_mesh(v, n, f, m, repairable);
    if(!error.empty() && repairable && repair)
      error = repair_mesh(v, n, f, m);
    m_build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if(error.empty())
    {
      try
      {
        m_solver.reset(new Solver(m_mesh, VTP::parameters::number_of_threads(threads)));
      }
      catch(const VTP::Invalid_input_error& e)
      {
        error = std::string("the mesh cannot be used: ") + e.what();
      }
    }
  }
  if(!error.empty())
    value_error(error);
  for(std::size_t i = 0; i < m_mesh.number_of_vertices(); ++i)
    if(m_solver->vertex_id(Vertex_index(static_cast<Mesh::size_type>(i))) != i)
      value_error("internal error: the solver numbers the vertices differently from V");
}

py::dict Core_solver::statistics() const
{
  VTP::Propagation_statistics st;
  {
    // a computation holds the mutex and takes the GIL now and then (matrices.cpp): never wait for it holding
    // the GIL
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    st = m_statistics;
  }
  py::dict d;
  vtp_support::for_each_statistic(st, [&](const char* name, const auto& value, vtp_support::Statistic_unit) {
    d[name] = value;
  });
  // the stages from V and F to the answer, from their description (vtp_support/statistics.h): the solver's
  // (checking V and F and building the mesh as "repair_seconds", its preprocessing, the last propagation); when V
  // and F are the arrays that the last read_mesh() returned, its reading as "read_seconds" and its check of the
  // faces in "repair_seconds" (see take_read()); else the file was read by the caller: read_seconds is 0. The
  // outputs are the caller's: write_seconds is 0
  vtp_support::Stage_seconds stages;
  stages.read = m_read_seconds;
  stages.repair = m_read_check_seconds + m_build_seconds;
  stages.preprocessing = m_solver->preprocessing_seconds();
  stages.propagation = st.seconds;
  stages.total = stages.read + stages.repair + stages.preprocessing + stages.propagation;
  vtp_support::for_each_stage(stages, [&](const char* name, double value, vtp_support::Statistic_unit) {
    d[name] = value;
  });
  d["mesh_build_seconds"] = m_build_seconds;
  return d;
}

// Checks V and F and builds the mesh; returns the problem, or an empty string (`repairable`: the problem is one
// that the repair fixes).
std::string Core_solver::build_mesh(const double* v, std::size_t n, const std::int64_t* f, std::size_t m,
                                    bool& repairable)
{
  repairable = false;
  for(std::size_t i = 0; i < n; ++i)
    if(!(std::isfinite(v[3 * i]) && std::isfinite(v[3 * i + 1]) && std::isfinite(v[3 * i + 2])))
      return "vertex " + std::to_string(i) + " has a non-finite coordinate (NaN or infinity)";
  std::int64_t lo = (std::numeric_limits<std::int64_t>::max)(), hi = (std::numeric_limits<std::int64_t>::min)();
  for(std::size_t k = 0; k < 3 * m; ++k)
  {
    lo = (std::min)(lo, f[k]);
    hi = (std::max)(hi, f[k]);
  }
  if(lo < 0 || hi >= static_cast<std::int64_t>(n))
  {
    for(std::size_t k = 0; k < 3 * m; ++k)
      if(f[k] < 0 || f[k] >= static_cast<std::int64_t>(n))
      {
        std::string s = "face " + std::to_string(k / 3) + " has vertex index " + std::to_string(f[k])
                        + ", out of range [0, " + std::to_string(n) + ")";
        if(lo >= 1 && hi == static_cast<std::int64_t>(n))
          s += " (are the faces numbered from 1? pass F - 1)";
        return s;
      }
  }
  std::vector<vtp_support::fast_off_detail::Triangle> triangles(m);
  for(std::size_t j = 0; j < m; ++j)
  {
    for(int k = 0; k < 3; ++k)
      triangles[j][std::size_t(k)] = static_cast<std::uint32_t>(f[3 * j + std::size_t(k)]);
    if(f[3 * j] == f[3 * j + 1] || f[3 * j + 1] == f[3 * j + 2] || f[3 * j + 2] == f[3 * j])
    {
      repairable = true;
      return "face " + std::to_string(j) + " has a repeated vertex (" + std::to_string(f[3 * j]) + ", "
             + std::to_string(f[3 * j + 1]) + ", " + std::to_string(f[3 * j + 2])
             + ") (Solver(V, F, repair=True) removes such faces)";
    }
  }
  m_mesh.reserve(static_cast<Mesh::size_type>(n), 0, 0);
  for(std::size_t i = 0; i < n; ++i)
    m_mesh.add_vertex(Point_3(v[3 * i], v[3 * i + 1], v[3 * i + 2]));
  // V and F as read_mesh() returned them: its seconds in the statistics, its check of the faces not done again
  Read_record read;
  if(take_read(n, triangles, read))
  {
    m_read_seconds = read.read_seconds;
    m_read_check_seconds = read.check_seconds;
  }
  std::string reason;
  if(!vtp_support::fast_off_detail::build_triangle_mesh(triangles, m_mesh, reason, m_threads,
                                                        read.has_tables ? &read.tables : nullptr))
  {
    repairable = true;
    return "the faces do not form a manifold, consistently oriented triangle mesh: " + reason
           + " (Solver(V, F, repair=True) repairs them as the tool does)";
  }
  if(m_mesh.number_of_faces() != m)
    return "internal error: the mesh has " + std::to_string(m_mesh.number_of_faces()) + " faces, F has "
           + std::to_string(m);
  // Each face's halfedge runs from its first corner in F to its second (build_triangle_mesh() makes it so):
  // then the barycentric coordinates need no permutation and F need not be kept (3 x 4 bytes a face).
  bool same_order = true;
  for(std::size_t j = 0; j < m && same_order; ++j)
  {
    const Halfedge_index h = m_mesh.halfedge(Face_index(static_cast<Mesh::size_type>(j)));
    same_order = static_cast<std::size_t>(m_mesh.source(h)) == triangles[j][0]
                 && static_cast<std::size_t>(m_mesh.target(h)) == triangles[j][1];
  }
  if(!same_order)
    m_triangles = std::move(triangles);
  return std::string();
}

// The threads of a computation: `threads` if positive, else the solver's, else all cores.
int Core_solver::threads_or_default(int threads) const
{
  const int t = threads > 0 ? threads : m_threads;
  return t > 0 ? t : vtp_support::default_threads();
}

void Core_solver::set_sources(const std::vector<Vertex_index>& vertices, const std::vector<Face_location>& points)
{
  m_field_kept = false;  // the next computation replaces the field (distances(..., keep_field=True) sets it after)
  m_solver->clear_sources();
  for(Vertex_index s : vertices)
    m_solver->add_source(s);
  for(const Face_location& l : points)
    m_solver->add_source(l);
}

void define_solver(py::class_<Core_solver>& c)
{
  c.def(py::init<const Double_array&, const Index_array&, int, bool, bool>(), py::arg("V"), py::arg("F"),
         py::arg("threads"), py::arg("repair"), py::arg("through_pinches"))
    .def_property_readonly("number_of_vertices", &Core_solver::number_of_vertices)
    .def_property_readonly("number_of_faces", &Core_solver::number_of_faces)
    .def_property_readonly("repairs", &Core_solver::repairs)
    .def_property_readonly("mesh_vertices", &Core_solver::mesh_vertices)
    .def_property_readonly("mesh_faces", &Core_solver::mesh_faces)
    .def("vertex_copies", &Core_solver::vertex_copies)
    .def_property_readonly("join_runs", &Core_solver::join_runs)
    .def_property_readonly("mean_edge_length", &Core_solver::mean_edge_length)
    .def_property_readonly("preprocessing_seconds", &Core_solver::preprocessing_seconds)
    .def("statistics", &Core_solver::statistics);
}

} // namespace vtp_python
