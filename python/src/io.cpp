// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Input and output: reading a mesh file with the tools' readers and repairs, the symmetric minimum of a CSR
// matrix (the gdist drop-in's symmetric matrices), and the conversions between Python's arrays and the
// library: vertex indices, face locations, barycentric coordinates in F's corner order (see core_solver.h).

#include "core_solver.h"

#include <CGAL/VTP_geodesics/Invalid_input_error.h>

#include <vtp_support/mesh_formats.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

namespace vtp_python {

// ---------------------------------------------------------------------------------------------------------------
// Arrays of vertex indices and face locations (read within their sizes: their shapes are checked in Python)
// ---------------------------------------------------------------------------------------------------------------
std::size_t Core_solver::vertex_of(std::int64_t i, const char* what) const
{
  const std::size_t n = number_of_vertices();
  if(i < 0 || i >= static_cast<std::int64_t>(n))
    value_error(std::string(what) + ": vertex index " + std::to_string(i) + " out of range [0, " + std::to_string(n)
                + ")");
  return static_cast<std::size_t>(i);
}

std::vector<std::size_t> Core_solver::vertices_of(const Index_array& a, const char* what) const
{
  std::vector<std::size_t> r;
  r.reserve(static_cast<std::size_t>(a.size()));
  const std::int64_t* p = a.data();
  for(py::ssize_t i = 0; i < a.size(); ++i)
    r.push_back(vertex_of(p[i], what));
  return r;
}

Caller_sources Core_solver::sources_of(const Index_array& sources, const Index_array& point_faces,
                                       const Double_array& point_bary) const
{
  Caller_sources r;
  r.vertices = vertices_of(sources, "sources");
  r.points = locations_of(point_faces, point_bary, "points");
  if(r.vertices.empty() && r.points.empty())
    value_error("no source: give at least one vertex in sources or one point in points");
  return r;
}

// The points (faces[i], bary[i]) of faces (k,) and bary (k, 3).
std::vector<Face_location> Core_solver::locations_of(const Index_array& faces, const Double_array& bary,
                                                     const char* what) const
{
  const std::size_t m = number_of_faces();
  const std::size_t k = (std::min)(static_cast<std::size_t>(faces.size()), static_cast<std::size_t>(bary.size()) / 3);
  std::vector<Face_location> r;
  const std::int64_t* f = faces.data();
  const double* b = bary.data();
  for(std::size_t i = 0; i < k; ++i)
  {
    if(f[i] < 0 || f[i] >= static_cast<std::int64_t>(m))
      value_error(std::string(what) + ": face index " + std::to_string(f[i]) + " out of range [0, "
                  + std::to_string(m) + ")");
    const double* bi = b + 3 * i;
    const double sum = bi[0] + bi[1] + bi[2];
    if(!(std::isfinite(sum) && bi[0] >= -1e-9 && bi[1] >= -1e-9 && bi[2] >= -1e-9 && std::abs(sum - 1.) <= 1e-9))
      value_error(std::string(what) + ": the barycentric coordinates of point " + std::to_string(i)
                  + " must be finite, non-negative and of sum 1");
    if(!m_repairs.empty())
    {
      // the corners of face f[i] of F in the library's order of its mesh face
      const std::int64_t mf = m_mesh_face_of[static_cast<std::size_t>(f[i])];
      if(mf < 0)
        value_error(std::string(what) + ": face " + std::to_string(f[i])
                    + " of F is not in the mesh (the repair removed it as degenerate)");
      const Face_index face(static_cast<Mesh::size_type>(mf));
      const Halfedge_index h = m_mesh.halfedge(face);
      const Vertex_index lib[3] = { m_mesh.source(h), m_mesh.target(h), m_mesh.target(m_mesh.next(h)) };
      std::array<double, 3> lb = { { 0., 0., 0. } };
      for(std::size_t c = 0; c < 3; ++c)
        for(std::size_t k = 0; k < 3; ++k)
          if(canonical_of(m_caller_faces[static_cast<std::size_t>(f[i])][k]) == m_caller_of[std::size_t(lib[c])])
            lb[c] = bi[k];
      r.push_back(Face_location(face, lb));
      continue;
    }
    const Face_index face(static_cast<Mesh::size_type>(f[i]));
    r.push_back(Face_location(face, from_user_barycentric(face, { { bi[0], bi[1], bi[2] } })));
  }
  return r;
}

// The point (face, bary[0]) of bary (1, 3).
Face_location Core_solver::location_of(std::int64_t face, const Double_array& bary, const char* what) const
{
  Index_array faces(1);
  faces.mutable_data()[0] = face;
  return locations_of(faces, bary, what).at(0);
}

// ---------------------------------------------------------------------------------------------------------------
// Barycentric coordinates: F's corner order (Python) and the library's
// ---------------------------------------------------------------------------------------------------------------
// Position in the face's row of F of each corner of the library's order.
std::array<int, 3> Core_solver::corner_order(Face_index f) const
{
  if(!m_repairs.empty())
  {
    // the mesh face's corners in the order of a face of F with the same corners
    const auto& t = m_caller_faces[m_caller_face_of[static_cast<std::size_t>(f)]];
    const Halfedge_index h = m_mesh.halfedge(f);
    const Vertex_index lib[3] = { m_mesh.source(h), m_mesh.target(h), m_mesh.target(m_mesh.next(h)) };
    std::array<int, 3> pos = { { 0, 1, 2 } };
    for(int i = 0; i < 3; ++i)
      for(int k = 0; k < 3; ++k)
        if(m_caller_of[static_cast<std::size_t>(lib[i])] == canonical_of(t[std::size_t(k)]))
          pos[std::size_t(i)] = k;
    return pos;
  }
  if(m_triangles.empty())
    return { { 0, 1, 2 } };
  const Halfedge_index h = m_mesh.halfedge(f);
  const Vertex_index lib[3] = { m_mesh.source(h), m_mesh.target(h), m_mesh.target(m_mesh.next(h)) };
  const auto& t = m_triangles[static_cast<std::size_t>(f)];
  std::array<int, 3> pos = { { 0, 1, 2 } };
  for(int i = 0; i < 3; ++i)
    for(int k = 0; k < 3; ++k)
      if(static_cast<std::size_t>(lib[i]) == t[std::size_t(k)])
        pos[std::size_t(i)] = k;
  return pos;
}

std::array<double, 3> Core_solver::from_user_barycentric(Face_index f, const std::array<double, 3>& b) const
{
  const std::array<int, 3> pos = corner_order(f);
  return { { b[std::size_t(pos[0])], b[std::size_t(pos[1])], b[std::size_t(pos[2])] } };
}

// The face of F of a mesh face.
std::int64_t Core_solver::to_user_face(Face_index f) const
{
  return static_cast<std::int64_t>(m_repairs.empty() ? static_cast<std::size_t>(f)
                                                     : m_caller_face_of[static_cast<std::size_t>(f)]);
}

std::array<double, 3> Core_solver::to_user_barycentric(const Face_location& l) const
{
  const std::array<int, 3> pos = corner_order(l.first);
  std::array<double, 3> u = { { 0., 0., 0. } };
  for(int i = 0; i < 3; ++i)
    u[std::size_t(pos[std::size_t(i)])] = l.second[std::size_t(i)];
  return u;
}

// ---------------------------------------------------------------------------------------------------------------
// Free functions
// ---------------------------------------------------------------------------------------------------------------
namespace {

// A plain ASCII OFF file of a valid triangle mesh (the common case for large meshes): parsed and checked, without
// the halfedge structure that read_input_mesh() builds (Solver(V, F) builds its own): the same V and F. Returns
// false for anything else (other formats, repairs, errors: read_input_mesh() reads them, and says what is wrong).
bool read_valid_off(const std::string& path, int threads, py::tuple& result)
{
  if(vtp_support::lower_extension(path) != "off")
    return false;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> xyz;
  std::vector<vtp_support::fast_off_detail::Triangle> triangles;
  Read_record record;
  {
    py::gil_scoped_release release;
    try
    {
      const vtp_support::Fast_off_result r =
        vtp_support::read_off_triangle_soup(path, xyz, triangles, threads, &record.tables);
      if(r.status != vtp_support::Fast_off_result::MESH)
        return false;
      record.check_seconds = r.build_seconds;
      record.has_tables = true;
    }
    catch(const vtp_support::Fast_off_error&)
    {
      return false;
    }
  }
  const std::size_t n = xyz.size() / 3, m = triangles.size();
  py::array_t<double> V({ static_cast<py::ssize_t>(n), py::ssize_t(3) });
  py::array_t<std::int64_t> F({ static_cast<py::ssize_t>(m), py::ssize_t(3) });
  double* v = V.mutable_data();
  std::int64_t* f = F.mutable_data();
  {
    py::gil_scoped_release release;
    std::copy(xyz.begin(), xyz.end(), v);
    std::vector<double>().swap(xyz);
    for(std::size_t j = 0; j < m; ++j)
      for(std::size_t k = 0; k < 3; ++k)
        f[3 * j + k] = static_cast<std::int64_t>(triangles[j][k]);
  }
  record.read_seconds = seconds_since(t0) - record.check_seconds;
  remember_read(n, std::move(triangles), std::move(record));
  result = py::make_tuple(V, F, std::string(), std::string("fast OFF reader"), true);
  return true;
}

// The mesh of a file: (V (n, 3), F (m, 3), the repairs done, the reader's name, whether it was read as is).
// `as_in_file`: the vertices and triangles of the file as they are (not repaired; Solver(V, F) repairs them as
// the tools do); a file with faces of more than three vertices is refused then.
py::tuple read_mesh(const std::string& path, int threads, bool as_in_file)
{
  forget_read();
  const auto t0 = std::chrono::steady_clock::now();
  {
    py::tuple r;
    if(read_valid_off(path, threads, r))
      return r;
  }
  vtp_support::Input_mesh input;
  std::string error;
  {
    py::gil_scoped_release release;
    try
    {
      vtp_support::read_input_mesh(path, input, threads);
    }
    catch(const vtp_support::Input_error& e)
    {
      error = e.what();
    }
    catch(const VTP::Invalid_input_error& e)
    {
      error = "cannot use '" + path + "': " + e.what();
    }
  }
  if(!error.empty())
    value_error(error);
  if(as_in_file && !input.direct)
  {
    const std::size_t n = input.file_points.size(), m = input.file_polygons.size();
    for(std::size_t j = 0; j < m; ++j)
      if(input.file_polygons[j].size() != 3)
        value_error("read_mesh('" + path + "', repair=False): face " + std::to_string(j) + " has "
                    + std::to_string(input.file_polygons[j].size())
                    + " vertices; only triangles can be returned as they are (repair=True triangulates them)");
    py::array_t<double> V({ static_cast<py::ssize_t>(n), py::ssize_t(3) });
    py::array_t<std::int64_t> F({ static_cast<py::ssize_t>(m), py::ssize_t(3) });
    double* v = V.mutable_data();
    std::int64_t* f = F.mutable_data();
    for(std::size_t i = 0; i < n; ++i)
      for(int k = 0; k < 3; ++k)
        v[3 * i + std::size_t(k)] = input.file_points[i][k];
    for(std::size_t j = 0; j < m; ++j)
      for(std::size_t k = 0; k < 3; ++k)
        f[3 * j + k] = static_cast<std::int64_t>(input.file_polygons[j][k]);
    remember_other_read(n, f, m, input, t0);
    return py::make_tuple(V, F, std::string(), input.reader, false);
  }
  const Mesh& mesh = input.mesh;
  const std::size_t n = mesh.number_of_vertices(), m = mesh.number_of_faces();
  py::array_t<double> V({ static_cast<py::ssize_t>(n), py::ssize_t(3) });
  py::array_t<std::int64_t> F({ static_cast<py::ssize_t>(m), py::ssize_t(3) });
  double* v = V.mutable_data();
  std::int64_t* f = F.mutable_data();
  {
    py::gil_scoped_release release;
    std::vector<std::int64_t> index(mesh.num_vertices() + mesh.number_of_removed_vertices(), -1);
    std::size_t i = 0;
    for(Vertex_index u : mesh.vertices())
    {
      index[static_cast<std::size_t>(u)] = static_cast<std::int64_t>(i);
      const Point_3& p = mesh.point(u);
      v[3 * i] = p.x();
      v[3 * i + 1] = p.y();
      v[3 * i + 2] = p.z();
      ++i;
    }
    std::size_t j = 0;
    for(Face_index face : mesh.faces())
    {
      // source(halfedge(f)) first: for a mesh read as is, the triangle of the file, so that Solver(V, F) builds
      // the same mesh, halfedge for halfedge, as the tools do
      const Halfedge_index h = mesh.halfedge(face);
      const Vertex_index corners[3] = { mesh.source(h), mesh.target(h), mesh.target(mesh.next(h)) };
      for(int k = 0; k < 3; ++k)
        f[3 * j + std::size_t(k)] = index[static_cast<std::size_t>(corners[k])];
      ++j;
    }
  }
  remember_other_read(n, f, m, input, t0);
  return py::make_tuple(V, F, input.repairs.summary(), input.reader, input.direct);
}

// min(M, M^T) on the union of the patterns of M and M^T, for a square CSR matrix (of indptr.size() - 1 rows) with
// sorted rows.
py::tuple symmetric_min_csr(const Double_array& data, const Index_array& indices, const Index_array& indptr)
{
  if(indptr.size() < 1)
    value_error("symmetric_min_csr: inconsistent CSR arrays");
  const std::size_t N = static_cast<std::size_t>(indptr.size()) - 1;
  const std::int64_t n = static_cast<std::int64_t>(N);
  const double* d = data.data();
  const std::int64_t* ix = indices.data();
  const std::int64_t* ip = indptr.data();
  if(ip[0] != 0 || ip[N] != indices.size() || indices.size() != data.size())
    value_error("symmetric_min_csr: inconsistent CSR arrays");
  for(std::size_t r = 0; r < N; ++r)
    if(ip[r + 1] < ip[r])
      value_error("symmetric_min_csr: inconsistent CSR arrays");
  for(py::ssize_t k = 0; k < indices.size(); ++k)
    if(ix[k] < 0 || ix[k] >= n)
      value_error("symmetric_min_csr: column index out of range");
  std::vector<std::int64_t> tp, ti, rp, ri;
  std::vector<double> td, rd;
  {
    py::gil_scoped_release release;
    const std::size_t nnz = static_cast<std::size_t>(ip[N]);
    // the transpose (counting sort by column: its rows come out sorted)
    tp.assign(N + 1, 0);
    for(std::size_t k = 0; k < nnz; ++k)
      ++tp[static_cast<std::size_t>(ix[k]) + 1];
    for(std::size_t r = 0; r < N; ++r)
      tp[r + 1] += tp[r];
    ti.resize(nnz);
    td.resize(nnz);
    {
      std::vector<std::int64_t> fill(tp.begin(), tp.end() - 1);
      for(std::size_t r = 0; r < N; ++r)
        for(std::int64_t k = ip[r]; k < ip[r + 1]; ++k)
        {
          const std::size_t c = static_cast<std::size_t>(ix[k]);
          ti[static_cast<std::size_t>(fill[c])] = static_cast<std::int64_t>(r);
          td[static_cast<std::size_t>(fill[c]++)] = d[k];
        }
    }
    // merge row r of M with row r of M^T
    rp.assign(N + 1, 0);
    ri.reserve(nnz + nnz / 8);
    rd.reserve(nnz + nnz / 8);
    for(std::size_t r = 0; r < N; ++r)
    {
      std::int64_t a = ip[r], ae = ip[r + 1], b = tp[r], be = tp[r + 1];
      while(a < ae || b < be)
      {
        if(b >= be || (a < ae && ix[a] < ti[static_cast<std::size_t>(b)]))
        {
          ri.push_back(ix[a]);
          rd.push_back(d[a++]);
        }
        else if(a >= ae || ti[static_cast<std::size_t>(b)] < ix[a])
        {
          ri.push_back(ti[static_cast<std::size_t>(b)]);
          rd.push_back(td[static_cast<std::size_t>(b++)]);
        }
        else
        {
          ri.push_back(ix[a]);
          rd.push_back((std::min)(d[a], td[static_cast<std::size_t>(b)]));
          ++a;
          ++b;
        }
      }
      rp[r + 1] = static_cast<std::int64_t>(ri.size());
    }
  }
  py::array_t<double> od(static_cast<py::ssize_t>(rd.size()));
  py::array_t<std::int64_t> oi(static_cast<py::ssize_t>(ri.size()));
  py::array_t<std::int64_t> op(static_cast<py::ssize_t>(rp.size()));
  std::copy(rd.begin(), rd.end(), od.mutable_data());
  std::copy(ri.begin(), ri.end(), oi.mutable_data());
  std::copy(rp.begin(), rp.end(), op.mutable_data());
  return py::make_tuple(od, oi, op);
}

} // namespace

void define_io(py::module_& m)
{
  m.def("read_mesh", &read_mesh, py::arg("path"), py::arg("threads"), py::arg("as_in_file"));
  m.def("symmetric_min_csr", &symmetric_min_csr, py::arg("data"), py::arg("indices"), py::arg("indptr"));
}

} // namespace vtp_python
