// vtp_distance_matrix: the output file, written row by row, and resumable after any kill (see
// matrix_store.h for the files and the order of the writes).

#include "matrix_store.h"
#include "hashing.h"
#include "tool_error.h"

#include <cmath>
#include <cstring>
#include <map>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace vtp_matrix {
namespace {

const char journal_magic[8] = { 'V', 'T', 'P', 'D', 'M', 'J', '0', '1' };
// journal header: magic, header bytes, rows, generation, signature bytes (5 x 8 bytes), signature,
// zeros up to a multiple of 32 bytes; then the entries
constexpr std::uint64_t generation_field = 24;
constexpr std::uint64_t header_fields = 40;
constexpr std::uint64_t entry_bytes = 32;
// the row data is synced and the journal entries written at most this often (seconds)
constexpr double commit_period = 1.;

// Plain byte encoding of what rank 0 broadcasts.
struct Byte_writer
{
  std::vector<char> bytes;
  void u64(std::uint64_t v)
  {
    const char* p = reinterpret_cast<const char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(v));
  }
  void raw(const void* data, std::size_t n)
  {
    if(n == 0)
      return;
    const char* p = static_cast<const char*>(data);
    bytes.insert(bytes.end(), p, p + n);
  }
};

struct Byte_reader
{
  const std::vector<char>& bytes;
  std::size_t at = 0;
  std::uint64_t u64()
  {
    std::uint64_t v = 0;
    raw(&v, sizeof(v));
    return v;
  }
  void raw(void* data, std::size_t n)
  {
    if(n == 0)
      return;
    if(at + n > bytes.size())
      throw Tool_error("internal error: truncated message between ranks");
    std::memcpy(data, bytes.data() + at, n);
    at += n;
  }
};

// A file descriptor for reading, closed at the end of its scope.
struct Read_descriptor
{
  int fd;
  explicit Read_descriptor(const std::string& path) : fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {}
  Read_descriptor(const Read_descriptor&) = delete;
  Read_descriptor& operator=(const Read_descriptor&) = delete;
  ~Read_descriptor()
  {
    if(fd >= 0)
      ::close(fd);
  }
};

// What differs between the signature `then` of a file and the signature `now` of this run.
std::string describe_difference(const std::string& then, const std::string& now)
{
  auto value_of = [](const std::string& signature, const std::string& key) {
    std::string::size_type at = 0;
    while(at < signature.size())
    {
      std::string::size_type end = signature.find('\n', at);
      if(end == std::string::npos)
        end = signature.size();
      const std::string line = signature.substr(at, end - at);
      if(line.compare(0, key.size() + 1, key + "=") == 0)
        return line.substr(key.size() + 1);
      at = end + 1;
    }
    return std::string("(none)");
  };
  std::string::size_type at = 0;
  while(at < now.size())
  {
    std::string::size_type end = now.find('\n', at);
    if(end == std::string::npos)
      end = now.size();
    const std::string line = now.substr(at, end - at);
    const std::string key = line.substr(0, line.find('='));
    const std::string a = value_of(then, key), b = value_of(now, key);
    if(a != b)
    {
      if(key == "mesh")
        return "another mesh";
      return "other arguments (" + key + ": " + a + " then, " + b + " now)";
    }
    at = end + 1;
  }
  return "other arguments";
}

} // namespace

struct Matrix_store::Plan
{
  bool complete = false;
  std::uint64_t generation = 0;
  std::uint64_t data_offset = 0;
  std::int64_t done_before = 0;
  std::vector<std::int64_t> missing;
  std::string note;
};

Matrix_store::Matrix_store(Job& job, const Matrix_spec& spec)
  : m_job(job), m_spec(spec)
{
  m_part = spec.output + ".part";
  m_journal = m_part + ".journal";
  m_spool_prefix = m_part + ".spool-";
  Hash64 h;
  h.add_bytes(spec.file.signature.data(), spec.file.signature.size());
  m_signature_hash = h.value();
  m_header_bytes = (header_fields + spec.file.signature.size() + entry_bytes - 1) / entry_bytes * entry_bytes;
  m_value_bytes = spec.file.float32 ? 4 : 8;
  static_assert(sizeof(Entry) == entry_bytes, "a journal entry is 32 bytes");
}

