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
//   solver.cpp     Core_solver(V, F, threads, repair, through_pinches): the Surface_mesh and the per-mesh
//                  preprocessing; statistics()
//   repair.cpp     the repair of V and F that are not a valid mesh (the tools' repair), and the caller's indices:
//                  sources, targets and results mapped between the vertices and faces of V and F and the mesh's
//   queries.cpp    distances() (keep_field: the field of the run kept), path(), distance(), locate()
//   source_curves.cpp  curve_distances(): distances from vertices, points, curves and the border (signed or not)
//   field.cpp      field_query(): the distance and nearest source at any vertex or point of the surface, from
//                  the field that the last distances(..., keep_field=True) kept
//   matrices.cpp   matrix_dense(), matrix_sparse(): rows on all cores, Ctrl-C and progress every 0.2 s
//   sampling.cpp   farthest_point_sampling(), with the Voronoi cell areas (exact methods: from a kept field)
//   straightest.cpp  trace(): straightest geodesics (the exp map), many walks on the solver's threads
//   log_map.cpp    log_map(): geodesic polar coordinates (VTP, PVTP), in the caller's frames
//   curves.cpp     curves() (isolines, cell borders), cell_areas(): exact, from one run of the given sources that
//                  keeps its field, or from the field that distances(..., keep_field=True) kept
//   patches.cpp    polar_patches(): the log map around many centres cut at a radius, CSR arrays, Ctrl-C
//   interrupt.h    Ctrl-C (KeyboardInterrupt) and progress for matrices.cpp and patches.cpp
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
//
// The caller's indices: every index that Python gives or gets is a row of V or of F. When V and F form a valid
// mesh, mesh vertex i is row i of V and mesh face j is row j of F. Otherwise (with repair), the mesh is the one
// the tools make of the same file (vtp_support::triangle_mesh_from_soup()), and repair.cpp maps: a vertex of V
// stands for its copies in the mesh (several for a vertex the repair split, none for one it dropped); a source
// or a target is all its copies; a result is the least over its copies (+inf, label -1 without copy, 0 at a
// source); a face of F stands for the mesh face of the same corners (none if it was degenerate).

#include <vtp_support/fast_off_reader.h>
#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>
#include <vtp_support/surface_locator.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <chrono>
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
typedef VTP::Face_location<Face_index> Face_location;
typedef VTP::Geodesic_distance_solver<Mesh> Solver;
typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

constexpr double infinity = std::numeric_limits<double>::infinity();

[[noreturn]] inline void value_error(const std::string& what) { throw py::value_error(what); }

// The method called `name`, available in this build, with a valid `lam` if it is approximate.
const vtp_support::Method_info& method_named(const std::string& name, double lam);

// max_distance >= 0 (+inf: no limit).
void check_limit(double max_distance);

// What the last read_mesh() did, for the Solver built on the arrays it returned (io.cpp): its seconds (the file
// read into V and F; the check that they form a valid mesh), and the tables of that check (fast OFF reader only),
// so that the Solver's statistics include the reading and its constructor does not check the same faces again.
struct Read_record
{
  double read_seconds = 0., check_seconds = 0.;
  bool has_tables = false;
  vtp_support::fast_off_detail::Corner_tables tables;
};

// Keeps the record of read_mesh() (replacing the one before), with the faces it returned (`triangles`) and their
// number of vertices.
void remember_read(std::size_t n, std::vector<vtp_support::fast_off_detail::Triangle>&& triangles,
                   Read_record&& record);

// If the last read_mesh() returned `n` vertices and these faces, moves its record into `record` and forgets it
// (a second Solver on the same arrays reads nothing and checks again), returns true; else false.
bool take_read(std::size_t n, const std::vector<vtp_support::fast_off_detail::Triangle>& triangles,
               Read_record& record);

// Forgets the record of the last read_mesh() (a read that failed).
void forget_read();

// Keeps the record of a read by vtp_support's read_input_mesh() (no tables: the Solver checks the faces), that
// returned n vertices and the m faces f; the time since t0 less the reader's checks and repairs is the reading.
void remember_other_read(std::size_t n, const std::int64_t* f, std::size_t m, const vtp_support::Input_mesh& input,
                         std::chrono::steady_clock::time_point t0);

// The sources of a query as the caller gives them: vertices of V (`sources`), then points of the surface (`points`).
struct Caller_sources
{
  std::vector<std::size_t> vertices;
  std::vector<Face_location> points;
};

// Seconds since t0.
double seconds_since(std::chrono::steady_clock::time_point t0);

// The solver of one mesh, as Python's vtp_geodesics.Solver holds it.
class Core_solver
{
public:
  // solver.cpp
  Core_solver(const Double_array& V, const Index_array& F, int threads, bool repair, bool through_pinches);
  // of V and F (the caller's)
  std::size_t number_of_vertices() const { return m_n; }
  std::size_t number_of_faces() const { return m_m; }
  // what the repair did ("" if V and F form a valid mesh); the mesh's counts; the copies of the vertices of V
  // (repair.cpp); the joining runs of the last computation (through_pinches)
  std::string repairs() const { return m_repairs; }
  std::size_t mesh_vertices() const { return m_mesh.number_of_vertices(); }
  std::size_t mesh_faces() const { return m_mesh.number_of_faces(); }
  py::tuple vertex_copies() const;
  std::size_t join_runs() const { return m_join_runs; }
  double mean_edge_length() const { return m_solver->mean_edge_length(); }
  double preprocessing_seconds() const { return m_solver->preprocessing_seconds(); }
  py::dict statistics() const;

