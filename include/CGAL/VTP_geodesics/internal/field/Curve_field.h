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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_FIELD_CURVE_FIELD_H
#define CGAL_VTP_GEODESICS_INTERNAL_FIELD_CURVE_FIELD_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/field/Curve_candidate.h>
#include <CGAL/VTP_geodesics/internal/paths/Path_record.h>
#include <CGAL/VTP_geodesics/internal/propagation/Seeding.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The distance field inside the faces, from the record of a computation. The candidates (Curve_candidate.h)
// of face f are
//  - its corners v, with base D(v) (the path to v, then straight to p: a real path, an upper bound);
//  - with the kept field (field/Kept_field.h: keep_field): the windows that crossed f, each a real path to every
//    point of f (straight through its interval, else bent at an end). The least candidate is then the exact
//    distance (Kept_field.h says why; the tests check it);
//  - else, from the trace-back record (Path_record.h), the image of the origin of each corner's recorded offer
//    (the window through which the geodesic reached the corner), unfolded into f when the offer came through f
//    itself or through a face sharing an edge of f at that corner, with base the origin's distance; a bent offer
//    gives its bend point instead. Exact where the geodesic to p comes through one of these images; above it
//    where it comes through a window that reached no corner of f, below it where an image is used for a point
//    its window does not see (doc/VTP_geodesics/curves.txt measures how often);
//  - the sources lying in f (or on its edges), base 0.
// The field in f is the least candidate distance.
class Curve_field
{
public:
  // `distances`: per vertex, in the engine's unit (+infinity: unreached); `labels`: the engine's labels if
  // it has them (else empty: the labels are found along the record).
  // `crossings`: the windows that crossed each face, if the run kept the field (else nullptr).
  Curve_field(const Mesh_arrays& m, const Path_record& record, const std::vector<Seed>& seeds,
              const std::vector<double>& distances, const std::vector<Index>& labels,
              const Kept_field* crossings = nullptr)
    : m_mesh(m), m_record(record), m_seeds(seeds), m_distance(distances), m_crossings(crossings)
  {
    for(auto& c : m_cache)
      c.first = NO_INDEX;
    for(std::size_t i = 0; i < seeds.size(); ++i)
    {
      const Seed& s = seeds[i];
      if(s.kind == Seed::IN_FACE)
        m_face_seeds.emplace_back(s.element, static_cast<Index>(i));
      else if(s.kind == Seed::ON_EDGE)
      {
        m_face_seeds.emplace_back(Mesh_arrays::face(s.element), static_cast<Index>(i));
        if(m.opposite[s.element] != NO_INDEX)
          m_face_seeds.emplace_back(Mesh_arrays::face(m.opposite[s.element]), static_cast<Index>(i));
      }
    }
    std::sort(m_face_seeds.begin(), m_face_seeds.end());
    if(labels.size() == distances.size())
      m_label = labels;
    else
      find_labels();
  }

  double distance(Index v) const { return m_distance[static_cast<std::size_t>(v)]; }
  // whether the field comes from the windows that crossed the faces (exact; its candidates have no gate)
  bool from_crossings() const { return m_crossings != nullptr; }
  // an upper bound of the field all over face f: a corner's distance plus its farthest point of the face
  // (+infinity without the kept field, where the extraction does not use it)
  double face_bound(Index f) const
  {
    if(m_crossings == nullptr)
      return std::numeric_limits<double>::infinity();
    double bound = std::numeric_limits<double>::infinity();
    for(int k = 0; k < 3; ++k)
      bound = (std::min)(bound, distance(m_mesh.source[3 * f + k])
                                  + (std::max)(m_mesh.geometry[3 * f + k].length, m_mesh.geometry[3 * f + (k + 2) % 3].length));
    return bound;
  }
  Index label(Index v) const { return m_label[static_cast<std::size_t>(v)]; }

  // the candidates of face f (see above), in the frame of f
  void candidates(Index f, std::vector<Curve_candidate>& out) const
  {
    if(m_crossings != nullptr)
    {
      // (the extraction asks for a face and its neighbours many times: the last few are kept)
      for(const auto& c : m_cache)
        if(c.first == f)
        {
          out = c.second;
          return;
        }
      build_candidates(f, out);
      m_cache[m_next_cache] = std::make_pair(f, out);
      m_next_cache = (m_next_cache + 1) % m_cache.size();
      return;
    }
    build_candidates(f, out);
  }