Matrix_store::~Matrix_store()
{
  unlock();
}

void Matrix_store::lock()
{
  const std::string path = m_part + ".lock";
  m_lock_fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if(m_lock_fd < 0)
    throw Tool_error("cannot create '" + path + "': " + std::strerror(errno));
  if(::flock(m_lock_fd, LOCK_EX | LOCK_NB) != 0)
  {
    const int e = errno;
    ::close(m_lock_fd);
    m_lock_fd = -1;
    if(e == EWOULDBLOCK)
      throw Tool_error("another run is writing '" + m_spec.output + "' ('" + path + "' is locked)");
    throw Tool_error("cannot lock '" + path + "': " + std::strerror(e));
  }
}

void Matrix_store::unlock()
{
  if(m_lock_fd < 0)
    return;
  // removed while still held: a run that opened it meanwhile has failed to lock it (no waiting)
  ::unlink((m_part + ".lock").c_str());
  ::close(m_lock_fd);
  m_lock_fd = -1;
}

std::string Matrix_store::spool_path(std::uint32_t generation, std::uint32_t rank) const
{
  return m_spool_prefix + std::to_string(generation) + "-" + std::to_string(rank);
}

std::uint64_t Matrix_store::entry_check(std::int64_t row, const Entry& e) const
{
  Hash64 h;
  h.add(m_signature_hash);
  h.add(static_cast<std::uint64_t>(row));
  h.add(e.offset);
  h.add(e.count);
  h.add(e.generation);
  h.add(e.rank);
  return h.value() == 0 ? 1 : h.value();
}

bool Matrix_store::read_journal(std::uint64_t& generation, std::vector<Entry>& entries, std::string& signature)
{
  Read_descriptor in(m_journal);
  if(in.fd < 0)
    return false;
  char magic[8];
  std::uint64_t header[4];  // header bytes, rows, generation, signature bytes
  if(!read_at(in.fd, 0, magic, sizeof(magic)) || std::memcmp(magic, journal_magic, sizeof(magic)) != 0
     || !read_at(in.fd, sizeof(magic), header, sizeof(header)))
    return false;
  const std::uint64_t header_bytes = header[0], rows = header[1], signature_bytes = header[3];
  generation = header[2];
  if(signature_bytes > (1u << 20) || header_bytes != (header_fields + signature_bytes + entry_bytes - 1) / entry_bytes * entry_bytes
     || rows > (std::uint64_t(1) << 40))
    return false;
  signature.assign(static_cast<std::size_t>(signature_bytes), ' ');
  if(signature_bytes > 0 && !read_at(in.fd, header_fields, &signature[0], signature.size()))
    return false;
  if(rows != m_spec.file.sources.size())
    return true;  // the signatures differ too (they contain the number of sources)
  entries.assign(static_cast<std::size_t>(rows), Entry());
  // entries beyond the end of a (damaged, shortened) journal stay zero, that is invalid
  const long long size = file_size(m_journal);
  const std::uint64_t available =
    size > static_cast<long long>(header_bytes) ? (static_cast<std::uint64_t>(size) - header_bytes) / entry_bytes : 0;
  const std::uint64_t n = available < rows ? available : rows;
  if(n > 0 && !read_at(in.fd, header_bytes, entries.data(), static_cast<std::size_t>(n * entry_bytes)))
    return false;
  return true;
}

void Matrix_store::remove_partial_files()
{
  // the journal first: without it, the other files are never taken for a partial run
  remove_file(m_journal);
  remove_file(m_journal + ".tmp");
  remove_file(m_part);
  for(const std::string& spool : files_with_prefix(m_spool_prefix))
    remove_file(spool);
}

