// vtp_distance_matrix: computing the rows (the one place where the library is called).
//
//   compute_rows(input, sources, rows, method, threads, sink)
// computes, for each row r of `rows`, the distances from the source vertex sources[r] to every vertex
// of the file, on `threads` OpenMP threads with a dynamic schedule (one row at a time per thread),
// and hands each finished row to sink(r, sources[r], distances), one call at a time, in any order.
//
// Today it is written with the library's single-source solver: one Geodesic_distance_solver per
// thread (each solver keeps its own per-mesh arrays and work space; the mesh is shared, read-only),
// compute_dense<CGAL::Sequential_tag>() then distances(), and a critical section around the sink.
// When the library has its batch call, the body becomes one call, roughly
//   solver.compute_each<CGAL::Parallel_tag>(mesh_sources, sink, CGAL::parameters::number_of_threads(T)
//                                           .maximum_distance(R) ...)
// with the same sink, and the distance limit moves into the library (see Matrix_store::write_row).

#ifndef VTP_DISTANCE_MATRIX_ROW_BATCH_H
#define VTP_DISTANCE_MATRIX_ROW_BATCH_H

#include "mesh_input.h"

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <limits>
#include <memory>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace vtp_matrix {

struct Row_method
{
  bool approximate = false;  // AVTP instead of VTP
  double lambda = CGAL::VTP_geodesics::Propagation_options::recommended_lambda;
};

// The number of threads when none is asked for: OpenMP's default.
inline int default_thread_count()
{
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

namespace internal {

typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;

// The distances from file vertex `source` to every file vertex, into `file_row`. A file vertex that
// the repair cut into several mesh vertices is a source at each of its copies (one run each and the
// minimum, as vtp_geodesics does); each file vertex gets the smallest distance over its copies, and
// the source itself 0 (also when the repair removed it: then every other vertex is at +inf).
inline void row_distances(const Mesh_input& input, Solver& solver, std::int64_t source,
                          const CGAL::VTP_geodesics::Propagation_options& options,
                          const std::vector<std::size_t>& id_of_mesh_vertex,
                          std::vector<double>& mesh_row, std::vector<double>& file_row)
{
  const double infinity = std::numeric_limits<double>::infinity();
  const std::size_t s = static_cast<std::size_t>(source);
  file_row.resize(input.file_vertices);
  if(input.same_vertices)
  {
    solver.compute_dense<CGAL::Sequential_tag>(input.copies[s], options);
    const std::vector<double>& d = solver.distances();
    for(std::size_t i = 0; i < input.file_vertices; ++i)
      file_row[i] = d[id_of_mesh_vertex[i]];
  }
  else
  {
    mesh_row.assign(input.mesh.number_of_vertices(), infinity);
    for(std::size_t k = input.copy_begin[s]; k < input.copy_begin[s + 1]; ++k)
    {
      solver.compute_dense<CGAL::Sequential_tag>(input.copies[k], options);
      const std::vector<double>& d = solver.distances();
      for(std::size_t j = 0; j < mesh_row.size(); ++j)
        mesh_row[j] = (std::min)(mesh_row[j], d[j]);
    }
    for(std::size_t i = 0; i < input.file_vertices; ++i)
    {
      double m = infinity;
      for(std::size_t k = input.copy_begin[i]; k < input.copy_begin[i + 1]; ++k)
        m = (std::min)(m, mesh_row[id_of_mesh_vertex[static_cast<std::size_t>(input.copies[k])]]);
      file_row[i] = m;
    }
  }
  file_row[s] = 0.;
}

} // namespace internal

// Throws whatever the solver or the sink threw (the first of them); once one threw, no new row starts.
template <class Sink>
void compute_rows(const Mesh_input& input, const std::vector<std::int64_t>& sources,
                  const std::vector<std::int64_t>& rows, const Row_method& method, int threads, Sink&& sink)
{
  typedef internal::Solver Solver;
  if(rows.empty())
    return;
  const int team = static_cast<int>((std::min)(static_cast<std::size_t>((std::max)(threads, 1)), rows.size()));

  // The solvers are built one after the other: building one adds property maps to the mesh.
  std::vector<std::unique_ptr<Solver> > solvers;
  for(int t = 0; t < team; ++t)
    solvers.emplace_back(new Solver(input.mesh));
  // solver index of each mesh vertex (by Surface_mesh index); the same for every solver
  std::vector<std::size_t> id_of_mesh_vertex(input.mesh.number_of_vertices());
  for(Vertex_index v : vertices(input.mesh))
    id_of_mesh_vertex[static_cast<std::size_t>(v)] = solvers[0]->vertex_id(v);

  CGAL::VTP_geodesics::Propagation_options options;
  if(method.approximate)
    options.lambda = method.lambda;

  std::exception_ptr error;
  std::atomic<bool> failed(false);
  const std::int64_t n = static_cast<std::int64_t>(rows.size());
#ifdef _OPENMP
#pragma omp parallel num_threads(team)
#endif
  {
#ifdef _OPENMP
    Solver& solver = *solvers[static_cast<std::size_t>(omp_get_thread_num())];
#else
    Solver& solver = *solvers[0];
#endif
    std::vector<double> mesh_row, file_row;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
    for(std::int64_t k = 0; k < n; ++k)
    {
      if(failed.load())
        continue;
      const std::int64_t row = rows[static_cast<std::size_t>(k)];
      const std::int64_t source = sources[static_cast<std::size_t>(row)];
      std::exception_ptr row_error;
      try
      {
        internal::row_distances(input, solver, source, options, id_of_mesh_vertex, mesh_row, file_row);
      }
      catch(...)
      {
        row_error = std::current_exception();
      }
#ifdef _OPENMP
#pragma omp critical(vtp_matrix_sink)
#endif
      {
        if(row_error)
        {
          if(!error)
            error = row_error;
          failed.store(true);
        }
        else if(!failed.load())
        {
          try
          {
            sink(row, source, static_cast<const std::vector<double>&>(file_row));
          }
          catch(...)
          {
            error = std::current_exception();
            failed.store(true);
          }
        }
      }
    }
  }
  if(error)
    std::rethrow_exception(error);
}

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_ROW_BATCH_H
