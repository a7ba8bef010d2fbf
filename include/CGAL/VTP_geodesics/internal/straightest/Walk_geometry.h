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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_WALK_GEOMETRY_H
#define CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_WALK_GEOMETRY_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/internal/straightest/Straightest_walk.h>
#include <CGAL/VTP_geodesics/internal/log_map/Tangent_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_index.h>

#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The geometry in space that the walks need beside the arrays: the points of the faces (vertex point map),
// the start of a walk at a vertex in its tangent frame (Tangent_frame.h: an angle theta, or a 3D vector
// projected onto the tangent plane), the plane of a face (3D vectors in and out of the frame of its 3f).
template <class TriangleMesh, class VertexPointMap>
class Walk_geometry
{
public:
  typedef Mesh_index<TriangleMesh> Index_map;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef std::array<double, 3> Vec;

  Walk_geometry(const Index_map& index, VertexPointMap vpm) : m_index(index), m_vpm(vpm) {}

  // The state at vertex v going in the direction theta of its tangent frame (Tangent_frame.h: at a border
  // vertex, a theta outside [0, pi] is taken to the nearer border edge), or in the 3D direction d projected
  // (`d` not null). False if the direction goes into a face of (almost) zero area.
  bool state_at_vertex(Index v, double theta, const double* d, Straightest_walk::State& s,
                       const std::string& name) const
  {
    const Mesh_arrays& m = m_index.arrays;
    Vertex_frame frame;
    if(!make_vertex_frame(m, v, vertex_reference_halfedge(m_index, m_index.vertices[static_cast<std::size_t>(v)]),
                          frame))
      throw Invalid_input_error(name + ": the start, vertex " + std::to_string(m_index.position_of(v))
                                + ", has no tangent frame (its faces are not one fan)");
    if(d != nullptr)
    {
      const std::string what = name + ": the direction";
      theta = vertex_theta_of_3d(m, frame, [this](Index u) { return position(u); }, Vector_3d{ { d[0], d[1], d[2] } },
                                 what.c_str());
    }
    Index h;
    double alpha;
    frame.direction(theta, h, alpha);
    return Straightest_walk(m).corner_state(h, alpha, s);
  }

  // the direction (dx, dy) in the frame of 3f (unit) of the 3D vector d projected onto the plane of face f
  void face_direction(Index f, const double* d, double& dx, double& dy, const std::string& name) const
  {
    const std::string what = name + ": the direction";
    const std::array<Vector_3d, 3> p = { { corner(f, 0), corner(f, 1), corner(f, 2) } };
    const double theta = face_theta_of_3d(p, Vector_3d{ { d[0], d[1], d[2] } }, what.c_str());
    dx = std::cos(theta);
    dy = std::sin(theta);
  }

  // the unit 3D vector of the direction (dx, dy) of the frame of 3f
  Vec vector_of(Index f, double dx, double dy) const
  {
    Vec e1, e2;
    basis(f, e1, e2);
    return unit(Vec{ { dx * e1[0] + dy * e2[0], dx * e1[1] + dy * e2[1], dx * e1[2] + dy * e2[2] } });
  }

  // the point of face f of barycentric coordinates b
  Point_3 point(Index f, const double* b) const
  {
    double c[3] = { 0., 0., 0. };
    for(int k = 0; k < 3; ++k)
    {
      const Vec p = corner(f, k);
      for(int j = 0; j < 3; ++j)
        c[j] += b[k] * p[j];
    }
    return Point_3(c[0], c[1], c[2]);
  }

private:
  // corner k of face f (the source of 3f + k), and vertex v, in space
  Vec corner(Index f, int k) const { return position(m_index.arrays.source[3 * f + k]); }
  Vec position(Index v) const
  {
    const Point_3& p = get(m_vpm, m_index.vertices[static_cast<std::size_t>(v)]);
    return Vec{ { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) } };
  }

  // the axes of the frame of 3f in space: e1 along the half-edge, e2 towards the third corner
  void basis(Index f, Vec& e1, Vec& e2) const
  {
    const Vec a = corner(f, 0), ab = sub(corner(f, 1), a), ac = sub(corner(f, 2), a);
    e1 = unit(ab);
    e2 = unit(project(ac, e1));
  }

  static Vec sub(const Vec& a, const Vec& b) { return Vec{ { a[0] - b[0], a[1] - b[1], a[2] - b[2] } }; }
  static double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
  static Vec cross(const Vec& a, const Vec& b)
  {
    return Vec{ { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
  }
  static Vec unit(const Vec& a)
  {
    const double l = norm(a);
    return l > 0. ? Vec{ { a[0] / l, a[1] / l, a[2] / l } } : a;
  }
  // a without its component along the unit vector u
  static Vec project(const Vec& a, const Vec& u)
  {
    const double t = dot(a, u);
    return Vec{ { a[0] - t * u[0], a[1] - t * u[1], a[2] - t * u[2] } };
  }

  const Index_map& m_index;
  VertexPointMap m_vpm;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_STRAIGHTEST_WALK_GEOMETRY_H
