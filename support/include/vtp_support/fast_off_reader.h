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

#ifdef _OPENMP
#include <omp.h>
#endif

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

typedef std::array<std::uint32_t, 3> Triangle;

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

// Checks that the triangles form a valid mesh and builds its halfedge structure in `mesh`, whose vertices are
// already there. Returns false (and leaves `mesh` to be cleared) if the triangles are not a valid mesh.
//
// Corner 3f+k is the halfedge t[k] -> t[k+1] of face f. The outgoing corners of each vertex are sorted by target
// (as 64-bit keys target << 32 | corner, so that the sort and the searches read contiguous memory); the opposite
// of every corner is found once, and everything else follows from the array of opposites.
//
// The loops over vertices, corners and faces that write only their own entries run on `threads` OpenMP threads
// (0: OpenMP's default); the mesh built does not depend on their number (it is the one that adding the edges in the order of their first
// corner, then the faces in order, would give).
template <class Point>
bool build_triangle_mesh(const std::vector<Triangle>& triangles, CGAL::Surface_mesh<Point>& mesh,
                         std::string& reason, int threads = 1)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Face_index Face_index;
  typedef typename Mesh::size_type size_type;
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  const std::size_t n = mesh.number_of_vertices();
  const std::uint32_t nc = static_cast<std::uint32_t>(3 * triangles.size());
  const long long nl = static_cast<long long>(n), ncl = static_cast<long long>(nc);
  const long long nfl = static_cast<long long>(triangles.size());
#ifdef _OPENMP
  if(threads <= 0)
    threads = omp_get_max_threads();
#else
  (void)threads;
#endif
  threads = (std::max)(1, threads);

  auto source_of = [&](std::uint32_t c) { return triangles[c / 3][c % 3]; };
  auto target_of = [&](std::uint32_t c) { return triangles[c / 3][(c % 3 + 1) % 3]; };
  auto previous = [](std::uint32_t c) { return c - c % 3 + (c % 3 + 2) % 3; }; // the corner ending at source_of(c)

  std::vector<std::uint32_t> begin(n + 1, 0);
  for(const Triangle& t : triangles)
  {
    if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
    {
      reason = "a face has a repeated vertex";
      return false;
    }
    for(std::uint32_t v : t)
      ++begin[v + 1];
  }
  for(std::size_t v = 0; v < n; ++v)
    begin[v + 1] += begin[v];
  std::vector<std::uint64_t> out(nc);
  {
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for(std::uint32_t c = 0; c < nc; ++c)
      out[fill[source_of(c)]++] = (std::uint64_t(target_of(c)) << 32) | c;
  }
  bool repeated_edge = false;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1) reduction(|| : repeated_edge)
#endif
  for(long long vl = 0; vl < nl; ++vl)
  {
    const std::size_t v = static_cast<std::size_t>(vl);
    std::uint64_t* first = out.data() + begin[v];
    std::uint64_t* last = out.data() + begin[v + 1];
    std::sort(first, last);
    for(std::uint64_t* k = first; k + 1 < last; ++k)
      repeated_edge = repeated_edge || (k[0] >> 32) == (k[1] >> 32);
  }
  if(repeated_edge)
  {
    reason = "two faces have the same oriented edge";
    return false;
  }

  // opposite[c]: the corner target_of(c) -> source_of(c), or `none` (then the other side is a border). The pair
  // of a -> b and b -> a is found from the smaller vertex a, which writes both entries: no entry is written twice.
  std::vector<std::uint32_t> opposite(nc, none);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1)
#endif
  for(long long al = 0; al < nl; ++al)
  {
    const std::uint32_t a = static_cast<std::uint32_t>(al);
    for(std::uint32_t k = begin[a]; k < begin[a + 1]; ++k)
    {
      const std::uint32_t c = static_cast<std::uint32_t>(out[k]);
      const std::uint32_t b = static_cast<std::uint32_t>(out[k] >> 32);
      if(b < a)
        continue;
      const std::uint64_t key = std::uint64_t(a) << 32;
      const std::uint64_t* first = out.data() + begin[b];
      const std::uint64_t* last = out.data() + begin[b + 1];
      const std::uint64_t* it = std::lower_bound(first, last, key);
      if(it != last && (*it >> 32) == a)
      {
        opposite[c] = static_cast<std::uint32_t>(*it);
        opposite[static_cast<std::uint32_t>(*it)] = c;
      }
    }
  }

  // Every vertex must be a single fan: around v, the corner after v -> b is the opposite of the corner that ends
  // at v in the face of v -> b. Exactly one chain (border vertex) or one cycle (interior vertex).
  // last_in[v]: the corner that ends at v in the last face of v (its halfedge becomes the halfedge of v).
  std::vector<std::uint32_t> last_in(n, none);
  bool manifold = true;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1) reduction(&& : manifold)
