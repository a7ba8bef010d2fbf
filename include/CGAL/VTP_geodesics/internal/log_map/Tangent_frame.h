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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_TANGENT_FRAME_H
#define CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_TANGENT_FRAME_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>

#include <CGAL/assertions.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The tangent frame shared by the log map and the straightest geodesics (the exp map), written once, in
// terms of the mesh arrays (half-edges 3f, 3f+1, 3f+2 of face f; the engine's vertex numbering).
//
// - Angles grow counter-clockwise seen from the side the faces' normals point to.
// - At a vertex c the reference is the half-edge from c to source(halfedge(c)) of the user's mesh (an
//   interior vertex; vertex_reference_halfedge() finds it), or, at a border vertex, the border half-edge
//   leaving c (its face lies counter-clockwise of it, so every direction into the surface has an angle in
//   [0, pi]). The unscaled angle phi of a direction in a face around c is the sum of the corner angles at c
//   from the reference, counter-clockwise, plus the angle inside that face; theta = phi * scale, with
//   scale = 2 pi / (sum of the corner angles) at an interior vertex, pi / sum at a border vertex.
// - In a face location (f, b) the reference is the half-edge 3f (halfedge(f) of the user's mesh), angles in
//   the plane of f, unscaled. A point on an edge uses the plane of the face given.
// - A 3D direction is projected onto the tangent plane: the plane of the face; at a vertex, the plane
//   orthogonal to the angle-weighted normal, where the projected edges give a piecewise-linear map to phi.

const double TANGENT_FRAME_PI = 3.14159265358979323846;

// The next half-edge leaving source(h) counter-clockwise (opposite(prev(h))), NO_INDEX at the border.
inline Index ccw_outgoing(const Mesh_arrays& a, Index h) { return a.opposite[Mesh_arrays::prev(h)]; }

// The next half-edge leaving source(h) clockwise (next(opposite(h))), NO_INDEX at the border.
inline Index cw_outgoing(const Mesh_arrays& a, Index h)
{
  const Index o = a.opposite[h];
  return o == NO_INDEX ? NO_INDEX : Mesh_arrays::next(o);
}

// The corner angle at source(h) in face(h): from h counter-clockwise to the reverse of prev(h). Computed as
// atan2 in the frame of h, as the windows place the third vertex (accurate for needles and caps).
inline double corner_angle_of(const Mesh_arrays& a, Index h)
{
  const Halfedge_geometry g = a.geometry[h];
  return std::atan2(g.cy, g.cx);
}

// The direction of half-edge g (of the face of h) in the frame of h (A = source(h) at the origin, h along
// the x-axis, the face above): 0 for h, then the angles of next(h) and prev(h), in (-pi, pi].
inline double halfedge_direction_in_frame(const Mesh_arrays& a, Index h, Index g)
{
  CGAL_precondition(Mesh_arrays::face(h) == Mesh_arrays::face(g));
  if(g == h)
    return 0.;
  const Halfedge_geometry q = a.geometry[h];
  if(g == Mesh_arrays::next(h))
    return std::atan2(q.cy, q.cx - q.length);  // B -> C
  return std::atan2(-q.cy, -q.cx);             // C -> A
}

// The same direction as a vector (not of unit length): cheaper where only angles between vectors are needed.
inline std::array<double, 2> halfedge_vector_in_frame(const Mesh_arrays& a, Index h, Index g)
{
  CGAL_precondition(Mesh_arrays::face(h) == Mesh_arrays::face(g));
  const Halfedge_geometry q = a.geometry[h];
  if(g == h)
    return {{1., 0.}};
  if(g == Mesh_arrays::next(h))
    return {{q.cx - q.length, q.cy}};
  return {{-q.cx, -q.cy}};
}

// x moved by a multiple of `sum` into [low, low + sum), x within a few turns of it (an angle in a fan whose
// corner angles sum to `sum`)
inline double wrap_in_fan(double x, double sum, double low)
{
  if(!(sum > 0.))
    return x;
  for(int k = 0; k < 8 && x < low; ++k)
    x += sum;
  for(int k = 0; k < 8 && x >= low + sum; ++k)
    x -= sum;
  return x;
}

