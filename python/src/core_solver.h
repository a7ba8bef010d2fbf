// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_PYTHON_CORE_SOLVER_H
#define VTP_GEODESICS_PYTHON_CORE_SOLVER_H

// vtp_geodesics._core: the thin pybind11 layer under the Python package `vtp_geodesics` (python/vtp_geodesics/).
// The declarations its files share; each file defines one topic, and the Python names of that topic:
//
//   module.cpp     PYBIND11_MODULE: the module's attributes, the method table, the topics below registered
//   solver.cpp     Core_solver(V, F, threads): the Surface_mesh and the per-mesh preprocessing; statistics()
//   queries.cpp    distances(), path(), distance(), locate()
//   matrices.cpp   matrix_dense(), matrix_sparse(): rows on all cores, Ctrl-C and progress every 0.2 s
//   sampling.cpp   farthest_point_sampling(), with the Voronoi cell areas
//   io.cpp         read_mesh(), symmetric_min_csr(); the conversions of vertex indices, face locations and
//                  barycentric coordinates between Python's arrays and the library
//
// The files are compiled as one unity translation unit (python/CMakeLists.txt): the library's templates are
// instantiated once.
//
// Checks: the Python package checks the types, dtypes and shapes of the arguments (the one place; its messages
// name the arguments as the user gave them) and hands over C-ordered float64 and int64 arrays; this layer
// checks the values: indices in range, finite coordinates, barycentric coordinates, a manifold mesh, the
// method, the limits. It reads each array within its size (the number of rows of a (k, 3) array is its size
// divided by 3), never its shape, so that no call can make it read outside an array.
//
// The computations go through the public API of the library (CGAL::VTP_geodesics::Geodesic_distance_solver)
// with the GIL released; one mutex per solver serialises the calls from several Python threads (it is never
// waited for with the GIL held). A method is turned into a call of the library by the support layer's
// vtp_support::with_method() (the one dispatch of the tools, the benchmark and this module).
//
// Barycentric coordinates seen from Python are with respect to the corners of the face as given in F (F[f, 0],
// F[f, 1], F[f, 2]); the library's are with respect to source(halfedge(f)), target(halfedge(f)),
// target(next(halfedge(f))): io.cpp converts them both ways.

#include <vtp_support/fast_off_reader.h>
#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>
#include <vtp_support/surface_locator.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace vtp_python {

namespace py = pybind11;
namespace VTP = CGAL::VTP_geodesics;

typedef vtp_support::Mesh Mesh;
typedef vtp_support::Point_3 Point_3;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Halfedge_index Halfedge_index;
typedef std::pair<Face_index, std::array<double, 3> > Face_location;
typedef VTP::Geodesic_distance_solver<Mesh> Solver;
typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

constexpr double infinity = std::numeric_limits<double>::infinity();

[[noreturn]] inline void value_error(const std::string& what) { throw py::value_error(what); }

// The method called `name`, available in this build, with a valid `lam` if it is approximate.
const vtp_support::Method_info& method_named(const std::string& name, double lam);

// max_distance >= 0 (+inf: no limit).
void check_limit(double max_distance);

// The solver of one mesh, as Python's vtp_geodesics.Solver holds it.
class Core_solver
{
public:
  // solver.cpp
  Core_solver(const Double_array& V, const Index_array& F, int threads);
  std::size_t number_of_vertices() const { return m_mesh.number_of_vertices(); }
  std::size_t number_of_faces() const { return m_mesh.number_of_faces(); }
  double mean_edge_length() const { return m_solver->mean_edge_length(); }
  double preprocessing_seconds() const { return m_solver->preprocessing_seconds(); }
  py::dict statistics() const;

  // queries.cpp
  py::tuple distances(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                      double max_distance, const Index_array& targets, const std::string& method_name, double lam,
                      int threads, bool want_labels);
  py::tuple path(std::int64_t target_vertex, std::int64_t target_face, const Double_array& target_bary,
                 const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                 double max_distance);
  double distance(std::int64_t a_vertex, std::int64_t a_face, const Double_array& a_bary, std::int64_t b_vertex,
                  std::int64_t b_face, const Double_array& b_bary, const std::string& method_name, double lam);
  py::tuple locate(const Double_array& P);

  // matrices.cpp
  py::array matrix_dense(const Index_array& sources, const Index_array& columns, bool all_columns,
                         double max_distance, bool single, const std::string& method_name, double lam, int threads,
                         bool progress);
  py::tuple matrix_sparse(const Index_array& sources, const Index_array& columns, bool all_columns,
                          double max_distance, bool single, const std::string& method_name, double lam, int threads,
                          bool progress);

  // sampling.cpp
  py::tuple farthest_point_sampling(std::int64_t k, std::int64_t first, double radius, const std::string& method_name,
                                    double lam, int threads);

private:
  // solver.cpp
  std::string build_mesh(const double* v, std::size_t n, const std::int64_t* f, std::size_t m);
  int threads_or_default(int threads) const;
  // Sets the sources of the next computation (the mutex held).
  void set_sources(const std::vector<Vertex_index>& vertices, const std::vector<Face_location>& points);

  // io.cpp
  Vertex_index vertex_of(std::int64_t i, const char* what) const;
  std::vector<Vertex_index> vertices_of(const Index_array& a, const char* what) const;
  std::vector<Face_location> locations_of(const Index_array& faces, const Double_array& bary, const char* what) const;
  Face_location location_of(std::int64_t face, const Double_array& bary, const char* what) const;
  std::array<int, 3> corner_order(Face_index f) const;
  std::array<double, 3> from_user_barycentric(Face_index f, const std::array<double, 3>& b) const;
  std::array<double, 3> to_user_barycentric(const Face_location& l) const;

  // matrices.cpp
  template <class Write>
  void run_rows(const std::vector<Vertex_index>& rows, double max_distance, const std::string& method_name,
                double lam, int threads, bool progress, Write&& write);

  Mesh m_mesh;
  // F as given, for barycentric coordinates; empty when each face's halfedge starts at its first corner in F
  std::vector<vtp_support::fast_off_detail::Triangle> m_triangles;
  std::unique_ptr<Solver> m_solver;
  std::unique_ptr<vtp_support::Surface_locator> m_locator;        // of locate(), built on first use
  VTP::Propagation_statistics m_statistics;                       // of the last computation
  int m_threads = 0;
  double m_build_seconds = 0.;                                    // checking V, F and building the mesh
  mutable std::mutex m_mutex;
};

// The Python names of each topic (each defined in its file).
void define_solver(py::class_<Core_solver>& c);
void define_queries(py::class_<Core_solver>& c);
void define_matrices(py::class_<Core_solver>& c);
void define_sampling(py::class_<Core_solver>& c);
void define_io(py::module_& m);

} // namespace vtp_python

#endif // VTP_GEODESICS_PYTHON_CORE_SOLVER_H
