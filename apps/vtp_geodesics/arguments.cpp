// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#include "arguments.h"

#include <vtp_tools/methods.h>
#include <vtp_tools/mesh_formats.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace vtp_geodesics_app {

namespace {

std::size_t parse_index(const std::string& option, const std::string& s)
{
  if(s.empty() || !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; }))
    throw Tool_error("invalid value '" + s + "' for " + option + " (expected a non-negative integer)");
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if(errno == ERANGE || v > static_cast<unsigned long long>(std::numeric_limits<std::size_t>::max()))
    throw Tool_error("value '" + s + "' for " + option + " is too large");
  return static_cast<std::size_t>(v);
}

double parse_double(const std::string& option, const std::string& s)
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

std::string file_name(const std::string& option, const std::string& s)
{
  if(s.empty())
    throw Tool_error("empty file name for " + option);
  return s;
}

std::string methods_help()
{
  std::string s;
  for(const vtp_tools::Method_info* m = vtp_tools::methods_begin(); m != vtp_tools::methods_end(); ++m)
    s += std::string(m == vtp_tools::methods_begin() ? "" : "\n") + m->name + ": " + m->description
         + (m == vtp_tools::methods_begin() ? " (default)" : "");
  return s;
}

} // namespace

const std::vector<Option>& option_table()
{
  static const std::vector<Option> table = {
    { "--source", "V", "index of the source vertex, in file order (default: 0)",
      [](Arguments& a, const std::string& n, const std::string& v) { a.source = parse_index(n, v); } },
    { "--output", "FILE",
      "write the distances; the format follows the extension of FILE:\n"
      "  .ply: the mesh as read (file vertex order) with per-vertex properties\n"
      "        'distance' (double, inf if unreachable) and red/green/blue colours\n"
      "        (viridis; grey: unreachable), binary little-endian\n"
      "  anything else (.txt): one distance per line, in file vertex order\n"
      "        (shortest text that reads back exactly; \"inf\" if unreachable)\n"
      "  -: the text format on standard output",
      [](Arguments& a, const std::string& n, const std::string& v) { a.output = file_name(n, v); } },
    { "--picture", "FILE",
      "draw the distances as a PNG picture: the mesh coloured by distance\n"
      "(viridis), shaded, with isolines, a colour bar and the source marked",
      [](Arguments& a, const std::string& n, const std::string& v) { a.picture = file_name(n, v); } },
    { "--isolines", "N", "about N isolines on the picture, at round distances (default: 10;\n0: none)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        const std::size_t k = parse_index(n, v);
        if(k > 1000)
          throw Tool_error("too many isolines for " + n + " (at most 1000)");
        a.isolines = static_cast<int>(k);
      } },
    { "--view", "X,Y,Z",
      "viewing direction of the picture (default: along the shortest side\n"
      "of the bounding box)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        std::string::size_type begin = 0;
        for(int k = 0; k < 3; ++k)
        {
          const std::string::size_type end = v.find(',', begin);
          if((k < 2) != (end != std::string::npos))
            throw Tool_error("invalid value '" + v + "' for " + n + " (expected three numbers X,Y,Z)");
          a.view[k] = parse_double(n, v.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
          if(!std::isfinite(a.view[k]))
            throw Tool_error("invalid value '" + v + "' for " + n + " (expected finite numbers)");
          begin = end + 1;
        }
        if(a.view[0] == 0. && a.view[1] == 0. && a.view[2] == 0.)
          throw Tool_error("the direction given to " + n + " is zero");
        a.has_view = true;
      } },
    { "--stats-json", "FILE|-", "write statistics as one JSON object to FILE, or to stdout with \"-\"",
      [](Arguments& a, const std::string& n, const std::string& v) { a.stats_json = file_name(n, v); } },
    { "--check-cgal", nullptr,
      "also run CGAL::Surface_mesh_shortest_path from the same source and\n"
      "report the largest absolute and relative differences",
      [](Arguments& a, const std::string&, const std::string&) { a.check_cgal = true; } },
    { "--method", "M", nullptr, // help made from the table of methods in print_usage()
      [](Arguments& a, const std::string&, const std::string& v) { a.method = v; } },
    { "--threads", "T",
      "number of threads of the parallel methods (0: OpenMP default);\n"
      "ignored by the sequential methods",
      [](Arguments& a, const std::string& n, const std::string& v) {
        const std::size_t t = parse_index(n, v);
        if(t > 4096)
          throw Tool_error("too many threads for " + n);
        a.threads = static_cast<int>(t);
        a.has_threads = true;
      } },
    { "--lambda", "L",
      "window-reset period of avtp / pavtp, in mean edge lengths (> 0,\n"
      "default 8)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.lambda = parse_double(n, v);
        if(!(a.lambda > 0.))
          throw Tool_error(n + " must be > 0");
        a.has_lambda = true;
      } },
    { "--lambda-g", "G", "guard band of avtp / pavtp, in mean edge lengths (>= 0, default 1)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.lambda_g = parse_double(n, v);
        if(!(a.lambda_g >= 0.) || std::isinf(a.lambda_g))
          throw Tool_error(n + " must be finite and >= 0");
        a.has_lambda_g = true;
      } },
    { "--help", nullptr, "print this help and exit",
      [](Arguments& a, const std::string&, const std::string&) { a.help = true; } },
  };
  return table;
}

