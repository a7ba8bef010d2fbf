// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_DISTANCE_ROWS_H
#define VTP_SUPPORT_DISTANCE_ROWS_H

// Rows of a distance matrix: the computation of vtp_distance_matrix, also timed by the benchmark's
// matrix_benchmark.
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

#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace vtp_support {

// How the rows are computed: a sequential method of the table (each row is one sequential propagation; the
// rows run in parallel), its lambda (approximate methods only), a distance limit.
struct Row_method
{
  const Method_info* method = find_method("vtp");
  double lambda = default_lambda;
  double max_distance = std::numeric_limits<double>::infinity();  // the distance limit (none: +inf)
};

// Throws whatever the library or the sink threw (once one threw, no new row starts).
template <class Sink>
void compute_rows(const Input_mesh& input, const std::vector<std::int64_t>& sources,
                  const std::vector<std::int64_t>& rows, const Row_method& method, int threads, Sink&& sink)
{
  typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
  if(rows.empty())
    return;
  const auto np = method_parameters(*method.method, method.lambda, (std::max)(threads, 1))
                    .maximum_distance(method.max_distance);
  Solver solver(input.mesh, CGAL::VTP_geodesics::parameters::number_of_threads((std::max)(threads, 1)));

  // The solver's index of each mesh vertex (by Surface_mesh index).
  std::vector<std::size_t> id(input.mesh.number_of_vertices());
  for(Vertex_index v : input.mesh.vertices())
    id[static_cast<std::size_t>(v)] = solver.vertex_id(v);
  std::vector<double> file_row(input.file_vertices);
  // a row of the solver (indexed by vertex_id) to file order
  auto to_file_order = [&](const std::vector<double>& d, std::int64_t source) {
    input.on_file_vertices([&](Vertex_index v) { return d[id[static_cast<std::size_t>(v)]]; }, file_row);
    file_row[static_cast<std::size_t>(source)] = 0.;
  };

  // Rows whose source is one mesh vertex: the batch.
  std::vector<Vertex_index> batch_sources;
  std::vector<std::int64_t> batch_rows, other_rows;
  for(std::int64_t r : rows)
  {
    const std::vector<Vertex_index> copies =
      input.mesh_vertices_of(static_cast<std::size_t>(sources[static_cast<std::size_t>(r)]));
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
  compute_each_on_threads(solver, batch_sources, row_sink, np);

  // The other rows (sources cut by the repair, or removed by it), one multi-source run each.
  const CGAL::Constant_property_map<Vertex_index, double> no_map;
  for(std::int64_t row : other_rows)
  {
    const std::int64_t source = sources[static_cast<std::size_t>(row)];
    const std::vector<Vertex_index> copies = input.mesh_vertices_of(static_cast<std::size_t>(source));
    if(copies.empty())
    {
      std::fill(file_row.begin(), file_row.end(), std::numeric_limits<double>::infinity());
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

} // namespace vtp_support

#endif // VTP_SUPPORT_DISTANCE_ROWS_H
