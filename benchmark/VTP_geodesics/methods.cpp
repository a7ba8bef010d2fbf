// vtp_benchmark: the methods it compares, parsed from --methods (see vtp_benchmark.h).

#include "vtp_benchmark.h"

#include <vtp_support/methods.h>

#include <cerrno>
#include <cstdlib>
#include <string>
#include <vector>

namespace vtp_benchmark {

namespace {

int parse_int_field(const std::string& method, const std::string& s, int min_value)
{
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if(s.empty() || *end != '\0' || errno == ERANGE || v < min_value || v > 4096)
    throw Tool_error("invalid parameter '" + s + "' in method '" + method + "'");
  return static_cast<int>(v);
}

double parse_positive_field(const std::string& method, const std::string& s)
{
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if(s.empty() || *end != '\0' || !(v > 0.))
    throw Tool_error("invalid parameter '" + s + "' in method '" + method + "'");
  return v;
}

struct Method_parser
{
  const char* name;
  const char* syntax;
  bool available;
  // fields[0] is the name; the parser reads the parameters and fills `m`.
  void (*parse)(const std::vector<std::string>& fields, Method& m);
};

void expect_fields(const std::vector<std::string>& fields, std::size_t n, const char* syntax)
{
  if(fields.size() != n)
    throw Tool_error("invalid method '" + fields[0] + "...' (expected " + syntax + ")");
}

// How a method of the table is written: the name, then ":T" for a parallel method and ":lambda" for an
// approximate one.
std::string vtp_method_syntax(const vtp_support::Method_info& info)
{
  return std::string(info.name) + (info.parallel ? ":T" : "") + (info.approximate ? ":lambda" : "");
}

// The VTP family (vtp, pvtp:T, avtp:lambda, pavtp:T:lambda, vsp, pvsp:T, vsp2, pvsp2:T) comes from the table
// of methods shared with the command-line tools (vtp_support/methods.h), written as vtp_method_syntax() says.
// Returns false if `fields[0]` is not one of them.
bool parse_vtp_method(const std::vector<std::string>& fields, Method& m)
{
  const vtp_support::Method_info* info = vtp_support::find_method(fields[0]);
  if(info == nullptr)
    return false;
  const std::string syntax = vtp_method_syntax(*info);
  expect_fields(fields, 1 + (info->parallel ? 1 : 0) + (info->approximate ? 1 : 0), syntax.c_str());
  m.kind = Method_kind::VTP_FAMILY;
  m.info = info;
  std::size_t k = 1;
  if(info->parallel)
    m.threads = parse_int_field(m.label, fields[k++], 1);
  if(info->approximate)
    m.lambda = parse_positive_field(m.label, fields[k++]);
  if(!vtp_support::method_available(*info))
    throw Tool_error("method " + std::string(info->name) + " is not available (vtp_benchmark was built without OpenMP)");
  return true;
}

const Method_parser method_parsers[] = {
  { "cgal", "cgal", true,
    [](const std::vector<std::string>& f, Method& m) { expect_fields(f, 1, "cgal"); m.kind = Method_kind::CGAL_SMSP; } },
#ifdef VTP_BENCHMARK_WITH_HEAT_METHOD
  { "heat", "heat", true,
#else
  { "heat", "heat", false,
#endif
    [](const std::vector<std::string>& f, Method& m) { expect_fields(f, 1, "heat"); m.kind = Method_kind::HEAT_DIRECT; } },
#ifdef VTP_BENCHMARK_WITH_HEAT_METHOD
  { "heat_idt", "heat_idt", true,
#else
  { "heat_idt", "heat_idt", false,
#endif
    [](const std::vector<std::string>& f, Method& m) { expect_fields(f, 1, "heat_idt"); m.kind = Method_kind::HEAT_IDT; } },
};

} // namespace

Method parse_method(const std::string& spec)
{
  const std::vector<std::string> fields = split(spec, ':');
  {
    Method m;
    m.label = spec;
    if(parse_vtp_method(fields, m))
      return m;
  }
  for(const Method_parser& p : method_parsers)
  {
    if(fields[0] != p.name)
      continue;
    Method m;
    m.label = spec;
    p.parse(fields, m);
    if(!p.available)
    {
#ifndef VTP_BENCHMARK_WITH_HEAT_METHOD
      if(m.kind == Method_kind::HEAT_DIRECT || m.kind == Method_kind::HEAT_IDT)
        throw Tool_error("method " + spec + " is not available (vtp_benchmark was built without Eigen)");
#endif
      throw Tool_error("method " + std::string(p.name) + " is not available (vtp_benchmark was built without OpenMP)");
    }
    return m;
  }
  std::string known;
  for(const vtp_support::Method_info* i = vtp_support::methods_begin(); i != vtp_support::methods_end(); ++i)
    known += (known.empty() ? "" : ", ") + vtp_method_syntax(*i);
  for(const Method_parser& p : method_parsers)
    known += (known.empty() ? "" : ", ") + std::string(p.syntax);
  throw Tool_error("unknown method '" + spec + "' (known: " + known + ")");
}

} // namespace vtp_benchmark
