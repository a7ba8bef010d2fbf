// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_FAST_OFF_READER_H
#define VTP_SUPPORT_FAST_OFF_READER_H

// A fast path from a plain ASCII OFF file that is a valid triangle mesh to a `Surface_mesh`: the file is read
// in blocks, the lines of each block parsed with std::from_chars by several threads, each taking ranges of
// whole lines (see parse_off_triangles()); the triangles are checked to be a valid mesh with the same rules as
// `CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()` (no face with a repeated vertex, no directed
// edge twice, every vertex a single fan of faces), and its halfedge structure is built directly from sorted
// per-vertex lists instead of through a polygon soup.
//
// Anything the fast path does not handle (another OFF flavour, polygons, an invalid mesh, unusual
// formatting) is left to CGAL's reader and repair: `read_off_triangle_mesh()` then returns NOT_HANDLED. Definite
// errors of the file (too few lines, non-finite coordinates, indices out of range) throw `Fast_off_error`.

#include <vtp_support/build_triangle_mesh.h>
#include <vtp_support/off_text.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace vtp_support {

struct Fast_off_error : std::runtime_error
{
  explicit Fast_off_error(const std::string& what) : std::runtime_error(what) {}
};

struct Fast_off_result
{
  enum Status { MESH, NOT_HANDLED };
  Status status = NOT_HANDLED;
  std::string reason;          // why NOT_HANDLED
  double read_seconds = 0.;    // parsing
  double build_seconds = 0.;   // checking and building the halfedge structure
};

namespace fast_off_detail {

// What a range of lines of the body (after the header) holds: its lines with content, and the first problem met
// in its lines, at the index of its line among the lines with content of the body.
struct Line_range
{
  const char* begin = nullptr;
  const char* end = nullptr;
  std::uint64_t lines = 0;
  std::uint64_t problem_line = (std::numeric_limits<std::uint64_t>::max)();
  bool error = false;    // a definite error of the file (else a file for CGAL's reader)
  std::string problem;   // the message of the error, or the reason it is left to CGAL

