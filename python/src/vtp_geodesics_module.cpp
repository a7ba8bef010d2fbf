// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// vtp_geodesics._core: the thin pybind11 layer under the Python package `vtp_geodesics` (python/vtp_geodesics/).
//
// It takes arrays that the Python layer has already converted (float64 and int64, C order) and checks
// everything else itself, so that no input can crash it: shapes, finite coordinates, indices in range, a
// manifold triangle mesh. The computations go through the public API of the library
// (CGAL::VTP_geodesics::Geodesic_distance_solver) with the GIL released; one mutex per solver serialises calls
// from several Python threads. The mesh readers and the method table are those of the support layer.
//
//   Core_solver(V, F, threads)          the Surface_mesh and the per-mesh preprocessing
//   distances(...)                      one propagation from vertices and face locations, labels, targets
//   path(...), distance(...)            a geodesic path / one distance, with early stop at the target
//   farthest_point_sampling(...)        samples, radii, the field and its labels, the Voronoi cell areas
//   locate(P)                           nearest surface points (AABB tree, built on first use)
//   matrix_dense(...), matrix_sparse(...)  rows on all cores (compute_each), Ctrl-C checked every 0.2 s
//   statistics()                        the last computation's Propagation_statistics as a dict
//   read_mesh(path, threads)            the tools' readers and repairs
//   symmetric_min_csr(...)              min(M, M^T) of a CSR pattern (the gdist drop-in's symmetric matrices)
//
// Barycentric coordinates seen from Python are with respect to the corners of the face as given in F (F[f, 0],
// F[f, 1], F[f, 2]); the library's are with respect to source(halfedge(f)), target(halfedge(f)),
// target(next(halfedge(f))): the conversion is done here both ways.

#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>
#include <vtp_support/surface_locator.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/geodesic_voronoi_cells.h>
#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace py = pybind11;
namespace VTP = CGAL::VTP_geodesics;

