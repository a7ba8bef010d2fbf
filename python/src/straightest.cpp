// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Straightest geodesics (the exp map): Solver.trace() of the package, many walks at once on the solver's threads.

#include "core_solver.h"

#include <vtp_support/methods.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <cmath>
#include <string>

namespace vtp_python {

// The walks from starts[i] (start_vertices[i] >= 0: that vertex of V; else the point (start_faces[i],
// start_bary[i])), in directions[i] (n, 2): the tangent frame of the start, (n, 3): projected), for lengths[i].
// A 2D direction at a point of a face is in the frame of F[face] (x along F[face][0] -> F[face][1], y towards
// F[face][2]). Returns (points (total, 3), offsets (n + 1,), end faces (n,), end barycentric (n, 3), end
// directions (n, 3), lengths walked (n,), reached border (n,)).
py::tuple Core_solver::trace(const Index_array& start_vertices, const Index_array& start_faces,
                             const Double_array& start_bary, const Double_array& directions,
                             const Double_array& lengths, int threads)
{
  const std::size_t n = static_cast<std::size_t>(start_vertices.size());
  if(directions.ndim() != 2 || static_cast<std::size_t>(directions.shape(0)) != n
     || (directions.shape(1) != 2 && directions.shape(1) != 3))
    value_error("directions must be of shape (n, 2) or (n, 3), n the number of starts");
  if(static_cast<std::size_t>(lengths.size()) != n || static_cast<std::size_t>(start_faces.size()) != n
     || static_cast<std::size_t>(start_bary.size()) != 3 * n)
    value_error("the starts, the directions and the lengths must be as many");
  const std::size_t dim = static_cast<std::size_t>(directions.shape(1));
  const std::int64_t* sv = start_vertices.data();
  const double* dir = directions.data();
  // every start as a face location of the mesh (a vertex: a corner of one of its faces, which the library
  // takes as the vertex), every direction in the library's frame of the start
  std::vector<Face_location> starts(n);
  std::vector<std::array<double, 2> > d2(dim == 2 ? n : 0);
  std::vector<std::array<double, 3> > d3(dim == 3 ? n : 0);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::string name = "start " + std::to_string(i);
    if(sv[i] >= 0)
    {
      std::vector<Vertex_index> copies;
      append_copies(vertex_of(sv[i], "start"), copies);
      Halfedge_index h;
      if(!copies.empty() && !m_mesh.is_isolated(copies.front()))
        for(Halfedge_index g : CGAL::halfedges_around_target(m_mesh.halfedge(copies.front()), m_mesh))
          if(!m_mesh.is_border(g))
            h = g;
      if(h == Halfedge_index())
        value_error(name + ": vertex " + std::to_string(sv[i]) + " is in no face of the mesh");
      const Face_index f = m_mesh.face(h);
      Face_location l(f, { { 0., 0., 0. } });
      int k = 0;
      for(Halfedge_index g = m_mesh.halfedge(f); m_mesh.source(g) != copies.front(); g = m_mesh.next(g))
        ++k;
      l.second[std::size_t(k)] = 1.;
      starts[i] = l;
    }
    else
    {
      Index_array face(1);
      face.mutable_data()[0] = start_faces.data()[i];
      Double_array bary({ py::ssize_t(1), py::ssize_t(3) });
      for(int k = 0; k < 3; ++k)
        bary.mutable_data()[k] = start_bary.data()[3 * i + std::size_t(k)];
      starts[i] = locations_of(face, bary, "start").at(0);
    }
    if(dim == 3)
      d3[i] = { { dir[3 * i], dir[3 * i + 1], dir[3 * i + 2] } };
    else if(sv[i] >= 0)
      d2[i] = { { dir[2 * i], dir[2 * i + 1] } };
    else
    {
      // the frame of F[face] (the caller's corner order) to the frame of halfedge(f): the transpose of
      // caller_face_frame() (log_map.cpp), a rotation
      const std::array<double, 4> m = caller_face_frame(starts[i].first);
      const double a = dir[2 * i], b = dir[2 * i + 1];
      const double norm = std::sqrt(a * a + b * b);
      // (a zero or non-finite direction stays so: the library names it)
      d2[i] = std::isfinite(norm) && norm > 0. ? std::array<double, 2>{ { m[0] * a + m[2] * b, m[1] * a + m[3] * b } }
                                               : std::array<double, 2>{ { a, b } };
    }
  }
  const std::vector<double> len(lengths.data(), lengths.data() + n);
  typedef VTP::Straightest_geodesic<Face_index, Point_3> Walk;
  std::vector<Walk> walks;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto np = VTP::parameters::number_of_threads(threads_or_default(threads));
    walks = dim == 2 ? m_solver->straightest_geodesics<vtp_support::Rows_tag>(starts, d2, len, np)
                     : m_solver->straightest_geodesics<vtp_support::Rows_tag>(starts, d3, len, np);
  }
  std::size_t total = 0;
  for(const Walk& w : walks)
    total += w.points.size();
  py::array_t<double> P({ static_cast<py::ssize_t>(total), py::ssize_t(3) });
  py::array_t<std::int64_t> offsets(static_cast<py::ssize_t>(n + 1));
  py::array_t<std::int64_t> faces(static_cast<py::ssize_t>(n));
  py::array_t<double> bary({ static_cast<py::ssize_t>(n), py::ssize_t(3) });
  py::array_t<double> end_dir({ static_cast<py::ssize_t>(n), py::ssize_t(3) });
  py::array_t<double> walked(static_cast<py::ssize_t>(n));
  py::array_t<bool> border(static_cast<py::ssize_t>(n));
  double* p = P.mutable_data();
  std::int64_t* o = offsets.mutable_data();
  o[0] = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Walk& w = walks[i];
    for(const Point_3& q : w.points)
      for(int j = 0; j < 3; ++j)
        *p++ = q[j];
    o[i + 1] = o[i] + static_cast<std::int64_t>(w.points.size());
    faces.mutable_data()[i] = to_user_face(w.end_location.first);
    const std::array<double, 3> b = to_user_barycentric(w.end_location);
    for(int j = 0; j < 3; ++j)
    {
      bary.mutable_data()[3 * i + std::size_t(j)] = b[std::size_t(j)];
      end_dir.mutable_data()[3 * i + std::size_t(j)] = w.end_direction[std::size_t(j)];
    }
    walked.mutable_data()[i] = w.length;
    border.mutable_data()[i] = w.reached_border;
  }
  return py::make_tuple(P, offsets, faces, bary, end_dir, walked, border);
}

void define_straightest(py::class_<Core_solver>& c) { c.def("trace", &Core_solver::trace); }

} // namespace vtp_python
