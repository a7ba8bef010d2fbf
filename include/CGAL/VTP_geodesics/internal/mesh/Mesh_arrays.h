// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the VTP_geodesics package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_ARRAYS_H
#define CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_ARRAYS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

typedef std::int32_t Index;
const Index NO_INDEX = -1;

// Local geometry of the face of a half-edge h = (A -> B), in the frame where A = (0,0),
// B = (length, 0) and the third vertex C of face(h) lies at (cx, cy), cy >= 0.
struct Halfedge_geometry
{
  double length;  // |AB|
  double cx, cy;  // C in the frame of h
  double l_next;  // |BC|
  double l_prev;  // |CA|
};

// The lengths and the area of a face: enough to place each of its half-edges (Halfedge_geometry).
struct Face_geometry
{
  double length[3];  // of the half-edges 3f, 3f+1, 3f+2
  double area;       // a negative value: unknown (Mesh_arrays::build() computes it from the lengths)
};

// The geometry of the half-edges, kept per face (32 bytes per face instead of 40 per half-edge) and
// computed when asked: geometry[h].
class Halfedge_geometry_table
{
public:
  std::vector<Face_geometry> faces;

  Halfedge_geometry operator[](Index h) const
  {
    CGAL_assertion(h >= 0);
    const std::uint32_t u = static_cast<std::uint32_t>(h);  // (unsigned: cheaper divisions by 3)
    const Face_geometry& f = faces[u / 3u];
    const int k = static_cast<int>(u % 3u);
    Halfedge_geometry g;
    g.length = f.length[k];
    g.l_next = f.length[k == 2 ? 0 : k + 1];  // |BC|
    g.l_prev = f.length[k == 0 ? 2 : k - 1];  // |CA|
    const double l = g.length, la = g.l_prev, lb = g.l_next;
    if(l > 0.)
    {
      g.cx = (l * l + la * la - lb * lb) / (2. * l);
      // the height from the area: sqrt(la^2 - cx^2) loses accuracy for needle triangles
      g.cy = 2. * f.area / l;
    }
    else
    {
      g.cx = 0.;
      g.cy = la;
    }
    return g;
  }

  std::size_t size() const { return 3 * faces.size(); }
};

// Compact, index-based description of a triangle mesh, built once per mesh.
// The half-edges of face f are 3f, 3f+1, 3f+2 (in the order of `next`), so that
// next/prev/face are index arithmetic; only `opposite` and the vertices are stored.
// About 150 bytes per vertex (a closed mesh has 2 faces and 6 half-edges per vertex).
struct Mesh_arrays
{
  Index nv = 0;
  Index nf = 0;
  std::vector<Index> source;     // per half-edge: its source vertex A
  std::vector<Index> opposite;   // per half-edge: opposite half-edge, NO_INDEX on the border
  Halfedge_geometry_table geometry;  // geometry[h]
  // Per vertex, the half-edges whose source is the vertex (one per incident face), CSR.
  std::vector<Index> corner_begin;
  std::vector<Index> corners;
  std::vector<unsigned char> is_pseudo_source; // saddle or boundary vertex
  // per face: (almost) zero area or a zero-length edge (see build())
  std::vector<unsigned char> is_degenerate_face;
  double mean_edge_length = 0.;
  double min_edge_length = 0.;
  double max_edge_length = 0.;
  double anisotropy = 1.;         // tau, see compute_anisotropy()
  std::size_t number_of_edges = 0;

  // (h is a half-edge, not NO_INDEX: unsigned arithmetic divides by 3 in fewer instructions)
  static Index next(Index h)
  {
    CGAL_assertion(h >= 0);
    return (static_cast<std::uint32_t>(h) % 3u == 2u) ? h - 2 : h + 1;
  }
  static Index prev(Index h)
  {
    CGAL_assertion(h >= 0);
    return (static_cast<std::uint32_t>(h) % 3u == 0u) ? h + 2 : h - 1;
  }
  static Index face(Index h)
  {
    CGAL_assertion(h >= 0);
    return static_cast<Index>(static_cast<std::uint32_t>(h) / 3u);
  }
  Index target(Index h) const { return source[next(h)]; }