void Matrix_store::start_afresh(Plan& plan)
{
  remove_partial_files();
  if(!m_spec.sparse)
  {
    plan.data_offset = create_dense_file(m_part, m_spec.file);
    sync_file(m_part);
  }
  // The journal is written whole under a temporary name, then renamed: a journal always comes with
  // its OUT.part.
  const std::string temporary = m_journal + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if(fd < 0)
    throw Tool_error("cannot create '" + temporary + "': " + std::strerror(errno));
  Byte_writer header;
  header.raw(journal_magic, sizeof(journal_magic));
  header.u64(m_header_bytes);
  header.u64(m_spec.file.sources.size());
  header.u64(1);  // generation
  header.u64(m_spec.file.signature.size());
  header.raw(m_spec.file.signature.data(), m_spec.file.signature.size());
  header.bytes.resize(static_cast<std::size_t>(m_header_bytes), 0);
  bool ok = ::pwrite(fd, header.bytes.data(), header.bytes.size(), 0) == static_cast<ssize_t>(header.bytes.size())
            && ::ftruncate(fd, static_cast<off_t>(m_header_bytes + entry_bytes * m_spec.file.sources.size())) == 0
            && ::fsync(fd) == 0;
  const int saved_errno = errno;
  ok = (::close(fd) == 0) && ok;
  if(!ok)
  {
    remove_file(temporary);
    throw Tool_error("cannot write '" + temporary + "': " + std::strerror(saved_errno));
  }
  rename_file(temporary, m_journal);
  plan.generation = 1;
  plan.done_before = 0;
  plan.missing.resize(m_spec.file.sources.size());
  for(std::size_t i = 0; i < plan.missing.size(); ++i)
    plan.missing[i] = static_cast<std::int64_t>(i);
}

