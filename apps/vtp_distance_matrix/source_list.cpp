// vtp_distance_matrix: the --sources argument.

#include "source_list.h"
#include "tool_error.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vtp_matrix {
namespace {

std::int64_t parse_index(const std::string& item, std::int64_t n, const std::string& where)
{
  if(item.empty())
    throw Tool_error("empty item in " + where);
  for(char c : item)
    if(!std::isdigit(static_cast<unsigned char>(c)))
      throw Tool_error("invalid vertex index '" + item + "' in " + where);
  errno = 0;
  const long long v = std::strtoll(item.c_str(), nullptr, 10);
  if(errno == ERANGE || v >= n)
    throw Tool_error("vertex index " + item + " in " + where + " is out of range (the mesh has "
                     + std::to_string(n) + " vertices)");
  return static_cast<std::int64_t>(v);
}

bool looks_like_a_list(const std::string& spec)
{
  for(std::size_t i = 0; i < spec.size(); ++i)
  {
    const char c = spec[i];
    if(!(std::isdigit(static_cast<unsigned char>(c)) || c == ',' || c == ':' || (c == '-' && i == 0)))
      return false;
  }
  return true;
}

} // namespace

std::vector<std::int64_t> parse_sources(const std::string& spec, std::int64_t n)
{
  std::vector<std::int64_t> sources;
  if(spec == "all")
  {
    for(std::int64_t i = 0; i < n; ++i)
      sources.push_back(i);
  }
  else if(looks_like_a_list(spec))
  {
    const std::string where = "--sources '" + spec + "'";
    const std::string::size_type colon = spec.find(':');
    if(colon != std::string::npos)
    {
      const std::string a = spec.substr(0, colon), b = spec.substr(colon + 1);
      if(b.find(':') != std::string::npos || a.find(',') != std::string::npos || b.find(',') != std::string::npos)
        throw Tool_error("invalid range " + where + " (expected A:B)");
      const std::int64_t first = parse_index(a, n, where);
      // B may be n itself (one past the last vertex)
      const std::int64_t last = parse_index(b, n + 1, where);
      if(first >= last)
        throw Tool_error("empty range " + where + " (A:B means A, ..., B-1)");
      for(std::int64_t i = first; i < last; ++i)
        sources.push_back(i);
    }
    else
    {
      std::string::size_type begin = 0;
      while(true)
      {
        const std::string::size_type comma = spec.find(',', begin);
        sources.push_back(parse_index(spec.substr(begin, comma - begin), n, where));
        if(comma == std::string::npos)
          break;
        begin = comma + 1;
      }
    }
  }
  else
  {
    std::ifstream in(spec);
    if(!in)
      throw Tool_error("cannot open the source file '" + spec + "'");
    std::string line;
    std::size_t line_number = 0;
    while(std::getline(in, line))
    {
      ++line_number;
      const std::string::size_type hash = line.find('#');
      if(hash != std::string::npos)
        line.erase(hash);
      for(char& c : line)
        if(c == ',' || c == '\t' || c == '\r')
          c = ' ';
      std::istringstream items(line);
      std::string item;
      while(items >> item)
        sources.push_back(parse_index(item, n, "line " + std::to_string(line_number) + " of '" + spec + "'"));
    }
    if(in.bad() || (!in.eof() && in.fail()))
      throw Tool_error("cannot read the source file '" + spec + "'");
    if(sources.empty())
      throw Tool_error("no source vertex in the file '" + spec + "'");
  }
  if(sources.empty())
    throw Tool_error("no source vertex");
  return sources;
}

} // namespace vtp_matrix
