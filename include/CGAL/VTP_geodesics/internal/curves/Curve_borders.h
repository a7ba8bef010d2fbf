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

#include <CGAL/VTP_geodesics/internal/curves/Curve_pieces.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
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
//  - in a face, the changes on its edges (counterclockwise, each from a label to the next) are joined inside
//    it: two -> one piece; three (three labels) -> a junction where the three labels' least are equal
//    (Curve_pieces::exact_junction(), from the circles that hold there: exact); more -> the planar ways to
//    join them (an arc whose two neighbours have one label closed by a piece, or by a junction if they differ,
//    again on what is left; searched depth first, a way dropped where a junction is not found in the face;
//    every way if none is left), each scored by its junctions (found inside the face or not), by the arcs of one
//    label it puts in two regions where the straight segment between them has that label all along (exact),
//    and by the label it gives at probe points against the field's; the best kept. Then each piece runs between its ends along the
//    points where its two labels change along lines across its chord (exact).
//  - the cells' areas in a face: per label, the area enclosed by its arcs of the face's border and the pieces
//    that have it on one side (Green's formula: they add up to the face's area to rounding).
// A cell lying in one face without reaching its edges (a source in the face, nearer than any edge) is not
// found.
class Exact_borders
{
public:
  Exact_borders(Curve_pieces& pieces, double tolerance) : m_pieces(pieces), m_tolerance(tolerance) {}

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
  struct Node
  {
    double x, y;  // in the frame of the face
    Curve_point point;
    std::int64_t key;
  };
  struct Crossing  // a change on the face's border, counterclockwise: from label `from` to `to`
  {
    Index from, to;
    int edge;  // edge k of the face (half-edge 3f + k), abscissa s along it
    double s;
  };
  struct End  // an end of the reduction: a node where the label changes from `from` to `to` (counterclockwise),
  {           // `region`: the region of the arc that follows it
    std::size_t node;
    Index from, to;
    int region;
  };
  struct Link  // a piece from node a to node b, label `left` on its left
  {
    std::size_t a, b;
    Index left, right;
  };
  struct Plan
  {
    std::vector<Node> nodes;
    std::vector<Link> links;
    std::vector<std::vector<Curve_point> > points;  // per link, from a to b
    int bad_junctions = 0;
    std::size_t undecided = 0;
    std::vector<int> region;  // per arc of the face's border, its region (the least arc in it)
  };

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
    m_nodes.clear();
    m_crossings.clear();
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
        Node n;
        n.point = Curve_pieces::edge_curve_point(h, lower, ch.u);
        const double s = h == lower ? ch.u : 1. - ch.u;
        m_pieces.edge_point(h, s, n.x, n.y);
        n.key = edge_key(lower, rank);
        m_nodes.push_back(n);
        m_crossings.push_back(Crossing{ h == lower ? ch.from : ch.to, h == lower ? ch.to : ch.from, k, s });
      }
    }
    const std::size_t n = m_crossings.size();
    if(n == 0)
    {
      add_area(l[0], face_area(m, f), 0.);
      return;
    }
    for(std::size_t i = 0; i < n; ++i)
      CGAL_assertion(m_crossings[i].to == m_crossings[(i + 1) % n].from);
    field.candidates(f, m_c);
    // the ways to join the changes inside the face: those whose junctions are all found in it, else every way
    std::vector<std::vector<int> > ways;
    if(n <= 3)
      ways.emplace_back();
    else
    {
      ++many_ends;
      find_witnesses(fr);
      std::map<std::vector<int>, std::vector<int> > found;
      std::vector<End> ends(n);
      for(std::size_t i = 0; i < n; ++i)
        ends[i] = End{ i, m_crossings[i].from, m_crossings[i].to, static_cast<int>(i) };
      std::vector<int> parent(n), choice;
      std::iota(parent.begin(), parent.end(), 0);
      std::vector<std::array<int, 3> > triples;
      std::vector<Node> nodes(m_nodes);
      std::size_t explored = 0;
      search(f, fr, ends, parent, triples, nodes, choice, found, explored);
      if(found.empty())
      {
        explored = 0;
        enumerate(ends, parent, triples, choice, found, explored);
      }
      for(auto& w : found)
        ways.push_back(std::move(w.second));
    }
    std::size_t best = 0;
    double best_score = std::numeric_limits<double>::infinity();
    m_plans.resize((std::max)(m_plans.size(), ways.size()));
    for(std::size_t w = 0; w < ways.size(); ++w)
    {
      build(f, fr, ways[w], m_plans[w]);
      if(ways.size() == 1)
        break;
      std::size_t split = 0;  // (arcs that are one region, in two)
      for(const auto& pair : m_witnesses)
        split += m_plans[w].region[pair.first] != m_plans[w].region[pair.second] ? 1 : 0;
      const double score = 1000. * (static_cast<double>(m_plans[w].bad_junctions) + static_cast<double>(split))
                           + 100. * static_cast<double>(disagreements(f, fr, m_plans[w]))
                           + static_cast<double>(m_plans[w].undecided);
      if(score < best_score)
      {
        best_score = score;
        best = w;
      }
    }
    Plan& plan = m_plans[best];
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
    for(Node& node : plan.nodes)
      if(node.key < 0)
        node.key = (junction_base << 20) + junction++;
    for(std::size_t i = 0; i < plan.links.size(); ++i)
    {
      const Link& k = plan.links[i];
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
      arc(fr, i, m_arc);
      double twice = 0.;
      for(std::size_t j = 0; j + 1 < m_arc.size(); ++j)
        twice += m_arc[j].first * m_arc[j + 1].second - m_arc[j + 1].first * m_arc[j].second;
      add_twice(m_crossings[i].to, twice, 0.);
    }
    for(const auto& t : m_twice)
      add_area(t.first, 0.5 * t.second.first, t.second.second);
  }

  // the arc of the face's border from crossing i to the next one, counterclockwise (corners included)
  void arc(const Face_frame& fr, std::size_t i, std::vector<std::pair<double, double> >& points) const
  {
    const std::size_t n = m_crossings.size(), j = (i + 1) % n;
    points.emplace_back(m_nodes[i].x, m_nodes[i].y);
    const int a = m_crossings[i].edge, b = m_crossings[j].edge;
    if(!(j > i && a == b))
    {
      int k = a;
      do
      {
        k = (k + 1) % 3;
        points.emplace_back(fr.x[k], fr.y[k]);
      } while(k != b);
    }
    points.emplace_back(m_nodes[j].x, m_nodes[j].y);
  }

  static int find(std::vector<int>& parent, int i)
  {
    while(parent[static_cast<std::size_t>(i)] != i)
      i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    return i;
  }

  // One step of the reduction: the arc after end p is closed. If the labels on both sides of it are the same,
  // by a piece between its two ends (the regions on both sides are one), else by a junction of the three labels,
  // which becomes an end from the first label to the third. `link(a, b, left, right)`, `junction(p, q)` (the
  // node of the junction of ends p and q).
  template <class Link_fn, class Junction_fn>
  static void reduce(std::vector<End>& ends, std::size_t p, std::vector<int>& parent,
                     std::vector<std::array<int, 3> >& triples, Link_fn link, Junction_fn junction)
  {
    const std::size_t n = ends.size(), q = (p + 1) % n;
    const Index x = ends[p].from, y = ends[p].to, z = ends[q].to;
    const int before = ends[(p + n - 1) % n].region, mid = ends[p].region, after = ends[q].region;
    if(x == z)
    {
      link(ends[p].node, ends[q].node, x, y);
      parent[static_cast<std::size_t>(find(parent, before))] = find(parent, after);
      ends.erase(ends.begin() + static_cast<std::ptrdiff_t>((std::max)(p, q)));
      ends.erase(ends.begin() + static_cast<std::ptrdiff_t>((std::min)(p, q)));
      return;
    }
    const std::size_t j = junction(p, q);
    link(ends[p].node, j, x, y);
    link(ends[q].node, j, y, z);
    triples.push_back({ { before, mid, after } });
    ends[p] = End{ j, x, z, after };
    ends.erase(ends.begin() + static_cast<std::ptrdiff_t>(q));
  }

  // Every planar way to join the ends (by the order in which arcs are closed), once per topology (the regions
  // that are one, and the regions around each junction): `found` maps a topology to the choices that give it.
  void enumerate(const std::vector<End>& ends, const std::vector<int>& parent,
                 const std::vector<std::array<int, 3> >& triples, std::vector<int>& choice,
                 std::map<std::vector<int>, std::vector<int> >& found, std::size_t& explored) const
  {
    if(found.size() >= 16 || ++explored > 4000)
      return;
    if(ends.size() <= 3)
    {
      found.emplace(topology(ends, parent, triples), choice);
      return;
    }
    for(std::size_t p = 0; p < ends.size(); ++p)
    {
      std::vector<End> e(ends);
      std::vector<int> pa(parent);
      std::vector<std::array<int, 3> > t(triples);
      std::size_t next_node = m_crossings.size() + t.size();
      reduce(e, p, pa, t, [](std::size_t, std::size_t, Index, Index) {},
             [&](std::size_t, std::size_t) { return next_node++; });
      choice.push_back(static_cast<int>(p));
      enumerate(e, pa, t, choice, found, explored);
      choice.pop_back();
    }
  }

  // As enumerate(), each junction solved where it is made (as build() does), the ways where one is not found in
  // the face dropped there; the arcs closed first are those whose two sides are one region for sure
  // (find_witnesses()), then those of a label met once. At most 8 ways.
  void search(Index f, const Face_frame& fr, const std::vector<End>& ends, const std::vector<int>& parent,
              const std::vector<std::array<int, 3> >& triples, std::vector<Node>& nodes, std::vector<int>& choice,
              std::map<std::vector<int>, std::vector<int> >& found, std::size_t& explored)
  {
    if(found.size() >= 8 || ++explored > 400)
      return;
    if(ends.size() <= 3)
    {
      if(ends.size() == 3)
      {
        const Index l[3] = { ends[0].from, ends[1].from, ends[2].from };
        double gx = 0., gy = 0.;
        for(const End& e : ends)
        {
          gx += nodes[e.node].x / 3.;
          gy += nodes[e.node].y / 3.;
        }
        Node node;
        if(!junction_node(f, fr, l, gx, gy, nodes[ends[0].node], nodes[ends[1].node], nodes[ends[2].node], nodes,
                          node))
          return;
      }
      found.emplace(topology(ends, parent, triples), choice);
      return;
    }
    const std::size_t n = ends.size();
    int rank[64];
    for(std::size_t p = 0; p < n && p < 64; ++p)
    {
      const std::size_t before = (p + n - 1) % n, q = (p + 1) % n;
      int count = 0;
      for(const End& e : ends)
        count += e.to == ends[p].to ? 1 : 0;
      bool witnessed = false;
      for(const auto& w : m_witnesses)
      {
        const int a = find_const(parent, static_cast<int>(w.first)), b = find_const(parent, static_cast<int>(w.second));
        const int r0 = find_const(parent, ends[before].region), r1 = find_const(parent, ends[q].region);
        witnessed = witnessed || (a == r0 && b == r1) || (a == r1 && b == r0);
      }
      rank[p] = ends[p].from == ends[q].to ? (witnessed ? 0 : 2) : (count == 1 ? 1 : 3);
    }
    for(int r = 0; r < 4; ++r)
      for(std::size_t p = 0; p < n && p < 64; ++p)
      {
        if(rank[p] != r)
          continue;
        std::vector<End> e(ends);
        std::vector<int> pa(parent);
        std::vector<std::array<int, 3> > t(triples);
        const std::size_t size = nodes.size();
        bool failed = false;
        const double cx = (fr.x[0] + fr.x[1] + fr.x[2]) / 3., cy = (fr.y[0] + fr.y[1] + fr.y[2]) / 3.;
        reduce(e, p, pa, t, [](std::size_t, std::size_t, Index, Index) {},
               [&](std::size_t a, std::size_t b) {
                 const Node na = nodes[e[a].node], nb = nodes[e[b].node];
                 const Index l[3] = { e[a].from, e[a].to, e[b].to };
                 Node node;
                 failed = !junction_node(f, fr, l, (na.x + nb.x + cx) / 3., (na.y + nb.y + cy) / 3., na, nb, nb,
                                         nodes, node);
                 nodes.push_back(node);
                 return nodes.size() - 1;
               });
        if(!failed)
        {
          choice.push_back(static_cast<int>(p));
          search(f, fr, e, pa, t, nodes, choice, found, explored);
          choice.pop_back();
        }
        nodes.resize(size);
      }
  }

  static int find_const(const std::vector<int>& parent, int i)
  {
    while(parent[static_cast<std::size_t>(i)] != i)
      i = parent[static_cast<std::size_t>(i)];
    return i;
  }

  // The topology of a way to join the ends, as a key: each arc's region (named by its least arc), then the
  // regions around each junction.
  static std::vector<int> topology(const std::vector<End>& ends, const std::vector<int>& parent,
                                   const std::vector<std::array<int, 3> >& triples)
  {
    {
      std::vector<int> p(parent);
      std::vector<std::array<int, 3> > t(triples);
      if(ends.size() == 3)
        t.push_back({ { ends[0].region, ends[1].region, ends[2].region } });
      // (each region named by the least arc in it)
      std::vector<int> least(p.size(), static_cast<int>(p.size()));
      for(std::size_t i = 0; i < p.size(); ++i)
      {
        int& l = least[static_cast<std::size_t>(find(p, static_cast<int>(i)))];
        l = (std::min)(l, static_cast<int>(i));
      }
      std::vector<int> key;
      for(std::size_t i = 0; i < p.size(); ++i)
        key.push_back(least[static_cast<std::size_t>(find(p, static_cast<int>(i)))]);
      std::vector<std::array<int, 3> > sorted;
      for(std::array<int, 3> a : t)
      {
        for(int& r : a)
          r = least[static_cast<std::size_t>(find(p, r))];
        std::sort(a.begin(), a.end());
        sorted.push_back(a);
      }
      std::sort(sorted.begin(), sorted.end());
      key.push_back(-1);
      for(const auto& a : sorted)
        key.insert(key.end(), a.begin(), a.end());
      return key;
    }
  }

  // the plan of the choices `choice`: its nodes (the crossings, then the junctions), its links and their points
  void build(Index f, const Face_frame& fr, const std::vector<int>& choice, Plan& plan)
  {
    const std::size_t n = m_crossings.size();
    plan.nodes.assign(m_nodes.begin(), m_nodes.end());  // (a junction's key is set when the plan is kept)
    plan.links.clear();
    plan.bad_junctions = 0;
    plan.undecided = 0;
    std::vector<End> ends(n);
    for(std::size_t i = 0; i < n; ++i)
      ends[i] = End{ i, m_crossings[i].from, m_crossings[i].to, static_cast<int>(i) };
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<std::array<int, 3> > triples;
    const double cx = (fr.x[0] + fr.x[1] + fr.x[2]) / 3., cy = (fr.y[0] + fr.y[1] + fr.y[2]) / 3.;
    auto link = [&](std::size_t a, std::size_t b, Index left, Index right) {
      plan.links.push_back(Link{ a, b, left, right });
    };
    // a junction of labels (x, y, z), from a guess
    auto solve = [&](const Index l[3], double gx, double gy, std::size_t a, std::size_t b, std::size_t c) {
      Node node;
      if(!junction_node(f, fr, l, gx, gy, plan.nodes[a], plan.nodes[b], plan.nodes[c], plan.nodes, node))
        ++plan.bad_junctions;
      plan.nodes.push_back(node);
      return plan.nodes.size() - 1;
    };
    std::size_t step = 0;
    while(ends.size() > 3)
    {
      const std::size_t p = static_cast<std::size_t>(choice[step++]) % ends.size();
      reduce(ends, p, parent, triples, link, [&](std::size_t a, std::size_t b) {
        const Node &na = plan.nodes[ends[a].node], &nb = plan.nodes[ends[b].node];
        const Index l[3] = { ends[a].from, ends[a].to, ends[b].to };
        return solve(l, (na.x + nb.x + cx) / 3., (na.y + nb.y + cy) / 3., ends[a].node, ends[b].node, ends[b].node);
      });
    }
    if(ends.size() == 3)
    {
      const Index l[3] = { ends[0].from, ends[1].from, ends[2].from };
      double gx = 0., gy = 0.;
      for(const End& e : ends)
      {
        gx += plan.nodes[e.node].x / 3.;
        gy += plan.nodes[e.node].y / 3.;
      }
      const std::size_t j = solve(l, gx, gy, ends[0].node, ends[1].node, ends[2].node);
      for(const End& e : ends)
        link(e.node, j, e.from, e.to);
    }
    else if(ends.size() == 2)
      link(ends[0].node, ends[1].node, ends[0].from, ends[0].to);
    plan.points.resize(plan.links.size());
    for(std::size_t i = 0; i < plan.links.size(); ++i)
      link_points(f, fr, plan, plan.links[i], plan.points[i]);
    plan.region.assign(n, static_cast<int>(n));
    for(std::size_t i = 0; i < n; ++i)
    {
      int& r = plan.region[static_cast<std::size_t>(find(parent, static_cast<int>(i)))];
      r = (std::min)(r, static_cast<int>(i));
    }
    for(std::size_t i = 0; i < n; ++i)
      plan.region[i] = plan.region[static_cast<std::size_t>(find(parent, static_cast<int>(i)))];
  }

  // The pairs of arcs of the face's border with one label that are one region for sure: the segment between
  // their middles (moved by 1% towards the middle of the face) has that label all along (Label_envelope).
  void find_witnesses(const Face_frame& fr)
  {
    const std::size_t n = m_crossings.size();
    const double cx = (fr.x[0] + fr.x[1] + fr.x[2]) / 3., cy = (fr.y[0] + fr.y[1] + fr.y[2]) / 3.;
    const double size = std::abs(fr.x[1]) + std::abs(fr.x[2]) + std::abs(fr.y[2]);
    m_middles.resize(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      m_arc.clear();
      arc(fr, i, m_arc);
      double length = 0.;
      for(std::size_t j = 0; j + 1 < m_arc.size(); ++j)
        length += std::hypot(m_arc[j + 1].first - m_arc[j].first, m_arc[j + 1].second - m_arc[j].second);
      double x = m_arc.front().first, y = m_arc.front().second, left = 0.5 * length;
      for(std::size_t j = 0; j + 1 < m_arc.size(); ++j)
      {
        const double l = std::hypot(m_arc[j + 1].first - m_arc[j].first, m_arc[j + 1].second - m_arc[j].second);
        if(l >= left && l > 0.)
        {
          x = m_arc[j].first + left / l * (m_arc[j + 1].first - m_arc[j].first);
          y = m_arc[j].second + left / l * (m_arc[j + 1].second - m_arc[j].second);
          break;
        }
        left -= l;
      }
      m_middles[i] = std::make_pair(0.99 * x + 0.01 * cx, 0.99 * y + 0.01 * cy);
    }
    m_witnesses.clear();
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 1; j < n; ++j)
      {
        const Index label = m_crossings[i].to;
        if(m_crossings[j].to != label)
          continue;
        const double x = m_middles[i].first, y = m_middles[i].second;
        const double scale = Curve_field::value(m_c, x, y) + size;
        if(m_pieces.has_one_label(m_c, x, y, m_middles[j].first - x, m_middles[j].second - y, label, scale))
          m_witnesses.emplace_back(i, j);
      }
  }

  // The junction of labels l (x, y, z) in face f from the guess (gx, gy), else from points between the nodes of
  // its ends a, b, c (a junction near an edge, between two of its crossings, is found from there); false if
  // not found in the face (then at the guess).
  // A point found where another junction of the way is (`made`: the nodes so far, the junctions after the
  // crossings) does not count: two junctions of one way are apart (the point is that of the other, from the
  // same circles; this one is where other circles of the labels hold).
  bool junction_node(Index f, const Face_frame& fr, const Index l[3], double gx, double gy, const Node& a,
                     const Node& b, const Node& c, const std::vector<Node>& made, Node& node)
  {
    const double cx = (fr.x[0] + fr.x[1] + fr.x[2]) / 3., cy = (fr.y[0] + fr.y[1] + fr.y[2]) / 3.;
    const double size = std::abs(fr.x[1]) + std::abs(fr.x[2]) + std::abs(fr.y[2]);
    auto solved = [&]() {
      if(!m_pieces.exact_junction(f, m_c, l, node.x, node.y))
        return false;
      for(std::size_t i = m_crossings.size(); i < made.size(); ++i)
        if(std::hypot(made[i].x - node.x, made[i].y - node.y) <= 1e-9 * size)
          return false;
      return true;
    };
    node.x = gx;
    node.y = gy;
    node.key = -1;
    bool found = solved();
    const Node* around[3] = { &a, &b, &c };
    for(int i = 0; i < 3 && !found; ++i)
      for(int j = i + 1; j < 3 && !found; ++j)
        for(double pull : { 0.01, 0.1 })
        {
          const Node &ni = *around[i], &nj = *around[j];
          if(found || (ni.x == nj.x && ni.y == nj.y))
            continue;
          node.x = (1. - pull) * 0.5 * (ni.x + nj.x) + pull * cx;
          node.y = (1. - pull) * 0.5 * (ni.y + nj.y) + pull * cy;
          found = solved();
        }
    if(!found)
    {
      node.x = gx;
      node.y = gy;
    }
    node.point = Curve_pieces::point_in_face(f, fr, node.x, node.y);
    return found;
  }

  // The points of a link: its ends, and between them, on lines across its chord, where the label changes from
  // its right one to its left one (the nearest to the chord); then, between two points, the point found so on
  // the line across their chord at its middle is added where it is farther from that chord than the chord
  // tolerance (a kink: the border crosses the cut locus of one of its labels), and the two halves done again
  // (at most 6 times deep). (From the field's values only: two runs whose windows differ to rounding give the
  // same points.)
  void link_points(Index f, const Face_frame& fr, Plan& plan, const Link& k, std::vector<Curve_point>& points)
  {
    const Node &a = plan.nodes[k.a], &b = plan.nodes[k.b];
    points.clear();
    points.push_back(a.point);
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    const double r = (std::min)(Curve_field::value(m_c, a.x, a.y), Curve_field::value(m_c, b.x, b.y));
    const int chords = len > 0. ? m_pieces.number_of_chords(len, r) : 1;
    double x0 = a.x, y0 = a.y;
    bool found0 = true;
    for(int i = 1; i <= chords; ++i)
    {
      double x = b.x, y = b.y;
      bool found = true;
      if(i < chords)
      {
        const double s = static_cast<double>(i) / chords;
        found = border_across(f, fr, k.left, k.right, a.x, a.y, b.x, b.y, a.x + s * dx, a.y + s * dy, r, x, y);
        plan.undecided += found ? 0 : 1;
      }
      if(found0 && found)
        refine(f, fr, k.left, k.right, x0, y0, x, y, r, 0, points);
      if(i < chords)
        points.push_back(Curve_pieces::point_in_face(f, fr, x, y));
      x0 = x;
      y0 = y;
      found0 = found;
    }
    points.push_back(b.point);
  }

  // The point of the border of `left` | `right` on the line across the chord (ax, ay) - (bx, by) through its
  // point (qx, qy), inside the face (Curve_pieces::border_on_segment(): the change from the right label to the
  // left one nearest to the chord); else (qx, qy) if it is on the border (the border along the chord: along an
  // edge, where the line starts); false if neither (then (qx, qy)). `r`: the distances there.
  bool border_across(Index f, const Face_frame& fr, Index left, Index right, double ax, double ay, double bx,
                     double by, double qx, double qy, double r, double& x, double& y)
  {
    CGAL_USE(f);
    const double dx = bx - ax, dy = by - ay, len = std::sqrt(dx * dx + dy * dy);
    const double size = std::abs(fr.x[1]) + std::abs(fr.x[2]) + std::abs(fr.y[2]);
    x = qx;
    y = qy;
    if(!(len > 0.))
      return false;
    const double nx = -dy / len, ny = dx / len;  // (towards the left label)
    // the line q + u (nx, ny) inside the face: left of each edge
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    for(int e = 0; e < 3; ++e)
    {
      const int j = (e + 1) % 3;
      const double ex = fr.x[j] - fr.x[e], ey = fr.y[j] - fr.y[e];
      const double alpha = ex * (qy - fr.y[e]) - ey * (qx - fr.x[e]), beta = ex * ny - ey * nx;
      if(beta > 0.)
        lo = (std::max)(lo, -alpha / beta);
      else if(beta < 0.)
        hi = (std::min)(hi, -alpha / beta);
    }
    double u = 0.;
    if(lo < hi && std::isfinite(lo) && std::isfinite(hi)
       && m_pieces.border_on_segment(m_c, qx + lo * nx, qy + lo * ny, (hi - lo) * nx, (hi - lo) * ny, left, right,
                                     -lo / (hi - lo), r + size, u))
    {
      x = qx + (lo + u * (hi - lo)) * nx;
      y = qy + (lo + u * (hi - lo)) * ny;
      return true;
    }
    return on_border(left, right, qx, qy, size);
  }

  // The points strictly between two points of the border (x0, y0) and (x1, y1), appended: the border on the
  // line across their chord at its middle, if farther from it than the chord tolerance, and again on either
  // side (see link_points()).
  void refine(Index f, const Face_frame& fr, Index left, Index right, double x0, double y0, double x1, double y1,
              double r, int depth, std::vector<Curve_point>& points)
  {
    if(depth >= 6)
      return;
    const double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
    double x, y;
    if(!border_across(f, fr, left, right, x0, y0, x1, y1, mx, my, r, x, y) || !(std::hypot(x - mx, y - my) > m_tolerance))
      return;
    refine(f, fr, left, right, x0, y0, x, y, r, depth + 1, points);
    points.push_back(Curve_pieces::point_in_face(f, fr, x, y));
    refine(f, fr, left, right, x, y, x1, y1, r, depth + 1, points);
  }

  // whether (x, y) is on the border of `left` | `right`: the two labels' least equal and least of all, to 1e-10 of
  // the distances (`size`: of the face)
  bool on_border(Index left, Index right, double x, double y, double size) const
  {
    const double vl = Curve_field::value(m_c, x, y, left), vr = Curve_field::value(m_c, x, y, right);
    const double tolerance = 1e-10 * ((std::max)(vl, vr) + size);
    return std::abs(vl - vr) <= tolerance && Curve_field::value(m_c, x, y) >= (std::max)(vl, vr) - tolerance;
  }

  // The probe points (the middle of the crossings, and the middles of two crossings on different edges, each
  // moved by 1% towards the middle of the face) where the label the plan gives (the region whose boundary winds
  // around the point) is not the field's, where the field's is clear.
  std::size_t disagreements(Index f, const Face_frame& fr, const Plan& plan)
  {
    CGAL_USE(f);
    const std::size_t n = m_crossings.size();
    const double cx = (fr.x[0] + fr.x[1] + fr.x[2]) / 3., cy = (fr.y[0] + fr.y[1] + fr.y[2]) / 3.;
    std::vector<std::pair<double, double> > probes;
    double mx = 0., my = 0.;
    for(std::size_t i = 0; i < n; ++i)
    {
      mx += m_nodes[i].x / static_cast<double>(n);
      my += m_nodes[i].y / static_cast<double>(n);
      for(std::size_t j = i + 1; j < n; ++j)
        if(m_crossings[i].edge != m_crossings[j].edge)
          probes.emplace_back(0.99 * 0.5 * (m_nodes[i].x + m_nodes[j].x) + 0.01 * cx,
                              0.99 * 0.5 * (m_nodes[i].y + m_nodes[j].y) + 0.01 * cy);
    }
    probes.emplace_back(0.99 * mx + 0.01 * cx, 0.99 * my + 0.01 * cy);
    const double size = std::abs(fr.x[1]) + std::abs(fr.x[2]) + std::abs(fr.y[2]);
    std::size_t wrong = 0;
    for(const auto& q : probes)
    {
      // the field's label, if the next label is farther by more than rounding
      Index best = NO_INDEX;
      double least = std::numeric_limits<double>::infinity(), second = least;
      for(std::size_t i = 0; i < n; ++i)
      {
        const Index label = m_crossings[i].to;
        bool seen = false;
        for(std::size_t j = 0; j < i; ++j)
          seen = seen || m_crossings[j].to == label;
        if(seen)
          continue;
        const double v = Curve_field::value(m_c, q.first, q.second, label);
        if(v < least)
        {
          second = least;
          least = v;
          best = label;
        }
        else if(v < second)
          second = v;
      }
      if(!(second - least > 1e-9 * (least + size)))
        continue;
      // the plan's: winding numbers of the regions' boundaries (arcs, and links on either side)
      m_winding.clear();
      auto add = [&](Index label, double angle) {
        for(auto& w : m_winding)
          if(w.first == label)
          {
            w.second += angle;
            return;
          }
        m_winding.emplace_back(label, angle);
      };
      auto angle = [&](double x0, double y0, double x1, double y1) {
        const double ax = x0 - q.first, ay = y0 - q.second, bx = x1 - q.first, by = y1 - q.second;
        return std::atan2(ax * by - ay * bx, ax * bx + ay * by);
      };
      for(std::size_t i = 0; i < n; ++i)
      {
        m_arc.clear();
        arc(fr, i, m_arc);
        double a = 0.;
        for(std::size_t j = 0; j + 1 < m_arc.size(); ++j)
          a += angle(m_arc[j].first, m_arc[j].second, m_arc[j + 1].first, m_arc[j + 1].second);
        add(m_crossings[i].to, a);
      }
      for(std::size_t i = 0; i < plan.links.size(); ++i)
      {
        double a = 0., x0, y0, x1, y1;
        const std::vector<Curve_point>& p = plan.points[i];
        for(std::size_t j = 0; j + 1 < p.size(); ++j)
        {
          frame_point(fr, p[j], x0, y0);
          frame_point(fr, p[j + 1], x1, y1);
          a += angle(x0, y0, x1, y1);
        }
        add(plan.links[i].left, a);
        add(plan.links[i].right, -a);
      }
      Index mine = NO_INDEX;
      for(const auto& w : m_winding)
        if(w.second > 3.141592653589793)
          mine = w.first;
      wrong += mine != best ? 1 : 0;
    }
    return wrong;
  }

  Curve_pieces& m_pieces;
  double m_tolerance;
  std::vector<char> m_in;  // per face: in the search
  std::unordered_map<Index, std::pair<std::size_t, std::size_t> > m_edges;  // lower half-edge -> its changes
  std::vector<Label_change> m_all, m_changes;
  std::vector<Node> m_nodes;  // the crossings of the face, counterclockwise
  std::vector<Crossing> m_crossings;
  std::vector<Curve_candidate> m_c;
  std::vector<Plan> m_plans;
  std::vector<std::pair<Index, std::pair<double, double> > > m_twice;
  std::vector<std::pair<double, double> > m_arc;
  std::vector<std::pair<Index, double> > m_winding;
  std::vector<std::pair<double, double> > m_middles;   // (find_witnesses(): per arc, its middle)
  std::vector<std::pair<std::size_t, std::size_t> > m_witnesses;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDERS_H