namespace {

typedef vtp_support::Mesh Mesh;
typedef vtp_support::Point_3 Point_3;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Halfedge_index Halfedge_index;
typedef std::pair<Face_index, std::array<double, 3> > Face_location;
typedef VTP::Geodesic_distance_solver<Mesh> Solver;
typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

const double infinity = std::numeric_limits<double>::infinity();

[[noreturn]] void value_error(const std::string& what) { throw py::value_error(what); }

std::string shape_text(const py::array& a)
{
  std::string s = "(";
  for(py::ssize_t k = 0; k < a.ndim(); ++k)
    s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

int default_threads()
{
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// Runs `f(tag)` with the concurrency tag of `method`. The one place that turns a method of the support layer's
// table into a call of the library: a new kind of method is one more branch here.
template <class F>
void with_method_tag(const vtp_support::Method_info& method, F&& f)
{
  if(!method.parallel)
  {
    f(CGAL::Sequential_tag());
    return;
  }
#ifdef _OPENMP
  f(CGAL::Parallel_tag());
#else
  throw py::value_error(std::string("method '") + method.name + "' needs OpenMP, and this module was built without it");
#endif
}

const vtp_support::Method_info& method_named(const std::string& name)
{
  const vtp_support::Method_info* m = vtp_support::find_method(name);
  if(m == nullptr)
    value_error("unknown method '" + name + "' (expected " + vtp_support::method_names() + ")");
  if(!vtp_support::method_available(*m))
    value_error("method '" + name + "' needs OpenMP, and this module was built without it");
  return *m;
}

// Set in the sink by the thread that called into the module when Python reports a pending exception
// (KeyboardInterrupt): thrown through compute_each(), which stops handing out rows.
struct Python_error_pending
{};

// The error indicator fetched while the GIL was held briefly inside a computation, restored afterwards.
struct Saved_python_error
{
  PyObject* type = nullptr;
  PyObject* value = nullptr;
  PyObject* traceback = nullptr;
  bool set() const { return type != nullptr; }
  void fetch() { PyErr_Fetch(&type, &value, &traceback); }
  [[noreturn]] void restore_and_throw()
  {
    PyErr_Restore(type, value, traceback);
    type = value = traceback = nullptr;
    throw py::error_already_set();
  }
};

// Calls Python every 0.2 s from the thread that entered the module (only that thread may run signal handlers):
// checks for a pending signal (Ctrl-C) and, if asked, writes the progress to sys.stderr.
class Interrupt_check
{
public:
  Interrupt_check(std::size_t total, bool progress)
    : m_caller(std::this_thread::get_id()), m_last(std::chrono::steady_clock::now()), m_total(total),
      m_progress(progress)
  {}

  // Called (serially) after each row; throws Python_error_pending once Python has an exception to raise.
  void row_done()
  {
    const std::size_t done = ++m_done;
    if(std::this_thread::get_id() != m_caller)
      return;
    const auto now = std::chrono::steady_clock::now();
    if(now - m_last < std::chrono::milliseconds(200) && done != m_total)
      return;
    m_last = now;
    py::gil_scoped_acquire gil;
    if(m_progress)
      write_progress(done);
    if(PyErr_CheckSignals() != 0)
    {
      error.fetch();
      throw Python_error_pending();
    }
  }

  void finish()
  {
    if(m_progress)
    {
      write_progress(m_done);
      try
      {
        py::module_::import("sys").attr("stderr").attr("write")("\n");
      }
      catch(py::error_already_set&)
      {
      }
    }
  }

  Saved_python_error error;

private:
  void write_progress(std::size_t done)
  {
    std::ostringstream s;
    s << "\rvtp_geodesics: " << done << " / " << m_total << " rows";
    try
    {
      py::module_::import("sys").attr("stderr").attr("write")(s.str());
    }
    catch(py::error_already_set&)
    {
    }
  }

  std::thread::id m_caller;
  std::chrono::steady_clock::time_point m_last;
  std::size_t m_total, m_done = 0;
  bool m_progress;
};

py::dict statistics_dict(const VTP::Propagation_statistics& st, double preprocessing_seconds)
{
  py::dict d;
  d["vertices"] = st.vertices;
  d["faces"] = st.faces;
  d["sources"] = st.sources;
  d["method"] = st.method;
  d["threads"] = st.threads;
  d["windows_created"] = st.windows_created;
  d["windows_propagated"] = st.windows_propagated;
  d["peak_live_windows"] = st.peak_live_windows;
  d["peak_window_bytes"] = st.peak_window_bytes;
  d["vertices_processed"] = st.vertices_processed;
  d["pseudo_sources"] = st.pseudo_sources;
  d["resets"] = st.resets;
  d["stopped_early"] = st.stopped_early;
  d["rounds"] = st.rounds;
  d["parallel_rounds"] = st.parallel_rounds;
  d["selection_seconds"] = st.selection_seconds;
  d["propagation_seconds"] = st.propagation_seconds;
  d["merge_seconds"] = st.merge_seconds;
  d["reached_vertices"] = st.reached_vertices;
  d["max_distance"] = st.max_distance;
  d["seconds"] = st.seconds;
  d["output_seconds"] = st.output_seconds;
  d["preprocessing_seconds"] = preprocessing_seconds;
  return d;
}

// ---------------------------------------------------------------------------------------------------------------
// The solver of one mesh
// ---------------------------------------------------------------------------------------------------------------
class Core_solver
{
public:
  Core_solver(const Double_array& V, const Index_array& F, int threads) : m_threads(threads)
  {
    if(threads < 0)
      value_error("threads must be >= 0 (0: all cores), got " + std::to_string(threads));
    if(V.ndim() != 2 || V.shape(1) != 3)
      value_error("V must have shape (n, 3), got shape " + shape_text(V));
    if(F.ndim() != 2 || F.shape(1) != 3)
      value_error("F must have shape (m, 3) (triangles), got shape " + shape_text(F));
    const std::size_t n = static_cast<std::size_t>(V.shape(0)), m = static_cast<std::size_t>(F.shape(0));
    if(n == 0)
      value_error("the mesh has no vertices");
    if(m == 0)
      value_error("the mesh has no faces");
    if(n >= (std::size_t(1) << 31) - 1 || m >= ((std::size_t(1) << 31) - 1) / 3)
      value_error("the mesh is too large (at most 2^31 - 2 vertices and (2^31 - 1) / 3 faces)");
    const double* v = V.data();
    const std::int64_t* f = F.data();
    std::string error;
    {
      py::gil_scoped_release release;
      const auto t0 = std::chrono::steady_clock::now();
      error = build_mesh(v, n, f, m);
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
    for(std::size_t i = 0; i < n; ++i)
      if(m_solver->vertex_id(Vertex_index(static_cast<Mesh::size_type>(i))) != i)
        value_error("internal error: the solver numbers the vertices differently from V");
  }

  std::size_t number_of_vertices() const { return m_mesh.number_of_vertices(); }
  std::size_t number_of_faces() const { return m_mesh.number_of_faces(); }
  double mean_edge_length() const { return m_solver->mean_edge_length(); }
  double preprocessing_seconds() const { return m_solver->preprocessing_seconds(); }

  py::dict statistics() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    py::dict d = statistics_dict(m_statistics, m_solver->preprocessing_seconds());
    d["mesh_build_seconds"] = m_build_seconds;
    return d;
  }

  // One propagation. Returns (distances (n,), labels (n,) int64 or None, target distances (len(targets),)).
  py::tuple distances(const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                      double max_distance, const Index_array& targets, const std::string& method_name, double lam,
                      int threads, bool want_labels)
  {
    const vtp_support::Method_info& method = method_named(method_name);
    check_threads(threads);
    check_limit(max_distance);
    if(method.approximate && !(lam > 0.))
      value_error("lam must be > 0, got " + std::to_string(lam));
    std::vector<Vertex_index> source_vertices = vertices_of(sources, "sources");
    std::vector<Face_location> source_points = locations_of(point_faces, point_bary, "points");
    std::vector<Vertex_index> target_vertices = vertices_of(targets, "targets");
    if(source_vertices.empty() && source_points.empty())
      value_error("no source: give at least one vertex in sources or one point in points");
    const std::size_t n = number_of_vertices();
    py::array_t<double> out(static_cast<py::ssize_t>(n));
    py::array_t<std::int64_t> labels_out(static_cast<py::ssize_t>(want_labels ? n : 0));
    py::array_t<double> target_out(static_cast<py::ssize_t>(target_vertices.size()));
    double* d = out.mutable_data();
    std::int64_t* lab = labels_out.mutable_data();
    double* td = target_out.mutable_data();
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      // isolated vertices are never reached: not targets of the stop rule (their distance is +inf)
      std::vector<Vertex_index> live_targets;
      for(Vertex_index t : target_vertices)
        if(!m_mesh.is_isolated(t))
          live_targets.push_back(t);
      m_solver->clear_sources();
      for(Vertex_index s : source_vertices)
        m_solver->add_source(s);
      for(const Face_location& l : source_points)
        m_solver->add_source(l);
      const double lambda = method.approximate ? lam : infinity;
      const auto vdm = boost::make_iterator_property_map(d, get(boost::vertex_index, m_mesh));
      const auto np = VTP::parameters::number_of_threads(threads_or_default(threads))
                        .lambda(lambda)
                        .virtual_sources(method.virtual_sources).virtual_sources_per_vertex(method.per_vertex)
                        .maximum_distance(max_distance)
                        .targets(live_targets)
                        .stop_at_targets(!live_targets.empty())
                        .statistics(m_statistics);
      std::vector<std::size_t> labels;
      with_method_tag(method, [&](auto tag) {
        typedef decltype(tag) Tag;
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
      if(want_labels)
        for(std::size_t i = 0; i < n; ++i)
          lab[i] = (labels[i] == VTP::no_source || !(d[i] < infinity)) ? -1 : static_cast<std::int64_t>(labels[i]);
      std::size_t k = 0;
      for(std::size_t i = 0; i < target_vertices.size(); ++i)
        td[i] = m_mesh.is_isolated(target_vertices[i]) ? infinity : m_solver->target_distance(k++);
    }
    return py::make_tuple(out, want_labels ? py::object(labels_out) : py::object(py::none()), target_out);
  }

  // Farthest-point sampling: up to k samples from `first` (-1: the vertex farthest from vertex 0) until the
  // covering radius is <= radius. Returns (samples (s,), radii (s,), distances (n,), labels (n,) with -1 for
  // none, cell areas (s,), cell uncertainty (s,)).
  py::tuple farthest_point_sampling(std::int64_t k, std::int64_t first, double radius, const std::string& method_name,
                                    double lam, int threads)
  {
    const vtp_support::Method_info& method = method_named(method_name);
    check_threads(threads);
    if(k < 0)
      value_error("k must be >= 0, got " + std::to_string(k));
    if(!(radius >= 0.))
      value_error("radius must be >= 0, got " + std::to_string(radius));
    if(method.approximate && !(lam > 0.))
      value_error("lam must be > 0, got " + std::to_string(lam));
    const bool has_first = first >= 0;
    Vertex_index first_vertex;
    if(has_first)
      first_vertex = vertices_of(one_index(first), "first")[0];
    VTP::Farthest_point_samples<Vertex_index> r;
    VTP::Voronoi_cell_areas cells;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      const auto np = VTP::parameters::number_of_threads(threads_or_default(threads))
                        .lambda(method.approximate ? lam : infinity)
                        .sampling_radius(radius)
                        .virtual_sources(method.virtual_sources)
                        .virtual_sources_per_vertex(method.per_vertex);
      with_method_tag(method, [&](auto tag) {
        typedef decltype(tag) Tag;
        r = has_first ? m_solver->template farthest_point_sampling<Tag>(static_cast<std::size_t>(k),
                                                                          np.first_sample(first_vertex))
                      : m_solver->template farthest_point_sampling<Tag>(static_cast<std::size_t>(k), np);
      });
      m_statistics = r.statistics;
      cells = VTP::geodesic_voronoi_cell_areas(m_mesh, r.samples.size(), r.labels, r.distances);
    }
    const std::size_t n = number_of_vertices(), s = r.samples.size();
    py::array_t<std::int64_t> samples(static_cast<py::ssize_t>(s)), labels(static_cast<py::ssize_t>(n));
    py::array_t<double> radii(static_cast<py::ssize_t>(s)), distances(static_cast<py::ssize_t>(n)),
      areas(static_cast<py::ssize_t>(s)), uncertainty(static_cast<py::ssize_t>(s));
    for(std::size_t i = 0; i < s; ++i)
    {
      samples.mutable_data()[i] = static_cast<std::int64_t>(std::size_t(r.samples[i]));
      radii.mutable_data()[i] = r.radii[i];
      areas.mutable_data()[i] = cells.areas[i];
      uncertainty.mutable_data()[i] = cells.uncertainty[i];
    }
    for(std::size_t i = 0; i < n; ++i)
    {
      distances.mutable_data()[i] = r.distances[i];
      labels.mutable_data()[i] = r.labels[i] == VTP::no_source ? -1 : static_cast<std::int64_t>(r.labels[i]);
    }
    return py::make_tuple(samples, radii, distances, labels, areas, uncertainty);
  }

  // The geodesic path to a target (a vertex if target_vertex >= 0, else the face location), from the sources.
  // Returns (points (k, 3), faces (k,), barycentric (k, 3), distance), from the source to the target.
  py::tuple path(std::int64_t target_vertex, std::int64_t target_face, const Double_array& target_bary,
                 const Index_array& sources, const Index_array& point_faces, const Double_array& point_bary,
                 double max_distance)
  {
    check_limit(max_distance);
    std::vector<Vertex_index> source_vertices = vertices_of(sources, "sources");
    std::vector<Face_location> source_points = locations_of(point_faces, point_bary, "points");
    if(source_vertices.empty() && source_points.empty())
      value_error("no source: give at least one vertex in sources or one point in points");
    const bool at_vertex = target_vertex >= 0;
    Vertex_index tv;
    Face_location tl;
    if(at_vertex)
      tv = vertices_of(one_index(target_vertex), "target")[0];
    else
    {
      Index_array faces = one_index(target_face);
      tl = locations_of(faces, target_bary, "target")[0];
    }
    std::vector<Point_3> points;
    std::vector<Face_location> locations;
    double distance = infinity;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      m_solver->clear_sources();
      for(Vertex_index s : source_vertices)
        m_solver->add_source(s);
      for(const Face_location& l : source_points)
        m_solver->add_source(l);
      const CGAL::Constant_property_map<Vertex_index, double> no_map;
      const auto np = VTP::parameters::maximum_distance(max_distance).record_paths(true).stop_at_targets(true)
                        .statistics(m_statistics);
      if(at_vertex)
      {
        if(m_mesh.is_isolated(tv))
          throw VTP::Invalid_input_error("no path: the target is an isolated vertex, which no source reaches");
        m_solver->compute<CGAL::Sequential_tag>(no_map, np.targets(tv));
        distance = m_solver->target_distance(0);
        m_solver->shortest_path_points(tv, std::back_inserter(points));
        m_solver->shortest_path_locations(tv, std::back_inserter(locations));
      }
      else
      {
        m_solver->compute<CGAL::Sequential_tag>(no_map, np.targets(tl));
        distance = m_solver->target_distance(0);
        m_solver->shortest_path_points(tl, std::back_inserter(points));
        m_solver->shortest_path_locations(tl, std::back_inserter(locations));
      }
    }
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
      pf[i] = static_cast<std::int64_t>(static_cast<std::size_t>(l.first));
      const std::array<double, 3> b = to_user_barycentric(l);
      for(int j = 0; j < 3; ++j)
        pb[3 * i + std::size_t(j)] = b[std::size_t(j)];
    }
    return py::make_tuple(P, PF, PB, distance);
  }

  // The distance from one source (vertex or location) to one target (vertex or location), stopping once the
  // target's distance is final.
  double distance(std::int64_t a_vertex, std::int64_t a_face, const Double_array& a_bary, std::int64_t b_vertex,
                  std::int64_t b_face, const Double_array& b_bary, const std::string& method_name, double lam)
  {
    const vtp_support::Method_info& method = method_named(method_name);
    if(method.approximate && !(lam > 0.))
      value_error("lam must be > 0, got " + std::to_string(lam));
    Vertex_index av, bv;
    Face_location al, bl;
    if(a_vertex >= 0)
      av = vertices_of(one_index(a_vertex), "a")[0];
    else
      al = locations_of(one_index(a_face), a_bary, "a")[0];
    if(b_vertex >= 0)
      bv = vertices_of(one_index(b_vertex), "b")[0];
    else
      bl = locations_of(one_index(b_face), b_bary, "b")[0];
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    if(b_vertex >= 0 && m_mesh.is_isolated(bv))
      return a_vertex == b_vertex ? 0. : infinity;
    m_solver->clear_sources();
    if(a_vertex >= 0)
      m_solver->add_source(av);
    else
      m_solver->add_source(al);
    const CGAL::Constant_property_map<Vertex_index, double> no_map;
    const auto np = VTP::parameters::number_of_threads(threads_or_default(0))
                      .lambda(method.approximate ? lam : infinity)
                      .virtual_sources(method.virtual_sources).virtual_sources_per_vertex(method.per_vertex)
                      .stop_at_targets(true)
                      .statistics(m_statistics);
    with_method_tag(method, [&](auto tag) {
      typedef decltype(tag) Tag;
      if(b_vertex >= 0)
        m_solver->template compute<Tag>(no_map, np.targets(bv));
      else
        m_solver->template compute<Tag>(no_map, np.targets(bl));
    });
    return m_solver->target_distance(0);
  }

  // Nearest points of the surface: (faces (k,), barycentric (k, 3)).
  py::tuple locate(const Double_array& P)
  {
    if(P.ndim() != 2 || P.shape(1) != 3)
      value_error("points must have shape (k, 3), got shape " + shape_text(P));
    const std::size_t k = static_cast<std::size_t>(P.shape(0));
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
      for(std::size_t i = 0; i < k && error.empty(); ++i)
      {
        Face_location l;
        if(!m_locator->locate(Point_3(p[3 * i], p[3 * i + 1], p[3 * i + 2]), l))
        {
          error = "cannot locate point " + std::to_string(i) + " on the surface (its nearest face is degenerate)";
          break;
        }
        const std::array<double, 3> u = to_user_barycentric(l);
        fo[i] = static_cast<std::int64_t>(static_cast<std::size_t>(l.first));
        for(int j = 0; j < 3; ++j)
          bo[3 * i + std::size_t(j)] = u[std::size_t(j)];
      }
    }
    if(!error.empty())
      value_error(error);
    return py::make_tuple(faces, bary);
  }

