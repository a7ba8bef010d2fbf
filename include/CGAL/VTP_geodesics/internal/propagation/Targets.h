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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_TARGETS_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_TARGETS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A point whose distance is wanted: a vertex, or a point of a face given in the frame of each of the
// face's half-edges (so that the windows of any list crossing the face can be evaluated at it). The stop
// rule (Stop_rule.h) tracks the distances of the targets; the path record (Path_record.h) keeps how
// each was reached.
struct Target
{
  Index vertex = NO_INDEX;  // a vertex target; otherwise:
  Index face = NO_INDEX;
  double x[3] = { 0., 0., 0. }, y[3] = { 0., 0., 0. };  // the point in the frame of half-edge 3f + k
  double corner_distance[3] = { 0., 0., 0. };           // its distance to vertex source(3f + k)
};

// The target at the point (px, py) of face f, given in the frame of half-edge 3f: its coordinates in the
// frames of the three half-edges of f, and its distances to the corners.
inline Target face_target(const Mesh_arrays& m, Index f, double px, double py)
{
  Target t;
  t.face = f;
  const Face_frame frame(m, f);
  for(int k = 0; k < 3; ++k)
  {
    double qy;
    frame.to_edge_frame(k, px, py, t.x[k], qy);
    t.y[k] = (std::max)(0., qy);
    const double rx = px - frame.x[k], ry = py - frame.y[k];
    t.corner_distance[k] = std::sqrt(rx * rx + ry * ry);
  }
  return t;
}

// The target at the point of face f with barycentric coordinates (b0, b1, b2) (see seed_from_barycentric()
// in Seeding.h). A point with two zero coordinates is the vertex it denotes. A point of a face of (almost)
// zero area is taken on the longest edge of the face, in the face on the other side of that edge when that
// one is not degenerate (windows cannot cross a face of zero area).
inline Target target_from_barycentric(const Mesh_arrays& m, Index f, double b0, double b1, double b2)
{
  const Index h0 = 3 * f;
  const double b[3] = { b0, b1, b2 };
  for(int k = 0; k < 3; ++k)
    if(b[(k + 1) % 3] == 0. && b[(k + 2) % 3] == 0.)
    {
      Target t;
      t.vertex = m.source[h0 + k];
      return t;
    }
  const Face_frame frame(m, f);
  double px = b1 * frame.x[1] + b2 * frame.x[2], py = b2 * frame.y[2];
  if(m.is_degenerate_face[f])
  {
    const int k = longest_edge(m, f);
    const double length = m.geometry[h0 + k].length;
    const double t = (std::min)((std::max)(frame.projection(k, px, py), 0.), length);
    const Index o = m.opposite[h0 + k];
    if(o != NO_INDEX && !m.is_degenerate_face[Mesh_arrays::face(o)])
    {
      const Index g = Mesh_arrays::face(o);
      Face_frame(m, g).from_edge_frame(static_cast<int>(o % 3), length - t, 0., px, py);
      return face_target(m, g, px, py);
    }
    frame.from_edge_frame(k, t, 0., px, py);
  }
  return face_target(m, f, px, py);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_TARGETS_H
