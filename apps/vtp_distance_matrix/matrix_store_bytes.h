// vtp_distance_matrix: what the two files of Matrix_store (matrix_store.cpp, matrix_store_rows.cpp) share: the
// layout of the journal, the work of rank 0 that every rank agrees on (and the byte encoding of what it
// broadcasts), a file descriptor for reading.

#ifndef VTP_DISTANCE_MATRIX_MATRIX_STORE_BYTES_H
#define VTP_DISTANCE_MATRIX_MATRIX_STORE_BYTES_H

#include "job.h"
#include "tool_error.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace vtp_matrix {

namespace matrix_store_bytes {

constexpr char journal_magic[8] = { 'V', 'T', 'P', 'D', 'M', 'J', '0', '1' };
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

// Collective: rank 0 runs f(), which may throw Tool_error; then every rank throws Job_error if it did.
template <class F>
void run_on_root(Job& job, const F& f)
{
  std::string error;
  if(job.is_root())
  {
    try
    {
      f();
    }
    catch(const Tool_error& e)
    {
      error = e.what();
    }
  }
  job.agree(error);
}

// Collective: rank 0 runs f(writer), as run_on_root(), to write what every rank receives; returns those bytes.
template <class F>
std::vector<char> broadcast_from_root(Job& job, const F& f)
{
  Byte_writer w;
  run_on_root(job, [&] { f(w); });
  job.broadcast(w.bytes);
  return w.bytes;
}

} // namespace matrix_store_bytes

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_MATRIX_STORE_BYTES_H
