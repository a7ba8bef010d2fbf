// vtp_benchmark, parent side: forks a child per run (child_run.cpp), reads its report through a pipe and
// its peak resident memory from wait4.

#include "vtp_benchmark.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include <sys/resource.h> // struct rusage
#include <sys/wait.h>     // wait4
#include <unistd.h>       // fork, pipe, read, close

namespace vtp_benchmark {

double ns_per_window(const Run_result& r)
{
  if(!r.ok || !r.header.has_windows || r.header.windows_propagated == 0)
    return nan_value;
  return r.header.seconds * 1e9 / static_cast<double>(r.header.windows_propagated);
}

double total_seconds(const Run_result& r) { return r.header.seconds + r.header.preprocessing_seconds; }

// Reads everything the child `pid` writes to `fd` (before waiting: the child blocks when the pipe is full),
// closes `fd`, then waits for the child: its exit status and peak RSS (MB).
std::string read_all_and_wait(int fd, pid_t pid, int& status, double& peak_rss_mb)
{
  std::string text;
  char buffer[1 << 16];
  for(;;)
  {
    const ssize_t r = ::read(fd, buffer, sizeof(buffer));
    if(r < 0 && errno == EINTR)
      continue;
    if(r <= 0)
      break;
    text.append(buffer, static_cast<std::size_t>(r));
  }
  ::close(fd);
  status = 0;
  struct rusage usage;
  std::memset(&usage, 0, sizeof(usage));
  while(::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {}
  peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.; // ru_maxrss is in KB on Linux
  return text;
}

pid_t fork_with_pipe(int& fd)
{
  int fds[2];
  if(::pipe(fds) != 0)
    throw std::runtime_error(std::string("pipe() failed: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork() failed: ") + std::strerror(errno));
  }
  ::close(fds[pid == 0 ? 0 : 1]);
  fd = fds[pid == 0 ? 1 : 0];
  return pid;
}

Run_result run_forked(Mesh& mesh, Vertex_index source, const Method& method, int repeat)
{
  Run_result result;
  result.method = method;
  int fd = -1;
  const pid_t pid = fork_with_pipe(fd);
  if(pid == 0)
    run_in_child(fd, mesh, source, method, repeat);
  int status = 0;
  const std::string message = read_all_and_wait(fd, pid, status, result.peak_rss_mb);

  if(WIFSIGNALED(status))
  {
    result.status = "killed by signal " + std::to_string(WTERMSIG(status));
    return result;
  }
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0 || message.size() < sizeof(Child_header))
  {
    result.status = "child failed";
    return result;
  }
  std::memcpy(&result.header, message.data(), sizeof(Child_header));
  const Child_header& h = result.header;
  const std::size_t expected = sizeof(Child_header) + h.number_of_distances * sizeof(double) + h.error_length;
  if(message.size() != expected)
  {
    result.status = "truncated child report";
    return result;
  }
  result.distances.resize(h.number_of_distances);
  if(h.number_of_distances > 0)
    std::memcpy(result.distances.data(), message.data() + sizeof(Child_header), h.number_of_distances * sizeof(double));
  if(h.error_length > 0)
  {
    result.status = "error: " + message.substr(sizeof(Child_header) + h.number_of_distances * sizeof(double));
    return result;
  }
  result.ok = true;
  return result;
}

} // namespace vtp_benchmark