  // Dense rows: out[i, j] = d(sources[i], columns[j]) (all vertices if `all_columns`), as float32 or float64.
  py::array matrix_dense(const Index_array& sources, const Index_array& columns, bool all_columns,
                         double max_distance, bool single, const std::string& method_name, double lam, int threads,
                         bool progress)
  {
    const std::vector<Vertex_index> rows = vertices_of(sources, "sources");
    const std::vector<std::size_t> cols = column_ids(columns, all_columns);
    const std::size_t nc = all_columns ? number_of_vertices() : cols.size();
    py::array out = single ? py::array(py::array_t<float>({ static_cast<py::ssize_t>(rows.size()),
                                                            static_cast<py::ssize_t>(nc) }))
                           : py::array(py::array_t<double>({ static_cast<py::ssize_t>(rows.size()),
                                                             static_cast<py::ssize_t>(nc) }));
    void* data = out.mutable_data();
    auto fill = [&](auto* o) {
      typedef typename std::remove_pointer<decltype(o)>::type T;
      run_rows(rows, max_distance, method_name, lam, threads, progress,
               [&](std::size_t i, const std::vector<double>& d) {
                 T* row = o + i * nc;
                 if(all_columns)
                   for(std::size_t j = 0; j < nc; ++j)
                     row[j] = static_cast<T>(d[j]);
                 else
                   for(std::size_t j = 0; j < nc; ++j)
                     row[j] = static_cast<T>(d[cols[j]]);
               });
    };
    if(single)
      fill(static_cast<float*>(data));
    else
      fill(static_cast<double*>(data));
    return out;
  }