  void build_candidates(Index f, std::vector<Curve_candidate>& out) const
  {
    out.clear();
    const Face_frame frame(m_mesh, f);
    for(int k = 0; k < 3; ++k)
    {
      const Index v = m_mesh.source[3 * f + k];
      const double d = distance(v);
      if(!(d < std::numeric_limits<double>::infinity()))
        continue;
      out.push_back(Curve_candidate{frame.x[k], frame.y[k], d, label(v)});
      if(m_crossings != nullptr)
        continue;  // (the windows that crossed f, below, hold every image the corners' offers would give)
      const Offer& o = m_record.vertex[static_cast<std::size_t>(v)];
      if(o.origin == NO_INDEX)
        continue;
      if(o.halfedge == NO_INDEX && o.origin < m_mesh.nv)
      {
        // straight along an edge from the vertex o.origin: its position unfolded around v into f, counted only
        // where no windowed candidate sees the point (an empty window: it sees nothing)
        double p[3][2];
        const Index g = face_with_edge(v, o.origin, p[0][0], p[0][1]);
        if(g != NO_INDEX && g != f && unfold(g, p, 1, f, k))
        {
          Curve_candidate q{p[0][0], p[0][1], distance(o.origin), label(v)};
          q.gated = true;
          q.gx0 = q.gx1 = p[0][0];
          q.gy0 = q.gy1 = p[0][1];
          out.push_back(q);
        }
        continue;
      }
      if(o.halfedge == NO_INDEX)
      {
        // straight from a source point of a face next to f (those of f and its edges are added below)
        if(o.origin >= m_mesh.nv)
        {
          const Seed& s = m_seeds[static_cast<std::size_t>(o.origin - m_mesh.nv)];
          const Index g = s.kind == Seed::IN_FACE ? s.element
                        : (s.kind == Seed::ON_EDGE ? Mesh_arrays::face(s.element) : NO_INDEX);
          if(g == NO_INDEX || has_seed(f, o.origin - m_mesh.nv))
            continue;
          double p[3][2];
          for(int side = 0; side < 2; ++side)
          {
            const Index gg = side == 0 ? g
                           : (s.kind == Seed::ON_EDGE && m_mesh.opposite[s.element] != NO_INDEX
                                ? Mesh_arrays::face(m_mesh.opposite[s.element]) : NO_INDEX);
            if(gg == NO_INDEX)
              continue;
            seed_in_face(s, gg, p[0][0], p[0][1]);
            if(unfold(gg, p, 1, f, k))
            {
              out.push_back(Curve_candidate{p[0][0], p[0][1], 0., s.label});
              break;
            }
          }
        }
        continue;
      }
      const bool bent = is_bent(o);
      const double ix = bent ? o.bend : o.sx, iy = bent ? 0. : o.sy;
      double p[3][2] = { { ix, iy }, { o.b0, 0. }, { o.b1, 0. } };
      const Index g = Mesh_arrays::face(o.halfedge);
      const Face_frame gframe(m_mesh, g);
      for(int i = 0; i < 3; ++i)
        gframe.from_edge_frame(static_cast<int>(o.halfedge % 3), p[i][0], p[i][1], p[i][0], p[i][1]);
      if(unfold(g, p, bent ? 1 : 3, f, k))
      {
        const Halfedge_geometry& hg = m_mesh.geometry[o.halfedge];
        const double base = o.distance - std::sqrt((hg.cx - ix) * (hg.cx - ix) + (hg.cy - iy) * (hg.cy - iy));
        Curve_candidate q{p[0][0], p[0][1], (std::max)(base, 0.), label(v)};
        if(!bent)
        {
          q.gated = true;
          q.gx0 = p[1][0];
          q.gy0 = p[1][1];
          q.gx1 = p[2][0];
          q.gy1 = p[2][1];
        }
        out.push_back(q);
      }
    }
    if(m_crossings != nullptr)
      add_crossing_candidates(*m_crossings, f, frame, [this](Index origin) { return label_of_origin(origin); }, out);
    auto range = std::equal_range(m_face_seeds.begin(), m_face_seeds.end(), std::make_pair(f, Index(-1)),
                                  [](const std::pair<Index, Index>& a, const std::pair<Index, Index>& b) {
                                    return a.first < b.first;
                                  });
    for(auto it = range.first; it != range.second; ++it)
    {
      const Seed& s = m_seeds[static_cast<std::size_t>(it->second)];
      if(s.segment)
      {
        out.push_back(piece_candidate(s.x, s.y, s.x1, s.y1, s.side, s.label));
        continue;
      }
      double x, y;
      seed_in_face(s, f, x, y);
      out.push_back(Curve_candidate{x, y, 0., s.label});
    }
    if(m_crossings != nullptr)
      prune_candidates(frame, out, m_bound);
  }

