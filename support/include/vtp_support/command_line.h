// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_COMMAND_LINE_H
#define VTP_SUPPORT_COMMAND_LINE_H

// The command line of every program of the project (the two tools, the benchmarks, the stress program): one
// table of options per program, from which the parser and (if the program wants it) the help are made.
//
//   struct Arguments { int repeat = 1; std::vector<std::string> meshes; bool help = false; };
//   const vtp_support::Option_table<Arguments> table = {
//     { "--repeat", "R", "run R times (default 1)",
//       [](Arguments& a, const std::string& n, const std::string& v) { a.repeat = int(parse_integer(n, v, 1, 1000)); } },
//     { "--help", nullptr, "print this help", [](Arguments& a, const std::string&, const std::string&) { a.help = true; } } };
//   Arguments a;
//   vtp_support::parse_command_line(argc, argv, table, a,
//                                   [](Arguments& a, const std::string& operand) { a.meshes.push_back(operand); });
//
// Options are written "--name value" or "--name=value"; a flag (no value) takes none. "-h" is "--help" when the
// table has "--help". An argument that starts with '-' (and is not "-" alone) is an option, anything else is an
// operand. Every error is a Tool_error with one line of text; the programs print it as
// "<program>: error: <text>" and exit with code 2.

#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vtp_support {

// The one error type of the command-line programs (bad arguments, and what the tools find wrong later).
struct Tool_error : std::runtime_error
{
  explicit Tool_error(const std::string& what) : std::runtime_error(what) {}
};

// ---------------------------------------------------------------------------------------------------------------
// Values. `option` names the option in the messages.
// ---------------------------------------------------------------------------------------------------------------

// A number as strtod reads it, the whole text: "inf" is accepted, NaN and overflow are not.
inline double parse_double(const std::string& option, const std::string& s)
{
  const char* begin = s.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if(s.empty() || end != begin + s.size() || std::isspace(static_cast<unsigned char>(s[0])) || std::isnan(v)
     || (errno == ERANGE && std::isinf(v)))
    throw Tool_error("invalid value '" + s + "' for " + option + " (expected a number)");
  return v;
}

inline bool all_digits(const std::string& s)
{
  for(unsigned char c : s)
    if(std::isdigit(c) == 0)
      return false;
  return !s.empty();
}

// A distance limit (--max-distance of the tools): a number >= 0, +infinity included.
inline double parse_distance_limit(const std::string& option, const std::string& s)
{
  const double r = parse_double(option, s);
  if(!(r >= 0.))
    throw Tool_error(option + " must be >= 0");
  return r;
}

// A decimal integer in [low, high] (digits only: no sign, no blank).
inline unsigned long long parse_integer(const std::string& option, const std::string& s, unsigned long long low,
                                        unsigned long long high)
{
  if(!all_digits(s))
    throw Tool_error("invalid value '" + s + "' for " + option + " (expected an integer)");
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if(errno == ERANGE || v < low || v > high)
    throw Tool_error("value '" + s + "' for " + option + " is out of range [" + std::to_string(low) + ", "
                     + std::to_string(high) + "]");
  return v;
}

// A vertex index: a non-negative decimal integer.
inline std::size_t parse_index(const std::string& option, const std::string& s)
{
  if(!all_digits(s))
    throw Tool_error("invalid value '" + s + "' for " + option + " (expected a non-negative integer)");
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if(errno == ERANGE || v > static_cast<unsigned long long>((std::numeric_limits<std::size_t>::max)()))
    throw Tool_error("value '" + s + "' for " + option + " is too large");
  return static_cast<std::size_t>(v);
}

