// vtp_benchmark, parent side: forks a child per run (child_run.cpp), reads its report through a pipe and
// its peak resident memory from wait4.

#include "vtp_benchmark.h"

#include <vtp_support/statistics.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <sys/resource.h> // struct rusage
#include <sys/wait.h>     // wait4
#include <unistd.h>       // fork, pipe, read, close

namespace vtp_benchmark {

double ns_per_window(const Run_result& r)
{
  if(!r.ok || !r.has_statistics || r.statistics.windows_propagated == 0)
    return nan_value;
  return r.header.seconds * 1e9 / static_cast<double>(r.statistics.windows_propagated);
}

double total_seconds(const Run_result& r) { return r.header.seconds + r.header.preprocessing_seconds; }

namespace {

// A value of the statistics as vtp_support::json_value() writes it, at `p`.
void read_json_value(const char* p, std::string& value)
{
  value.clear();
  if(*p++ != '"')
    return;
  for(; *p != '\0' && *p != '"'; ++p)
  {
    if(*p != '\\')
      value += *p;
    else if(p[1] == 'u' && p[2] != '\0' && p[3] != '\0' && p[4] != '\0' && p[5] != '\0')
    {
      value += static_cast<char>(std::strtol(std::string(p + 2, 4).c_str(), nullptr, 16));
      p += 5;
    }
    else if(p[1] != '\0')
      value += *++p;
  }
}
void read_json_value(const char* p, bool& value) { value = std::strncmp(p, "true", 4) == 0; }
void read_json_value(const char* p, double& value)
{
  value = std::strncmp(p, "null", 4) == 0 ? nan_value : std::strtod(p, nullptr);
}
void read_json_value(const char* p, int& value) { value = static_cast<int>(std::strtol(p, nullptr, 10)); }
void read_json_value(const char* p, std::size_t& value) { value = std::strtoull(p, nullptr, 10); }

// The statistics that the child wrote with vtp_support::write_statistics_json(), read back field by field from
// the same description (a field whose member is missing keeps its value).
void read_statistics_json(const std::string& text, CGAL::VTP_geodesics::Propagation_statistics& statistics)
{
  vtp_support::for_each_statistic(statistics, [&text](const char* name, auto& field, vtp_support::Statistic_unit) {
    const std::string member = std::string("\"") + name + "\": ";
    const std::string::size_type at = text.find(member);
    if(at != std::string::npos)
      read_json_value(text.c_str() + at + member.size(), field);
  });
}

} // namespace

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
  const std::size_t distances_at = sizeof(Child_header);
  const std::size_t error_at = distances_at + h.number_of_distances * sizeof(double);
  const std::size_t statistics_at = error_at + h.error_length;
  if(message.size() != statistics_at + h.statistics_length)
  {
    result.status = "truncated child report";
    return result;
  }
  result.distances.resize(h.number_of_distances);
  if(h.number_of_distances > 0)
    std::memcpy(result.distances.data(), message.data() + distances_at, h.number_of_distances * sizeof(double));
  if(h.error_length > 0)
  {
    result.status = "error: " + message.substr(error_at, h.error_length);
    return result;
  }
  if(h.statistics_length > 0)
  {
    read_statistics_json(message.substr(statistics_at), result.statistics);
    result.has_statistics = true;
  }
  result.ok = true;
  return result;
}

} // namespace vtp_benchmark