  // source_curves.cpp
  py::tuple curve_distances(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                            const Index_array& curve_faces, const Double_array& curve_bary, const Double_array& curve_xyz,
                            const Index_array& curve_offsets, bool border, bool signed_distance, double max_distance,
                            const Index_array& targets, const std::string& method_name, double lam, int threads,
                            bool want_labels, bool keep_field);

  // queries.cpp
  py::tuple distances(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                      double max_distance, const Index_array& targets, const std::string& method_name, double lam,
                      int threads, bool want_labels, bool keep_field);
  py::tuple path(std::int64_t target_vertex, std::int64_t target_face, const Double_array& target_bary,
                 const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                 double max_distance);
  double distance(std::int64_t a_vertex, std::int64_t a_face, const Double_array& a_bary, std::int64_t b_vertex,
                  std::int64_t b_face, const Double_array& b_bary, const std::string& method_name, double lam);
  py::tuple locate(const Double_array& P);

  // patches.cpp
  py::tuple polar_patches(const Index_array& centres, const Index_array& point_faces, const Double_array& point_bary,
                          double radius, bool strict, int threads);

  // straightest.cpp
  py::tuple trace(const Index_array& start_vertices, const Index_array& start_faces, const Double_array& start_bary,
                  const Double_array& directions, const Double_array& lengths, int threads);

  // log_map.cpp
  py::tuple log_map(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                    double max_distance, const Double_array& reference, bool strict, const std::string& method_name,
                    int threads);
  std::array<double, 4> caller_face_frame(Face_index f) const;

  // matrices.cpp
  py::array matrix_dense(const Index_array& sources, const Index_array& columns, bool all_columns,
                         double max_distance, bool single, const std::string& method_name, double lam, int threads,
                         bool progress);
  py::tuple matrix_sparse(const Index_array& sources, const Index_array& columns, bool all_columns,
                          double max_distance, bool single, const std::string& method_name, double lam, int threads,
                          bool progress);

  // field.cpp
  py::tuple field_query(const Index_array& vertices, const Index_array& faces, const Double_array& bary,
                        bool want_labels);
  bool has_kept_field() const;
  std::size_t field_bytes() const;

  // curves.cpp
  py::list curves(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                  const Double_array& levels, bool borders, double chord_tolerance, int exact_refinement,
                  bool from_field);
  py::tuple cell_areas(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                       double chord_tolerance, bool from_field);

  // sampling.cpp
  py::tuple farthest_point_sampling(std::int64_t k, std::int64_t first, double radius, const std::string& method_name,
                                    double lam, int threads, bool exact_cell_areas);

private:
  // solver.cpp
  std::string build_mesh(const double* v, std::size_t n, const std::int64_t* f, std::size_t m, bool& repairable);
  int threads_or_default(int threads) const;
  // Sets the sources of the next computation (the mutex held); forgets the kept field of distances() (every
  // computation of m_solver sets its sources here first: the next one replaces the field).
  void set_sources(const std::vector<Vertex_index>& vertices, const std::vector<Face_location>& points);

  // field.cpp
  // Throws Invalid_input_error unless the last computation is a distances(..., keep_field=True) (the mutex held).
  void require_kept_field() const;

  // curves.cpp
  // The sources of a run for curves (checked): the mesh vertices (every copy of each vertex of V), the points, and
  // the caller's label of each library source.
  std::vector<std::int64_t> curve_sources(const Index_array& sources, const Index_array& point_faces,
                                          const Double_array& point_bary, std::vector<Vertex_index>& mesh_sources,
                                          std::vector<Face_location>& points) const;
  // One exact run from these sources that keeps its field (the mutex held).
  void run_keeping_field(const std::vector<Vertex_index>& mesh_sources, const std::vector<Face_location>& points);

