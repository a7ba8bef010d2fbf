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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDERS_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDERS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/curves/Curve_border_face.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_pieces.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The borders between the cells from the kept field (Curve_field::from_crossings(), exact), wherever the label
// of the least candidate changes, not only where the labels of the vertices do:
//  - on an edge, every change of the label along it (Curve_pieces::border_changes(): the envelope of the
//    candidates of its two faces, exact);
//  - which edges are searched: those of the faces whose corners have two or three labels, or that hold a
//    source, and, from there, of every face across an edge where a change was found. This finds every change:
//    a point p of cell b in a face whose corners are not in b is joined to source b by a shortest path that
//    stays in cell b; going back along it from p, the faces it crosses have no corner in b until one does, and
//    that one has a corner of another label too (it shares an edge with the one before); each edge it crosses
//    on the way has a change (points of cell b between two corners of other labels). So the faces reached by
//    the search are those the cells poke into from a face with several corner labels.
//  - in a face, the changes on its edges are joined inside it (Curve_border_face.h): pieces, junctions;
//  - the cells' areas in a face: per label, the area enclosed by its arcs of the face's border and the pieces
//    that have it on one side (Green's formula: they add up to the face's area to rounding).
// A cell lying in one face without reaching its edges (a source in the face, nearer than any edge) is not
// found.
class Exact_borders
{
public:
  Exact_borders(Curve_pieces& pieces, double tolerance)
    : m_pieces(pieces), m_tolerance(tolerance), m_face(pieces, tolerance)
  {}

  std::size_t edge_fallbacks = 0;      // edges whose sweep gave up (rounding)
  std::size_t junction_fallbacks = 0;  // junctions not found inside their face (kept at their guess)
  std::size_t faces = 0;               // faces searched
  std::size_t poked_faces = 0;         // of which with one corner label, reached from a neighbour
  std::size_t many_ends = 0;           // faces with more than three changes on their edges

  // `set_index(a, b)`: the set of the border of cells a and b; `add_area(label, area, bound)`.
  template <class Set_index, class Add_area>
  void run(std::vector<Curve_piece>& out, Set_index set_index, Add_area add_area)
  {
    const Curve_field& field = m_pieces.field();
    const Mesh_arrays& m = field.mesh();
    m_in.assign(static_cast<std::size_t>(m.nf), 0);
    m_edges.clear();
    m_all.clear();
    std::vector<Index> work;
    for(Index f = 0; f < m.nf; ++f)
    {
      Index l[3];
      if(!labels(f, l))
        continue;
      if(l[0] != l[1] || l[1] != l[2] || field.has_seeds(f))
      {
        m_in[static_cast<std::size_t>(f)] = 1;
        work.push_back(f);
      }
    }
    while(!work.empty())
    {
      const Index f = work.back();
      work.pop_back();
      ++faces;
      face(f, work, out, set_index, add_area);
    }
    for(Index f = 0; f < m.nf; ++f)
    {
      Index l[3];
      if(!m_in[static_cast<std::size_t>(f)] && labels(f, l))
        add_area(l[0], face_area(m, f), 0.);
    }
  }

private:
  bool labels(Index f, Index l[3]) const
  {
    const Curve_field& field = m_pieces.field();
    const Mesh_arrays& m = field.mesh();
    for(int k = 0; k < 3; ++k)
    {
      l[k] = field.label(m.source[3 * f + k]);
      if(l[k] == NO_INDEX)
        return false;  // (a face with an unreached corner is in no cell)
    }
    return true;
  }

  static Index lower_of(const Mesh_arrays& m, Index h)
  {
    const Index o = m.opposite[h];
    return (o == NO_INDEX || h < o) ? h : o;
  }

  // the changes on the edge of the lower half-edge c: [first, first + count) of m_all
  std::pair<std::size_t, std::size_t> edge(Index c)
  {
    const auto known = m_edges.find(c);
    if(known != m_edges.end())
      return known->second;
    const Curve_field& field = m_pieces.field();
    const Mesh_arrays& m = field.mesh();
    if(!m_pieces.border_changes(c, field.label(m.source[c]), field.label(m.target(c)), m_changes))
      ++edge_fallbacks;
    const std::pair<std::size_t, std::size_t> r(m_all.size(), m_changes.size());
    m_all.insert(m_all.end(), m_changes.begin(), m_changes.end());
    m_edges.emplace(c, r);
    return r;
  }

  static std::int64_t edge_key(Index lower, std::size_t rank)
  {
    return (static_cast<std::int64_t>(lower) << 20) + static_cast<std::int64_t>(rank);
  }