#endif
  for(long long vl = 0; vl < nl; ++vl)
  {
    const std::uint32_t v = static_cast<std::uint32_t>(vl);
    const std::uint32_t d = begin[v + 1] - begin[v];
    if(d == 0)
      continue;
    std::uint32_t start = static_cast<std::uint32_t>(out[begin[v]]), starts = 0, last_out = 0;
    for(std::uint32_t k = begin[v]; k < begin[v + 1]; ++k)
    {
      const std::uint32_t c = static_cast<std::uint32_t>(out[k]);
      last_out = (std::max)(last_out, c);
      if(opposite[c] == none) // nothing before c around v
      {
        start = c;
        ++starts;
      }
    }
    last_in[v] = previous(last_out);
    std::uint32_t steps = 1;
    if(starts <= 1)
      for(std::uint32_t c = opposite[previous(start)]; c != none && c != start; c = opposite[previous(c)])
        if(++steps > d)
          break;
    manifold = manifold && starts <= 1 && steps == d;
  }
  if(!manifold)
  {
    reason = "a vertex is not manifold";
    return false;
  }
  std::vector<std::uint64_t>().swap(out);
  std::vector<std::uint32_t>().swap(begin);

  // Edges: one per pair of opposite corners (made by the first of the two) and per corner without opposite (then
  // its other halfedge is a border halfedge); edge e is the halfedges 2e (along its first corner) and 2e + 1.
  std::vector<std::uint32_t> halfedge_of(nc);
  std::uint32_t ne = 0;
  for(std::uint32_t c = 0; c < nc; ++c)
    if(opposite[c] == none || c < opposite[c])
      halfedge_of[c] = 2 * ne++;
  mesh.resize(static_cast<size_type>(n), static_cast<size_type>(ne), static_cast<size_type>(triangles.size()));
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1)
#endif
  for(long long cl = 0; cl < ncl; ++cl)
  {
    const std::uint32_t c = static_cast<std::uint32_t>(cl);
    if(opposite[c] == none || c < opposite[c])
    {
      const Halfedge_index h(halfedge_of[c]);
      mesh.set_target(h, Vertex_index(target_of(c)));
      mesh.set_target(mesh.opposite(h), Vertex_index(source_of(c)));
    }
  }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1)
#endif
  for(long long cl = 0; cl < ncl; ++cl)
  {
    const std::uint32_t c = static_cast<std::uint32_t>(cl);
    if(opposite[c] != none && c > opposite[c])
      halfedge_of[c] = halfedge_of[opposite[c]] + 1;
  }
  // border_in[v], border_out[v]: the border halfedges into and out of v (at most one each on a single fan)
  std::vector<std::uint32_t> border_in(n, none), border_out(n, none);
  for(std::uint32_t c = 0; c < nc; ++c)
    if(opposite[c] == none)
    {
      const std::uint32_t border = halfedge_of[c] + 1; // target_of(c) -> source_of(c), no face
      border_out[target_of(c)] = border;
      border_in[source_of(c)] = border;
    }
  std::vector<std::uint32_t>().swap(opposite);

  // Faces: each writes its own three halfedges.
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1)
#endif
  for(long long fl = 0; fl < nfl; ++fl)
  {
    const std::size_t f = static_cast<std::size_t>(fl);
    const Face_index fi(static_cast<size_type>(f));
    const Halfedge_index h0(halfedge_of[3 * f]), h1(halfedge_of[3 * f + 1]), h2(halfedge_of[3 * f + 2]);
    mesh.set_face(h0, fi);
    mesh.set_face(h1, fi);
    mesh.set_face(h2, fi);
    mesh.set_next(h0, h1);
    mesh.set_next(h1, h2);
    mesh.set_next(h2, h0);
    mesh.set_halfedge(fi, h0);
  }
  // Vertices: a border vertex's halfedge is its incoming border halfedge, followed by the outgoing one; an
  // interior vertex's is its halfedge in its last face.
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1)
#endif
  for(long long vl = 0; vl < nl; ++vl)
  {
    const std::uint32_t v = static_cast<std::uint32_t>(vl);
    if(border_in[v] != none)
    {
      mesh.set_next(Halfedge_index(border_in[v]), Halfedge_index(border_out[v]));
      mesh.set_halfedge(Vertex_index(v), Halfedge_index(border_in[v]));
    }
    else if(last_in[v] != none)
      mesh.set_halfedge(Vertex_index(v), Halfedge_index(halfedge_of[last_in[v]]));
  }
  return true;
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
  const Clock::time_point t0 = Clock::now();
  Fast_off_result result;
  mesh.clear();

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

  mesh.reserve(static_cast<typename CGAL::Surface_mesh<Point>::size_type>(nv), 0, 0);
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
    mesh.add_vertex(Point(x[0], x[1], x[2]));
  }

  std::vector<Triangle> triangles(static_cast<std::size_t>(nf));
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
  const Clock::time_point t1 = Clock::now();
  result.read_seconds = std::chrono::duration<double>(t1 - t0).count();

  std::string reason;
  if(!build_triangle_mesh(triangles, mesh, reason, threads))
    return not_handled(reason);
  result.status = Fast_off_result::MESH;
  result.build_seconds = std::chrono::duration<double>(Clock::now() - t1).count();
  return result;
}

} // namespace vtp_support

#endif // VTP_SUPPORT_FAST_OFF_READER_H
