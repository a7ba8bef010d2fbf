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

// A fast path from a plain ASCII OFF file that is a valid triangle mesh to a `Surface_mesh`: the file is parsed in
// chunks with std::from_chars, checked to be a valid mesh with the same rules as
// `CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()` (no face with a repeated vertex, no directed
// edge twice, every vertex a single fan of faces), and its halfedge structure is built directly from sorted
// per-vertex lists instead of through a polygon soup.
//
// Anything the fast path does not handle (another OFF flavour, polygons, an invalid mesh, unusual
// formatting) is left to CGAL's reader and repair: `read_off_triangle_mesh()` then returns NOT_HANDLED. Definite
// errors of the file (too few lines, non-finite coordinates, indices out of range) throw `Fast_off_error`.

#include <vtp_support/build_triangle_mesh.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
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

// Reads a file in chunks; a line is always entirely in the buffer when it is parsed (lines longer than
// `max_line` are not handled).
class Chunk_reader
{
public:
  static constexpr std::size_t max_line = 1 << 16;

  explicit Chunk_reader(std::FILE* f) : m_file(f), m_buffer(std::size_t(1) << 22)
  {
    m_p = m_end = m_buffer.data();
  }

  // Makes sure that the rest of the current line is in the buffer, unless the file ends first.
  void refill_if_needed()
  {
    if(m_eof || static_cast<std::size_t>(m_end - m_p) >= max_line)
      return;
    char* const first = m_buffer.data();
    char* const last = first + m_buffer.size();
    const std::size_t rest = static_cast<std::size_t>(m_end - m_p);
    if(rest > 0)
      std::memmove(first, m_p, rest);
    m_p = first;
    char* end = first + rest;
    while(!m_eof && end < last)
    {
      const std::size_t n = std::fread(end, 1, static_cast<std::size_t>(last - end), m_file);
      end += n;
      if(n == 0)
      {
        m_eof = true;
        m_error = std::ferror(m_file) != 0;
      }
    }
    m_end = end;
  }

  const char*& p() { return m_p; }
  const char* end() const { return m_end; }
  bool at_end() const { return m_p == m_end && m_eof; }
  bool error() const { return m_error; }

private:
  std::FILE* m_file;
  std::vector<char> m_buffer;
  const char* m_p;
  const char* m_end;
  bool m_eof = false, m_error = false;
};

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Skips blanks on the current line (not the newline).
inline void skip_blanks(const char*& p, const char* end)
{
  while(p != end && is_blank(*p))
    ++p;
}

// True if only blanks and an optional comment are left on the line; moves past its newline.
inline bool end_of_line(const char*& p, const char* end)
{
  skip_blanks(p, end);
  if(p != end && *p == '#')
    while(p != end && *p != '\n')
      ++p;
  if(p == end)
    return true;
  if(*p != '\n')
    return false;
  ++p;
  return true;
}

// Moves to the start of the next line with content (skipping empty lines and comment lines).
inline void next_content_line(Chunk_reader& r)
{
  for(;;)
  {
    r.refill_if_needed();
    const char*& p = r.p();
    skip_blanks(p, r.end());
    if(p == r.end())
    {
      if(r.at_end())
        return;
      continue;
    }
    if(*p == '\n')
    {
      ++p;
      continue;
    }
    if(*p == '#')
    {
      while(p != r.end() && *p != '\n')
        ++p;
      continue;
    }
    return;
  }
}

enum Number_status { NUMBER_OK, NUMBER_MISSING, NUMBER_OUT_OF_RANGE };

inline Number_status parse_double(const char*& p, const char* end, double& x)
{
  skip_blanks(p, end);
  if(p == end || *p == '\n' || *p == '#' || *p == '+')
    return NUMBER_MISSING;
  const std::from_chars_result r = std::from_chars(p, end, x);
  if(r.ec == std::errc::result_out_of_range)
  {
    // overflow (a non-finite value) or underflow (a tiny value, kept as strtod rounds it)
    const std::string token(p, r.ptr);
    x = std::strtod(token.c_str(), nullptr);
    p = r.ptr;
    return std::isinf(x) ? NUMBER_OUT_OF_RANGE : NUMBER_OK;
  }
  if(r.ec != std::errc() || (r.ptr != end && !is_blank(*r.ptr) && *r.ptr != '\n' && *r.ptr != '#'))
    return NUMBER_MISSING;
  p = r.ptr;
  return NUMBER_OK;
}

inline bool parse_index(const char*& p, const char* end, std::uint64_t& i)
{
  skip_blanks(p, end);
  if(p == end || *p < '0' || *p > '9')
    return false;
  const std::from_chars_result r = std::from_chars(p, end, i);
  if(r.ec != std::errc() || (r.ptr != end && !is_blank(*r.ptr) && *r.ptr != '\n' && *r.ptr != '#'))
    return false;
  p = r.ptr;
  return true;
}

} // namespace fast_off_detail