  // Sparse rows within `max_distance` (finite): the CSR arrays (data, indices, indptr), indices sorted in each
  // row, int32 indices when they fit (as scipy makes them), else int64.
  py::tuple matrix_sparse(const Index_array& sources, const Index_array& columns, bool all_columns,
                          double max_distance, bool single, const std::string& method_name, double lam, int threads,
                          bool progress)
  {
    if(!(max_distance < infinity))
      value_error("a sparse matrix needs a finite max_distance");
    const std::vector<Vertex_index> rows = vertices_of(sources, "sources");
    const std::vector<std::size_t> cols = column_ids(columns, all_columns);
    const std::size_t nc = all_columns ? number_of_vertices() : cols.size();
    // the entries of each row, kept in the output's type (float32 output: no float64 copy of the entries)
    auto compute = [&](auto value_type) {
      typedef decltype(value_type) T;
      std::vector<std::vector<std::uint32_t> > row_columns(rows.size());
      std::vector<std::vector<T> > row_values(rows.size());
      run_rows(rows, max_distance, method_name, lam, threads, progress,
               [&](std::size_t i, const std::vector<double>& d) {
                 std::vector<std::uint32_t>& c = row_columns[i];
                 std::vector<T>& v = row_values[i];
                 for(std::size_t j = 0; j < nc; ++j)
                 {
                   const double x = d[all_columns ? j : cols[j]];
                   if(x <= max_distance)
                   {
                     c.push_back(static_cast<std::uint32_t>(j));
                     v.push_back(static_cast<T>(x));
                   }
                 }
               });
      std::size_t nnz = 0;
      for(const auto& c : row_columns)
        nnz += c.size();
      auto assemble = [&](auto index_type) {
        typedef decltype(index_type) I;
        py::array_t<T> data(static_cast<py::ssize_t>(nnz));
        py::array_t<I> indices(static_cast<py::ssize_t>(nnz));
        py::array_t<I> indptr(static_cast<py::ssize_t>(rows.size() + 1));
        T* dp = data.mutable_data();
        I* ip = indices.mutable_data();
        I* pp = indptr.mutable_data();
        {
          py::gil_scoped_release release;
          std::size_t k = 0;
          pp[0] = 0;
          for(std::size_t r = 0; r < rows.size(); ++r)
          {
            std::copy(row_values[r].begin(), row_values[r].end(), dp + k);
            for(std::size_t e = 0; e < row_columns[r].size(); ++e)
              ip[k + e] = static_cast<I>(row_columns[r][e]);
            k += row_columns[r].size();
            std::vector<std::uint32_t>().swap(row_columns[r]);
            std::vector<T>().swap(row_values[r]);
            pp[r + 1] = static_cast<I>(k);
          }
        }
        return py::make_tuple(data, indices, indptr);
      };
      // int32 indices when they fit (as scipy makes them), else int64
      if(nnz >= (std::size_t(1) << 31) || nc >= (std::size_t(1) << 31))
        return assemble(std::int64_t());
      return assemble(std::int32_t());
    };
    return single ? compute(float()) : compute(double());
  }

private:
  // Checks V and F and builds the mesh; returns the problem, or an empty string.
  std::string build_mesh(const double* v, std::size_t n, const std::int64_t* f, std::size_t m)
  {
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
            s += " (are the faces numbered from 1? subtract 1, or pass is_one_indexed=True to the gdist functions)";
          return s;
        }
    }
    std::vector<vtp_support::fast_off_detail::Triangle> triangles(m);
    for(std::size_t j = 0; j < m; ++j)
    {
      for(int k = 0; k < 3; ++k)
        triangles[j][std::size_t(k)] = static_cast<std::uint32_t>(f[3 * j + std::size_t(k)]);
      if(f[3 * j] == f[3 * j + 1] || f[3 * j + 1] == f[3 * j + 2] || f[3 * j + 2] == f[3 * j])
        return "face " + std::to_string(j) + " has a repeated vertex (" + std::to_string(f[3 * j]) + ", "
               + std::to_string(f[3 * j + 1]) + ", " + std::to_string(f[3 * j + 2]) + ")";
    }
    m_mesh.reserve(static_cast<Mesh::size_type>(n), 0, 0);
    for(std::size_t i = 0; i < n; ++i)
      m_mesh.add_vertex(Point_3(v[3 * i], v[3 * i + 1], v[3 * i + 2]));
    std::string reason;
    if(!vtp_support::fast_off_detail::build_triangle_mesh(triangles, m_mesh, reason, m_threads))
      return "the faces do not form a manifold, consistently oriented triangle mesh: " + reason
             + " (read_mesh() repairs such files)";
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

  int threads_or_default(int threads) const
  {
    const int t = threads > 0 ? threads : m_threads;
    return t > 0 ? t : default_threads();
  }

  static void check_threads(int threads)
  {
    if(threads < 0)
      value_error("threads must be >= 0 (0: the solver's), got " + std::to_string(threads));
  }

  static void check_limit(double max_distance)
  {
    if(!(max_distance >= 0.))
      value_error("max_distance must be >= 0 (inf for none), got " + std::to_string(max_distance));
  }

  static Index_array one_index(std::int64_t i)
  {
    Index_array a(1);
    a.mutable_data()[0] = i;
    return a;
  }

  std::vector<Vertex_index> vertices_of(const Index_array& a, const char* what) const
  {
    if(a.ndim() != 1)
      value_error(std::string(what) + " must be a 1-dimensional array of vertex indices, got shape " + shape_text(a));
    const std::size_t n = number_of_vertices();
    std::vector<Vertex_index> r;
    r.reserve(static_cast<std::size_t>(a.shape(0)));
    const std::int64_t* p = a.data();
    for(py::ssize_t i = 0; i < a.shape(0); ++i)
    {
      if(p[i] < 0 || p[i] >= static_cast<std::int64_t>(n))
        value_error(std::string(what) + ": vertex index " + std::to_string(p[i]) + " out of range [0, "
                    + std::to_string(n) + ")");
      r.push_back(Vertex_index(static_cast<Mesh::size_type>(p[i])));
    }
    return r;
  }

  std::vector<std::size_t> column_ids(const Index_array& a, bool all_columns) const
  {
    std::vector<std::size_t> r;
    if(all_columns)
      return r;
    for(Vertex_index v : vertices_of(a, "targets"))
      r.push_back(static_cast<std::size_t>(v));
    return r;
  }

  std::vector<Face_location> locations_of(const Index_array& faces, const Double_array& bary, const char* what) const
  {
    if(faces.ndim() != 1)
      value_error(std::string(what) + ": the faces must be a 1-dimensional array, got shape " + shape_text(faces));
    if(bary.ndim() != 2 || bary.shape(1) != 3 || bary.shape(0) != faces.shape(0))
      value_error(std::string(what) + ": the barycentric coordinates must have shape (" + std::to_string(faces.shape(0))
                  + ", 3), got shape " + shape_text(bary));
    const std::size_t m = number_of_faces();
    std::vector<Face_location> r;
    const std::int64_t* f = faces.data();
    const double* b = bary.data();
    for(py::ssize_t i = 0; i < faces.shape(0); ++i)
    {
      if(f[i] < 0 || f[i] >= static_cast<std::int64_t>(m))
        value_error(std::string(what) + ": face index " + std::to_string(f[i]) + " out of range [0, "
                    + std::to_string(m) + ")");
      const double* bi = b + 3 * i;
      const double sum = bi[0] + bi[1] + bi[2];
      if(!(std::isfinite(sum) && bi[0] >= -1e-9 && bi[1] >= -1e-9 && bi[2] >= -1e-9 && std::abs(sum - 1.) <= 1e-9))
        value_error(std::string(what) + ": the barycentric coordinates of point " + std::to_string(i)
                    + " must be finite, non-negative and of sum 1");
      const Face_index face(static_cast<Mesh::size_type>(f[i]));
      r.push_back(Face_location(face, from_user_barycentric(face, { { bi[0], bi[1], bi[2] } })));
    }
    return r;
  }

  // Position in the face's row of F of each corner of the library's order.
  std::array<int, 3> corner_order(Face_index f) const
  {
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

  std::array<double, 3> from_user_barycentric(Face_index f, const std::array<double, 3>& b) const
  {
    const std::array<int, 3> pos = corner_order(f);
    return { { b[std::size_t(pos[0])], b[std::size_t(pos[1])], b[std::size_t(pos[2])] } };
  }

  std::array<double, 3> to_user_barycentric(const Face_location& l) const
  {
    const std::array<int, 3> pos = corner_order(l.first);
    std::array<double, 3> u = { { 0., 0., 0. } };
    for(int i = 0; i < 3; ++i)
      u[std::size_t(pos[std::size_t(i)])] = l.second[std::size_t(i)];
    return u;
  }

  // Rows from `rows` on `threads` threads through compute_each(); `write(i, distances)` is called serially.
  template <class Write>
  void run_rows(const std::vector<Vertex_index>& rows, double max_distance, const std::string& method_name,
                double lam, int threads, bool progress, Write&& write)
  {
    const vtp_support::Method_info& method = method_named(method_name);
    check_threads(threads);
    check_limit(max_distance);
    if(method.approximate && !(lam > 0.))
      value_error("lam must be > 0, got " + std::to_string(lam));
    if(rows.empty())
      return;
    Interrupt_check check(rows.size(), progress);
    bool interrupted = false;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(m_mutex);
      const auto np = VTP::parameters::number_of_threads(threads_or_default(threads))
                        .lambda(method.approximate ? lam : infinity)
                        .virtual_sources(method.virtual_sources).virtual_sources_per_vertex(method.per_vertex)
                        .maximum_distance(max_distance);
      auto sink = [&](std::size_t i, Vertex_index, const std::vector<double>& d) {
        write(i, d);
        check.row_done();
      };
      try
      {
#ifdef _OPENMP
        m_solver->compute_each<CGAL::Parallel_tag>(rows, sink, np);
#else
        m_solver->compute_each<CGAL::Sequential_tag>(rows, sink, np);
#endif
      }
      catch(const Python_error_pending&)
      {
        interrupted = true;
      }
      m_statistics = m_solver->statistics();
    }
    if(interrupted)
    {
      check.finish();
      check.error.restore_and_throw();
    }
    check.finish();
  }

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

