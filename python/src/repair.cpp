// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The repair of V and F that do not form a valid mesh, as the tools repair a file (the support layer's
// triangle_mesh_from_soup(): duplicate points merged, degenerate and duplicate faces removed, faces reoriented,
// the surface cut at non-manifold edges and vertices), and the correspondence of the caller's vertices and
// faces (the rows of V and F) with the mesh's, both ways (see core_solver.h).

#include "core_solver.h"

#include <vtp_support/triangle_mesh_from_soup.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>

#include <algorithm>
#include <utility>

namespace vtp_python {

// Builds the repaired mesh of V and F (checked values) and the correspondence; returns the problem, or "".
std::string Core_solver::repair_mesh(const double* v, std::size_t n, const std::int64_t* f, std::size_t m)
{
  std::vector<Point_3> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  std::vector<std::vector<std::size_t> > polygons(m, std::vector<std::size_t>(3));
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t k = 0; k < 3; ++k)
      polygons[j][k] = static_cast<std::size_t>(f[3 * j + k]);
  m_triangles.clear();
  vtp_support::Soup_repair_report report;
  try
  {
    report = vtp_support::triangle_mesh_from_soup(std::move(points), std::move(polygons), m_mesh, m_copy_begin,
                                                  m_copies);
  }
  catch(const VTP::Invalid_input_error& e)
  {
    return std::string("the faces cannot be repaired into a triangle mesh: ") + e.what();
  }
  m_repairs = report.summary();
  if(m_repairs.empty())
    m_repairs = "rebuilt the mesh";
  m_caller_of.assign(m_mesh.number_of_vertices(), 0);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = m_copy_begin[i]; k < m_copy_begin[i + 1]; ++k)
      m_caller_of[std::size_t(m_copies[k])] = i;
  map_faces(f, m);
  for(std::size_t i = 0; i < n; ++i)
    if(m_copy_begin[i + 1] - m_copy_begin[i] > 1 && canonical_of(i) == i)
      m_split.emplace_back(m_copies.begin() + std::ptrdiff_t(m_copy_begin[i]),
                           m_copies.begin() + std::ptrdiff_t(m_copy_begin[i + 1]));
  return std::string();
}

// The vertex of V that stands for the mesh vertices of vertex i (merged coincident vertices of V share one).
std::size_t Core_solver::canonical_of(std::size_t i) const
{
  return m_copy_begin[i] < m_copy_begin[i + 1] ? m_caller_of[std::size_t(m_copies[m_copy_begin[i]])] : i;
}

// m_mesh_face_of and m_caller_face_of: faces of F and of the mesh with the same corners (as vertices of V, merged
// coincident vertices being one).
void Core_solver::map_faces(const std::int64_t* f, std::size_t m)
{
  typedef std::array<std::size_t, 3> Key;
  std::vector<std::pair<Key, std::size_t> > mesh_keys;
  mesh_keys.reserve(m_mesh.number_of_faces());
  for(Face_index face : m_mesh.faces())
  {
    Key k;
    std::size_t c = 0;
    for(Vertex_index u : CGAL::vertices_around_face(m_mesh.halfedge(face), m_mesh))
      k[c++] = m_caller_of[std::size_t(u)];
    std::sort(k.begin(), k.end());
    mesh_keys.emplace_back(k, std::size_t(face));
  }
  std::sort(mesh_keys.begin(), mesh_keys.end());
  m_caller_faces.resize(m);
  m_mesh_face_of.assign(m, -1);
  m_caller_face_of.assign(m_mesh.number_of_faces(), 0);
  std::vector<unsigned char> has_caller(m_mesh.number_of_faces(), 0);
  for(std::size_t j = 0; j < m; ++j)
  {
    Key k;
    for(std::size_t c = 0; c < 3; ++c)
    {
      m_caller_faces[j][c] = static_cast<std::uint32_t>(f[3 * j + c]);
      k[c] = canonical_of(static_cast<std::size_t>(f[3 * j + c]));
    }
    std::sort(k.begin(), k.end());
    if(k[0] == k[1] || k[1] == k[2])
      continue;
    const auto it = std::lower_bound(mesh_keys.begin(), mesh_keys.end(), std::make_pair(k, std::size_t(0)));
    if(it == mesh_keys.end() || it->first != k)
      continue;
    m_mesh_face_of[j] = static_cast<std::int64_t>(it->second);
    if(!has_caller[it->second])
    {
      has_caller[it->second] = 1;
      m_caller_face_of[it->second] = j;
    }
  }
}

void Core_solver::append_copies(std::size_t i, std::vector<Vertex_index>& out) const
{
  if(m_repairs.empty())
    out.push_back(Vertex_index(static_cast<Mesh::size_type>(i)));
  else
    out.insert(out.end(), m_copies.begin() + std::ptrdiff_t(m_copy_begin[i]),
               m_copies.begin() + std::ptrdiff_t(m_copy_begin[i + 1]));
}

void Core_solver::to_caller(const std::vector<double>& mesh_d, const std::vector<std::size_t>* mesh_labels,
                            double* d, std::int64_t* lab) const
{
  auto label = [&](std::size_t v) {
    const std::size_t l = (*mesh_labels)[v];
    return (l == VTP::no_source || !(mesh_d[v] < infinity)) ? std::int64_t(-1) : static_cast<std::int64_t>(l);
  };
  if(m_repairs.empty())
  {
    std::copy(mesh_d.begin(), mesh_d.end(), d);
    if(lab != nullptr)
      for(std::size_t i = 0; i < m_n; ++i)
        lab[i] = label(i);
    return;
  }
  for(std::size_t i = 0; i < m_n; ++i)
  {
    double best = infinity;
    std::int64_t best_label = -1;
    for(std::size_t k = m_copy_begin[i]; k < m_copy_begin[i + 1]; ++k)
    {
      const std::size_t c = std::size_t(m_copies[k]);
      if(mesh_d[c] < best)
      {
        best = mesh_d[c];
        if(lab != nullptr)
          best_label = label(c);
      }
    }
    d[i] = best;
    if(lab != nullptr)
      lab[i] = best_label;
  }
}

py::tuple Core_solver::vertex_copies() const
{
  py::array_t<std::int64_t> begin(static_cast<py::ssize_t>(m_n + 1)), copies(static_cast<py::ssize_t>(
                                                                           m_repairs.empty() ? m_n : m_copies.size()));
  std::int64_t* b = begin.mutable_data();
  std::int64_t* c = copies.mutable_data();
  for(std::size_t i = 0; i <= m_n; ++i)
    b[i] = static_cast<std::int64_t>(m_repairs.empty() ? i : m_copy_begin[i]);
  for(py::ssize_t k = 0; k < copies.size(); ++k)
    c[k] = static_cast<std::int64_t>(m_repairs.empty() ? std::size_t(k) : std::size_t(m_copies[std::size_t(k)]));
  return py::make_tuple(begin, copies);
}

} // namespace vtp_python