  // Builds the arrays from triangles (3 vertex indices each, counterclockwise), the opposite of
  // each half-edge (NO_INDEX on the border) and the lengths and, where known, the area of each
  // face. A face's height is taken from its area: from the lengths alone, a nearly flat
  // triangle's height is only accurate to about sqrt(epsilon) times its size. The angle sums are
  // computed by `threads` OpenMP threads; the result does not depend on their number.
  void build(Index number_of_vertices,
             std::vector<Index>&& triangle_vertices,
             std::vector<Index>&& opposite_halfedges,
             std::vector<Face_geometry>&& faces,
             int threads = 1)
  {
    nv = number_of_vertices;
    source = std::move(triangle_vertices);
    opposite = std::move(opposite_halfedges);
    geometry.faces = std::move(faces);
    const Index nh = static_cast<Index>(source.size());
    CGAL_precondition(nh % 3 == 0);
    CGAL_precondition(opposite.size() == source.size());
    CGAL_precondition(3 * geometry.faces.size() == source.size());
    nf = nh / 3;
    for(Face_geometry& f : geometry.faces)
      if(!(f.area >= 0.))
        f.area = triangle_area(f.length[0], f.length[1], f.length[2]);  // Kahan's stable Heron formula

    // corners per vertex
    corner_begin.assign(nv + 1, 0);
    for(Index h = 0; h < nh; ++h)
      ++corner_begin[source[h] + 1];
    for(Index v = 0; v < nv; ++v)
      corner_begin[v + 1] += corner_begin[v];
    corners.resize(nh);
    {
      std::vector<Index> fill(corner_begin.begin(), corner_begin.end() - 1);
      for(Index h = 0; h < nh; ++h)
        corners[fill[source[h]]++] = h;
    }

    // Saddle flags: the corner angles (one acos each) are computed by the threads and summed per vertex
    // in the order of the half-edges, so that the sums do not depend on the number of threads.
    is_pseudo_source.assign(nv, 0);
    {
      std::vector<double> angle_sum(nv, 0.);
      computed_in_parallel_added_in_order(
        nh, threads,
        [this](Index h) {
          // corner angle at source(h) between h (A->B) and the reversed prev(h) (A->C)
          const Halfedge_geometry g = geometry[h];
          return corner_angle(g.length, g.l_prev, g.l_next);
        },
        [&](Index h, double angle) { angle_sum[source[h]] += angle; });
      const double two_pi = 2. * 3.14159265358979323846;
      for(Index v = 0; v < nv; ++v)
        if(angle_sum[v] > two_pi + 1e-9)
          is_pseudo_source[v] = 1;
    }
    // boundary flags, edge statistics
    double sum_len = 0.;
    std::size_t ne = 0;
    min_edge_length = (nh > 0) ? geometry.faces[0].length[0] : 0.;
    max_edge_length = 0.;
    for(Index h = 0; h < nh; ++h)
    {
      if(opposite[h] == NO_INDEX)
      {
        is_pseudo_source[source[h]] = 1;
        is_pseudo_source[target(h)] = 1;
      }
      if(opposite[h] == NO_INDEX || opposite[h] > h) // count each edge once
      {
        const double l = geometry.faces[static_cast<std::size_t>(h / 3)].length[h % 3];
        sum_len += l;
        ++ne;
        min_edge_length = (std::min)(min_edge_length, l);
        max_edge_length = (std::max)(max_edge_length, l);
      }
    }
    number_of_edges = ne;
    mean_edge_length = ne > 0 ? sum_len / double(ne) : 0.;
    // Windows cannot cross a face of (almost) zero area or an edge of zero length, and the angles
    // of such a face are meaningless: its vertices are made pseudo-sources, so that the paths
    // through them are not lost.
    is_degenerate_face.assign(nf, 0);
    for(Index f = 0; f < nf; ++f)
    {
      const Halfedge_geometry g = geometry[3 * f];
      const double lmax = (std::max)(g.length, (std::max)(g.l_next, g.l_prev));
      const double lmin = (std::min)(g.length, (std::min)(g.l_next, g.l_prev));
      if(lmin > 0. && g.cy * g.length > 1e-12 * lmax * lmax)
        continue;
      is_degenerate_face[f] = 1;
      for(Index k = 0; k < 3; ++k)
        is_pseudo_source[source[3 * f + k]] = 1;
    }
    compute_anisotropy(threads);
  }