  void set_problem(std::uint64_t line, bool is_error, const std::string& what)
  {
    problem_line = line;
    error = is_error;
    problem = what;
  }
};

// Parses the line with content at `p` (number `line` among the lines with content of the body): a vertex, a
// face, or nothing (after the faces). Returns false, with the problem in `range`, if the line is not what it
// must be.
template <class Set_point>
bool parse_body_line(const char* p, const char* end, std::uint64_t line, std::uint64_t nv, std::uint64_t nf,
                     const Set_point& set_point, std::vector<Triangle>& triangles, Line_range& range)
{
  if(line < nv)
  {
    double x[3];
    for(int k = 0; k < 3; ++k)
    {
      const Number_status s = parse_double(p, end, x[k]);
      if(s == NUMBER_MISSING)
      {
        range.set_problem(line, false, "unexpected vertex line");
        return false;
      }
      if(s == NUMBER_OUT_OF_RANGE || !std::isfinite(x[k]))
      {
        range.set_problem(line, true, "vertex " + std::to_string(line) + " has a non-finite coordinate");
        return false;
      }
    }
    if(!end_of_line(p, end))
    {
      range.set_problem(line, false, "unexpected vertex line");
      return false;
    }
    set_point(static_cast<std::size_t>(line), x[0], x[1], x[2]);
    return true;
  }
  if(line >= nv + nf)
    return true;
  const std::uint64_t i = line - nv;
  std::uint64_t k = 0, id = 0;
  if(!parse_index(p, end, k))
  {
    range.set_problem(line, false, "unexpected face line");
    return false;
  }
  if(k != 3)
  {
    range.set_problem(line, false, "a face is not a triangle");
    return false;
  }
  for(int j = 0; j < 3; ++j)
  {
    if(!parse_index(p, end, id))
    {
      range.set_problem(line, false, "unexpected face line");
      return false;
    }
    if(id >= nv)
    {
      range.set_problem(line, true, "face " + std::to_string(i) + " refers to vertex " + std::to_string(id)
                                      + ", out of range (there are " + std::to_string(nv) + " vertices)");
      return false;
    }
    triangles[static_cast<std::size_t>(i)][j] = static_cast<std::uint32_t>(id);
  }
  // The rest of a face line (e.g. a colour) is ignored, as CGAL's reader does.
  return true;
}

// Parses the lines of [first, stop) (whole lines), the first of them with content being number `line` among the
// lines with content of the body: cut into ranges of whole lines of about `range_bytes`, whose lines with
// content `threads` OpenMP threads count, then parse, each knowing from the counts whether a line is a vertex
// or a face, and which. Adds the lines with content to `line`; returns the range of the first problem (in the
// order of the lines), or null.
template <class Set_point>
const Line_range* parse_lines(const char* first, const char* stop, std::uint64_t& line, std::uint64_t nv,
                              std::uint64_t nf, const Set_point& set_point, std::vector<Triangle>& triangles,
                              int threads, std::size_t range_bytes, std::vector<Line_range>& ranges)
{
  ranges.clear();
  const std::size_t size = static_cast<std::size_t>(stop - first);
  const std::size_t n = (std::max)(std::size_t(1), size / (std::max)(std::size_t(1), range_bytes));
  for(std::size_t r = 1; r <= n; ++r)
  {
    const char* last = r == n ? stop : next_line(first + r * (size / n) - 1, stop);
    if(last <= (ranges.empty() ? first : ranges.back().end))
      continue;
    Line_range range;
    range.begin = ranges.empty() ? first : ranges.back().end;
    range.end = last;
    ranges.push_back(range);
  }
  const long long nr = static_cast<long long>(ranges.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) if(threads > 1 && nr > 1)
#endif
  for(long long r = 0; r < nr; ++r)
  {
    Line_range& range = ranges[static_cast<std::size_t>(r)];
    for(const char* q = range.begin; q != range.end; q = next_line(q, range.end))
    {
      const char* c = q;
      range.lines += content_at(c, range.end) ? 1 : 0;
    }
  }
  std::vector<std::uint64_t> first_line(ranges.size());
  for(std::size_t r = 0; r < ranges.size(); ++r)
  {
    first_line[r] = line;
    line += ranges[r].lines;
  }
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) if(threads > 1 && nr > 1)
#endif
  for(long long r = 0; r < nr; ++r)
  {
    Line_range& range = ranges[static_cast<std::size_t>(r)];
    std::uint64_t l = first_line[static_cast<std::size_t>(r)];
    for(const char* q = range.begin; q != range.end && l < nv + nf; q = next_line(q, range.end))
    {
      const char* c = q;
      if(!content_at(c, range.end))
        continue;
      if(!parse_body_line(c, range.end, l, nv, nf, set_point, triangles, range))
        break;
      ++l;
    }
  }
  for(const Line_range& range : ranges)
    if(range.problem_line != (std::numeric_limits<std::uint64_t>::max)())
      return &range;
  return nullptr;
}

