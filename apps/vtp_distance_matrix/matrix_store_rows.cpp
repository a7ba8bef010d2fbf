// vtp_distance_matrix: the output file, written row by row (see matrix_store.h for the files and the order of
// the writes): the rows, the journal entries that record them, and the complete file at the end (the sparse
// arrays assembled from the spools). The start of a run (a new one, or one that resumes) is matrix_store.cpp.

#include "matrix_store.h"
#include "matrix_store_bytes.h"
#include "tool_error.h"

#include <cmath>
#include <map>
#include <memory>
#include <utility>

namespace vtp_matrix {

using namespace matrix_store_bytes;

void Matrix_store::write_row(std::int64_t row, const double* d)
{
  const std::size_t columns = static_cast<std::size_t>(m_spec.file.columns);
  Entry e;
  e.generation = m_generation;
  e.rank = static_cast<std::uint32_t>(m_job.rank());
  if(!m_spec.sparse)
  {
    const std::uint64_t at = m_data_offset + static_cast<std::uint64_t>(row) * columns * m_value_bytes;
    if(m_spec.file.float32)
    {
      m_float_row.resize(columns);
      for(std::size_t j = 0; j < columns; ++j)
        m_float_row[j] = static_cast<float>(d[j]);
      m_data.write_at(at, m_float_row.data(), columns * sizeof(float));
    }
    else
      m_data.write_at(at, d, columns * sizeof(double));
    e.offset = 0;
    e.count = columns;
  }
  else
  {
    // The library stops each propagation at the limit and gives +inf beyond it: the entries kept are
    // the finite ones (<= the limit).
    m_sparse_indices.clear();
    m_sparse_values.clear();
    for(std::size_t j = 0; j < columns; ++j)
      if(std::isfinite(d[j]) && d[j] <= m_spec.max_distance)
      {
        m_sparse_indices.push_back(static_cast<std::int64_t>(j));
        m_sparse_values.push_back(d[j]);
      }
    const double* values = m_sparse_values.data();
    write_sparse_row(row, m_sparse_indices.data(), &values, 1, m_sparse_indices.size());
    return;
  }
  e.check = entry_check(row, e);
  m_pending.emplace_back(row, e);
  ++m_rows_written;
  commit(false);
}

void Matrix_store::write_polar_row(std::int64_t row, const std::int64_t* indices, const double* rho,
                                   const double* theta, std::size_t nnz)
{
  const double* values[2] = { rho, theta };
  write_sparse_row(row, indices, values, 2, nnz);
}

// Appends a sparse row to this rank's spool (the indices, then each array of values) and records it.
void Matrix_store::write_sparse_row(std::int64_t row, const std::int64_t* indices, const double* const* values,
                                    std::size_t arrays, std::size_t nnz)
{
  Entry e;
  e.generation = m_generation;
  e.rank = static_cast<std::uint32_t>(m_job.rank());
  e.offset = m_spool_end;
  e.count = nnz;
  if(nnz > 0)
  {
    std::uint64_t at = m_spool_end;
    m_data.write_at(at, indices, nnz * sizeof(std::int64_t));
    at += nnz * sizeof(std::int64_t);
    for(std::size_t a = 0; a < arrays; ++a)
    {
      if(m_spec.file.float32)
      {
        m_float_row.resize(nnz);
        for(std::size_t k = 0; k < nnz; ++k)
          m_float_row[k] = static_cast<float>(values[a][k]);
        m_data.write_at(at, m_float_row.data(), nnz * sizeof(float));
      }
      else
        m_data.write_at(at, values[a], nnz * sizeof(double));
      at += nnz * m_value_bytes;
    }
    m_spool_end = at;
  }
  e.check = entry_check(row, e);
  m_pending.emplace_back(row, e);
  ++m_rows_written;
  commit(false);
}

void Matrix_store::commit(bool now)
{
  if(m_pending.empty())
    return;
  const double t = now_seconds();
  if(!now && t - m_last_commit < commit_period)
    return;
  // the rows' data reaches the disk before the entries that say they are complete
  m_data.sync();
  for(const auto& p : m_pending)
    m_journal_file.write_at(m_header_bytes + static_cast<std::uint64_t>(p.first) * entry_bytes, &p.second, sizeof(Entry));
  m_pending.clear();
  m_last_commit = t;
}

void Matrix_store::abandon()
{
  m_pending.clear();
  try { m_data.close(false); } catch(const Tool_error&) {}
  try { m_journal_file.close(false); } catch(const Tool_error&) {}
}

std::vector<Matrix_store::Entry> Matrix_store::recorded_entries()
{
  std::uint64_t generation = 0;
  std::vector<Entry> entries;
  std::string signature;
  if(!read_journal(generation, entries, signature) || signature != m_spec.file.signature)
    throw Tool_error("'" + m_journal + "' was changed during the run");
  for(std::size_t row = 0; row < entries.size(); ++row)
    if(entries[row].generation == 0 || entries[row].check != entry_check(static_cast<std::int64_t>(row), entries[row]))
      throw Tool_error("internal error: row " + std::to_string(row) + " was not recorded");
  return entries;
}

void Matrix_store::finish()
{
  std::string error;
  try
  {
    commit(true);
    m_data.close(true);
    m_journal_file.close(true);
  }
  catch(const Tool_error& e)
  {
    error = e.what();
  }
  m_job.agree(error);

  if(m_spec.sparse)
  {
    assemble_sparse();
    return;
  }
  run_on_root(m_job, [&] {
    recorded_entries();
    rename_file(m_part, m_spec.output);
    remove_partial_files();
    unlock();
  });
}

void Matrix_store::assemble_sparse()
{
  // 1. rank 0: the row lengths from the journal give the row pointers; OUT.part is made with the
  //    exact sizes (any OUT.part of an earlier, interrupted assembly is replaced).
  const std::vector<char> bytes = broadcast_from_root(m_job, [&](Byte_writer& w) {
    const std::vector<Entry> entries = recorded_entries();
    std::vector<std::int64_t> indptr(entries.size() + 1, 0);
    for(std::size_t row = 0; row < entries.size(); ++row)
      indptr[row + 1] = indptr[row] + static_cast<std::int64_t>(entries[row].count);
    remove_file(m_part);
    const Sparse_offsets offsets = create_sparse_file(m_part, m_spec.file, indptr);
    sync_file(m_part);
    w.u64(offsets.data);
    w.u64(offsets.indices);
    w.u64(offsets.angles);
    w.raw(entries.data(), entries.size() * sizeof(Entry));
  });

  // 2. every rank copies every N-th row from its spool to its place, one row in memory at a time
  std::string error;
  try
  {
    Byte_reader r{ bytes };
    const std::uint64_t data_offset = r.u64(), indices_offset = r.u64(), angles_offset = r.u64();
    std::vector<Entry> entries(m_spec.file.sources.size());
    r.raw(entries.data(), entries.size() * sizeof(Entry));
    std::uint64_t position = 0;  // indptr[row], as the rows go by
    Raw_file part;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::unique_ptr<Read_descriptor> > spools;
    std::vector<char> indices, values;
    for(std::size_t row = 0; row < entries.size(); ++row)
    {
      const Entry& e = entries[row];
      const std::uint64_t start = position;
      position += e.count;
      if(row % static_cast<std::size_t>(m_job.size()) != static_cast<std::size_t>(m_job.rank()) || e.count == 0)
        continue;
      if(!part.is_open())
        part.open_existing(m_part, m_job.uses_mpi());
      std::unique_ptr<Read_descriptor>& spool = spools[std::make_pair(e.generation, e.rank)];
      const std::string spool_name = spool_path(e.generation, e.rank);
      if(!spool)
        spool.reset(new Read_descriptor(spool_name));
      indices.resize(static_cast<std::size_t>(e.count * sizeof(std::int64_t)));
      values.resize(static_cast<std::size_t>(e.count * (spool_entry_bytes() - 8)));  // rho (and theta)
      if(spool->fd < 0 || !read_at(spool->fd, e.offset, indices.data(), indices.size())
         || !read_at(spool->fd, e.offset + indices.size(), values.data(), values.size()))
        throw Tool_error("cannot read '" + spool_name + "'");
      const std::size_t one = static_cast<std::size_t>(e.count * m_value_bytes);
      part.write_at(indices_offset + start * sizeof(std::int64_t), indices.data(), indices.size());
      part.write_at(data_offset + start * m_value_bytes, values.data(), one);
      if(m_spec.file.polar)
        part.write_at(angles_offset + start * m_value_bytes, values.data() + one, one);
    }
    if(part.is_open())
      part.close(true);
  }
  catch(const Tool_error& e)
  {
    error = e.what();
  }
  m_job.agree(error);

  // 3. rank 0: the complete file takes the name of the output
  run_on_root(m_job, [&] {
    rename_file(m_part, m_spec.output);
    remove_partial_files();
    unlock();
  });
}

} // namespace vtp_matrix
