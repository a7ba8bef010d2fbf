// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_BUILD_TRIANGLE_MESH_H
#define VTP_SUPPORT_BUILD_TRIANGLE_MESH_H

// The halfedge structure of a `Surface_mesh` built directly from a list of triangles (vertex indices), after
// checking that they form a valid mesh with the same rules as
// `CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()` (no face with a repeated vertex, no directed
// edge twice, every vertex a single fan of faces): the last step of the fast OFF reader (fast_off_reader.h), also
// used on triangles that are already in memory (the reading of other formats, the Python module).

#include <CGAL/Surface_mesh.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace vtp_support {

namespace fast_off_detail {

typedef std::array<std::uint32_t, 3> Triangle;

// What the check of the triangles finds, and the building of the halfedge structure uses: per corner 3f+k
// (the halfedge t[k] -> t[k+1] of face f) its opposite corner, and per vertex the corner ending at it in its last
// face (`none` for a vertex without face).
struct Corner_tables
{
  std::vector<std::uint32_t> opposite, last_in;
};

// Checks that the triangles (vertex indices below n) form a valid mesh: no face with a repeated vertex, no
// directed edge twice, every vertex a single fan of faces (the rules of
// CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()). Returns false, with the reason, if not;
// fills `tables` (if given) if so.
//
// The outgoing corners of each vertex are listed (as 64-bit keys target << 32 | corner, so that the searches read
// contiguous memory; long lists sorted by target); the opposite of every corner is found once, and the fans follow
// from the array of opposites. The loops over vertices that write only their own entries run on `threads`
// OpenMP threads (0: OpenMP's default), in chunks taken as they come (a thread that the system has descheduled holds
// back only its chunk); the result does not depend on their number.
inline bool check_triangle_mesh(const std::vector<Triangle>& triangles, std::size_t n, std::string& reason,
                                int threads = 1, Corner_tables* tables = nullptr)
{
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  const std::uint32_t nc = static_cast<std::uint32_t>(3 * triangles.size());
  const long long nl = static_cast<long long>(n);
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
  // The lists of most vertices are short (6 corners on average): they are searched as they are, in the order of
  // their corners; only those longer than `short_list` are sorted by target (then searched by bisection).
  const std::uint32_t short_list = 16;
  bool repeated_edge = false;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads) if(threads > 1) reduction(|| : repeated_edge)
#endif
  for(long long vl = 0; vl < nl; ++vl)
  {
    const std::size_t v = static_cast<std::size_t>(vl);
    std::uint64_t* first = out.data() + begin[v];
    std::uint64_t* last = out.data() + begin[v + 1];
    if(last - first > std::ptrdiff_t(short_list))
    {
      std::sort(first, last);
      for(std::uint64_t* k = first; k + 1 < last; ++k)
        repeated_edge = repeated_edge || (k[0] >> 32) == (k[1] >> 32);
    }
    else
      for(std::uint64_t* k = first; k < last; ++k)
        for(std::uint64_t* j = first; j < k; ++j)
          repeated_edge = repeated_edge || (k[0] >> 32) == (j[0] >> 32);
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
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads) if(threads > 1)
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
      const std::uint64_t* first = out.data() + begin[b];
      const std::uint64_t* last = out.data() + begin[b + 1];
      const std::uint64_t* it = first;
      if(last - first > std::ptrdiff_t(short_list))
        it = std::lower_bound(first, last, std::uint64_t(a) << 32);
      else
        while(it != last && (*it >> 32) != a)
          ++it;
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
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads) if(threads > 1) reduction(&& : manifold)
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
  if(tables != nullptr)
  {
    tables->opposite = std::move(opposite);
    tables->last_in = std::move(last_in);
  }
  return true;
}

// Checks that the triangles form a valid mesh (check_triangle_mesh()) and builds its halfedge structure in
// `mesh`, whose vertices are already there. Returns false (and leaves `mesh` to be cleared) if the triangles are
// not a valid mesh. `checked`, if given, holds the tables of an earlier check of the same triangles and the same
// number of vertices (check_triangle_mesh() returned true): the check is not done again, and the tables are
// consumed (moved from).
//
// The loops over corners, faces and vertices that write only their own entries run on `threads` OpenMP threads
// (0: OpenMP's default); the mesh built does not depend on their number (it is the one that adding the edges in
// the order of their first corner, then the faces in order, would give).
template <class Point>
bool build_triangle_mesh(const std::vector<Triangle>& triangles, CGAL::Surface_mesh<Point>& mesh,
                         std::string& reason, int threads = 1, Corner_tables* checked = nullptr)
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
#endif
  threads = (std::max)(1, threads);
  Corner_tables tables;
  if(checked != nullptr)
  {
    CGAL_precondition(checked->opposite.size() == nc && checked->last_in.size() == n);
    tables = std::move(*checked);
  }
  else if(!check_triangle_mesh(triangles, n, reason, threads, &tables))
    return false;
  std::vector<std::uint32_t>& opposite = tables.opposite;
  const std::vector<std::uint32_t>& last_in = tables.last_in;
  auto source_of = [&](std::uint32_t c) { return triangles[c / 3][c % 3]; };
  auto target_of = [&](std::uint32_t c) { return triangles[c / 3][(c % 3 + 1) % 3]; };


  // Edges: one per pair of opposite corners (made by the first of the two) and per corner without opposite (then
  // its other halfedge is a border halfedge); edge e is the halfedges 2e (along its first corner) and 2e + 1.
  std::vector<std::uint32_t> halfedge_of(nc);
  std::uint32_t ne = 0;
  for(std::uint32_t c = 0; c < nc; ++c)
    if(opposite[c] == none || c < opposite[c])
      halfedge_of[c] = 2 * ne++;
  mesh.resize(static_cast<size_type>(n), static_cast<size_type>(ne), static_cast<size_type>(triangles.size()));
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads) if(threads > 1)
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
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads) if(threads > 1)
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
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads) if(threads > 1)
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
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads) if(threads > 1)
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

} // namespace vtp_support

#endif // VTP_SUPPORT_BUILD_TRIANGLE_MESH_H
