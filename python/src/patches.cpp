// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Polar patches: Solver.polar_patches() of the package, the log map around many centres (vertices and points of
// faces) cut at a radius, on the solver's threads (the library's Geodesic_distance_solver::compute_each_polar_patch()),
// as CSR arrays; Ctrl-C as for the distance matrices (interrupt.h).

#include "core_solver.h"
#include "interrupt.h"

#include <vtp_support/methods.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <cmath>
#include <string>

namespace vtp_python {

// The patches of the vertices `centres` of V, then of the face locations (point_faces, point_bary), within
// `radius`: (indptr int64 (k + 1,), indices int64 (nnz,), rho float64 (nnz,), theta float64 (nnz,)), row i the
// patch of the i-th centre (the vertices first, then the points), its vertices (rows of V) ascending.
// A centre vertex must stand for one vertex of the mesh (not a vertex the repair split or dropped); a vertex of
// V that the repair split appears once in a patch, with the entry of its copy of least rho. The theta of a point's
// patch is in the caller's frame of its face (caller_face_frame(), as log_map() without a reference). Ctrl-C
// stops the handing out of patches (interrupt.h) and raises KeyboardInterrupt once those under way are done.
py::tuple Core_solver::polar_patches(const Index_array& centres, const Index_array& point_faces,
                                     const Double_array& point_bary, double radius, bool strict, int threads)
{
  if(!(radius >= 0.))
    value_error("radius must be >= 0 (inf for whole log maps), got " + std::to_string(radius));
  const std::size_t kv = static_cast<std::size_t>(centres.size());
  std::vector<Vertex_index> mesh_centres(kv);
  for(std::size_t i = 0; i < kv; ++i)
  {
    const std::size_t v = vertex_of(centres.data()[i], "centres");
    std::vector<Vertex_index> copies;
    append_copies(v, copies);
    if(copies.size() != 1 || m_mesh.is_isolated(copies[0]))
      value_error("centres: vertex " + std::to_string(v)
                  + (copies.size() > 1 ? " was split by the repair (a non-manifold vertex): it has no tangent plane"
                                       : " is in no face of the mesh"));
    mesh_centres[i] = copies[0];
  }
  const std::vector<Face_location> point_centres = locations_of(point_faces, point_bary, "points");
  std::vector<std::array<double, 4> > frames;
  for(const Face_location& l : point_centres)
    frames.push_back(caller_face_frame(l.first));
  const std::size_t k = kv + point_centres.size();
  std::vector<std::int64_t> indptr(k + 1, 0), indices;
  std::vector<double> rho, theta;
  Interrupt_check check(k, false);
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    std::vector<std::size_t> start(k, 0), count(k, 0);
    std::vector<std::pair<std::size_t, std::size_t> > row;  // (caller vertex, entry) of one patch
    std::vector<std::int64_t> best;                          // per caller vertex, its entry in the row, or -1
    if(!m_repairs.empty())
      best.assign(m_n, -1);
    // the angle of an entry of row i: for a point, turned into the caller's frame of its face
    auto angle = [&](std::size_t i, double t) {
      if(i < kv)
        return t;
      const std::array<double, 4>& m = frames[i - kv];
      const double c = std::cos(t), s = std::sin(t);
      double a = std::atan2(m[2] * c + m[3] * s, m[0] * c + m[1] * s);
      if(a < 0.)
        a += 2. * CGAL_PI;
      return a < 2. * CGAL_PI ? a : 0.;
    };
    auto sink = [&](std::size_t i, const std::vector<std::uint32_t>& v, const std::vector<double>& r,
                    const std::vector<double>& t) {
      start[i] = indices.size();
      if(m_repairs.empty())
      {
        indices.insert(indices.end(), v.begin(), v.end());
        rho.insert(rho.end(), r.begin(), r.end());
        for(double x : t)
          theta.push_back(angle(i, x));
      }
      else
      {
        // the mesh vertices of the patch on the rows of V: one entry per row, the copy of least rho
        row.clear();
        for(std::size_t e = 0; e < v.size(); ++e)
        {
          const std::size_t c = caller_of(m_solver->vertex_list()[v[e]]);
          if(best[c] < 0)
          {
            best[c] = static_cast<std::int64_t>(row.size());
            row.push_back(std::make_pair(c, e));
          }
          else if(r[e] < r[row[static_cast<std::size_t>(best[c])].second])
            row[static_cast<std::size_t>(best[c])].second = e;
        }
        std::sort(row.begin(), row.end());
        for(const auto& p : row)
        {
          best[p.first] = -1;
          indices.push_back(static_cast<std::int64_t>(p.first));
          rho.push_back(r[p.second]);
          theta.push_back(angle(i, t[p.second]));
        }
      }
      count[i] = indices.size() - start[i];
      check.row_done();
    };
    const auto np = VTP::parameters::number_of_threads(threads_or_default(threads)).log_map_strict(strict);
    auto run = [&](const auto& items, std::size_t offset) {
      if(items.empty())
        return;
      auto offset_sink = [&](std::size_t i, const auto&, const std::vector<std::uint32_t>& v,
                             const std::vector<double>& r, const std::vector<double>& t) { sink(offset + i, v, r, t); };
      m_solver->compute_each_polar_patch<vtp_support::Rows_tag>(items, radius, offset_sink, np);
    };
    try
    {
      run(mesh_centres, 0);
      run(point_centres, kv);
    }
    catch(const Python_error_pending&)
    {
      interrupted = true;
    }
    m_statistics = m_solver->statistics();
    if(!interrupted)
    {
      for(std::size_t i = 0; i < k; ++i)
        indptr[i + 1] = indptr[i] + static_cast<std::int64_t>(count[i]);
      // the rows in the order of the centres (they came in any order)
      bool in_order = true;
      for(std::size_t i = 0; i < k; ++i)
        in_order = in_order && start[i] == static_cast<std::size_t>(indptr[i]);
      if(!in_order)
      {
        std::vector<std::int64_t> ordered_indices(indices.size());
        std::vector<double> ordered_rho(rho.size()), ordered_theta(theta.size());
        for(std::size_t i = 0; i < k; ++i)
        {
          const std::size_t to = static_cast<std::size_t>(indptr[i]);
          std::copy_n(indices.begin() + static_cast<std::ptrdiff_t>(start[i]), count[i], ordered_indices.begin() + static_cast<std::ptrdiff_t>(to));
          std::copy_n(rho.begin() + static_cast<std::ptrdiff_t>(start[i]), count[i], ordered_rho.begin() + static_cast<std::ptrdiff_t>(to));
          std::copy_n(theta.begin() + static_cast<std::ptrdiff_t>(start[i]), count[i], ordered_theta.begin() + static_cast<std::ptrdiff_t>(to));
        }
        indices.swap(ordered_indices);
        rho.swap(ordered_rho);
        theta.swap(ordered_theta);
      }
    }
  }
  if(interrupted)
    check.error.restore_and_throw();
  auto to_array = [](auto& v) {
    typedef typename std::decay<decltype(v)>::type::value_type T;
    py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
  };
  return py::make_tuple(to_array(indptr), to_array(indices), to_array(rho), to_array(theta));
}

void define_patches(py::class_<Core_solver>& c)
{
  c.def("polar_patches", &Core_solver::polar_patches);
}

} // namespace vtp_python