  // whether seed i lies in face f or on its edges
  bool has_seed(Index f, Index i) const
  {
    return std::binary_search(m_face_seeds.begin(), m_face_seeds.end(), std::make_pair(f, i));
  }
  // whether a seed lies in face f or on its edges
  bool has_seeds(Index f) const
  {
    const auto it = std::lower_bound(m_face_seeds.begin(), m_face_seeds.end(), std::make_pair(f, Index(-1)));
    return it != m_face_seeds.end() && it->first == f;
  }

  // the least candidate distance at (x, y), over the candidates of label `label` (any if NO_INDEX); sets
  // `which` to the index of the least one (-1: none)
  // (the candidates seen through a window count where the segment to the point crosses it; where no such
  // candidate does, they all count)
  static double value(const std::vector<Curve_candidate>& c, double x, double y, Index label, int& which)
  {
    double best = std::numeric_limits<double>::infinity();
    which = -1;
    bool seen = false;
    for(int pass = 0; pass < 2 && !seen; ++pass)
      for(std::size_t i = 0; i < c.size(); ++i)
        if(label == NO_INDEX || c[i].label == label)
        {
          if(c[i].gated)
          {
            if(pass == 0 && !c[i].sees(x, y))
              continue;
            seen = true;
          }
          else if(pass == 1)
            continue;  // (counted in the first pass)
          const double d = c[i].distance_at(x, y);
          if(d < best)
          {
            best = d;
            which = static_cast<int>(i);
          }
        }
    return best;
  }
  static double value(const std::vector<Curve_candidate>& c, double x, double y, Index label = NO_INDEX)
  {
    int which;
    return value(c, x, y, label, which);
  }

  const Mesh_arrays& mesh() const { return m_mesh; }

private:
  Index label_of_origin(Index origin) const
  {
    return origin < m_mesh.nv ? label(origin) : m_seeds[static_cast<std::size_t>(origin - m_mesh.nv)].label;
  }

  // The points p[0 .. n-1] of the frame of face g in the frame of f, where g and f are faces around corner k
  // of f: unfolded across the edges at that corner, the way that crosses fewer edges (at most 16).
  bool unfold(Index g, double p[3][2], int n, Index f, int k) const
  {
    if(g == f)
      return true;
    const Index v = m_mesh.source[3 * f + k];
    // the number of edges to cross each way around v (-1: f not reached)
    int steps[2] = { -1, -1 };
    for(int way = 0; way < 2; ++way)
    {
      Index cur = g;
      for(int s = 1; s <= 16; ++s)
      {
        const Index e = crossing(cur, v, way);
        if(e == NO_INDEX)
          break;
        cur = Mesh_arrays::face(m_mesh.opposite[e]);
        if(cur == f)
        {
          steps[way] = s;
          break;
        }
      }
    }
    const int way = steps[0] < 0 ? 1 : (steps[1] < 0 ? 0 : (steps[1] < steps[0] ? 1 : 0));
    if(steps[way] < 0)
      return false;
    Index cur = g;
    for(int s = 0; s < steps[way]; ++s)
    {
      const Index e = crossing(cur, v, way);
      const Index oe = m_mesh.opposite[e];
      // in the frame of e (cur on its left), then in that of oe (reversed, its face on its left)
      const Face_frame from(m_mesh, cur);
      cur = Mesh_arrays::face(oe);
      const Face_frame to(m_mesh, cur);
      for(int i = 0; i < n; ++i)
      {
        double qx, qy;
        from.to_edge_frame(static_cast<int>(e % 3), p[i][0], p[i][1], qx, qy);
        to.from_edge_frame(static_cast<int>(oe % 3), m_mesh.geometry[e].length - qx, -qy, p[i][0], p[i][1]);
      }
    }
    return true;
  }

