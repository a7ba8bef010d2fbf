// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// Distance matrices: one row per source, rows on all cores (the library's compute_each()), dense or sparse
// (CSR within a limit), float32 or float64. The thread that called into the module checks for Ctrl-C (and
// writes the progress, if asked) every 0.2 s; a pending KeyboardInterrupt stops handing out rows
// (interrupt.h).

#include "core_solver.h"
#include "interrupt.h"

#include <algorithm>
#include <type_traits>

namespace vtp_python {

// Rows from the vertices `sources` of V on `threads` threads through compute_each(); `write(i, distances)` is
// called serially, with the row i of `sources` and the distances of the mesh vertices (on a repaired mesh, once
// per copy of the source: the row is the least of them).
template <class Write>
void Core_solver::run_rows(const std::vector<std::size_t>& sources, double max_distance,
                           const std::string& method_name, double lam, int threads, bool progress, Write&& write)
{
  const vtp_support::Method_info& method = method_named(method_name, lam);
  check_limit(max_distance);
  if(m_through_pinches && !m_repairs.empty())
    value_error("matrices are not computed through the vertices that the repair split (the solver was made with "
                "through_pinches=True): use distances() row by row, or through_pinches=False");
  std::vector<Vertex_index> rows;
  std::vector<std::size_t> row_of;
  for(std::size_t i = 0; i < sources.size(); ++i)
  {
    append_copies(sources[i], rows);
    row_of.resize(rows.size(), i);
  }
  if(rows.empty())
    return;
  Interrupt_check check(rows.size(), progress);
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_mutex);
    // each row on one thread, the rows on `threads` threads: compute_each()'s Parallel_tag whatever the method
    const auto np = vtp_support::method_parameters(method, lam, threads_or_default(threads))
                      .maximum_distance(max_distance);
    auto sink = [&](std::size_t i, Vertex_index, const std::vector<double>& d) {
      write(row_of[i], d);
      check.row_done();
    };
    try
    {
      vtp_support::compute_each_on_threads(*m_solver, rows, sink, np);
    }
    catch(const Python_error_pending&)
    {
      interrupted = true;
    }
    m_statistics = m_solver->statistics();
  }
  check.finish();
  if(interrupted)
    check.error.restore_and_throw();
}

// Dense rows: out[i, j] = d(sources[i], columns[j]) (all vertices if `all_columns`), as float32 or float64.
py::array Core_solver::matrix_dense(const Index_array& sources, const Index_array& columns, bool all_columns,
                                    double max_distance, bool single, const std::string& method_name, double lam,
                                    int threads, bool progress)
{
  const std::vector<std::size_t> rows = vertices_of(sources, "sources");
  const std::vector<std::size_t> cols = all_columns ? std::vector<std::size_t>() : vertices_of(columns, "targets");
  const std::size_t nc = all_columns ? number_of_vertices() : cols.size();
  const std::vector<py::ssize_t> shape = { static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(nc) };
  py::array out = single ? py::array(py::array_t<float>(shape)) : py::array(py::array_t<double>(shape));
  void* data = out.mutable_data();
  auto fill = [&](auto* o) {
    typedef typename std::remove_pointer<decltype(o)>::type T;
    if(!m_repairs.empty())
    {
      // the least over the copies of the source and of each column; 0 at the source, +inf without copy
      std::fill(o, o + rows.size() * nc, static_cast<T>(infinity));
      run_rows(rows, max_distance, method_name, lam, threads, progress,
               [&](std::size_t i, const std::vector<double>& d) {
                 T* row = o + i * nc;
                 for(std::size_t j = 0; j < nc; ++j)
                   row[j] = (std::min)(row[j], static_cast<T>(caller_value(d, all_columns ? j : cols[j])));
               });
      for(std::size_t i = 0; i < rows.size(); ++i)
        for(std::size_t j = 0; j < nc; ++j)
          if((all_columns ? j : cols[j]) == rows[i])
            o[i * nc + j] = T(0);
      return;
    }
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
py::tuple Core_solver::matrix_sparse(const Index_array& sources, const Index_array& columns, bool all_columns,
                                     double max_distance, bool single, const std::string& method_name, double lam,
                                     int threads, bool progress)
{
  if(!(max_distance < infinity))
    value_error("a sparse matrix needs a finite max_distance");
  const std::vector<std::size_t> rows = vertices_of(sources, "sources");
  const std::vector<std::size_t> cols = all_columns ? std::vector<std::size_t>() : vertices_of(columns, "targets");
  const std::size_t nc = all_columns ? number_of_vertices() : cols.size();
  const bool repaired = !m_repairs.empty();
  // the entries of each row, kept in the output's type (float32 output: no float64 copy of the entries)
  auto compute = [&](auto value_type) {
    typedef decltype(value_type) T;
    std::vector<std::vector<std::uint32_t> > row_columns(rows.size());
    std::vector<std::vector<T> > row_values(rows.size());
    run_rows(rows, max_distance, method_name, lam, threads, progress,
             [&](std::size_t i, const std::vector<double>& d) {
               std::vector<std::uint32_t>& c = row_columns[i];
               std::vector<T>& v = row_values[i];
               if(repaired && !c.empty())
               {
                 // another copy of the source: the least of both rows
                 std::vector<std::uint32_t> c2;
                 std::vector<T> v2;
                 std::size_t k = 0;
                 for(std::size_t j = 0; j < nc; ++j)
                 {
                   const double x = caller_value(d, all_columns ? j : cols[j]);
                   const bool here = k < c.size() && c[k] == j;
                   if(x <= max_distance || here)
                   {
                     c2.push_back(static_cast<std::uint32_t>(j));
                     v2.push_back(here ? (std::min)(v[k], static_cast<T>(x)) : static_cast<T>(x));
                   }
                   if(here)
                     ++k;
                 }
                 c.swap(c2);
                 v.swap(v2);
                 return;
               }
               for(std::size_t j = 0; j < nc; ++j)
               {
                 const double x = repaired ? caller_value(d, all_columns ? j : cols[j]) : d[all_columns ? j : cols[j]];
                 if(x <= max_distance)
                 {
                   c.push_back(static_cast<std::uint32_t>(j));
                   v.push_back(static_cast<T>(x));
                 }
               }
             });
    if(repaired) // a source in no face: 0 in its own column, nothing else
      for(std::size_t r = 0; r < rows.size(); ++r)
        if(m_copy_begin[rows[r]] == m_copy_begin[rows[r] + 1])
          for(std::size_t j = 0; j < nc; ++j)
            if((all_columns ? j : cols[j]) == rows[r])
            {
              const auto at = std::lower_bound(row_columns[r].begin(), row_columns[r].end(),
                                               static_cast<std::uint32_t>(j));
              if(at == row_columns[r].end() || *at != j)
              {
                row_values[r].insert(row_values[r].begin() + (at - row_columns[r].begin()), T(0));
                row_columns[r].insert(at, static_cast<std::uint32_t>(j));
              }
            }
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

void define_matrices(py::class_<Core_solver>& c)
{
  c.def("matrix_dense", &Core_solver::matrix_dense).def("matrix_sparse", &Core_solver::matrix_sparse);
}

} // namespace vtp_python