void Matrix_store::continue_partial(Plan& plan)
{
  std::uint64_t generation = 0;
  std::vector<Entry> entries;
  std::string signature;
  if(!read_journal(generation, entries, signature))
    throw Tool_error("cannot resume: '" + m_journal + "' is damaged (start again with --force)");
  if(signature != m_spec.file.signature)
    throw Tool_error("cannot resume: the partial output '" + m_part + "' was made from "
                     + describe_difference(signature, m_spec.file.signature) + " (start again with --force)");
  const std::uint64_t rows = m_spec.file.sources.size(), columns = static_cast<std::uint64_t>(m_spec.file.columns);
  if(!m_spec.sparse)
  {
    const long long size = file_size(m_part);
    if(!dense_data_offset(m_part, m_spec.file, plan.data_offset) || size < 0
       || static_cast<std::uint64_t>(size) < plan.data_offset + rows * columns * m_value_bytes)
      throw Tool_error("cannot resume: '" + m_part + "' is missing or damaged (start again with --force)");
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, long long> spool_sizes;
  for(std::uint64_t row = 0; row < rows; ++row)
  {
    const Entry& e = entries[static_cast<std::size_t>(row)];
    bool valid = e.generation != 0 && e.generation <= generation && e.check == entry_check(static_cast<std::int64_t>(row), e);
    if(valid && !m_spec.sparse)
      valid = e.offset == 0 && e.count == columns;
    if(valid && m_spec.sparse)
    {
      const std::pair<std::uint32_t, std::uint32_t> spool(e.generation, e.rank);
      auto it = spool_sizes.find(spool);
      if(it == spool_sizes.end())
        it = spool_sizes.emplace(spool, file_size(spool_path(e.generation, e.rank))).first;
      valid = e.count <= columns && it->second >= 0
              && static_cast<std::uint64_t>(it->second) >= e.offset + e.count * (8 + m_value_bytes);
    }
    if(valid)
      ++plan.done_before;
    else
      plan.missing.push_back(static_cast<std::int64_t>(row));
  }
  if(generation >= 0xffffffffULL)
    throw Tool_error("cannot resume: '" + m_journal + "' was resumed too often");
  plan.generation = generation + 1;
  // the new generation is durable before any rank writes a spool under its number
  {
    const int fd = ::open(m_journal.c_str(), O_WRONLY | O_CLOEXEC);
    const bool ok = fd >= 0
                    && ::pwrite(fd, &plan.generation, sizeof(plan.generation), static_cast<off_t>(generation_field))
                         == static_cast<ssize_t>(sizeof(plan.generation))
                    && ::fsync(fd) == 0;
    const int saved_errno = errno;
    if(fd >= 0)
      ::close(fd);
    if(!ok)
      throw Tool_error("cannot write '" + m_journal + "': " + std::strerror(saved_errno));
  }
  plan.note = "resuming: " + std::to_string(plan.done_before) + " of " + std::to_string(rows) + " rows were complete";
}

Matrix_store::Plan Matrix_store::make_plan(bool resume, bool force)
{
  Plan plan;
  const std::string& out = m_spec.output;
  if(is_directory(out))
    throw Tool_error("the output '" + out + "' is a folder");
  const bool out_exists = path_exists(out), journal_exists = path_exists(m_journal);
  if(resume)
  {
    std::string signature;
    const bool out_signed = out_exists && read_signature(out, signature);
    if(out_signed && signature == m_spec.file.signature)
    {
      plan.complete = true;
      plan.done_before = static_cast<std::int64_t>(m_spec.file.sources.size());
      plan.note = "'" + out + "' is already complete";
      // leftovers of a run stopped after its output was renamed
      remove_partial_files();
      return plan;
    }
    if(journal_exists)
    {
      continue_partial(plan);
      return plan;
    }
    if(out_exists && !out_signed)
      throw Tool_error("cannot resume: '" + out + "' exists and is not an output of vtp_distance_matrix");
    if(out_exists)
      throw Tool_error("cannot resume: '" + out + "' was made from " + describe_difference(signature, m_spec.file.signature)
                       + " (overwrite it with --force)");
  }
  else if(!force)
  {
    if(out_exists)
      throw Tool_error("'" + out + "' exists (overwrite it with --force, or continue it with --resume)");
    if(journal_exists)
      throw Tool_error("a partial run of '" + out + "' exists: continue it with --resume, or start again with --force");
  }
  start_afresh(plan);
  return plan;
}

void Matrix_store::open(bool resume, bool force)
{
  std::string error;
  std::vector<char> bytes;
  if(m_job.is_root())
  {
    try
    {
      lock();
      const Plan plan = make_plan(resume, force);
      Byte_writer w;
      w.u64(plan.complete ? 1 : 0);
      w.u64(plan.generation);
      w.u64(plan.data_offset);
      w.u64(static_cast<std::uint64_t>(plan.done_before));
      w.u64(plan.missing.size());
      w.raw(plan.missing.data(), plan.missing.size() * sizeof(std::int64_t));
      bytes.swap(w.bytes);
      m_note = plan.note;
    }
    catch(const Tool_error& e)
    {
      error = e.what();
    }
  }
  m_job.agree(error);
  m_job.broadcast(bytes);

  try
  {
    Byte_reader r{ bytes };
    m_complete = r.u64() != 0;
    m_generation = static_cast<std::uint32_t>(r.u64());
    m_data_offset = r.u64();
    m_done_before = static_cast<std::int64_t>(r.u64());
    std::vector<std::int64_t> missing(static_cast<std::size_t>(r.u64()));
    r.raw(missing.data(), missing.size() * sizeof(std::int64_t));
    // every N-th missing row to each of the N ranks: rows cost about the same, and within a rank the
    // threads balance the rest dynamically
    for(std::size_t k = static_cast<std::size_t>(m_job.rank()); k < missing.size(); k += static_cast<std::size_t>(m_job.size()))
      m_my_rows.push_back(missing[k]);
    if(!m_complete)
    {
      m_journal_file.open_existing(m_journal, m_job.uses_mpi());
      if(!m_spec.sparse)
        m_data.open_existing(m_part, m_job.uses_mpi());
      else
        m_data.create(spool_path(m_generation, static_cast<std::uint32_t>(m_job.rank())));
    }
  }
  catch(const Tool_error& e)
  {
    error = e.what();
  }
  m_job.agree(error);
  m_last_commit = now_seconds();
}

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
    const std::size_t nnz = m_sparse_indices.size();
    e.offset = m_spool_end;
    e.count = nnz;
    if(nnz > 0)
    {
      m_data.write_at(m_spool_end, m_sparse_indices.data(), nnz * sizeof(std::int64_t));
      if(m_spec.file.float32)
      {
        m_float_row.resize(nnz);
        for(std::size_t k = 0; k < nnz; ++k)
          m_float_row[k] = static_cast<float>(m_sparse_values[k]);
        m_data.write_at(m_spool_end + nnz * sizeof(std::int64_t), m_float_row.data(), nnz * sizeof(float));
      }
      else
        m_data.write_at(m_spool_end + nnz * sizeof(std::int64_t), m_sparse_values.data(), nnz * sizeof(double));
      m_spool_end += nnz * (sizeof(std::int64_t) + m_value_bytes);
    }
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
  if(m_job.is_root())
  {
    try
    {
      std::uint64_t generation = 0;
      std::vector<Entry> entries;
      std::string signature;
      if(!read_journal(generation, entries, signature) || signature != m_spec.file.signature)
        throw Tool_error("'" + m_journal + "' was changed during the run");
      for(std::size_t row = 0; row < entries.size(); ++row)
        if(entries[row].generation == 0 || entries[row].check != entry_check(static_cast<std::int64_t>(row), entries[row]))
          throw Tool_error("internal error: row " + std::to_string(row) + " was not recorded");
      rename_file(m_part, m_spec.output);
      remove_partial_files();
      unlock();
    }
    catch(const Tool_error& e)
    {
      error = e.what();
    }
  }
  m_job.agree(error);
}