  // a face with the edge (v, u) and the position of u in its frame (NO_INDEX: none)
  Index face_with_edge(Index v, Index u, double& x, double& y) const
  {
    for(Index i = m_mesh.corner_begin[v]; i < m_mesh.corner_begin[v + 1]; ++i)
    {
      const Index h = m_mesh.corners[i];  // from v, in face(h)
      const Index g = Mesh_arrays::face(h);
      for(int k = 0; k < 3; ++k)
        if(m_mesh.source[3 * g + k] == u)
        {
          const Face_frame fr(m_mesh, g);
          x = fr.x[k];
          y = fr.y[k];
          return g;
        }
    }
    return NO_INDEX;
  }

  // the edge of face `cur` at its corner v crossed going around v one way (out of v) or the other (into v);
  // NO_INDEX on the border
  Index crossing(Index cur, Index v, int way) const
  {
    int kc = 0;
    while(kc < 3 && m_mesh.source[3 * cur + kc] != v)
      ++kc;
    if(kc == 3)
      return NO_INDEX;
    const Index e = way == 0 ? 3 * cur + kc : 3 * cur + (kc + 2) % 3;
    return m_mesh.opposite[e] == NO_INDEX ? NO_INDEX : e;
  }

  // The position of seed s in the frame of face g (a face of its edge, or its face)
  void seed_in_face(const Seed& s, Index g, double& x, double& y) const
  {
    if(s.kind == Seed::IN_FACE)
    {
      x = s.x;
      y = s.y;
      return;
    }
    Index h = s.element;
    double t = s.x;
    if(Mesh_arrays::face(h) != g)
    {
      t = m_mesh.geometry[h].length - t;
      h = m_mesh.opposite[h];
    }
    Face_frame(m_mesh, g).from_edge_frame(static_cast<int>(h % 3), t, 0., x, y);
  }

  // Whether the offer bends at the end of its window: a bend on the straight line from the image to the
  // vertex (a window ending at a vertex the path goes straight through, up to rounding) is no bend.
  bool is_bent(const Offer& o) const
  {
    if(!(o.bend == o.bend))
      return false;
    const Halfedge_geometry& g = m_mesh.geometry[o.halfedge];
    const double straight = std::hypot(g.cx - o.sx, g.cy - o.sy);
    const double bent = std::hypot(g.cx - o.bend, g.cy) + std::hypot(o.bend - o.sx, o.sy);
    return bent - straight > 1e-12 * bent;
  }

  // The label of each vertex: that of the source its recorded path comes from (NO_INDEX: unreached).
  void find_labels()
  {
    const std::size_t nv = m_distance.size();
    const Index unknown = -2;
    m_label.assign(nv, unknown);
    for(const Seed& s : m_seeds)
      if(s.kind == Seed::AT_VERTEX)
      {
        Index& l = m_label[static_cast<std::size_t>(s.element)];
        l = (l == unknown || s.label < l) ? s.label : l;
      }
    std::vector<Index> chain;
    for(std::size_t v = 0; v < nv; ++v)
    {
      Index w = static_cast<Index>(v);
      Index found = NO_INDEX;
      chain.clear();
      for(std::size_t step = 0; step <= nv; ++step)
      {
        const Index l = m_label[static_cast<std::size_t>(w)];
        if(l != unknown)
        {
          found = l;
          break;
        }
        chain.push_back(w);
        const Offer& o = m_record.vertex[static_cast<std::size_t>(w)];
        if(!(m_distance[static_cast<std::size_t>(w)] < std::numeric_limits<double>::infinity())
           || o.origin == NO_INDEX)
          break;
        if(o.origin >= m_mesh.nv)
        {
          found = m_seeds[static_cast<std::size_t>(o.origin - m_mesh.nv)].label;
          break;
        }
        w = o.origin;
      }
      for(Index u : chain)
        m_label[static_cast<std::size_t>(u)] = found;
    }
  }

  const Mesh_arrays& m_mesh;
  const Path_record& m_record;
  const std::vector<Seed>& m_seeds;
  const std::vector<double>& m_distance;
  const Kept_field* m_crossings;
  std::vector<Index> m_label;
  std::vector<std::pair<Index, Index> > m_face_seeds;  // (face, seed), sorted
  mutable std::vector<std::pair<Index, double> > m_bound;  // (prune_candidates())
  mutable std::array<std::pair<Index, std::vector<Curve_candidate> >, 8> m_cache;  // the faces last built
  mutable std::size_t m_next_cache = 0;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_FIELD_CURVE_FIELD_H
