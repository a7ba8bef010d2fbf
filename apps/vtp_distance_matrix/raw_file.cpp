// vtp_distance_matrix: plain file access for the row data and the journal (see raw_file.h).

#include "raw_file.h"
#include "tool_error.h"

#include <vtp_support/paths.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#ifdef VTP_MATRIX_WITH_MPI
#include <mpi.h>
#endif

namespace vtp_matrix {
namespace {

std::string system_error(const std::string& what, const std::string& path)
{
  return what + " '" + path + "': " + std::strerror(errno);
}

#ifdef VTP_MATRIX_WITH_MPI
std::string mpi_error(int code)
{
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  return std::string(text, static_cast<std::size_t>(length));
}
#endif

using vtp_support::folder_of;

} // namespace

Raw_file::~Raw_file()
{
  if(m_fd >= 0)
    ::close(m_fd);
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi_file != nullptr)
  {
    MPI_File* f = static_cast<MPI_File*>(m_mpi_file);
    MPI_File_close(f);
    delete f;
  }
#endif
}

bool Raw_file::is_open() const
{
  return m_fd >= 0 || m_mpi_file != nullptr;
}

void Raw_file::open_existing(const std::string& path, bool mpi_io)
{
  m_path = path;
#ifdef VTP_MATRIX_WITH_MPI
  if(mpi_io)
  {
    MPI_File* f = new MPI_File;
    const int code = MPI_File_open(MPI_COMM_SELF, path.c_str(), MPI_MODE_WRONLY, MPI_INFO_NULL, f);
    if(code != MPI_SUCCESS)
    {
      delete f;
      throw Tool_error("cannot open '" + path + "' with MPI-IO: " + mpi_error(code));
    }
    MPI_File_set_errhandler(*f, MPI_ERRORS_RETURN);
    m_mpi_file = f;
    return;
  }
#else
  (void)mpi_io;
#endif
  m_fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if(m_fd < 0)
    throw Tool_error(system_error("cannot open", path));
}

void Raw_file::create(const std::string& path)
{
  m_path = path;
  m_fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if(m_fd < 0)
    throw Tool_error(system_error("cannot create", path));
}

void Raw_file::write_at(std::uint64_t offset, const void* data, std::size_t bytes)
{
  const char* p = static_cast<const char*>(data);
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi_file != nullptr)
  {
    MPI_File f = *static_cast<MPI_File*>(m_mpi_file);
    const std::size_t piece = std::size_t(1) << 30;  // MPI counts are ints
    while(bytes > 0)
    {
      const std::size_t n = bytes < piece ? bytes : piece;
      MPI_Status status;
      const int code = MPI_File_write_at(f, static_cast<MPI_Offset>(offset), p, static_cast<int>(n), MPI_BYTE, &status);
      int written = 0;
      MPI_Get_count(&status, MPI_BYTE, &written);
      if(code != MPI_SUCCESS)
        throw Tool_error("cannot write '" + m_path + "': " + mpi_error(code));
      if(written != static_cast<int>(n))
        throw Tool_error("cannot write '" + m_path + "': short write (disk full?)");
      p += n;
      offset += n;
      bytes -= n;
    }
    return;
  }
#endif
  while(bytes > 0)
  {
    const ssize_t n = ::pwrite(m_fd, p, bytes, static_cast<off_t>(offset));
    if(n < 0)
    {
      if(errno == EINTR)
        continue;
      throw Tool_error(system_error("cannot write", m_path));
    }
    if(n == 0)
    {
      errno = ENOSPC;
      throw Tool_error(system_error("cannot write", m_path));
    }
    p += n;
    offset += static_cast<std::uint64_t>(n);
    bytes -= static_cast<std::size_t>(n);
  }
}

void Raw_file::sync()
{
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi_file != nullptr)
  {
    const int code = MPI_File_sync(*static_cast<MPI_File*>(m_mpi_file));
    if(code != MPI_SUCCESS)
      throw Tool_error("cannot write '" + m_path + "': " + mpi_error(code));
    return;
  }
#endif
  if(m_fd >= 0 && ::fdatasync(m_fd) != 0)
    throw Tool_error(system_error("cannot write", m_path));
}

void Raw_file::close(bool sync_first)
{
  if(sync_first)
    sync();
#ifdef VTP_MATRIX_WITH_MPI
  if(m_mpi_file != nullptr)
  {
    MPI_File* f = static_cast<MPI_File*>(m_mpi_file);
    m_mpi_file = nullptr;
    const int code = MPI_File_close(f);
    delete f;
    if(code != MPI_SUCCESS)
      throw Tool_error("cannot write '" + m_path + "': " + mpi_error(code));
    return;
  }
#endif
  if(m_fd >= 0)
  {
    const int fd = m_fd;
    m_fd = -1;
    if(::close(fd) != 0)
      throw Tool_error(system_error("cannot write", m_path));
  }
}

bool read_at(int fd, std::uint64_t offset, void* data, std::size_t bytes)
{
  char* p = static_cast<char*>(data);
  while(bytes > 0)
  {
    const ssize_t n = ::pread(fd, p, bytes, static_cast<off_t>(offset));
    if(n < 0 && errno == EINTR)
      continue;
    if(n <= 0)
      return false;
    p += n;
    offset += static_cast<std::uint64_t>(n);
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

bool path_exists(const std::string& path)
{
  struct stat s;
  return ::stat(path.c_str(), &s) == 0;
}

bool is_directory(const std::string& path)
{
  struct stat s;
  return ::stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode);
}

long long file_size(const std::string& path)
{
  struct stat s;
  if(::stat(path.c_str(), &s) != 0 || !S_ISREG(s.st_mode))
    return -1;
  return static_cast<long long>(s.st_size);
}

void remove_file(const std::string& path)
{
  if(::unlink(path.c_str()) != 0 && errno != ENOENT)
    throw Tool_error(system_error("cannot remove", path));
}

void sync_file(const std::string& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if(fd < 0)
    throw Tool_error(system_error("cannot open", path));
  const int r = ::fsync(fd);
  ::close(fd);
  // some file systems refuse fsync on a folder: nothing more can be done there
  if(r != 0 && errno != EINVAL && errno != EBADF)
    throw Tool_error(system_error("cannot write", path));
}

void rename_file(const std::string& from, const std::string& to)
{
  if(::rename(from.c_str(), to.c_str()) != 0)
    throw Tool_error("cannot rename '" + from + "' to '" + to + "': " + std::strerror(errno));
  sync_file(folder_of(to));
}

std::vector<std::string> files_with_prefix(const std::string& prefix)
{
  std::vector<std::string> found;
  const std::string folder = folder_of(prefix);
  const bool bare_name = prefix.find('/') == std::string::npos;
  const std::string name_prefix = vtp_support::file_name_of(prefix);
  DIR* dir = ::opendir(folder.c_str());
  if(dir == nullptr)
    return found;
  while(dirent* e = ::readdir(dir))
  {
    const std::string name = e->d_name;
    if(name.compare(0, name_prefix.size(), name_prefix) == 0)
      found.push_back(bare_name ? name : folder + "/" + name);
  }
  ::closedir(dir);
  return found;
}

} // namespace vtp_matrix