namespace fast_off_detail {

// Parses `file` if it is a plain ASCII OFF file of triangles: reserve(nv) once the header is read, then
// add_point(x, y, z) for each vertex in order, and the triangles into `triangles`. Returns NOT_HANDLED (with the
// reason) for what CGAL's reader must read instead; throws Fast_off_error for definite errors of the file.
template <class Reserve, class Add_point>
Fast_off_result parse_off_triangles(const std::string& file, const Reserve& reserve, const Add_point& add_point,
                                    std::vector<Triangle>& triangles)
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point t0 = Clock::now();
  Fast_off_result result;
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if(f == nullptr)
    throw Fast_off_error(std::string("cannot open the file: ") + std::strerror(errno));
  struct Closer
  {
    std::FILE* f;
    ~Closer() { std::fclose(f); }
  } closer{ f };
  Chunk_reader r(f);
  auto not_handled = [&](const std::string& why) {
    result.status = Fast_off_result::NOT_HANDLED;
    result.reason = why;
    return result;
  };

  // Header: "OFF", then the numbers of vertices, faces and edges.
  next_content_line(r);
  const char*& p = r.p();
  if(r.end() - p < 3 || std::memcmp(p, "OFF", 3) != 0 || (r.end() - p > 3 && !is_blank(p[3]) && p[3] != '\n'))
    return not_handled("not a plain OFF header");
  p += 3;
  std::uint64_t counts[3];
  for(int k = 0; k < 3; ++k)
  {
    skip_blanks(p, r.end());
    if(p == r.end() || *p == '\n' || *p == '#')
    {
      end_of_line(p, r.end());
      next_content_line(r);
    }
    if(!parse_index(p, r.end(), counts[k]))
      return not_handled("unexpected header");
  }
  if(!end_of_line(p, r.end()))
    return not_handled("unexpected header");
  const std::uint64_t nv = counts[0], nf = counts[1];
  if(nv >= (std::uint64_t(1) << 31) || nf >= (std::uint64_t(1) << 31) / 3)
    return not_handled("too large for 32-bit indices");
  if(nv == 0)
    throw Fast_off_error("the mesh has no vertices");

  reserve(static_cast<std::size_t>(nv));
  for(std::uint64_t i = 0; i < nv; ++i)
  {
    next_content_line(r);
    if(r.at_end())
      throw Fast_off_error("the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    double x[3];
    for(int k = 0; k < 3; ++k)
    {
      const Number_status s = parse_double(p, r.end(), x[k]);
      if(s == NUMBER_MISSING)
        return not_handled("unexpected vertex line");
      if(s == NUMBER_OUT_OF_RANGE || !std::isfinite(x[k]))
        throw Fast_off_error("vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
    if((p == r.end() && !r.at_end()) || !end_of_line(p, r.end()))
      return not_handled("unexpected vertex line");
    add_point(x[0], x[1], x[2]);
  }

  triangles.resize(static_cast<std::size_t>(nf));
  for(std::uint64_t i = 0; i < nf; ++i)
  {
    next_content_line(r);
    if(r.at_end())
      throw Fast_off_error("the file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
    std::uint64_t k = 0, id = 0;
    if(!parse_index(p, r.end(), k))
      return not_handled("unexpected face line");
    if(k != 3)
      return not_handled("a face is not a triangle");
    for(int j = 0; j < 3; ++j)
    {
      if(!parse_index(p, r.end(), id))
        return not_handled("unexpected face line");
      if(id >= nv)
        throw Fast_off_error("face " + std::to_string(i) + " refers to vertex " + std::to_string(id)
                             + ", out of range (there are " + std::to_string(nv) + " vertices)");
      triangles[i][j] = static_cast<std::uint32_t>(id);
    }
    if(p == r.end() && !r.at_end())
      return not_handled("unexpected face line");
    // The rest of a face line (e.g. a colour) is ignored, as CGAL's reader does.
    while(p != r.end() && *p != '\n')
      ++p;
  }
  if(r.error())
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
  Fast_off_result result = parse_off_triangles(
    file, [&mesh](std::size_t nv) { mesh.reserve(static_cast<typename CGAL::Surface_mesh<Point>::size_type>(nv), 0, 0); },
    [&mesh](double x, double y, double z) { mesh.add_vertex(Point(x, y, z)); }, triangles);
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
// build_seconds is the time of the check.
inline Fast_off_result read_off_triangle_soup(const std::string& file, std::vector<double>& xyz,
                                              std::vector<fast_off_detail::Triangle>& triangles, int threads = 1)
{
  using namespace fast_off_detail;
  typedef std::chrono::steady_clock Clock;
  xyz.clear();
  Fast_off_result result = parse_off_triangles(
    file, [&xyz](std::size_t nv) { xyz.reserve(3 * nv); },
    [&xyz](double x, double y, double z) {
      xyz.push_back(x);
      xyz.push_back(y);
      xyz.push_back(z);
    },
    triangles);
  if(result.status != Fast_off_result::MESH)
    return result;
  const Clock::time_point t1 = Clock::now();
  if(!check_triangle_mesh(triangles, xyz.size() / 3, result.reason, threads))
  {
    result.status = Fast_off_result::NOT_HANDLED;
    return result;
  }
  result.build_seconds = std::chrono::duration<double>(Clock::now() - t1).count();
  return result;
}

} // namespace vtp_support

#endif // VTP_SUPPORT_FAST_OFF_READER_H