// The parts of `s` between the separators (empty parts included; one part if there is no separator).
inline std::vector<std::string> split(const std::string& s, char separator)
{
  std::vector<std::string> parts;
  std::string::size_type begin = 0;
  for(;;)
  {
    const std::string::size_type end = s.find(separator, begin);
    parts.push_back(s.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    if(end == std::string::npos)
      return parts;
    begin = end + 1;
  }
}

// "I,J,K": a non-empty list of indices.
inline std::vector<std::size_t> parse_index_list(const std::string& option, const std::string& s)
{
  std::vector<std::size_t> r;
  for(const std::string& item : split(s, ','))
  {
    if(item.empty())
      throw Tool_error("invalid list '" + s + "' for " + option + ": empty item (expected indices separated by commas, "
                       "e.g. 0,17,42)");
    r.push_back(parse_index(option, item));
  }
  return r;
}

// "X,Y,Z": three finite numbers.
inline std::array<double, 3> parse_point(const std::string& option, const std::string& s)
{
  const std::vector<std::string> parts = split(s, ',');
  std::array<double, 3> p = { { 0., 0., 0. } };
  for(std::size_t k = 0; k < 3; ++k)
  {
    if((k < 2) != (k + 1 < parts.size()))  // read from left to right: the first fault found is reported
      throw Tool_error("invalid value '" + s + "' for " + option + " (expected three numbers X,Y,Z)");
    p[k] = parse_double(option, parts[k]);
    if(!std::isfinite(p[k]))
      throw Tool_error("invalid value '" + s + "' for " + option + " (expected finite numbers)");
  }
  return p;
}

// ---------------------------------------------------------------------------------------------------------------
// Options
// ---------------------------------------------------------------------------------------------------------------

template <class Arguments>
struct Option
{
  const char* name;   // "--source"
  const char* value;  // name of the value in the help ("V"), or nullptr for a flag
  const char* help;   // lines separated by '\n'; nullptr: the program writes this help itself
  // Stores the value (empty for a flag); `name` is the option as written. Throws Tool_error on a bad value.
  void (*apply)(Arguments& a, const std::string& name, const std::string& value);
};

template <class Arguments>
using Option_table = std::vector<Option<Arguments> >;

// The `apply` of a distance limit option (--max-distance of both tools): stores the limit and that it was given.
template <class Arguments, double Arguments::*limit, bool Arguments::*given>
void apply_distance_limit(Arguments& a, const std::string& name, const std::string& value)
{
  a.*limit = parse_distance_limit(name, value);
  a.*given = true;
}

template <class Arguments>
const Option<Arguments>* find_option(const Option_table<Arguments>& table, const std::string& name)
{
  for(const Option<Arguments>& o : table)
    if(name == o.name || (name == "-h" && std::string(o.name) == "--help"))
      return &o;
  return nullptr;
}

// Reads argv[1 .. argc-1] into `a`: options through the table, operands through `operand(a, text)`.
template <class Arguments, class Operand>
void parse_command_line(int argc, char** argv, const Option_table<Arguments>& table, Arguments& a, Operand operand)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg.size() < 2 || arg[0] != '-')
    {
      operand(a, arg);
      continue;
    }
    // "--name=value" or "--name value"
    std::string name = arg, value;
    bool has_inline_value = false;
    const std::string::size_type eq = arg.find('=');
    if(arg.compare(0, 2, "--") == 0 && eq != std::string::npos)
    {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
      has_inline_value = true;
    }
    const Option<Arguments>* o = find_option(table, name);
    if(o == nullptr)
      throw Tool_error("unknown option '" + arg + "' (see --help)");
    if(o->value == nullptr)
    {
      if(has_inline_value)
        throw Tool_error("option " + name + " takes no value");
    }
    else if(!has_inline_value)
    {
      if(i + 1 >= argc)
        throw Tool_error("missing value for " + name);
      value = argv[++i];
    }
    o->apply(a, name, value);
  }
}

// One item of a help text: "  LEFT" then the lines of `help`, aligned at `column`.
inline void print_help_item(std::ostream& os, const std::string& left, const std::string& help, std::size_t column)
{
  std::string line = "  " + left;
  line += (line.size() + 1 < column) ? std::string(column - line.size(), ' ') : std::string(" ");
  std::string::size_type begin = 0;
  for(bool first = true; begin <= help.size(); first = false)
  {
    std::string::size_type end = help.find('\n', begin);
    if(end == std::string::npos)
      end = help.size();
    os << (first ? line : std::string(column, ' ')) << help.substr(begin, end - begin) << "\n";
    begin = end + 1;
  }
}

// The help of every option of the table that has one, in table order.
template <class Arguments>
void print_options(std::ostream& os, const Option_table<Arguments>& table, std::size_t column)
{
  for(const Option<Arguments>& o : table)
    if(o.help != nullptr)
      print_help_item(os, std::string(o.name) + (o.value != nullptr ? std::string(" ") + o.value : ""), o.help, column);
}

} // namespace vtp_support

#endif // VTP_SUPPORT_COMMAND_LINE_H