// An angle brought into [0, 2 pi).
inline double angle_in_0_2pi(double t)
{
  const double two_pi = 2. * TANGENT_FRAME_PI;
  // (the common cases without fmod, the same values: t - 2 pi is exact there)
  if(t >= two_pi && t < 2. * two_pi)
    t -= two_pi;
  else if(!(t >= -two_pi && t < two_pi))
    t = std::fmod(t, two_pi);
  if(t < 0.)
    t += two_pi;
  return t < two_pi ? t : 0.;
}

// The border half-edge leaving c (its opposite is NO_INDEX), NO_INDEX if c is not on the border.
inline Index border_outgoing(const Mesh_arrays& a, Index c)
{
  for(Index i = a.corner_begin[c]; i < a.corner_begin[c + 1]; ++i)
    if(a.opposite[a.corners[i]] == NO_INDEX)
      return a.corners[i];
  return NO_INDEX;
}

// The frame at a vertex: its half-edges counter-clockwise from the reference and their unscaled angles.
struct Vertex_frame
{
  Index vertex = NO_INDEX;
  bool border = false;
  double angle_sum = 0.;  // the sum of the corner angles at the vertex
  double scale = 1.;      // theta = phi * scale
  std::vector<Index> halfedges;  // leaving the vertex, counter-clockwise from the reference (halfedges[0])
  std::vector<double> phi;       // phi[i]: the unscaled angle of halfedges[i]; phi.back() = angle_sum

  Index reference() const { return halfedges.empty() ? NO_INDEX : halfedges.front(); }

  // the position of half-edge h in `halfedges` (h leaves the vertex)
  std::size_t position_of(Index h) const
  {
    for(std::size_t i = 0; i < halfedges.size(); ++i)
      if(halfedges[i] == h)
        return i;
    CGAL_precondition_msg(false, "the half-edge does not leave the vertex of the frame");
    return 0;
  }

  // theta of the direction at angle alpha from h (leaving the vertex) inside face(h)
  double theta(Index h, double alpha) const { return (phi[position_of(h)] + alpha) * scale; }

  // The unscaled angle of theta (taken modulo 2 pi; at a border vertex, clamped to [0, pi]).
  double phi_of(double theta) const
  {
    double t = angle_in_0_2pi(theta);
    if(border && t > TANGENT_FRAME_PI)
      t = (t < 1.5 * TANGENT_FRAME_PI) ? TANGENT_FRAME_PI : 0.;
    return (std::min)(t / scale, angle_sum);
  }

  // The face of a direction theta: the half-edge h leaving the vertex in whose face it lies, and its angle
  // alpha from h inside that face (0 <= alpha <= the corner angle of h).
  void direction(double theta, Index& h, double& alpha) const
  {
    CGAL_precondition(!halfedges.empty());
    const double p = phi_of(theta);
    std::size_t i = 0;
    while(i + 1 < halfedges.size() && phi[i + 1] <= p)
      ++i;
    h = halfedges[i];
    alpha = (std::max)(0., p - phi[i]);
  }
};

// The frame at vertex c with the given reference half-edge (leaving c; ignored at a border vertex, where
// the border half-edge leaving c is the reference). False when the faces around c are not one fan (an
// isolated vertex, a vertex where several fans meet, or a reference that does not leave c).
inline bool make_vertex_frame(const Mesh_arrays& a, Index c, Index reference, Vertex_frame& frame)
{
  frame = Vertex_frame();
  frame.vertex = c;
  const Index degree = a.corner_begin[c + 1] - a.corner_begin[c];
  const Index border = border_outgoing(a, c);
  frame.border = (border != NO_INDEX);
  Index h = frame.border ? border : reference;
  if(degree == 0 || h == NO_INDEX || h < 0 || static_cast<std::size_t>(h) >= a.source.size() || a.source[h] != c)
    return false;
  double sum = 0.;
  for(Index k = 0; k < degree; ++k)
  {
    frame.halfedges.push_back(h);
    frame.phi.push_back(sum);
    sum += corner_angle_of(a, h);
    h = ccw_outgoing(a, h);
    if(h == NO_INDEX || h == frame.halfedges.front())
      break;
  }
  frame.phi.push_back(sum);
  // one fan: every corner visited, and (interior) back to the reference
  if(static_cast<Index>(frame.halfedges.size()) != degree || (!frame.border && h != frame.halfedges.front()))
    return false;
  frame.angle_sum = sum;
  if(!(sum > 0.))
    return false;
  frame.scale = (frame.border ? TANGENT_FRAME_PI : 2. * TANGENT_FRAME_PI) / sum;
  return true;
}

