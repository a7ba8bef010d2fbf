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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_FACE_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_FACE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/curves/Curve_border_scores.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The pieces of the cell borders inside one face (Curve_borders.h), from the changes of label on its edges
// (counterclockwise, each from a label to the next): two -> one piece; three (three labels) -> a junction where
// the three labels' least are equal (Border_geometry::exact_junction(), from the circles that hold there: exact);
// more -> the planar ways to join them (an arc whose two neighbours have one label closed by a piece, or by a
// junction if they differ, again on what is left; searched depth first, a way dropped where a junction is not
// found in the face; every way if none is left), each scored by its junctions (found inside the face or not),
// by the arcs of one label it puts in two regions where the straight segment between them has that label all
// along (exact), and by the label it gives at probe points against the field's; the best kept. Then each piece
// runs between its ends along the points where its two labels change along lines across its chord (exact),
// refined where the border bends away from its chords (kinks).
class Border_face : public Border_scores
{
public:
  Border_face(Curve_pieces& pieces, double tolerance) : Border_scores(pieces, tolerance) {}

  // The way to join the changes of face f inside it (see above), with the points of its pieces; `many`: set if
  // there were several ways to try.
  Plan& join(Index f, bool& many)
  {
    const Curve_field& field = m_pieces.field();
    const Face_frame fr(field.mesh(), f);
    const std::size_t n = crossings.size();
    field.candidates(f, m_c);
    clear_junctions();
    // the ways to join the changes inside the face: those whose junctions are all found in it, else every way
    std::vector<std::vector<int> > ways;
    if(n <= 3)
      ways.emplace_back();
    else
    {
      many = true;
      find_witnesses(fr);
      std::map<std::vector<int>, std::vector<int> > found;
      std::vector<End> ends(n);
      for(std::size_t i = 0; i < n; ++i)
        ends[i] = End{ i, crossings[i].from, crossings[i].to, static_cast<int>(i) };
      std::vector<int> parent(n), choice;
      std::iota(parent.begin(), parent.end(), 0);
      std::vector<std::array<int, 3> > triples;
      std::vector<Node> made(nodes);
      std::size_t explored = 0;
      search(f, fr, ends, parent, triples, made, choice, found, explored);
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
        return m_plans[best];
  }

  // the arc of the face's border from crossing i to the next one, counterclockwise (corners included)
private:
  struct End  // an end of the reduction: a node where the label changes from `from` to `to` (counterclockwise),
  {           // `region`: the region of the arc that follows it
    std::size_t node;
    Index from, to;
    int region;
  };

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
      std::size_t next_node = crossings.size() + t.size();
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
              const std::vector<std::array<int, 3> >& triples, std::vector<Node>& made, std::vector<int>& choice,
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
          gx += made[e.node].x / 3.;
          gy += made[e.node].y / 3.;
        }
        Node node;
        if(!junction_node(f, fr, l, gx, gy, made[ends[0].node], made[ends[1].node], made[ends[2].node], made,
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
        const std::size_t size = made.size();
        bool failed = false;
        const double cx = (fr.x[0] + fr.x[1] + fr.x[2]) / 3., cy = (fr.y[0] + fr.y[1] + fr.y[2]) / 3.;
        reduce(e, p, pa, t, [](std::size_t, std::size_t, Index, Index) {},
               [&](std::size_t a, std::size_t b) {
                 const Node na = made[e[a].node], nb = made[e[b].node];
                 const Index l[3] = { e[a].from, e[a].to, e[b].to };
                 Node node;
                 failed = !junction_node(f, fr, l, (na.x + nb.x + cx) / 3., (na.y + nb.y + cy) / 3., na, nb, nb,
                                         made, node);
                 made.push_back(node);
                 return made.size() - 1;
               });
        if(!failed)
        {
          choice.push_back(static_cast<int>(p));
          search(f, fr, e, pa, t, made, choice, found, explored);
          choice.pop_back();
        }
        made.resize(size);
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
    const std::size_t n = crossings.size();
    plan.nodes.assign(nodes.begin(), nodes.end());  // (a junction's key is set when the plan is kept)
    plan.links.clear();
    plan.bad_junctions = 0;
    plan.undecided = 0;
    std::vector<End> ends(n);
    for(std::size_t i = 0; i < n; ++i)
      ends[i] = End{ i, crossings[i].from, crossings[i].to, static_cast<int>(i) };
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

  std::vector<Plan> m_plans;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_FACE_H

