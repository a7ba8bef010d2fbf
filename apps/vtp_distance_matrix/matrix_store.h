// vtp_distance_matrix: the output file, written row by row, and resumable after any kill.
//
// Files of an output OUT (all next to it):
//   OUT.part           the HDF5 file being filled (hdf5_layout.h); renamed to OUT once complete, so
//                      that OUT is always complete, and an existing OUT is replaced only by a complete
//                      file (with --force)
//   OUT.part.journal   the durable record of the completed rows: a header (the run's signature, the
//                      number of rows, a generation counter) and one 32-byte entry per row, at a fixed
//                      place, written only after the row's data is on disk
//   OUT.part.lock      held (flock) by rank 0 while the run is on: a second run on the same output is
//                      refused instead of mixing its rows with the first one's
//   OUT.part.spool-G-R sparse runs only: the rows finished by rank R during the G-th start of the run,
//                      appended in the order they finish (indices int64, then the values; polar patches:
//                      indices, rho, theta)
//
// Dense rows are written straight to their place in OUT.part (the HDF5 metadata was written and
// closed before, see hdf5_layout.h). Sparse rows have unknown lengths and finish out of order: they
// are appended to the spool of their rank, and once every row is done the CSR arrays are assembled
// in row order (each rank copying every N-th row, one row in memory at a time) into an OUT.part made
// at that moment with the exact sizes.
//
// Order of writes, so that a kill at any moment (even kill -9, even a crash of the machine) leaves
// files from which --resume continues: the row's data is written; at most once a second the data
// files are synced (fdatasync), and only then are the journal entries of those rows written. A
// journal entry holds where the row is (spool, offset, count) and a check value that covers its row
// number, its content and the run's signature: an entry that is torn, zero, or from another run is
// not valid, and its row is computed again. The journal is created complete (written to a temporary
// name, synced, renamed) after OUT.part, so a journal always comes with a valid OUT.part (dense).
// On --resume, rank 0 checks the signature of the journal (and of OUT.part) against the run's, reads
// the valid entries, and the missing rows are shared out again; a sparse run keeps the spools of the
// earlier starts (their entries point to them) and writes new ones under a new generation number.
// The final file does not depend on how often the run was interrupted nor on the number of ranks or
// threads: the HDF5 metadata is made by the same code from the same arguments, and every row's bytes
// are fixed.

#ifndef VTP_DISTANCE_MATRIX_MATRIX_STORE_H
#define VTP_DISTANCE_MATRIX_MATRIX_STORE_H

#include "hdf5_layout.h"
#include "job.h"
#include "raw_file.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace vtp_matrix {

struct Matrix_spec
{
  std::string output;
  File_description file;     // sources (rows), columns, float32, signature, attributes
  bool sparse = false;       // with --max-distance
  double max_distance = std::numeric_limits<double>::infinity();
};

class Matrix_store
{
public:
  Matrix_store(Job& job, const Matrix_spec& spec);
  ~Matrix_store();
  Matrix_store(const Matrix_store&) = delete;
  Matrix_store& operator=(const Matrix_store&) = delete;

  // Collective. Rank 0 looks at the files present and decides, with --resume / --force: start
  // afresh, continue a partial run, or nothing to do (OUT is complete and has the same signature);
  // or refuses (OUT exists, a partial run exists, another run's files). Then each rank opens what
  // it writes. Throws Job_error on every rank if any rank failed.
  void open(bool resume, bool force);

  bool complete() const { return m_complete; }
  // The rows this rank computes (indices into the source list), ascending.
  const std::vector<std::int64_t>& rows_to_compute() const { return m_my_rows; }
  // Rows already complete when this run started (the same on every rank).
  std::int64_t rows_done_before() const { return m_done_before; }
  // A line for the user about what open() found (rank 0; empty if nothing to say).
  const std::string& note() const { return m_note; }

  // Writes one row: the distances to every vertex (file order, +inf where unreachable). Call one at
  // a time. Throws Tool_error (e.g. a full disk).
  void write_row(std::int64_t row, const double* distances);
  // Writes one sparse row of polar patches (file.polar): nnz entries, the vertices ascending, rho and theta.
  void write_polar_row(std::int64_t row, const std::int64_t* indices, const double* rho, const double* theta,
                       std::size_t nnz);
  // Rows written by this rank in this run.
  std::int64_t rows_written() const { return m_rows_written; }

  // Collective: records the last rows, assembles the sparse arrays, renames OUT.part to OUT and
  // removes the partial files. Throws Job_error.
  void finish();
  // After an error: closes the files (the partial files stay, for --resume). Never throws.
  void abandon();

private:
  // One journal entry (32 bytes, native byte order): where row's data is, and a check value.
  struct Entry
  {
    std::uint64_t offset = 0, count = 0;     // sparse: byte offset in the spool and entries; dense: 0, columns
    std::uint32_t generation = 0, rank = 0;  // the spool (generation 0: no entry)
    std::uint64_t check = 0;
  };
  struct Plan;
  Plan make_plan(bool resume, bool force);
  void start_afresh(Plan& plan);
  void continue_partial(Plan& plan);
  void remove_partial_files();
  void lock();
  void unlock();
  void commit(bool force_now);
  std::uint64_t entry_check(std::int64_t row, const Entry& e) const;
  // Sparse: the bytes of one entry of a row in a spool (its index and its value, or its two values).
  std::uint64_t spool_entry_bytes() const { return 8 + m_value_bytes * (m_spec.file.polar ? 2 : 1); }
  void write_sparse_row(std::int64_t row, const std::int64_t* indices, const double* const* values,
                        std::size_t arrays, std::size_t nnz);
  bool read_journal(std::uint64_t& generation, std::vector<Entry>& entries, std::string& signature);
  void assemble_sparse();
  std::string spool_path(std::uint32_t generation, std::uint32_t rank) const;
  // The entries of the journal, every row recorded (else throws Tool_error).
  std::vector<Entry> recorded_entries();

  Job& m_job;
  Matrix_spec m_spec;
  std::string m_part, m_journal, m_spool_prefix;
  std::uint64_t m_signature_hash = 0;
  std::uint64_t m_header_bytes = 0;
  std::size_t m_value_bytes = 8;

  bool m_complete = false;
  std::uint32_t m_generation = 0;
  std::uint64_t m_data_offset = 0;   // dense: /distances in OUT.part
  std::vector<std::int64_t> m_my_rows;
  std::int64_t m_done_before = 0, m_rows_written = 0;
  std::string m_note;

  int m_lock_fd = -1;   // rank 0: OUT.part.lock, locked
  Raw_file m_data;      // dense: OUT.part; sparse: this rank's spool
  Raw_file m_journal_file;
  std::uint64_t m_spool_end = 0;
  std::vector<std::pair<std::int64_t, Entry> > m_pending;  // journal entries not yet written
  double m_last_commit = 0.;
  std::vector<float> m_float_row;
  std::vector<std::int64_t> m_sparse_indices;
  std::vector<double> m_sparse_values;
};

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_MATRIX_STORE_H
