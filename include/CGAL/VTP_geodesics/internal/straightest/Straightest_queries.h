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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_STRAIGHTEST_QUERIES_H
#define CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_STRAIGHTEST_QUERIES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Straightest_geodesic.h>
#include <CGAL/VTP_geodesics/internal/straightest/Straightest_walk.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_index.h>
#include <CGAL/VTP_geodesics/internal/straightest/Walk_geometry.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The straightest geodesics of the solver in the user's terms: the start (a vertex or a face location), the
// direction (2D in the tangent frame of the start, or 3D, projected) and the length are checked and turned
// into a state of Straightest_walk; its points into face locations and points of space.
template <class TriangleMesh, class VertexPointMap>
class Straightest_queries
{
public:
  typedef Mesh_index<TriangleMesh> Index_map;
  typedef typename Index_map::vertex_descriptor vertex_descriptor;
  typedef typename Index_map::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef Straightest_geodesic<face_descriptor, Point_3> Result;

  Straightest_queries(const Index_map& index, VertexPointMap vpm) : m_index(index), m_vpm(vpm), m_planes(index, vpm) {}

  // One walk; `position` names it in the error messages (Index_map::no_position: one walk alone).
  template <class Start, class Direction>
  Result walk(const Start& start, const Direction& direction, double length,
              std::size_t position = Index_map::no_position) const
  {
    const std::string name = position == Index_map::no_position ? std::string("the walk")
                                                                 : "walk " + std::to_string(position);
    if(!(length >= 0.) || !std::isfinite(length))
      throw Invalid_input_error(name + ": the length must be finite and non-negative");
    double d[3] = { 0., 0., 0. };
    const std::size_t dimension = std::size(direction);
    double norm = 0.;
    for(std::size_t i = 0; i < dimension; ++i)
    {
      d[i] = CGAL::to_double(direction[i]);
      norm += d[i] * d[i];
    }
    if(!std::isfinite(norm) || !(norm > 0.))
      throw Invalid_input_error(name + ": the direction must be finite and not zero");
    Straightest_walk::State s;
    bool leaves = false;  // the direction leaves the surface at once (from an edge of the border)
    Index vertex = NO_INDEX;
    Index face = NO_INDEX;
    double b[3];
    if(start_of(start, name, vertex, face, b))
      leaves = !m_planes.state_at_vertex(vertex, std::atan2(d[1], d[0]), dimension == 3 ? d : nullptr, s, name);
    else
    {
      double dx = d[0] / std::sqrt(norm), dy = d[1] / std::sqrt(norm);
      if(dimension == 3)
        m_planes.face_direction(face, d, dx, dy, name);
      leaves = !Straightest_walk(m_index.arrays).state_at_point(face, b, dx, dy, s);
    }
    Walk_result r;
    if(leaves)  // a walk of length 0 (s: its start, set by the walk)
    {
      r.points.push_back(Straightest_walk(m_index.arrays).point_of(s));
      r.end_face = s.face;
      r.dx = s.dx, r.dy = s.dy;
      r.stop = s.face != NO_INDEX && m_index.arrays.is_degenerate_face[static_cast<std::size_t>(s.face)]
                 ? Walk_result::DEGENERATE_FACE : Walk_result::BORDER;
    }
    else
      Straightest_walk(m_index.arrays).walk(s, length / m_index.length_scale, r);
    if(face != NO_INDEX && r.points.front().face == face)  // the start as given (exact even in a face of zero area)
      for(int k = 0; k < 3; ++k)
        r.points.front().b[k] = b[k];
    if(r.stop == Walk_result::NUMERICAL_FAILURE)
      throw std::runtime_error(name + ": the walk could not be followed through the faces (a numerical failure)");
    return result_of(r);
  }

