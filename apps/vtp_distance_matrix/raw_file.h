// vtp_distance_matrix: plain file access for the row data and the journal.
//
// Rows go to fixed places of files that already exist (the reserved datasets of the HDF5 file, the
// journal), with positioned writes. Alone, through POSIX pwrite/fdatasync; under MPI, through MPI-IO
// (each rank opens the shared file on MPI_COMM_SELF, so that its writes and syncs need no other rank:
// the ranks never write the same bytes). Small helpers on paths are here too.

#ifndef VTP_DISTANCE_MATRIX_RAW_FILE_H
#define VTP_DISTANCE_MATRIX_RAW_FILE_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vtp_matrix {

class Raw_file
{
public:
  Raw_file() = default;
  Raw_file(const Raw_file&) = delete;
  Raw_file& operator=(const Raw_file&) = delete;
  ~Raw_file();  // closes without syncing; never throws

  // Opens the existing file `path` for writing (never creates nor truncates it); through MPI-IO if
  // `mpi_io`. Throws Tool_error.
  void open_existing(const std::string& path, bool mpi_io);
  // Creates (or truncates) `path`, a file private to this process (POSIX). Throws Tool_error.
  void create(const std::string& path);
  bool is_open() const;
  const std::string& path() const { return m_path; }

  // Throws Tool_error (e.g. a full disk) naming the file.
  void write_at(std::uint64_t offset, const void* data, std::size_t bytes);
  // Data written so far is on disk when this returns. Throws Tool_error.
  void sync();
  // Syncs (if `sync_first`) and closes. Throws Tool_error.
  void close(bool sync_first);

private:
  std::string m_path;
  int m_fd = -1;
  void* m_mpi_file = nullptr;  // MPI_File*, under MPI-IO
};

// Reads `bytes` at `offset` of `path` into `data`; false if the file is shorter or unreadable.
bool read_at(int fd, std::uint64_t offset, void* data, std::size_t bytes);

bool path_exists(const std::string& path);
bool is_directory(const std::string& path);
// Size of a file, or -1.
long long file_size(const std::string& path);
// Removes `path` if it exists; throws Tool_error if it exists and cannot be removed.
void remove_file(const std::string& path);
// Atomically replaces `to` by `from`, and makes the rename durable. Throws Tool_error.
void rename_file(const std::string& from, const std::string& to);
// fsync of a file by name. Throws Tool_error.
void sync_file(const std::string& path);
// The files of the folder of `prefix` whose path starts with `prefix`.
std::vector<std::string> files_with_prefix(const std::string& prefix);

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_RAW_FILE_H
