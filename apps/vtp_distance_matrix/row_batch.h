// vtp_distance_matrix: computing the rows (the one place where the library is called).
//
//   compute_rows(input, sources, rows, method, threads, sink)
// computes, for each row r of `rows`, the distances from the file vertex sources[r] to every vertex of the
// file, and hands each finished row to sink(r, sources[r], distances) (a std::vector<double> in file order,
// +inf where unreachable or beyond the distance limit), one call at a time, in any order.
//
// The rows go through the library's batch call, Geodesic_distance_solver::compute_each(): rows in parallel
// over the sources on `threads` OpenMP threads (dynamic schedule), one workspace per thread, the per-mesh
// data shared; with a distance limit (maximum_distance), each propagation stops at the limit. A file vertex
// that the repair of the input cut into several mesh vertices (a non-manifold vertex) is a source at all its
// copies at once, in one multi-source run, as in vtp_geodesics; a file vertex that the repair removed reaches
// nothing. The source itself is at distance 0 in its row.

#ifndef VTP_DISTANCE_MATRIX_ROW_BATCH_H
#define VTP_DISTANCE_MATRIX_ROW_BATCH_H

#include "mesh_input.h"

#include <vtp_support/methods.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace vtp_matrix {

// How the rows are computed: a sequential method of the table (each row is one sequential propagation; the
// rows run in parallel), its lambda (approximate methods only), a distance limit.
struct Row_method
{
  const vtp_support::Method_info* method = vtp_support::find_method("vtp");
  double lambda = vtp_support::default_lambda;
  double max_distance = std::numeric_limits<double>::infinity();  // the distance limit (none: +inf)
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

// Throws whatever the library or the sink threw (once one threw, no new row starts).
template <class Sink>
void compute_rows(const Mesh_input& input, const std::vector<std::int64_t>& sources,
                  const std::vector<std::int64_t>& rows, const Row_method& method, int threads, Sink&& sink)
{
  typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
  if(rows.empty())
    return;
  const double infinity = std::numeric_limits<double>::infinity();
  const auto np = vtp_support::method_parameters(*method.method, method.lambda, (std::max)(threads, 1))
                    .maximum_distance(method.max_distance);
  Solver solver(input.mesh, CGAL::VTP_geodesics::parameters::number_of_threads((std::max)(threads, 1)));

  // The solver's index of each mesh vertex (by Surface_mesh index), and the file's vertex of each column.
  std::vector<std::size_t> id(input.mesh.number_of_vertices());
  for(Vertex_index v : input.mesh.vertices())
    id[static_cast<std::size_t>(v)] = solver.vertex_id(v);
  std::vector<double> file_row(input.file_vertices);
  // a row of the solver (indexed by vertex_id) to file order: the minimum over the copies of each vertex
  auto to_file_order = [&](const std::vector<double>& d, std::int64_t source) {
    if(input.direct)
      for(std::size_t i = 0; i < input.file_vertices; ++i)
        file_row[i] = d[id[i]];
    else
      for(std::size_t i = 0; i < input.file_vertices; ++i)
      {
        double m = infinity;
        for(std::size_t k = input.copy_begin[i]; k < input.copy_begin[i + 1]; ++k)
          m = (std::min)(m, d[id[static_cast<std::size_t>(input.copies[k])]]);
        file_row[i] = m;
      }
    file_row[static_cast<std::size_t>(source)] = 0.;
  };

  // Rows whose source is one mesh vertex: the batch.
  std::vector<Vertex_index> batch_sources;
  std::vector<std::int64_t> batch_rows, other_rows;
  for(std::int64_t r : rows)
  {
    const std::vector<Vertex_index> copies = input.mesh_vertices_of(static_cast<std::size_t>(sources[static_cast<std::size_t>(r)]));
    if(copies.size() == 1)
    {
      batch_sources.push_back(copies[0]);
      batch_rows.push_back(r);
    }
    else
      other_rows.push_back(r);
  }
  auto row_sink = [&](std::size_t i, Vertex_index, const std::vector<double>& d) {
    const std::int64_t row = batch_rows[i], source = sources[static_cast<std::size_t>(row)];
    to_file_order(d, source);
    sink(row, source, static_cast<const std::vector<double>&>(file_row));
  };
#ifdef _OPENMP
  solver.compute_each<CGAL::Parallel_tag>(batch_sources, row_sink, np);
#else
  solver.compute_each<CGAL::Sequential_tag>(batch_sources, row_sink, np);
#endif

  // The other rows (sources cut by the repair, or removed by it), one multi-source run each.
  const CGAL::Constant_property_map<Vertex_index, double> no_map;
  for(std::int64_t row : other_rows)
  {
    const std::int64_t source = sources[static_cast<std::size_t>(row)];
    const std::vector<Vertex_index> copies = input.mesh_vertices_of(static_cast<std::size_t>(source));
    if(copies.empty())
    {
      std::fill(file_row.begin(), file_row.end(), infinity);
      file_row[static_cast<std::size_t>(source)] = 0.;
    }
    else
    {
      solver.compute<CGAL::Sequential_tag>(no_map, copies, np);
      to_file_order(solver.distances(), source);
    }
    sink(row, source, static_cast<const std::vector<double>&>(file_row));
  }
}

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_ROW_BATCH_H