// The frame of a face location in face f: the reference half-edge 3f (halfedge(f) of the user's mesh).
inline Index face_reference(Index f) { return 3 * f; }

// theta (in the frame of face f) of the direction at angle `angle` in the frame of half-edge g of f
inline double face_theta(const Mesh_arrays& a, Index f, Index g, double angle)
{
  return angle + halfedge_direction_in_frame(a, face_reference(f), g);
}

// the angle in the frame of half-edge g of f of the direction theta (in the frame of face f)
inline double angle_in_halfedge_frame(const Mesh_arrays& a, Index f, Index g, double theta)
{
  return theta - halfedge_direction_in_frame(a, face_reference(f), g);
}

// ------------------------------------------------------------------------------------------------
// 3D directions (the user's reference), projected onto the tangent plane
// ------------------------------------------------------------------------------------------------
typedef std::array<double, 3> Vector_3d;

inline Vector_3d difference_3d(const Vector_3d& p, const Vector_3d& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
inline double dot_3d(const Vector_3d& u, const Vector_3d& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
inline Vector_3d cross_3d(const Vector_3d& u, const Vector_3d& v)
{
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
inline Vector_3d unit_3d(const Vector_3d& u)
{
  const double n = std::sqrt(dot_3d(u, u));
  return n > 0. ? Vector_3d{u[0] / n, u[1] / n, u[2] / n} : Vector_3d{0., 0., 0.};
}

// Throws Invalid_input_error unless d is a finite non-zero vector.
inline void check_direction_3d(const Vector_3d& d, const char* what)
{
  const double n = dot_3d(d, d);
  if(!std::isfinite(n) || !(n > 0.))
    throw Invalid_input_error(std::string(what) + " is zero or not finite");
}

// The angle of d, projected onto the plane of (x, y) (x, y orthonormal), from x towards y. Throws
// Invalid_input_error when d is (nearly) orthogonal to the plane.
inline double planar_angle_3d(const Vector_3d& d, const Vector_3d& x, const Vector_3d& y, const char* what)
{
  const double u = dot_3d(d, x), v = dot_3d(d, y);
  if(!(u * u + v * v > 1e-24 * dot_3d(d, d)))
    throw Invalid_input_error(std::string(what) + " is orthogonal to the tangent plane");
  return std::atan2(v, u);
}

// theta of the 3D direction d in the frame of face f, whose corners source(3f), target(3f) and the third
// are p[0], p[1], p[2] (in the face's plane; the same frame as face_theta()).
inline double face_theta_of_3d(const std::array<Vector_3d, 3>& p, const Vector_3d& d,
                               const char* what = "the reference direction")
{
  check_direction_3d(d, what);
  const Vector_3d x = unit_3d(difference_3d(p[1], p[0]));
  const Vector_3d n = cross_3d(difference_3d(p[1], p[0]), difference_3d(p[2], p[0]));
  const Vector_3d y = unit_3d(cross_3d(n, x));
  if(dot_3d(y, y) == 0.)
    throw Invalid_input_error(std::string(what) + ": the face of the location is degenerate");
  return planar_angle_3d(d, x, y, what);
}

// theta of the 3D direction d at the vertex of `frame`: d projected onto the plane orthogonal to the
// angle-weighted normal; between the projections of two consecutive edges, phi is interpolated linearly
// (the first wedge that contains the direction, counter-clockwise from the reference); at a border vertex a
// direction outside the surface takes the angle of the nearer border edge. point(v) gives the position of
// vertex v (its three coordinates, in any unit).
template <class PointOf>
double vertex_theta_of_3d(const Mesh_arrays& a, const Vertex_frame& frame, const PointOf& point, const Vector_3d& d,
                          const char* what = "the reference direction")
{
  check_direction_3d(d, what);
  const Vector_3d pc = point(frame.vertex);
  const std::size_t n = frame.halfedges.size();
  std::vector<Vector_3d> edge(n + 1);
  for(std::size_t i = 0; i < n; ++i)
    edge[i] = difference_3d(point(a.target(frame.halfedges[i])), pc);
  // the last edge of a border fan: the reverse of prev() of the last half-edge
  edge[n] = frame.border ? difference_3d(point(a.source[Mesh_arrays::prev(frame.halfedges[n - 1])]), pc) : edge[0];
  Vector_3d normal{0., 0., 0.};
  for(std::size_t i = 0; i < n; ++i)
  {
    const Vector_3d fn = unit_3d(cross_3d(edge[i], edge[i + 1]));
    const double w = frame.phi[i + 1] - frame.phi[i];
    for(int k = 0; k < 3; ++k)
      normal[static_cast<std::size_t>(k)] += w * fn[static_cast<std::size_t>(k)];
  }
  normal = unit_3d(normal);
  const Vector_3d x0 = difference_3d(edge[0], Vector_3d{normal[0] * dot_3d(edge[0], normal),
                                                       normal[1] * dot_3d(edge[0], normal),
                                                       normal[2] * dot_3d(edge[0], normal)});
  const Vector_3d x = unit_3d(x0);
  const Vector_3d y = unit_3d(cross_3d(normal, x));
  if(dot_3d(x, x) == 0. || dot_3d(y, y) == 0.)
    throw Invalid_input_error(std::string(what) + ": the tangent plane at the vertex is undefined");
  const double two_pi = 2. * TANGENT_FRAME_PI;
  const double psi = angle_in_0_2pi(planar_angle_3d(d, x, y, what));
  // the angles of the projected edges, counter-clockwise from the reference's (0)
  std::vector<double> e(n + 1, 0.);
  for(std::size_t i = 1; i <= n; ++i)
  {
    const double u = dot_3d(edge[i], x), v = dot_3d(edge[i], y);
    e[i] = angle_in_0_2pi(std::atan2(v, u));
  }
  if(!frame.border)
    e[n] = two_pi;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double span = (i + 1 == n && !frame.border) ? two_pi - e[i] : angle_in_0_2pi(e[i + 1] - e[i]);
    const double offset = angle_in_0_2pi(psi - e[i]);
    if(span > 0. && offset <= span)
      return (frame.phi[i] + (frame.phi[i + 1] - frame.phi[i]) * (offset / span)) * frame.scale;
  }
  if(!frame.border)
    return 0.;  // projected edges that fold over each other: the reference
  // outside the surface: the nearer border edge
  const double to_last = angle_in_0_2pi(psi - e[n]), to_first = angle_in_0_2pi(e[0] - psi);
  return to_first <= to_last ? 0. : TANGENT_FRAME_PI;
}

// ------------------------------------------------------------------------------------------------
// the user's mesh: the reference half-edge of a vertex
// ------------------------------------------------------------------------------------------------
// The half-edge of the arrays from v to source(halfedge(v)), NO_INDEX if that edge is on the border (the
// frame takes the border half-edge then), or for a vertex in no face. `index` is a Mesh_index (mesh/Mesh_index.h): its mesh `tm` and
// face_index().
template <class MeshIndex, class VertexDescriptor>
Index vertex_reference_halfedge(const MeshIndex& index, VertexDescriptor v)
{
  const auto& tm = index.tm;
  typedef typename std::decay<decltype(tm)>::type Mesh;
  if(halfedge(v, tm) == boost::graph_traits<Mesh>::null_halfedge())
    return NO_INDEX;  // a vertex in no face: no frame (make_vertex_frame() says so)
  const auto h = opposite(halfedge(v, tm), tm);
  if(is_border(h, tm))
    return NO_INDEX;
  const Index f = index.face_index(face(h, tm));
  CGAL_assertion(f != NO_INDEX);
  auto g = halfedge(face(h, tm), tm);
  for(Index k = 0; k < 3; ++k, g = next(g, tm))
    if(g == h)
      return 3 * f + k;
  CGAL_assertion_msg(false, "the half-edge is not in its face");
  return NO_INDEX;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_TANGENT_FRAME_H