  // repair.cpp
  std::string repair_mesh(const double* v, std::size_t n, const std::int64_t* f, std::size_t m);
  void map_faces(const std::int64_t* f, std::size_t m);
  std::size_t canonical_of(std::size_t caller_vertex) const;
  // The mesh vertices standing for vertex i of V (i checked), appended to `out`.
  void append_copies(std::size_t i, std::vector<Vertex_index>& out) const;
  // Distances (and labels) of the mesh vertices on the vertices of V, into d (and lab, if not null): the least
  // over the copies (its copy's label), +inf (-1) without copy.
  void to_caller(const std::vector<double>& mesh_d, const std::vector<std::size_t>* mesh_labels, double* d,
                 std::int64_t* lab) const;
  // The field of sources on the vertices of V (repaired mesh; queries.cpp).
  void field_on_caller(const std::vector<std::size_t>& source_vertices, const std::vector<Face_location>& source_points,
                       const std::vector<std::size_t>& target_vertices, double max_distance,
                       const vtp_support::Method_info& method, double lam, int threads, double* d, std::int64_t* lab,
                       bool keep_field);
  std::size_t caller_of(Vertex_index v) const
  {
    return m_caller_of.empty() ? std::size_t(v) : m_caller_of[std::size_t(v)];
  }
  // The least of `mesh_d` over the copies of vertex j of V (+inf without copy).
  double caller_value(const std::vector<double>& mesh_d, std::size_t j) const
  {
    if(m_repairs.empty())
      return mesh_d[j];
    double r = infinity;
    for(std::size_t k = m_copy_begin[j]; k < m_copy_begin[j + 1]; ++k)
      r = (std::min)(r, mesh_d[std::size_t(m_copies[k])]);
    return r;
  }

  // io.cpp
  std::size_t vertex_of(std::int64_t i, const char* what) const;         // checked, a vertex of V
  std::vector<std::size_t> vertices_of(const Index_array& a, const char* what) const;
  std::vector<Face_location> locations_of(const Index_array& faces, const Double_array& bary, const char* what) const;
  // The sources of a query (the one preamble of distances(), path(), log_map() and the curves): the vertices of
  // `sources` and the points (point_faces, point_bary), checked; throws ValueError if there is none.
  Caller_sources sources_of(const Index_array& sources, const Index_array& point_faces,
                            const Double_array& point_bary) const;
  Face_location location_of(std::int64_t face, const Double_array& bary, const char* what) const;
  std::array<int, 3> corner_order(Face_index f) const;
  std::array<double, 3> from_user_barycentric(Face_index f, const std::array<double, 3>& b) const;
  std::array<double, 3> to_user_barycentric(const Face_location& l) const;
  std::int64_t to_user_face(Face_index f) const;

  // matrices.cpp
  template <class Write>
  void run_rows(const std::vector<std::size_t>& sources, double max_distance, const std::string& method_name,
                double lam, int threads, bool progress, Write&& write);

  Mesh m_mesh;
  std::size_t m_n = 0, m_m = 0;                                   // rows of V and F
  // F as given, for barycentric coordinates; empty when each face's halfedge starts at its first corner in F
  // (or when the mesh was repaired: then m_caller_faces)
  std::vector<vtp_support::fast_off_detail::Triangle> m_triangles;
  // Repaired (m_repairs not empty; see repair.cpp): the copies of vertex i of V are
  // m_copies[m_copy_begin[i] .. m_copy_begin[i + 1]); m_caller_of: the vertex of V of each mesh vertex;
  // m_caller_faces: F; m_mesh_face_of: the mesh face of each face of F (-1: none); m_caller_face_of: a face of F
  // of each mesh face. All empty when V and F form a valid mesh.
  std::string m_repairs;
  bool m_through_pinches = false;
  std::size_t m_join_runs = 0;                                    // of the last computation (through_pinches)
  std::vector<std::size_t> m_copy_begin;
  std::vector<Vertex_index> m_copies;
  std::vector<std::size_t> m_caller_of;
  std::vector<vtp_support::fast_off_detail::Triangle> m_caller_faces;
  std::vector<std::int64_t> m_mesh_face_of;
  std::vector<std::size_t> m_caller_face_of;
  std::vector<std::vector<Vertex_index> > m_split;                // the copies of each split vertex of V
  std::unique_ptr<Solver> m_solver;
  std::unique_ptr<vtp_support::Surface_locator> m_locator;        // of locate(), built on first use
  VTP::Propagation_statistics m_statistics;                       // of the last computation
  // The field of the last computation of m_solver is that of distances(..., keep_field=True) (set_sources()
  // clears it), and the caller's label of each of its sources (the library's source index: copies of a vertex
  // of V, then the points; see field.cpp).
  bool m_field_kept = false;
  std::vector<std::int64_t> m_field_labels;
  std::size_t m_field_sources = 0;                                // the caller's sources of that run
  int m_threads = 0;
  double m_build_seconds = 0.;                                    // checking V, F and building the mesh
  // of read_mesh(), when V and F are the arrays it returned (see take_read()): reading, and checking the faces
  double m_read_seconds = 0., m_read_check_seconds = 0.;
  mutable std::mutex m_mutex;
};

// The Python names of each topic (each defined in its file).
void define_solver(py::class_<Core_solver>& c);
void define_queries(py::class_<Core_solver>& c);
void define_matrices(py::class_<Core_solver>& c);
void define_sampling(py::class_<Core_solver>& c);
void define_io(py::module_& m);
void define_straightest(py::class_<Core_solver>& c);
void define_log_map(py::class_<Core_solver>& c);
void define_curves(py::class_<Core_solver>& c);
void define_field(py::class_<Core_solver>& c);
void define_patches(py::class_<Core_solver>& c);
void define_source_curves(py::class_<Core_solver>& c);

} // namespace vtp_python

#endif // VTP_GEODESICS_PYTHON_CORE_SOLVER_H
