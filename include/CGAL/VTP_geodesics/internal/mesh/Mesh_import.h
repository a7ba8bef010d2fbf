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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_IMPORT_H
#define CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_IMPORT_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/mesh/Morton_code.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_index.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// Throws the error for face f, which has an edge of non-finite length: names the vertex with a
// non-finite coordinate if there is one, else the face (its coordinates are too large to be measured).
template <class TriangleMesh, class VertexPointMap>
[[noreturn]] void throw_non_finite(const Mesh_index<TriangleMesh>& index, VertexPointMap vpm, std::size_t f)
{
  const TriangleMesh& tm = index.tm;
  auto h = halfedge(index.faces[f], tm);
  for(int k = 0; k < 3; ++k, h = next(h, tm))
  {
    const auto p = get(vpm, source(h, tm));
    for(int j = 0; j < 3; ++j)
      if(!std::isfinite(CGAL::to_double(p[j])))
        throw Invalid_input_error("vertex " + std::to_string(index.position_of(get(index.vertex_id, source(h, tm))))
                                  + " has a non-finite coordinate");
  }
  throw Invalid_input_error("face " + std::to_string(index.face_position[f]) + " has an edge of non-finite length (coordinates too "
                            "large)");
}

// Imports the mesh of `index` into its arrays, on `threads` threads (at least 1; the result does not
// depend on their number): numbers the vertices, faces and half-edges, checks that every face is a
// triangle and that the mesh fits 32-bit indices, measures the edges and the face areas with the
// vertex point map `vpm` and the traits, and scales the lengths by a power of two (index.length_scale).
// Numbers the vertices of index.vertices_in_order along a Morton (Z-order) curve of their points, ties in
// the order of vertices(tm): neighbours on the surface get nearby indices, so that the per-vertex arrays
// of a propagation are read from memory a few lines at a time (virtual source propagation on a million
// vertices ordered by a Loop subdivision spends half its time waiting for memory otherwise). Fills
// index.vertices (in index order) and index.position. A non-finite coordinate (rejected later) counts
// as 0.
template <class TriangleMesh, class VertexPointMap>
void number_along_curve(Mesh_index<TriangleMesh>& index, VertexPointMap vpm)
{
  const std::size_t nv = index.vertices_in_order.size();
  std::vector<std::array<double, 3> > p(nv);
  double lo[3] = { 0., 0., 0. }, hi[3] = { 0., 0., 0. };
  bool first = true;
  for(std::size_t i = 0; i < nv; ++i)
  {
    const auto q = get(vpm, index.vertices_in_order[i]);
    bool finite = true;
    for(int j = 0; j < 3; ++j)
    {
      p[i][static_cast<std::size_t>(j)] = CGAL::to_double(q[j]);
      finite = finite && std::isfinite(p[i][static_cast<std::size_t>(j)]);
    }
    if(!finite)
    {
      p[i][0] = p[i][1] = p[i][2] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    for(std::size_t j = 0; j < 3; ++j)
    {
      lo[j] = first ? p[i][j] : (std::min)(lo[j], p[i][j]);
      hi[j] = first ? p[i][j] : (std::max)(hi[j], p[i][j]);
    }
    first = false;
  }
  double extent = 0.;
  for(int j = 0; j < 3; ++j)
    extent = (std::max)(extent, hi[j] - lo[j]);
  const double cells = Morton_code::cells;
  const double scale = extent > 0. && std::isfinite(cells / extent) ? cells / extent : 0.;
  std::vector<std::pair<std::uint64_t, Index> > key(nv);
  for(std::size_t i = 0; i < nv; ++i)  // a non-finite point (NaN) gets the first cell
    key[i] = std::make_pair(Morton_code::of(p[i].data(), lo, scale), static_cast<Index>(i));
  std::vector<std::array<double, 3> >().swap(p);
  std::sort(key.begin(), key.end());
  index.vertices.resize(nv);
  index.position.resize(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    index.position[i] = key[i].second;
    index.vertices[i] = index.vertices_in_order[static_cast<std::size_t>(key[i].second)];
  }
}

template <class TriangleMesh, class VertexPointMap, class Traits>
void import_mesh(Mesh_index<TriangleMesh>& index, VertexPointMap vpm, const Traits& traits, int threads)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<Index> >::const_type
    Halfedge_id_map;
  const TriangleMesh& tm = index.tm;
  // The per-mesh arrays number vertices and half-edges with 32-bit integers.
  const std::size_t max_index = static_cast<std::size_t>((std::numeric_limits<Index>::max)());
  if(static_cast<std::size_t>(num_vertices(tm)) > max_index || static_cast<std::size_t>(num_faces(tm)) > max_index / 3)
    throw Invalid_input_error("the mesh is too large (more than " + std::to_string(max_index) + " vertices or "
                              + std::to_string(max_index / 3) + " faces)");

  typename Traits::Compute_squared_distance_3 sqd = traits.compute_squared_distance_3_object();
  typename Traits::Compute_squared_area_3 sqa = traits.compute_squared_area_3_object();

  // The numbering writes the dynamic property maps: one thread (a dynamic map may be a hash map). It
  // checks that every face is a triangle.
  index.vertices_in_order.assign(vertices(tm).begin(), vertices(tm).end());
  const Index nv = static_cast<Index>(index.vertices_in_order.size());
  number_along_curve(index, vpm);
  for(Index i = 0; i < nv; ++i)
    put(index.vertex_id, index.vertices[static_cast<std::size_t>(i)], i);
  // Half-edges are numbered face by face (3f, 3f+1, 3f+2); the arrays are filled in place (no
  // per-half-edge temporary beyond the numbering map), so that the peak memory of the
  // construction stays close to that of the arrays.
  // Faces are numbered by their least vertex index (ties in the order of faces(tm)), so that the faces
  // around a vertex are near each other in memory too.
  std::vector<face_descriptor>& faces_in_order = index.faces;
  std::vector<face_descriptor> by_position;  // the faces in the order of faces(tm)
  std::vector<Index> id_of_position;         // per position in faces(tm), the index of the face
  {
    std::vector<Index> least_vertex;  // per position in faces(tm)
    least_vertex.reserve(num_faces(tm));
    faces_in_order.reserve(num_faces(tm));
    for(face_descriptor f : faces(tm))
    {
      const Index position = static_cast<Index>(faces_in_order.size());
      const halfedge_descriptor h0 = halfedge(f, tm);
      halfedge_descriptor h = h0;
      Index least = nv;
      for(int k = 0; k < 3; ++k)
      {
        least = (std::min)(least, get(index.vertex_id, source(h, tm)));
        h = next(h, tm);
        if((h == h0) != (k == 2))  // a face of another degree than 3
          throw Invalid_input_error("the mesh is not a triangle mesh (face " + std::to_string(position)
                                    + " is not a triangle)");
      }
      least_vertex.push_back(least);
      faces_in_order.push_back(f);
    }
    // a counting sort by least vertex (stable: ties in the order of faces(tm))
    const std::size_t nf_all = least_vertex.size();
    std::vector<Index> start(static_cast<std::size_t>(nv) + 1, 0);
    for(Index v : least_vertex)
      ++start[static_cast<std::size_t>(v) + 1];
    for(std::size_t v = 0; v < static_cast<std::size_t>(nv); ++v)
      start[v + 1] += start[v];
    index.face_position.resize(nf_all);
    for(std::size_t p = 0; p < nf_all; ++p)
      index.face_position[static_cast<std::size_t>(start[static_cast<std::size_t>(least_vertex[p])]++)] = static_cast<Index>(p);
    std::vector<Index>().swap(start);
    std::vector<Index>().swap(least_vertex);
    by_position.swap(faces_in_order);
    faces_in_order.resize(nf_all);
    id_of_position.resize(nf_all);
    for(std::size_t i = 0; i < nf_all; ++i)
    {
      faces_in_order[i] = by_position[static_cast<std::size_t>(index.face_position[i])];
      id_of_position[static_cast<std::size_t>(index.face_position[i])] = static_cast<Index>(i);
    }
  }
  // the maps and the pass below go through the faces in the order of the mesh (its memory)
  Halfedge_id_map hid = get(CGAL::dynamic_halfedge_property_t<Index>(), tm);
  for(std::size_t p = 0; p < by_position.size(); ++p)
  {
    const std::size_t id = static_cast<std::size_t>(id_of_position[p]);
    const face_descriptor f = by_position[p];
    put(index.face_id, f, static_cast<Index>(id));
    halfedge_descriptor h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
      put(hid, h, static_cast<Index>(3 * id + static_cast<std::size_t>(k)));
  }
  const std::size_t nf = faces_in_order.size();
  std::vector<Index> tri(3 * nf), opp(3 * nf);
  std::vector<Face_geometry> face_geometry(nf);
  // One pass over the faces (the mesh is read once), which only reads the mesh and the maps: the faces
  // are shared among the threads. The squared area is kept in `area` until the scale is known. The
  // longest edge and the first face (in faces(tm)) with a non-finite edge are found per thread, then over
  // the threads.
  struct alignas(64) Per_thread
  {
    double longest = 0.;
    std::size_t first_non_finite = (std::numeric_limits<std::size_t>::max)();
  };
  // The faces are taken by the threads in chunks as they come (a thread that the system has descheduled
  // holds back only its chunk).
  Parallel_for loop(threads, Parallel_for::DYNAMIC);
  const std::size_t chunk = 4096;
  const long long chunks = static_cast<long long>((nf + chunk - 1) / chunk);
  auto in_chunks = [&](const auto& body) {
    loop.run(chunks, [&](long long c, int t) {
      const std::size_t first = static_cast<std::size_t>(c) * chunk, last = (std::min)(nf, first + chunk);
      for(std::size_t i = first; i < last; ++i)
        body(i, t);
    });
  };
  std::vector<Per_thread> per_thread(static_cast<std::size_t>(loop.threads()));
  in_chunks([&](std::size_t position, int t) {
    const std::size_t f = static_cast<std::size_t>(id_of_position[position]);
    Per_thread& mine = per_thread[static_cast<std::size_t>(t)];
    halfedge_descriptor h = halfedge(by_position[position], tm);
    vertex_descriptor corner[3];
    for(std::size_t k = 0; k < 3; ++k, h = next(h, tm))
    {
      corner[k] = source(h, tm);
      tri[3 * f + k] = get(index.vertex_id, corner[k]);
      const halfedge_descriptor o = opposite(h, tm);
      opp[3 * f + k] = is_border(o, tm) ? NO_INDEX : get(hid, o);
    }
    Face_geometry& g = face_geometry[f];
    for(std::size_t k = 0; k < 3; ++k)
    {
      const double l = std::sqrt(CGAL::to_double(sqd(get(vpm, corner[k]), get(vpm, corner[(k + 1) % 3]))));
      if(!std::isfinite(l))
        mine.first_non_finite = (std::min)(mine.first_non_finite, position);
      g.length[k] = l;
      mine.longest = (std::max)(mine.longest, l);
    }
    g.area = CGAL::to_double(sqa(get(vpm, corner[0]), get(vpm, corner[1]), get(vpm, corner[2])));
  });
  double longest = 0.;
  std::size_t first_non_finite = (std::numeric_limits<std::size_t>::max)();
  for(const Per_thread& p : per_thread)
  {
    longest = (std::max)(longest, p.longest);
    first_non_finite = (std::min)(first_non_finite, p.first_non_finite);
  }
  if(first_non_finite < nf)
    throw_non_finite(index, vpm, static_cast<std::size_t>(id_of_position[first_non_finite]));
  std::vector<face_descriptor>().swap(by_position);
  std::vector<Index>().swap(id_of_position);
  // The engine works on lengths scaled by a power of two (exact in floating point) that brings the
  // longest edge into [0.5, 1): its squares and fourth powers can then neither overflow nor
  // underflow, whatever the scale of the coordinates. Distances are scaled back on output.
  int exponent = 0;
  if(longest > 0.)
    std::frexp(longest, &exponent);
  index.length_scale = std::ldexp(1., exponent);
  // multiplying by a power of two that is a normal number rounds as std::ldexp does (both are
  // correctly rounded); ldexp is kept for the extreme scales
  const bool multiply = exponent > -500 && exponent < 500;
  const double down = std::ldexp(1., -exponent), down2 = std::ldexp(1., -2 * exponent);
  auto scaled = [&](double x, int e, double factor) { return multiply ? x * factor : std::ldexp(x, e); };
  in_chunks([&](std::size_t fi, int) {
    Face_geometry& g = face_geometry[fi];
    const double longest_edge = (std::max)(g.length[0], (std::max)(g.length[1], g.length[2]));
    for(double& l : g.length)
      l = scaled(l, -exponent, down);
    // face areas from the points (accurate for nearly flat triangles, see VTPGeodesicTraits_3);
    // -1 where that overflows or underflows: the engine then uses the lengths
    const double a2 = g.area;  // the squared area, from the first pass
    g.area = -1.;
    const double a = scaled(std::sqrt(a2), -2 * exponent, down2);
    // a zero is trusted only where the squared area of a face of relative height 1e-12
    // could not have underflowed (edges longer than 1e-60)
    if(std::isfinite(a2) && std::isfinite(a) && (a > 0. || (a2 == 0. && longest_edge > 1e-60)))
      g.area = a;
  });
  index.arrays.build(nv, std::move(tri), std::move(opp), std::move(face_geometry), loop.threads());
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_MESH_MESH_IMPORT_H
