// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#include "query_points.h"
#include "arguments.h"

#include <vtp_support/number_format.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace vtp_geodesics_app {

namespace {

// The whole file (a folder, a missing or unreadable file: Tool_error naming `option`).
std::string read_text(const std::string& file, const std::string& option)
{
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
  if(!f)
    throw Tool_error("cannot read " + option + " file '" + file + "': " + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  std::size_t n;
  while((n = std::fread(buffer, 1, sizeof(buffer), f.get())) > 0)
    text.append(buffer, n);
  if(std::ferror(f.get()))
    throw Tool_error("cannot read " + option + " file '" + file + "': " + std::strerror(errno));
  return text;
}

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// The line as it can be shown in a one-line message: at most 40 characters, control characters as '?'.
std::string excerpt(const char* begin, const char* end)
{
  std::string s(begin, static_cast<std::size_t>(end - begin) > 40 ? begin + 40 : end);
  for(char& c : s)
    if(static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      c = '?';
  return static_cast<std::size_t>(end - begin) > 40 ? s + "..." : s;
}

// Calls `line(number, begin, end)` for each line of `text` (numbered from 1; without its '\n' and a final '\r').
template <class Line>
void for_each_line(const std::string& text, Line line)
{
  const char* p = text.c_str();
  const char* const text_end = p + text.size();
  for(std::size_t number = 1; p < text_end; ++number)
  {
    const char* end = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(text_end - p)));
    if(end == nullptr)
      end = text_end;
    const char* next = end < text_end ? end + 1 : end;
    if(end > p && end[-1] == '\r')
      --end;
    line(number, p, end);
    p = next;
  }
}

// Whether [p, end) is three finite numbers, each ended by a blank or the end of the line (std::strtod stops
// there: the text ends with '\0', and it does not skip blanks that are not before the number), into `x`.
bool parse_point_line(const char* p, const char* end, std::array<double, 3>& x)
{
  const char* q = p;
  bool ok = true;
  for(std::size_t k = 0; k < 3 && ok; ++k)
  {
    while(q < end && is_blank(*q))
      ++q;
    char* number_end = nullptr;
    x[k] = q < end ? std::strtod(q, &number_end) : 0.;
    ok = q < end && number_end != q && number_end <= end && (number_end == end || is_blank(*number_end))
         && std::isfinite(x[k]);
    q = number_end;
  }
  while(ok && q < end && is_blank(*q))
    ++q;
  return ok && q == end;
}

bool is_blank_line(const char* p, const char* end)
{
  while(p < end && is_blank(*p))
    ++p;
  return p == end;
}

} // namespace

std::vector<std::array<double, 3> > read_query_points(const std::string& file)
{
  const std::string text = read_text(file, "--query-points");
  std::vector<std::array<double, 3> > points;
  for_each_line(text, [&](std::size_t line, const char* p, const char* end) {
    std::array<double, 3> x = { { 0., 0., 0. } };
    if(!parse_point_line(p, end, x))
      throw Tool_error("--query-points file '" + file + "' line " + std::to_string(line)
                       + ": expected three finite numbers \"X Y Z\", got '" + excerpt(p, end) + "'");
    points.push_back(x);
  });
  return points;
}

std::vector<Point_file_curve> read_curve_file(const std::string& file)
{
  const std::string text = read_text(file, "--source-curve");
  std::vector<Point_file_curve> curves;
  bool after_blank = true;  // the next point starts a curve
  for_each_line(text, [&](std::size_t line, const char* p, const char* end) {
    if(is_blank_line(p, end))
    {
      after_blank = true;
      return;
    }
    std::array<double, 3> x = { { 0., 0., 0. } };
    if(!parse_point_line(p, end, x))
      throw Tool_error("--source-curve file '" + file + "' line " + std::to_string(line)
                       + ": expected three finite numbers \"X Y Z\" (or a blank line between curves), got '"
                       + excerpt(p, end) + "'");
    if(after_blank)
    {
      curves.push_back(Point_file_curve());
      curves.back().first_line = line;
    }
    after_blank = false;
    curves.back().points.push_back(x);
    curves.back().last_line = line;
  });
  if(curves.empty())
    throw Tool_error("--source-curve file '" + file + "' has no point (expected one \"X Y Z\" per line)");
  for(const Point_file_curve& c : curves)
    if(c.points.size() < 2)
      throw Tool_error("--source-curve file '" + file + "' line " + std::to_string(c.first_line)
                       + ": a curve of one point (a curve needs at least two points; a blank line starts a curve)");
  return curves;
}

void write_query_results(std::ostream& os, const std::vector<double>& distances, const std::vector<int>& labels)
{
  std::string text;
  text.reserve(distances.size() * 24);
  char buffer[vtp_support::max_double_chars];
  for(std::size_t i = 0; i < distances.size(); ++i)
  {
    text.append(buffer, vtp_support::format_double(buffer, distances[i]));
    text += ' ';
    text += std::to_string(labels[i]);
    text += '\n';
  }
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
}

} // namespace vtp_geodesics_app
