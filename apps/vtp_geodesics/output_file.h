// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_OUTPUT_FILE_H
#define VTP_GEODESICS_APP_OUTPUT_FILE_H

// Output files that never destroy anything (POSIX):
//
// - "-" is the standard output, written through.
// - A name that designates an open file descriptor (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N, or a
//   symbolic link to one of them) is written through that descriptor, as a shell redirection set it up: nothing
//   is reopened, truncated or replaced.
// - A regular file, or a name that does not exist yet, is written to a temporary file in the same folder, which
//   `commit()` renames over it: the file is written completely or not at all. A symbolic link (or a chain of
//   them) to a regular file is followed: the file it points to is replaced, the link stays.
// - Anything else (a FIFO, a character or block device such as /dev/null, a socket) is opened and written
//   through, never replaced.
//
// Typical use: open every output, write them, `close()` each (which reports write errors), then `commit()`
// each. An `Output_file` destroyed before `commit()` removes its temporary file.

#include <vtp_support/paths.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace vtp_geodesics_app {

// Error of an output file; the message is one line that names the file.
struct Output_error : std::runtime_error
{
  explicit Output_error(const std::string& what) : std::runtime_error(what) {}
};

namespace output_detail {

using vtp_support::folder_of;
inline std::string base_of(const std::string& path) { return vtp_support::file_name_of(path); }

// If `path` names a file descriptor of this process through /proc (/proc/self/fd/N, /dev/fd/N, which is a
// link to /proc/self/fd), returns N; else -1.
inline int descriptor_named_by(const std::string& path)
{
  const std::string base = base_of(path);
  if(base.empty() || base.find_first_not_of("0123456789") != std::string::npos || base.size() > 9)
    return -1;
  char* folder = ::realpath(folder_of(path).c_str(), nullptr);
  if(folder == nullptr)
    return -1;
  const std::string resolved = folder;
  std::free(folder);
  // realpath() turns /proc/self into /proc/<pid> and /proc/thread-self into /proc/<pid>/task/<tid>.
  const std::string own = "/proc/" + std::to_string(::getpid());
  const bool process_fd = resolved == own + "/fd";
  const bool thread_fd = resolved.compare(0, own.size() + 6, own + "/task/") == 0 && resolved.size() > 3
                         && resolved.compare(resolved.size() - 3, 3, "/fd") == 0;
  if(!process_fd && !thread_fd)
    return -1;
  return std::atoi(base.c_str());
}

// A stream buffer writing to a file descriptor, with a large buffer. Write errors are kept and reported
// through `error()`; the stream's badbit is set too.
class Descriptor_buffer : public std::streambuf
{
public:
  explicit Descriptor_buffer(int fd, std::size_t size = std::size_t(1) << 20) : m_fd(fd), m_buffer(size)
  {
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
  }

  // Writes what is buffered; returns false (and keeps errno in `error()`) on failure.
  bool flush_buffer()
  {
    const char* p = pbase();
    std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    bool ok = write_all(p, n);
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    return ok;
  }

  int error() const { return m_errno; }

protected:
  int_type overflow(int_type c) override
  {
    if(!flush_buffer())
      return traits_type::eof();
    if(!traits_type::eq_int_type(c, traits_type::eof()))
    {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }

  std::streamsize xsputn(const char* s, std::streamsize n) override
  {
    const std::size_t count = static_cast<std::size_t>(n);
    if(count <= static_cast<std::size_t>(epptr() - pptr()))
    {
      std::memcpy(pptr(), s, count);
      pbump(static_cast<int>(count));
      return n;
    }
    if(!flush_buffer())
      return 0;
    if(count >= m_buffer.size() / 2)
      return write_all(s, count) ? n : 0;
    std::memcpy(pptr(), s, count);
    pbump(static_cast<int>(count));
    return n;
  }

  int sync() override { return flush_buffer() ? 0 : -1; }

private:
  bool write_all(const char* p, std::size_t n)
  {
    if(m_errno != 0)
      return false;
    while(n > 0)
    {
      const ssize_t w = ::write(m_fd, p, n);
      if(w < 0)
      {
        if(errno == EINTR)
          continue;
        m_errno = errno;
        return false;
      }
      p += w;
      n -= static_cast<std::size_t>(w);
    }
    return true;
  }

  int m_fd;
  std::vector<char> m_buffer;
  int m_errno = 0;
};

} // namespace output_detail

class Output_file
{
public:
  enum Kind
  {
    REPLACED,      // regular file (or new file): temporary file, then rename
    WRITTEN_THROUGH // descriptor, FIFO, device, socket: written directly
  };

