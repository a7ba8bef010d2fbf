// vtp_distance_matrix: the output file, written row by row, and resumable after any kill (see
// matrix_store.h for the files and the order of the writes): the start of a run, a new one or one that resumes
// (the files found, the plan of rank 0 broadcast to every rank, the journal). Writing the rows and finishing
// the file is matrix_store_rows.cpp.

#include "matrix_store.h"
#include "hashing.h"
#include "matrix_store_bytes.h"
#include "tool_error.h"

#include <cmath>
#include <cstring>
#include <map>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace vtp_matrix {

using namespace matrix_store_bytes;

namespace {

// The lines of `text`, without their '\n'.
std::vector<std::string> lines_of(const std::string& text)
{
  std::vector<std::string> lines;
  std::string::size_type at = 0;
  while(at < text.size())
  {
    std::string::size_type end = text.find('\n', at);
    if(end == std::string::npos)
      end = text.size();
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return lines;
}

// What differs between the signature `then` of a file and the signature `now` of this run.
std::string describe_difference(const std::string& then, const std::string& now)
{
  auto value_of = [](const std::string& signature, const std::string& key) {
    for(const std::string& line : lines_of(signature))
      if(line.compare(0, key.size() + 1, key + "=") == 0)
        return line.substr(key.size() + 1);
    return std::string("(none)");
  };
  for(const std::string& line : lines_of(now))
  {
    const std::string key = line.substr(0, line.find('='));
    const std::string a = value_of(then, key), b = value_of(now, key);
    if(a != b)
    {
      if(key == "mesh")
        return "another mesh";
      return "other arguments (" + key + ": " + a + " then, " + b + " now)";
    }
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
              && static_cast<std::uint64_t>(it->second) >= e.offset + e.count * spool_entry_bytes();
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
  const std::vector<char> bytes = broadcast_from_root(m_job, [&](Byte_writer& w) {
    lock();
    const Plan plan = make_plan(resume, force);
    w.u64(plan.complete ? 1 : 0);
    w.u64(plan.generation);
    w.u64(plan.data_offset);
    w.u64(static_cast<std::uint64_t>(plan.done_before));
    w.u64(plan.missing.size());
    w.raw(plan.missing.data(), plan.missing.size() * sizeof(std::int64_t));
    m_note = plan.note;
  });

  std::string error;
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

} // namespace vtp_matrix