namespace {

const Option* find_option(const std::string& name)
{
  if(name == "-h")
    return &option_table().back();
  for(const Option& o : option_table())
    if(name == o.name)
      return &o;
  return nullptr;
}

void check_arguments(const Arguments& a)
{
  const vtp_tools::Method_info* m = vtp_tools::find_method(a.method);
  if(m == nullptr)
    throw Tool_error("unknown method '" + a.method + "' (expected " + vtp_tools::method_names() + ")");
  if((a.has_lambda || a.has_lambda_g) && !m->approximate)
    throw Tool_error("--lambda and --lambda-g need --method avtp or pavtp");
  const std::string* files[] = { &a.output, &a.stats_json, &a.picture };
  const char* names[] = { "--output", "--stats-json", "--picture" };
  for(int i = 0; i < 3; ++i)
    for(int j = i + 1; j < 3; ++j)
      if(!files[i]->empty() && *files[i] == *files[j])
        throw Tool_error(std::string(names[i]) + " and " + names[j] + " must name different files");
}

} // namespace

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  bool has_mesh = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg.size() > 1 && arg[0] == '-')
    {
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
      const Option* o = find_option(name);
      if(o == nullptr)
        throw Tool_error("unknown option '" + arg + "' (see --help)");
      if(o->value == nullptr)
      {
        if(has_inline_value)
          throw Tool_error("option " + name + " takes no value");
        value.clear();
      }
      else if(!has_inline_value)
      {
        if(i + 1 >= argc)
          throw Tool_error("missing value for " + name);
        value = argv[++i];
      }
      o->apply(a, name, value);
    }
    else
    {
      if(arg.empty() || arg == "-")
        throw Tool_error("invalid mesh file name '" + arg + "'");
      if(has_mesh)
        throw Tool_error("more than one mesh file given ('" + a.mesh + "' and '" + arg + "')");
      a.mesh = arg;
      has_mesh = true;
    }
  }
  if(!a.help)
    check_arguments(a);
  return a;
}

void print_usage(std::ostream& os, const std::string& default_mesh)
{
  os << "usage: vtp_geodesics [MESH] [options]\n"
        "\n"
        "Computes exact geodesic distances from one source vertex to all vertices of a triangle mesh\n"
        "by vertex-oriented triangle propagation (VTP).\n"
        "\n";
  const std::size_t column = 23;
  auto item = [&](const std::string& left, const std::string& help) {
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
  };
  item("MESH", "mesh file: " + vtp_tools::readable_extensions_text() + "\n(default: " + default_mesh + ")");
  for(const Option& o : option_table())
  {
    const std::string left = std::string(o.name) + (o.value != nullptr ? std::string(" ") + o.value : "");
    item(left, o.help != nullptr ? std::string(o.help) : methods_help());
  }
  os << "\n"
        "Input that is not a triangle mesh is repaired, and one line \"vtp_geodesics: note: ...\"\n"
        "on stderr says what was done:\n"
        "  - faces with more than three vertices (quads, polygons) are triangulated, without\n"
        "    adding vertices;\n"
        "  - a polygon soup that is not a valid mesh (non-manifold vertices or edges, faces with\n"
        "    repeated or coincident points, duplicate faces, inconsistent orientation) is repaired\n"
        "    with CGAL::Polygon_mesh_processing::repair_polygon_soup and orient_polygon_soup:\n"
        "    coincident points are merged, degenerate and duplicate faces removed, and the surface\n"
        "    is cut at non-manifold vertices and edges, which duplicates their vertices.\n"
        "The distances are then computed on the repaired surface (a shortest path does not go from\n"
        "one side of a cut to the other) and mapped back to the vertices of the file: a duplicated\n"
        "vertex gets the smallest distance over its copies (and, as the source, all its copies are\n"
        "sources), merged points share their distance, and a vertex left in no face is unreachable\n"
        "(\"inf\"). Outputs always have one value per vertex of the file, in file order.\n"
        "Input that cannot be repaired (no face left, faces that cannot be triangulated, bad\n"
        "indices, non-finite coordinates) is refused.\n"
        "\n"
        "Output files are never left half-written: a regular file is written to a temporary file\n"
        "in the same folder, then renamed over the target (a symbolic link is followed and stays);\n"
        "standard output (-, /dev/stdout), pipes and devices are written directly.\n"
        "\n"
        "Without --output and --stats-json, a short summary is printed. On error, one line\n"
        "\"vtp_geodesics: error: ...\" is printed on stderr, no output file is written, and the\n"
        "exit code is 2.\n";
}

} // namespace vtp_geodesics_app