// Parses `file` if it is a plain ASCII OFF file of triangles: resize(nv) once the header is read, then
// set_point(i, x, y, z) for each vertex i (from several threads, each i once), and the triangles into
// `triangles`. Returns NOT_HANDLED (with the reason) for what CGAL's reader must read instead; throws
// Fast_off_error for definite errors of the file.
//
// The file is read in blocks of `block_bytes` (one buffer, used again: no fresh memory per block), each cut
// after its last newline and parsed by parse_lines() on `threads` threads (0: OpenMP's default). The blocks are
// large (16 MB: 3 for a 423K-vertex mesh) because each is two parallel regions, and on a busy machine each
// region may wait for a descheduled thread (with 4 MB blocks, the parse on 2 threads was slower than on one). Of the problems
// found, the one of the first line counts, as if the file were parsed line after line: the outcome (the mesh,
// the reason or the error) does not depend on the number of threads, the ranges or the blocks. A header after
// more than a block of comments, or a line longer than a block, is left to CGAL's reader.
template <class Resize, class Set_point>
Fast_off_result parse_off_triangles(const std::string& file, const Resize& resize, const Set_point& set_point,
                                    std::vector<Triangle>& triangles, int threads = 1,
                                    std::size_t range_bytes = std::size_t(1) << 20,
                                    std::size_t block_bytes = std::size_t(1) << 24)
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point t0 = Clock::now();
  Fast_off_result result;
  auto not_handled = [&](const std::string& why) {
    result.status = Fast_off_result::NOT_HANDLED;
    result.reason = why;
    return result;
  };
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if(f == nullptr)
    throw Fast_off_error(std::string("cannot open the file: ") + std::strerror(errno));
  struct Closer
  {
    std::FILE* f;
    ~Closer() { std::fclose(f); }
  } closer{ f };
  std::vector<char> buffer((std::max)(std::size_t(16), block_bytes));
  std::size_t have = 0;
  bool eof = false, read_error = false;
  auto fill = [&]() {
    while(!eof && have < buffer.size())
    {
      const std::size_t n = std::fread(buffer.data() + have, 1, buffer.size() - have, f);
      have += n;
      if(n == 0)
      {
        eof = true;
        read_error = std::ferror(f) != 0;
      }
    }
  };
  fill();
  const char* p = buffer.data();
  const char* end = buffer.data() + have;

  // Header: "OFF", then the numbers of vertices, faces and edges.
  next_content_line(p, end);
  if(end - p < 3 || std::memcmp(p, "OFF", 3) != 0 || (end - p > 3 && !is_blank(p[3]) && p[3] != '\n'))
    return not_handled("not a plain OFF header");
  p += 3;
  std::uint64_t counts[3];
  for(int k = 0; k < 3; ++k)
  {
    skip_blanks(p, end);
    if(p == end || *p == '\n' || *p == '#')
    {
      end_of_line(p, end);
      next_content_line(p, end);
    }
    if(!parse_index(p, end, counts[k]))
      return not_handled("unexpected header");
  }
  if(!end_of_line(p, end) || (p == end && !eof))
    return not_handled("unexpected header");
  const std::uint64_t nv = counts[0], nf = counts[1];
  if(nv >= (std::uint64_t(1) << 31) || nf >= (std::uint64_t(1) << 31) / 3)
    return not_handled("too large for 32-bit indices");
  if(nv == 0)
    throw Fast_off_error("the mesh has no vertices");
#ifdef _OPENMP
  if(threads <= 0)
    threads = omp_get_max_threads();
#endif
  threads = (std::max)(1, threads);

  resize(static_cast<std::size_t>(nv));
  triangles.resize(static_cast<std::size_t>(nf));
  std::uint64_t line = 0;
  std::vector<Line_range> ranges;
  std::size_t consumed = static_cast<std::size_t>(p - buffer.data());
  for(;;)
  {
    if(consumed > 0)
    {
      std::memmove(buffer.data(), buffer.data() + consumed, have - consumed);
      have -= consumed;
      consumed = 0;
    }
    fill();
    const char* stop = buffer.data() + have;
    if(!eof)
    {
      while(stop != buffer.data() && stop[-1] != '\n')
        --stop;
      if(stop == buffer.data())
        return not_handled("a line is longer than " + std::to_string(buffer.size()) + " bytes");
    }
    if(const Line_range* problem = parse_lines(buffer.data(), stop, line, nv, nf, set_point, triangles, threads,
                                               range_bytes, ranges))
    {
      if(problem->error)
        throw Fast_off_error(problem->problem);
      return not_handled(problem->problem);
    }
    consumed = static_cast<std::size_t>(stop - buffer.data());
    if((eof && consumed == have) || line >= nv + nf)
      break;
  }
  if(line < nv)
    throw Fast_off_error("the file ends after " + std::to_string(line) + " of " + std::to_string(nv) + " vertices");
  if(line < nv + nf)
    throw Fast_off_error("the file ends after " + std::to_string(line - nv) + " of " + std::to_string(nf) + " faces");
  if(read_error)
    throw Fast_off_error("read error");
  if(nf == 0)
    throw Fast_off_error("the mesh has no faces");
  result.status = Fast_off_result::MESH;
  result.read_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return result;
}

} // namespace fast_off_detail