  // area of a triangle from its side lengths, accurate for needles (Kahan); 0 if degenerate
  static double triangle_area(double a, double b, double c)
  {
    if(a < b) std::swap(a, b);
    if(b < c) std::swap(b, c);
    if(a < b) std::swap(a, b);
    const double p = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
    return p > 0. ? 0.25 * std::sqrt(p) : 0.;
  }

  // angle opposite to side c in a triangle of sides a, b, c (robust for degenerate triangles)
  static double corner_angle(double a, double b, double c)
  {
    if(a <= 0. || b <= 0.)
      return 0.;
    double cosine = (a * a + b * b - c * c) / (2. * a * b);
    cosine = (std::max)(-1., (std::min)(1., cosine));
    return std::acos(cosine);
  }

  // Calls add(i, term(i)) for i = 0, ..., n - 1 in this order, the terms being computed by `threads`
  // OpenMP threads a block at a time: sums made by `add` do not depend on the number of threads. A block
  // is one parallel region (up to 2^18 terms, 2 MB), its terms taken by the threads in chunks as they come
  // (a thread that the system has descheduled holds back only the chunk it has taken: on a busy machine,
  // every region's barrier waits for its late threads).
  template <class Term, class Add>
  static void computed_in_parallel_added_in_order(Index n, int threads, const Term& term, const Add& add)
  {
    const Index block = Index(1) << 18, chunk = Index(1) << 12;
    std::vector<double> value((std::min)(n, block));
    Parallel_for loop(threads, Parallel_for::DYNAMIC);
    for(Index first = 0; first < n; first += block)
    {
      const Index last = (std::min)(n, first + block);
      const Index chunks = (last - first + chunk - 1) / chunk;
      loop.run(static_cast<long long>(chunks), [&](long long c, int) {
        const Index begin = first + static_cast<Index>(c) * chunk, end = (std::min)(last, begin + chunk);
        for(Index i = begin; i < end; ++i)
          value[static_cast<std::size_t>(i - first)] = term(i);
      });
      for(Index i = first; i < last; ++i)
        add(i, value[static_cast<std::size_t>(i - first)]);
    }
  }

  // Anisotropy degree tau: mean over faces of (longest edge / (2 sqrt(3) inradius)),
  // which is 1 for equilateral triangles and grows with elongation; capped for degenerate faces.
  void compute_anisotropy(int threads)
  {
    double acc = 0.;
    std::size_t n = 0;
    computed_in_parallel_added_in_order(
      nf, threads,
      [this](Index f) {
        const Face_geometry& g = geometry.faces[static_cast<std::size_t>(f)];
        const double a = g.length[0], b = g.length[1], c = g.length[2];
        const double area = triangle_area(a, b, c);
        if(!(area > 0.))
          return -1.;  // no term
        const double lmax = (std::max)(a, (std::max)(b, c));
        const double inradius = 2. * area / (a + b + c);
        return (std::min)(lmax / (2. * std::sqrt(3.) * inradius), 1e3);
      },
      [&](Index, double q) {
        if(q >= 0.)
        {
          acc += q;
          ++n;
        }
      });
    anisotropy = n > 0 ? (std::max)(1., acc / double(n)) : 1.;
  }
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_ARRAYS_H