// ---------------------------------------------------------------------------------------------------------------
// Free functions
// ---------------------------------------------------------------------------------------------------------------
py::tuple read_mesh(const std::string& path, int threads)
{
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
  return py::make_tuple(V, F, input.repairs.summary(), input.reader, input.direct);
}

// min(M, M^T) on the union of the patterns of M and M^T, for a square CSR matrix with sorted rows.
py::tuple symmetric_min_csr(const py::array_t<double, py::array::c_style | py::array::forcecast>& data,
                            const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& indices,
                            const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& indptr,
                            std::int64_t n)
{
  if(n < 0 || indptr.ndim() != 1 || indptr.shape(0) != n + 1 || indices.ndim() != 1 || data.ndim() != 1
     || indices.shape(0) != data.shape(0))
    value_error("symmetric_min_csr: inconsistent CSR arrays");
  const std::size_t N = static_cast<std::size_t>(n);
  const double* d = data.data();
  const std::int64_t* ix = indices.data();
  const std::int64_t* ip = indptr.data();
  if(ip[0] != 0 || ip[N] != indices.shape(0))
    value_error("symmetric_min_csr: inconsistent CSR arrays");
  for(std::size_t r = 0; r < N; ++r)
    if(ip[r + 1] < ip[r])
      value_error("symmetric_min_csr: inconsistent CSR arrays");
  for(py::ssize_t k = 0; k < indices.shape(0); ++k)
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

py::list method_table()
{
  py::list l;
  for(const vtp_support::Method_info* m = vtp_support::methods_begin(); m != vtp_support::methods_end(); ++m)
  {
    py::dict d;
    d["name"] = m->name;
    d["parallel"] = m->parallel;
    d["approximate"] = m->approximate;
    d["description"] = m->description;
    d["available"] = vtp_support::method_available(*m);
    l.append(d);
  }
  return l;
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "The compiled layer of vtp_geodesics (use the package vtp_geodesics, not this module).";
  py::class_<Core_solver>(m, "Solver")
    .def(py::init<const Double_array&, const Index_array&, int>(), py::arg("V"), py::arg("F"), py::arg("threads"))
    .def_property_readonly("number_of_vertices", &Core_solver::number_of_vertices)
    .def_property_readonly("number_of_faces", &Core_solver::number_of_faces)
    .def_property_readonly("mean_edge_length", &Core_solver::mean_edge_length)
    .def_property_readonly("preprocessing_seconds", &Core_solver::preprocessing_seconds)
    .def("statistics", &Core_solver::statistics)
    .def("distances", &Core_solver::distances)
    .def("path", &Core_solver::path)
    .def("distance", &Core_solver::distance)
    .def("farthest_point_sampling", &Core_solver::farthest_point_sampling)
    .def("locate", &Core_solver::locate)
    .def("matrix_dense", &Core_solver::matrix_dense)
    .def("matrix_sparse", &Core_solver::matrix_sparse);
  m.def("read_mesh", &read_mesh, py::arg("path"), py::arg("threads"));
  m.def("symmetric_min_csr", &symmetric_min_csr);
  m.def("method_table", &method_table);
  m.attr("recommended_lambda") = VTP::recommended_lambda;
#ifdef _OPENMP
  m.attr("openmp") = true;
#else
  m.attr("openmp") = false;
#endif
}