// Reads `file` into `mesh` (cleared first) if it is a plain ASCII OFF file of a valid triangle mesh (see the
// top of this file), the halfedge structure built by `threads` threads (see build_triangle_mesh()). On
// NOT_HANDLED, `mesh` must be cleared by the caller.
template <class Point>
Fast_off_result read_off_triangle_mesh(const std::string& file, CGAL::Surface_mesh<Point>& mesh, int threads = 1)
{
  using namespace fast_off_detail;
  typedef std::chrono::steady_clock Clock;
  mesh.clear();
  std::vector<Triangle> triangles;
  typedef typename CGAL::Surface_mesh<Point>::size_type size_type;
  typename CGAL::Surface_mesh<Point>::template Property_map<typename CGAL::Surface_mesh<Point>::Vertex_index, Point>
    points;
  Fast_off_result result = parse_off_triangles(
    file,
    [&](std::size_t nv) {
      mesh.resize(static_cast<size_type>(nv), 0, 0);
      points = mesh.points();
    },
    [&points](std::size_t i, double x, double y, double z) {
      points[typename CGAL::Surface_mesh<Point>::Vertex_index(static_cast<size_type>(i))] = Point(x, y, z);
    },
    triangles, threads);
  if(result.status != Fast_off_result::MESH)
    return result;
  const Clock::time_point t1 = Clock::now();
  if(!build_triangle_mesh(triangles, mesh, result.reason, threads))
  {
    result.status = Fast_off_result::NOT_HANDLED;
    return result;
  }
  result.build_seconds = std::chrono::duration<double>(Clock::now() - t1).count();
  return result;
}

// Reads `file` into `xyz` (3 coordinates per vertex) and `triangles` if it is a plain ASCII OFF file of a valid
// triangle mesh (see the top of this file): the same vertices and faces as read_off_triangle_mesh() (and
// read_input_mesh()), without building the halfedge structure (the mesh is only checked, by `threads` threads).
// build_seconds is the time of the check. `tables`, if given, receives the tables of the check (for
// build_triangle_mesh() on the same triangles, which then does not check them again).
inline Fast_off_result read_off_triangle_soup(const std::string& file, std::vector<double>& xyz,
                                              std::vector<fast_off_detail::Triangle>& triangles, int threads = 1,
                                              fast_off_detail::Corner_tables* tables = nullptr)
{
  using namespace fast_off_detail;
  typedef std::chrono::steady_clock Clock;
  xyz.clear();
  Fast_off_result result = parse_off_triangles(
    file, [&xyz](std::size_t nv) { xyz.resize(3 * nv); },
    [&xyz](std::size_t i, double x, double y, double z) {
      xyz[3 * i] = x;
      xyz[3 * i + 1] = y;
      xyz[3 * i + 2] = z;
    },
    triangles, threads);
  if(result.status != Fast_off_result::MESH)
    return result;
  const Clock::time_point t1 = Clock::now();
  if(!check_triangle_mesh(triangles, xyz.size() / 3, result.reason, threads, tables))
  {
    result.status = Fast_off_result::NOT_HANDLED;
    return result;
  }
  result.build_seconds = std::chrono::duration<double>(Clock::now() - t1).count();
  return result;
}

} // namespace vtp_support

#endif // VTP_SUPPORT_FAST_OFF_READER_H