  template <class Set_index, class Add_area>
  void face(Index f, std::vector<Index>& work, std::vector<Curve_piece>& out, Set_index& set_index, Add_area& add_area)
  {
    const Curve_field& field = m_pieces.field();
    const Mesh_arrays& m = field.mesh();
    const Face_frame fr(m, f);
    Index l[3];
    labels(f, l);
    if(l[0] == l[1] && l[1] == l[2] && !field.has_seeds(f))
      ++poked_faces;
    // the changes on the edges, counterclockwise; the faces across an edge with changes join the search
    std::vector<Border_face::Node>& nodes = m_face.nodes;
    std::vector<Border_face::Crossing>& crossings = m_face.crossings;
    nodes.clear();
    crossings.clear();
    for(int k = 0; k < 3; ++k)
    {
      const Index h = 3 * f + k, lower = lower_of(m, h);
      const std::pair<std::size_t, std::size_t> r = edge(lower);
      const Index o = m.opposite[h];
      if(r.second > 0 && o != NO_INDEX)
      {
        const Index g = Mesh_arrays::face(o);
        Index lg[3];
        if(!m_in[static_cast<std::size_t>(g)] && labels(g, lg))
        {
          m_in[static_cast<std::size_t>(g)] = 1;
          work.push_back(g);
        }
      }
      for(std::size_t i = 0; i < r.second; ++i)
      {
        const std::size_t rank = h == lower ? i : r.second - 1 - i;  // (changes are listed along the lower one)
        const Label_change& ch = m_all[r.first + rank];
        Border_face::Node n;
        n.point = Curve_pieces::edge_curve_point(h, lower, ch.u);
        const double s = h == lower ? ch.u : 1. - ch.u;
        m_pieces.edge_point(h, s, n.x, n.y);
        n.key = edge_key(lower, rank);
        nodes.push_back(n);
        crossings.push_back(Border_face::Crossing{ h == lower ? ch.from : ch.to, h == lower ? ch.to : ch.from, k, s });
      }
    }
    const std::size_t n = crossings.size();
    if(n == 0)
    {
      add_area(l[0], face_area(m, f), 0.);
      return;
    }
    for(std::size_t i = 0; i < n; ++i)
      CGAL_assertion(crossings[i].to == crossings[(i + 1) % n].from);
    bool many = false;
    Border_face::Plan& plan = m_face.join(f, many);
    many_ends += many ? 1 : 0;
    junction_fallbacks += static_cast<std::size_t>(plan.bad_junctions);
    m_pieces.undecided += plan.undecided;
    // the pieces, and the cells' areas (Green: twice the area is the sum of x dy - y dx along the boundaries)
    m_twice.clear();
    auto add_twice = [&](Index label, double a, double bound) {
      for(auto& t : m_twice)
        if(t.first == label)
        {
          t.second.first += a;
          t.second.second += bound;
          return;
        }
      m_twice.emplace_back(label, std::make_pair(a, bound));
    };
    std::int64_t junction = 0;
    const std::int64_t junction_base = static_cast<std::int64_t>(3) * m.nf + f;
    for(Border_face::Node& node : plan.nodes)
      if(node.key < 0)
        node.key = (junction_base << 20) + junction++;
    for(std::size_t i = 0; i < plan.links.size(); ++i)
    {
      const Border_face::Link& k = plan.links[i];
      Curve_piece piece;
      piece.set = set_index(k.left, k.right);
      piece.key[0] = plan.nodes[k.a].key;
      piece.key[1] = plan.nodes[k.b].key;
      piece.points = std::move(plan.points[i]);
      double twice = 0., x0, y0, x1, y1;
      for(std::size_t j = 0; j + 1 < piece.points.size(); ++j)
      {
        frame_point(fr, piece.points[j], x0, y0);
        frame_point(fr, piece.points[j + 1], x1, y1);
        twice += x0 * y1 - x1 * y0;
      }
      const double bound = m_tolerance * polyline_length(m, f, piece.points);
      add_twice(k.left, twice, bound);
      add_twice(k.right, -twice, bound);
      out.push_back(std::move(piece));
    }
    for(std::size_t i = 0; i < n; ++i)  // the arcs of the face's border, each in the cell of its label
    {
      m_arc.clear();
      m_face.arc(fr, i, m_arc);
      double twice = 0.;
      for(std::size_t j = 0; j + 1 < m_arc.size(); ++j)
        twice += m_arc[j].first * m_arc[j + 1].second - m_arc[j + 1].first * m_arc[j].second;
      add_twice(crossings[i].to, twice, 0.);
    }
    for(const auto& t : m_twice)
      add_area(t.first, 0.5 * t.second.first, t.second.second);
  }

  Curve_pieces& m_pieces;
  double m_tolerance;
  std::vector<char> m_in;  // per face: in the search
  std::unordered_map<Index, std::pair<std::size_t, std::size_t> > m_edges;  // lower half-edge -> its changes
  std::vector<Label_change> m_all, m_changes;
  Border_face m_face;  // (the changes on the border of the face at hand, joined)
  std::vector<std::pair<Index, std::pair<double, double> > > m_twice;
  std::vector<std::pair<double, double> > m_arc;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDERS_H
