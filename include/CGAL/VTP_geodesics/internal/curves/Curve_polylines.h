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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_POLYLINES_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_POLYLINES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The curves as polylines on the faces: their points and pieces, lengths and areas in a face, and the
// joining of the pieces into curves.

// A point of a curve: face f and its barycentric coordinates (corners source(3f + k)).
struct Curve_point
{
  Index face;
  double b[3];
};

// The part of a curve inside one face, from an end to the other; an end is an edge point (key, of an isoline:
// four times the lower half-edge of the edge, plus the crossing's rank along it; of a border: twice the lower
// half-edge) or a junction of three cells (key: twice the number of half-edges, plus the face).
struct Curve_piece
{
  Index set;
  std::int64_t key[2];
  std::vector<Curve_point> points;
};

// the area of face f (from its frame)
inline double face_area(const Mesh_arrays& m, Index f)
{
  const Halfedge_geometry g = m.geometry[3 * f];
  return 0.5 * g.length * g.cy;
}

inline void frame_point(const Face_frame& fr, const Curve_point& p, double& x, double& y)
{
  x = p.b[1] * fr.x[1] + p.b[2] * fr.x[2];
  y = p.b[2] * fr.y[2];
}

// the area of the polygon of corner k of face f, the points of `first` in order, then those of `second`
// backwards (if not null)
inline double polygon_area(const Mesh_arrays& m, Index f, int k, const std::vector<Curve_point>& first,
                         const std::vector<Curve_point>* second)
{
  const Face_frame fr(m, f);
  std::vector<std::pair<double, double> > q;
  q.emplace_back(fr.x[k], fr.y[k]);
  double x, y;
  for(const Curve_point& p : first)
  {
    frame_point(fr, p, x, y);
    q.emplace_back(x, y);
  }
  if(second != nullptr)
    for(std::size_t i = second->size(); i-- > 0;)
    {
      frame_point(fr, (*second)[i], x, y);
      q.emplace_back(x, y);
    }
  double twice = 0.;
  for(std::size_t i = 0; i < q.size(); ++i)
  {
    const std::pair<double, double>& a = q[i];
    const std::pair<double, double>& b = q[(i + 1) % q.size()];
    twice += a.first * b.second - a.second * b.first;
  }
  return 0.5 * std::abs(twice);
}

inline double polyline_length(const Mesh_arrays& m, Index f, const std::vector<Curve_point>& points)
{
  const Face_frame fr(m, f);
  double length = 0., x0 = 0., y0 = 0., x, y;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    frame_point(fr, points[i], x, y);
    if(i > 0)
      length += std::hypot(x - x0, y - y0);
    x0 = x;
    y0 = y;
  }
  return length;
}

// A curve of a set (a level, or a pair of cells): its points, each in a face, consecutive points in a
// common face; closed or open (an open curve ends on the border of the mesh, at a junction of three cells,
// or where a corner of a face is unreached).
struct Extracted_curve
{
  Index set;
  bool closed;
  std::vector<Curve_point> points;
};

// Joins the pieces of each set into curves, at the keys of their ends.
inline std::vector<Extracted_curve> chain_pieces(std::vector<Curve_piece>& pieces)
{
  std::stable_sort(pieces.begin(), pieces.end(),
                   [](const Curve_piece& a, const Curve_piece& b) { return a.set < b.set; });
  std::vector<Extracted_curve> curves;
  std::vector<char> used(pieces.size(), 0);
  std::unordered_map<std::int64_t, std::vector<std::size_t> > at;  // key -> 2 * piece + end
  for(std::size_t begin = 0; begin < pieces.size();)
  {
    std::size_t end = begin;
    while(end < pieces.size() && pieces[end].set == pieces[begin].set)
      ++end;
    at.clear();
    for(std::size_t i = begin; i < end; ++i)
      for(int e = 0; e < 2; ++e)
        at[pieces[i].key[e]].push_back(2 * i + static_cast<std::size_t>(e));
    auto walk = [&](std::size_t i, int e) {
      Extracted_curve curve;
      curve.set = pieces[i].set;
      curve.closed = false;
      const std::size_t first = i;
      for(;;)
      {
        used[i] = 1;
        std::vector<Curve_point>& p = pieces[i].points;
        if(e == 1)
          std::reverse(p.begin(), p.end());
        curve.points.insert(curve.points.end(), p.begin() + (curve.points.empty() ? 0 : 1), p.end());
        const std::int64_t key = pieces[i].key[1 - e];
        std::size_t next = pieces.size();
        int next_end = 0;
        for(std::size_t x : at[key])
          if(x / 2 != i && (!used[x / 2] || x / 2 == first))
          {
            next = x / 2;
            next_end = static_cast<int>(x % 2);
            break;
          }
        if(next == first)
        {
          curve.closed = true;
          curve.points.pop_back();
          break;
        }
        if(next == pieces.size())
          break;
        i = next;
        e = next_end;
      }
      curves.push_back(std::move(curve));
    };
    for(std::size_t i = begin; i < end; ++i)  // open curves from their ends
      for(int e = 0; e < 2 && !used[i]; ++e)
        if(at[pieces[i].key[e]].size() == 1)
          walk(i, e);
    for(std::size_t i = begin; i < end; ++i)  // closed curves
      if(!used[i])
        walk(i, 0);
    begin = end;
  }
  return curves;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_POLYLINES_H
