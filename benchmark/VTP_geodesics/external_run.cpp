// vtp_benchmark: external methods (--external NAME=COMMAND), run through /bin/sh in their own process.

#include "vtp_benchmark.h"

#include <vtp_support/statistics.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include <sys/wait.h>     // WIFEXITED
#include <unistd.h>       // fork, pipe, dup2, execl

namespace vtp_benchmark {

std::string replace_all(std::string s, const std::string& what, const std::string& with)
{
  for(std::string::size_type at = s.find(what); at != std::string::npos; at = s.find(what, at + with.size()))
    s.replace(at, what.size(), with);
  return s;
}

namespace {

// Value of "key=<value>" in `text`, at the start of the text or after a space, tab or new line.
bool find_value(const std::string& text, const std::string& key, std::string& value)
{
  const std::string k = key + "=";
  for(std::string::size_type at = text.find(k); at != std::string::npos; at = text.find(k, at + 1))
  {
    if(at > 0 && text[at - 1] != ' ' && text[at - 1] != '\t' && text[at - 1] != '\n')
      continue;
    const std::string::size_type begin = at + k.size();
    const std::string::size_type end = text.find_first_of(" \t\r\n", begin);
    value = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    return true;
  }
  return false;
}

// A count printed as name=N sets `field` (the counts only: the other statistics an external program does not have).
void read_count(const std::string& text, const char* name, std::size_t& field, bool& found)
{
  std::string value;
  if(find_value(text, name, value))
  {
    field = std::strtoull(value.c_str(), nullptr, 10);
    found = true;
  }
}
template <class T>
void read_count(const std::string&, const char*, T&, bool&)
{}

} // namespace

// Runs an external method (see --external) on the mesh written to `mesh_file`, in its own process
// (so its peak RSS is its own), and reads its time, window count and distances.
Run_result run_external(const std::string& mesh_file, std::size_t source, std::size_t number_of_vertices,
                        const Method& method, const std::string& output_file)
{
  Run_result result;
  result.method = method;
  std::string command = replace_all(method.command, "{mesh}", mesh_file);
  command = replace_all(command, "{source}", std::to_string(source));
  const bool wants_output = command.find("{output}") != std::string::npos;
  command = replace_all(command, "{output}", output_file);
  if(wants_output)
    std::remove(output_file.c_str());

  int fd = -1;
  const pid_t pid = fork_with_pipe(fd);
  if(pid == 0)
  {
    ::dup2(fd, 1);
    ::close(fd);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  const std::string text = read_all_and_wait(fd, pid, status, result.peak_rss_mb);
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    result.status = WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                        : "exit code " + std::to_string(WEXITSTATUS(status));
    return result;
  }
  std::string value;
  char* end = nullptr;
  if(!find_value(text, "seconds", value) || (result.header.seconds = std::strtod(value.c_str(), &end), *end != '\0'))
  {
    result.status = "no seconds=<time> in the output";
    return result;
  }
  result.header.preprocessing_seconds = nan_value;
  if(find_value(text, "cpu_seconds", value))
    result.header.cpu_seconds = std::strtod(value.c_str(), nullptr);
  // The counts it prints under the names of the library's statistics (for example windows_propagated=N).
  vtp_support::for_each_statistic(result.statistics, [&](const char* name, auto& field, vtp_support::Statistic_unit) {
    read_count(text, name, field, result.has_statistics);
  });
  if(wants_output)
  {
    std::ifstream in(output_file);
    std::string token;
    while(in >> token)
    {
      const double d = std::strtod(token.c_str(), &end);
      if(*end != '\0')
      {
        result.status = "unreadable distance '" + token + "' in " + output_file;
        return result;
      }
      result.distances.push_back(d);
    }
    if(result.distances.size() != number_of_vertices)
    {
      result.status = "wrong number of distances in " + output_file;
      return result;
    }
    std::remove(output_file.c_str());
  }
  result.ok = true;
  return result;
}

} // namespace vtp_benchmark