  // Many walks: starts[i], directions[i], lengths[i]; with `parallel`, on the threads of the named parameter
  // number_of_threads (dynamically, 64 walks at a time).
  template <class StartRange, class DirectionRange, class LengthRange, class NamedParameters>
  std::vector<Result> walks(const StartRange& starts, const DirectionRange& directions, const LengthRange& lengths,
                            bool parallel, const NamedParameters& np) const
  {
    const int threads = parallel ? number_of_threads(CGAL::parameters::choose_parameter(
                                     CGAL::parameters::get_parameter(np, internal_np::number_of_threads), 0))
                                 : 1;
    const std::vector<typename std::iterator_traits<decltype(std::begin(starts))>::value_type> s(std::begin(starts),
                                                                                                 std::end(starts));
    const std::vector<typename std::iterator_traits<decltype(std::begin(directions))>::value_type> d(
      std::begin(directions), std::end(directions));
    const std::vector<double> l(std::begin(lengths), std::end(lengths));
    if(d.size() != s.size() || l.size() != s.size())
      throw Invalid_input_error("the starts, the directions and the lengths of the walks must be as many ("
                                + std::to_string(s.size()) + ", " + std::to_string(d.size()) + ", "
                                + std::to_string(l.size()) + ")");
    std::vector<Result> results(s.size());
    const long long chunk = 64, n = static_cast<long long>(s.size());
    Parallel_for loop(threads, Parallel_for::DYNAMIC);
    loop.run((n + chunk - 1) / chunk, [&](long long c, int) {
      for(long long i = c * chunk; i < (std::min)(n, (c + 1) * chunk); ++i)
      {
        const std::size_t u = static_cast<std::size_t>(i);
        results[u] = walk(s[u], d[u], l[u], u);
      }
    });
    return results;
  }

private:
  // The start: true for a vertex (`vertex`), false for a point of a face (`face`, `b`). A face location with
  // one coordinate 1 is that vertex.
  bool start_of(vertex_descriptor v, const std::string& name, Index& vertex, Index&, double*) const
  {
    if(!m_index.is_vertex(v))
      throw Invalid_input_error(name + ": the start is not a vertex of the mesh");
    vertex = get(m_index.vertex_id, v);
    check_not_isolated(vertex, name);
    return true;
  }

  template <class FT>
  bool start_of(const std::pair<face_descriptor, std::array<FT, 3> >& location, const std::string& name,
                Index& vertex, Index& face, double* b) const
  {
    m_index.seed_of(location, 0, "the start of the walk", Index_map::no_position);  // checks
    face = m_index.face_index(location.first);
    double sum = 0.;
    for(int k = 0; k < 3; ++k)
      sum += (b[k] = (std::max)(0., CGAL::to_double(location.second[static_cast<std::size_t>(k)])));
    for(int k = 0; k < 3; ++k)
      b[k] /= sum;
    for(int k = 0; k < 3; ++k)
      if(b[k] == 1.)
      {
        vertex = m_index.arrays.source[3 * face + k];
        check_not_isolated(vertex, name);
        return true;
      }
    return false;
  }

  void check_not_isolated(Index v, const std::string& name) const
  {
    if(m_index.arrays.corner_begin[v] == m_index.arrays.corner_begin[v + 1])
      throw Invalid_input_error(name + ": the start, vertex " + std::to_string(m_index.position_of(v))
                                + ", is on no face");
  }

  Result result_of(const Walk_result& r) const
  {
    Result out;
    out.locations.reserve(r.points.size());
    out.points.reserve(r.points.size());
    for(const Walk_point& p : r.points)
    {
      out.locations.emplace_back(m_index.faces[static_cast<std::size_t>(p.face)],
                                 std::array<double, 3>{ { p.b[0], p.b[1], p.b[2] } });
      out.points.push_back(m_planes.point(p.face, p.b));
    }
    out.end_location = out.locations.back();
    out.end_point = out.points.back();
    out.end_direction = m_planes.vector_of(r.end_face, r.dx, r.dy);
    out.length = r.length * m_index.length_scale;
    out.reached_border = r.stop == Walk_result::BORDER;
    out.reached_degenerate_face = r.stop == Walk_result::DEGENERATE_FACE;
    return out;
  }

  const Index_map& m_index;
  VertexPointMap m_vpm;
  Walk_geometry<TriangleMesh, VertexPointMap> m_planes;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_STRAIGHTEST_QUERIES_H