void Matrix_store::assemble_sparse()
{
  // 1. rank 0: the row lengths from the journal give the row pointers; OUT.part is made with the
  //    exact sizes (any OUT.part of an earlier, interrupted assembly is replaced).
  std::string error;
  std::vector<char> bytes;
  if(m_job.is_root())
  {
    try
    {
      std::uint64_t generation = 0;
      std::vector<Entry> entries;
      std::string signature;
      if(!read_journal(generation, entries, signature) || signature != m_spec.file.signature)
        throw Tool_error("'" + m_journal + "' was changed during the run");
      std::vector<std::int64_t> indptr(entries.size() + 1, 0);
      for(std::size_t row = 0; row < entries.size(); ++row)
      {
        if(entries[row].generation == 0 || entries[row].check != entry_check(static_cast<std::int64_t>(row), entries[row]))
          throw Tool_error("internal error: row " + std::to_string(row) + " was not recorded");
        indptr[row + 1] = indptr[row] + static_cast<std::int64_t>(entries[row].count);
      }
      remove_file(m_part);
      const Sparse_offsets offsets = create_sparse_file(m_part, m_spec.file, indptr);
      sync_file(m_part);
      Byte_writer w;
      w.u64(offsets.data);
      w.u64(offsets.indices);
      w.raw(entries.data(), entries.size() * sizeof(Entry));
      bytes.swap(w.bytes);
    }
    catch(const Tool_error& e)
    {
      error = e.what();
    }
  }
  m_job.agree(error);
  m_job.broadcast(bytes);

  // 2. every rank copies every N-th row from its spool to its place, one row in memory at a time
  try
  {
    Byte_reader r{ bytes };
    const std::uint64_t data_offset = r.u64(), indices_offset = r.u64();
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
      values.resize(static_cast<std::size_t>(e.count * m_value_bytes));
      if(spool->fd < 0 || !read_at(spool->fd, e.offset, indices.data(), indices.size())
         || !read_at(spool->fd, e.offset + indices.size(), values.data(), values.size()))
        throw Tool_error("cannot read '" + spool_name + "'");
      part.write_at(indices_offset + start * sizeof(std::int64_t), indices.data(), indices.size());
      part.write_at(data_offset + start * m_value_bytes, values.data(), values.size());
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
  if(m_job.is_root())
  {
    try
    {
      rename_file(m_part, m_spec.output);
      remove_partial_files();
      unlock();
    }
    catch(const Tool_error& e)
    {
      error = e.what();
    }
  }
  m_job.agree(error);
}

} // namespace vtp_matrix