  // Opens the output named `name` (see the top of this file). Throws `Output_error`.
  explicit Output_file(const std::string& name) : m_name(name)
  {
    if(name.empty())
      throw Output_error("empty output file name");
    if(name == "-")
    {
      open_descriptor(STDOUT_FILENO);
      return;
    }

    std::string path = name;
    for(int hops = 0;; ++hops)
    {
      if(hops > 40)
        throw Output_error("cannot write '" + name + "': too many levels of symbolic links");
      const int fd = output_detail::descriptor_named_by(path);
      if(fd >= 0)
      {
        open_descriptor(fd);
        return;
      }
      struct stat st;
      if(::lstat(path.c_str(), &st) != 0)
      {
        if(errno != ENOENT)
          throw Output_error("cannot write '" + name + "': " + std::strerror(errno));
        open_temporary(path, nullptr); // a new file (possibly the target of a dangling link)
        return;
      }
      if(S_ISLNK(st.st_mode))
      {
        std::vector<char> target(PATH_MAX + 1);
        const ssize_t n = ::readlink(path.c_str(), target.data(), PATH_MAX);
        if(n < 0)
          throw Output_error("cannot write '" + name + "': " + std::strerror(errno));
        std::string next(target.data(), static_cast<std::size_t>(n));
        if(next.empty() || next[0] != '/')
          next = output_detail::folder_of(path) + "/" + next;
        path = next;
        continue;
      }
      if(S_ISDIR(st.st_mode))
        throw Output_error("cannot write '" + name + "': it is a folder");
      if(S_ISREG(st.st_mode))
      {
        open_temporary(path, &st);
        return;
      }
      // FIFO, device, socket: written through. No O_CREAT (it exists), no O_TRUNC (not a regular file).
      int d;
      do
        d = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
      while(d < 0 && errno == EINTR);
      if(d < 0)
        throw Output_error("cannot write '" + name + "': " + std::strerror(errno));
      m_fd = d;
      m_owns_fd = true;
      m_kind = WRITTEN_THROUGH;
      make_stream();
      return;
    }
  }

  Output_file(const Output_file&) = delete;
  Output_file& operator=(const Output_file&) = delete;

  ~Output_file()
  {
    if(m_stream)
      m_stream->flush();
    if(m_owns_fd && m_fd >= 0)
      ::close(m_fd);
    if(m_kind == REPLACED && !m_committed && !m_temporary.empty())
      ::unlink(m_temporary.c_str());
  }

  // The stream to write to (binary: no translation).
  std::ostream& stream() { return *m_stream; }

  Kind kind() const { return m_kind; }
  // The descriptor written to, when written through (STDOUT_FILENO for "-" and /dev/stdout), else -1.
  int descriptor() const { return m_kind == WRITTEN_THROUGH ? m_fd : -1; }
  bool writes_to_stdout() const { return m_kind == WRITTEN_THROUGH && m_fd == STDOUT_FILENO; }
  const std::string& name() const { return m_name; }
  // The file that `commit()` replaces (the end of the chain of symbolic links), for REPLACED outputs.
  const std::string& target() const { return m_target; }

  // Writes what is buffered and closes the file (a written-through descriptor of the process stays open);
  // throws `Output_error` if anything failed.
  void close()
  {
    if(m_closed)
      return;
    m_closed = true;
    const bool flushed = m_buffer->flush_buffer() && !m_stream->bad();
    int error = m_buffer->error();
    bool closed = true;
    if(m_owns_fd)
    {
      closed = ::close(m_fd) == 0;
      if(!closed && error == 0)
        error = errno;
      m_fd = -1;
    }
    if(!flushed || !closed)
      throw Output_error("cannot write '" + m_name + "'" + (error != 0 ? std::string(": ") + std::strerror(error) : ""));
  }

  // Closes the file if needed, then renames the temporary file over the target (REPLACED outputs).
  void commit()
  {
    close();
    if(m_kind != REPLACED || m_committed)
      return;
    if(::rename(m_temporary.c_str(), m_target.c_str()) != 0)
      throw Output_error("cannot write '" + m_name + "': " + std::strerror(errno));
    m_committed = true;
  }

private:
  void open_descriptor(int fd)
  {
    m_fd = fd;
    m_owns_fd = false;
    m_kind = WRITTEN_THROUGH;
    make_stream();
  }

  void open_temporary(const std::string& target, const struct stat* existing)
  {
    m_target = target;
    std::string pattern = target + ".tmp.XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    const int fd = ::mkstemp(buffer.data());
    if(fd < 0)
      throw Output_error("cannot write '" + m_name + "': cannot create a file in '" + output_detail::folder_of(target)
                         + "': " + std::strerror(errno));
    m_temporary = buffer.data();
    m_fd = fd;
    m_owns_fd = true;
    m_kind = REPLACED;
    // mkstemp() creates the file with mode 0600: give it the mode of the file it replaces, or the usual mode
    // of a new file.
    mode_t mode;
    if(existing != nullptr)
      mode = existing->st_mode & 07777;
    else
    {
      const mode_t mask = ::umask(0);
      ::umask(mask);
      mode = static_cast<mode_t>(0666) & ~mask;
    }
    ::fchmod(fd, mode);
    make_stream();
  }

  void make_stream()
  {
    m_buffer.reset(new output_detail::Descriptor_buffer(m_fd));
    m_stream.reset(new std::ostream(m_buffer.get()));
  }

  std::string m_name, m_target, m_temporary;
  int m_fd = -1;
  bool m_owns_fd = false;
  Kind m_kind = REPLACED;
  bool m_closed = false, m_committed = false;
  std::unique_ptr<output_detail::Descriptor_buffer> m_buffer;
  std::unique_ptr<std::ostream> m_stream;
};

// The output files of one run: opened and written one after the other, then all committed together (nothing
// is replaced unless every file was written).
class Output_files
{
public:
  // Opens `name` (see Output_file), calls write(stream), and closes the file.
  template <class Write>
  void write(const std::string& name, const Write& write)
  {
    m_files.emplace_back(new Output_file(name));
    write(m_files.back()->stream());
    m_files.back()->close();
  }

  // Commits every file, in the order they were written.
  void commit()
  {
    for(const std::unique_ptr<Output_file>& f : m_files)
      f->commit();
  }

  bool writes_to_stdout() const
  {
    for(const std::unique_ptr<Output_file>& f : m_files)
      if(f->writes_to_stdout())
        return true;
    return false;
  }

private:
  std::vector<std::unique_ptr<Output_file> > m_files;
};

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_OUTPUT_FILE_H
