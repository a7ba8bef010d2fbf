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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_EXTRACTION_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_EXTRACTION_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/curves/Curve_borders.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_march.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_pieces.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The isolines and the cell borders of a field (Curve_field.h). Which edges a curve crosses is decided by
// the values at their ends (the vertex distances, or labels), as marching triangles would, so that the
// pieces of two faces meet at the same edge point; where the curve crosses an edge and how it runs inside
// a face come from the candidates (Curve_pieces.h).
class Curve_extraction
{
public:
  Curve_extraction(const Curve_field& field, double tolerance) : m_pieces(field, tolerance), m_tolerance(tolerance) {}

  const Curve_pieces& pieces() const { return m_pieces; }

  // The isolines at `levels` (engine unit); set i is levels[i].
  std::vector<Extracted_curve> isolines(const std::vector<double>& levels)
  {
    const Curve_field& field = m_pieces.field();
    const Mesh_arrays& m = field.mesh();
    std::vector<std::size_t> order(levels.size());
    for(std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return levels[a] < levels[b]; });
    std::vector<double> sorted(levels.size());
    for(std::size_t i = 0; i < order.size(); ++i)
      sorted[i] = levels[order[i]];
    std::vector<Curve_piece> pieces;
    std::vector<Curve_candidate> c;
    m_number_of_sets = (std::max)(levels.size(), std::size_t(1));
    m_edge_crossings.clear();
    for(Index f = 0; f < m.nf; ++f)
    {
      double d[3];
      for(int k = 0; k < 3; ++k)
        d[k] = field.distance(m.source[3 * f + k]);
      double lo = (std::min)({ d[0], d[1], d[2] });
      double hi = (std::max)({ d[0], d[1], d[2] });
      if(!(lo < std::numeric_limits<double>::infinity()))
        continue;
      // on an edge of length l, the distance is at least (d_a + d_b - l) / 2 (a dip between two vertices above
      // a level); from the windows that crossed the faces, where the field rises above a level between two
      // vertices below it (at most (d_a + d_b + l) / 2) is found too
      for(int k = 0; k < 3; ++k)
      {
        const double sum = d[k] + d[(k + 1) % 3], l = m.geometry[3 * f + k].length;
        lo = (std::min)(lo, 0.5 * (sum - 1.01 * l));
        if(field.from_crossings() && std::isfinite(hi))
          hi = (std::max)(hi, (std::min)(0.5 * (sum + l), field.face_bound(f)));
      }
      auto first = std::upper_bound(sorted.begin(), sorted.end(), lo);  // levels above the least value
      if(first == sorted.end() || !(*first <= hi))
        continue;
      field.candidates(f, c);
      const double longest = (std::max)({ m.geometry[3 * f].length, m.geometry[3 * f + 1].length,
                                          m.geometry[3 * f + 2].length });
      for(auto it = first; it != sorted.end() && *it <= hi; ++it)
      {
        // (an interior point is close enough to its level at a few units of rounding of the distances there)
        m_pieces.set_value_tolerance(4e-15 * (*it + longest));
        face_isoline(f, c, d, *it, static_cast<Index>(order[static_cast<std::size_t>(it - sorted.begin())]), pieces);
      }
    }
    m_edge_crossings.clear();
    return chain_pieces(pieces);
  }

  // A crossing of an isoline with the boundary of a face, in the face's frame.
  struct Crossing
  {
    Curve_point point;
    double x, y;
    Index key;
    bool leaves;  // going counterclockwise, the boundary leaves the part below the level
  };

  // The pieces of face f followed along the isoline from each crossing where it leaves the part below the level
  // (Curve_march.h), each ended at the crossing nearest to where the march leaves the face (within a step), where
  // points on lines across the chords fail both ways (the curve is not a graph over its chords). Replaces m_kept
  // and returns true if every march arrives at a crossing of its own; else leaves m_kept as it is.
  bool march_pieces(Index f, const std::vector<Curve_candidate>& c, double level, Index set, const Crossing* cross,
                    int n)
  {
    const Mesh_arrays& m = m_pieces.field().mesh();
    const Face_frame fr(m, f);
    auto phi = [&c, level](double x, double y, double& gx, double& gy, double& cx, double& cy, double& b) {
      int which;
      const double v = Curve_field::value(c, x, y, NO_INDEX, which);
      if(which < 0)
        return std::numeric_limits<double>::quiet_NaN();
      const Curve_candidate& q = c[static_cast<std::size_t>(which)];
      if(q.front_at(x, y))
      {
        // a straight front: its gradient is its direction; as a circle (for the march's guesses, which it
        // checks against the field), one far behind the point
        gx = q.nx;
        gy = q.ny;
        q.active_circle(x, y, cx, cy, b);
        return v - level;
      }
      q.active_circle(x, y, cx, cy, b);
      const double dx = x - cx, dy = y - cy, r = std::sqrt(dx * dx + dy * dy);
      if(!(r > 0.))
        return std::numeric_limits<double>::quiet_NaN();
      gx = dx / r;
      gy = dy / r;
      return v - level;
    };
    double longest = 0.;
    for(int k = 0; k < 3; ++k)
      longest = (std::max)(longest, m.geometry[3 * f + static_cast<Index>(k)].length);
    std::vector<Curve_piece> marched;
    std::vector<std::pair<double, double> > inner;
    bool used[12] = { false };
    for(int i = 0; i < n; ++i)
    {
      if(!cross[i].leaves)
        continue;
      double gx = 0., gy = 0., cx = 0., cy = 0., b = 0.;
      const double at = phi(cross[i].x, cross[i].y, gx, gy, cx, cy, b);
      const double radius = at == at ? level - b : std::numeric_limits<double>::infinity();
      const double step = longest / m_pieces.number_of_chords(longest, radius);
      inner.clear();
      double ex, ey;
      if(!march_isoline(fr, phi, level, cross[i].x, cross[i].y, step, m_pieces.value_tolerance(), inner, ex, ey))
        return false;
      int end = -1;
      double nearest = std::numeric_limits<double>::infinity();
      for(int j = 0; j < n; ++j)
      {
        const double away = std::hypot(cross[j].x - ex, cross[j].y - ey);
        if(!cross[j].leaves && !used[j] && away < nearest)
        {
          nearest = away;
          end = j;
        }
      }
      if(end < 0 || !(nearest <= step))
        return false;
      used[end] = true;
      Curve_piece piece;
      piece.set = set;
      piece.key[0] = cross[i].key;
      piece.key[1] = cross[end].key;
      piece.points.push_back(cross[i].point);
      for(const auto& q : inner)
        piece.points.push_back(Curve_pieces::point_in_face(f, fr, q.first, q.second));
      piece.points.push_back(cross[end].point);
      marched.push_back(std::move(piece));
    }
    for(int j = 0; j < n; ++j)
      if(!cross[j].leaves && !used[j])
        return false;  // (a crossing that no march reached)
    m_kept.swap(marched);
    return true;
  }

  // The pieces of the isoline at `level` (set `set`) in face f (candidates c, corner distances d): the
  // crossings of its edges in counterclockwise order, each where the boundary leaves the part below the
  // level joined to the next where it enters it again (or to the previous one, see below; or followed through
  // the face, march_pieces(), where both leave points on their chords).
  void face_isoline(Index f, const std::vector<Curve_candidate>& c, const double d[3], double level, Index set,
                    std::vector<Curve_piece>& pieces)
  {
    const Curve_field& field = m_pieces.field();
    const Mesh_arrays& m = field.mesh();
    auto phi = [level](const std::vector<Curve_candidate>& cc, double px, double py, double dx, double dy, double u,
                       double& next) {
      int which;
      const double x = px + u * dx, y = py + u * dy;
      const double v = Curve_field::value(cc, x, y, NO_INDEX, which);
      next = std::numeric_limits<double>::quiet_NaN();
      if(which >= 0)
      {
        const Curve_candidate& q = cc[static_cast<std::size_t>(which)];
        if(q.front_at(x, y))
          next = q.front_on_line(px, py, dx, dy, level, u);
        else
        {
          double cx, cy, b;
          q.active_circle(x, y, cx, cy, b);
          next = circle_on_line(px, py, dx, dy, cx, cy, b, level, u);
        }
      }
      return v - level;
    };
    Crossing cross[12];
    int n = 0;
    for(int k = 0; k < 3; ++k)
    {
      const int j = (k + 1) % 3;
      const Index h = 3 * f + k;
      const Index lower = lower_of(m, h);
      const double da = h == lower ? d[k] : d[j], db = h == lower ? d[j] : d[k];
      // (an edge's crossings are found once, for the first of its faces, and kept for the second)
      const std::uint64_t key = static_cast<std::uint64_t>(lower) * m_number_of_sets + static_cast<std::uint64_t>(set);
      // (on the edge the field is at least (da + db - l) / 2 and at most (da + db + l) / 2: no crossing of two
      // vertices on one side of the level beyond these)
      const double length = m.geometry[h].length;
      // (nor where the field is below the level all over either face of the edge: Curve_field::face_bound())
      if((da < level && db < level
          && (0.5 * (da + db + length) < level || field.face_bound(f) < level
              || (m.opposite[h] != NO_INDEX && field.face_bound(Mesh_arrays::face(m.opposite[h])) < level)))
         || (da >= level && db >= level && 0.5 * (da + db - 1.01 * length) >= level))
        continue;
      Edge_crossings e;
      const auto known = m_edge_crossings.find(key);
      if(known != m_edge_crossings.end())
      {
        e = known->second;
        m_edge_crossings.erase(known);
      }
      else
      {
        e.count = field.from_crossings() ? m_pieces.exact_isoline_crossings(lower, level, da, db, e.t) : -1;
        if(e.count < 0)
          e.count = m_pieces.isoline_crossings(lower, level, da, db, e.t);
        if(m.opposite[h] != NO_INDEX)
          m_edge_crossings.emplace(key, e);
      }
      const int count = e.count;
      for(int i = 0; i < count; ++i)
      {
        const int along_lower = h == lower ? i : count - 1 - i;  // (crossings are listed in the order of h)
        const double ti = e.t[along_lower];
        Crossing& x = cross[n++];
        x.point = Curve_pieces::edge_curve_point(h, lower, ti);
        m_pieces.edge_point(h, h == lower ? ti : 1. - ti, x.x, x.y);
        x.key = 4 * lower + along_lower;
        // (along h from its source the field is below the level where d[k] is, and crosses it at each one)
        x.leaves = (d[k] < level) != (i % 2 == 1);
      }
    }
    // Each crossing where the boundary leaves the part below is joined to the next one ccw where it enters it
    // again (the parts above the level are apart inside the face); with 4 or more crossings the parts above may
    // instead be joined inside the face (a ridge of the field, the cut locus, from a corner above to a rise on
    // an edge): then each is joined to the previous one. The other way is tried when the first leaves
    // interior points on their chords (the field has no crossing across it there), and the one that leaves
    // fewer is kept.
    std::vector<Curve_piece>& trial = m_trial;
    std::size_t best_undecided = 0;
    for(int way = 0; way < (n >= 4 ? 2 : 1); ++way)
    {
      const std::size_t undecided_before = m_pieces.undecided;
      trial.clear();
      for(int i = 0; i < n; ++i)
      {
        if(!cross[i].leaves)
          continue;
        const int step = way == 0 ? 1 : n - 1;
        int j = (i + step) % n;
        while(j != i && cross[j].leaves)
          j = (j + step) % n;
        if(j == i)
          break;
        Curve_piece piece;
        piece.set = set;
        piece.key[0] = cross[i].key;
        piece.key[1] = cross[j].key;
        piece.points.push_back(cross[i].point);
        double radius = std::numeric_limits<double>::infinity();
        for(const Crossing* e : { &cross[i], &cross[j] })
        {
          int which;
          Curve_field::value(c, e->x, e->y, NO_INDEX, which);
          if(which >= 0)
            radius = (std::min)(radius, level - c[static_cast<std::size_t>(which)].base);
        }
        const double chord = std::hypot(cross[j].x - cross[i].x, cross[j].y - cross[i].y);
        m_pieces.interior(f, c, cross[i].x, cross[i].y, cross[j].x, cross[j].y,
                          m_pieces.number_of_chords(chord, radius), phi, piece.points);
        piece.points.push_back(cross[j].point);
        trial.push_back(std::move(piece));
      }
      const std::size_t undecided = m_pieces.undecided - undecided_before;
      m_pieces.undecided = undecided_before;
      if(way == 0 || undecided < best_undecided)
      {
        best_undecided = undecided;
        m_kept.swap(trial);
      }
      if(best_undecided == 0)
        break;
    }
    if(best_undecided > 0 && march_pieces(f, c, level, set, cross, n))
      best_undecided = 0;
    m_pieces.undecided += best_undecided;
    for(Curve_piece& piece : m_kept)
      pieces.push_back(std::move(piece));
    m_kept.clear();
  }

  // The borders between the cells of the labels; `pairs` receives the two labels of each set.
  std::vector<Extracted_curve> borders(std::vector<std::pair<Index, Index> >& pairs)
  {
    const Curve_field& field = m_pieces.field();
    const Mesh_arrays& m = field.mesh();
    std::map<std::pair<Index, Index>, Index> set_of;
    auto set_index = [&](Index a, Index b) {
      const std::pair<Index, Index> key(std::min(a, b), std::max(a, b));
      auto it = set_of.find(key);
      if(it != set_of.end())
        return it->second;
      const Index s = static_cast<Index>(pairs.size());
      pairs.push_back(key);
      set_of[key] = s;
      return s;
    };
    std::vector<Curve_piece> pieces;
    std::vector<Curve_candidate> c;
    m_pieces.set_value_tolerance(0.);
    if(field.from_crossings())
    {
      // (exact: every change of label along the edges, Curve_borders.h)
      Exact_borders exact(m_pieces, m_tolerance);
      exact.run(pieces, set_index, [this](Index label, double area, double bound) { add_area(label, area, bound); });
      m_border_fallbacks += exact.edge_fallbacks;
      m_pieces.junction_fallbacks += exact.junction_fallbacks;
      border_faces = exact.faces;
      poked_faces = exact.poked_faces;
      many_ends = exact.many_ends;
      return chain_pieces(pieces);
    }
    for(Index f = 0; f < m.nf; ++f)
    {
      Index l[3];
      for(int k = 0; k < 3; ++k)
        l[k] = field.label(m.source[3 * f + k]);
      if(l[0] == NO_INDEX || l[1] == NO_INDEX || l[2] == NO_INDEX)
        continue;  // (a face with an unreached corner is in no cell)
      if(l[0] == l[1] && l[1] == l[2])
      {
        add_area(l[0], face_area(m, f), 0.);
        continue;
      }
      field.candidates(f, c);
      // the edge points
      double ex[3], ey[3];
      Curve_point ep[3];
      for(int k = 0; k < 3; ++k)
      {
        const int j = (k + 1) % 3;
        if(l[k] == l[j])
          continue;
        const Index h = 3 * f + k;
        const Index o = m.opposite[h];
        const Index lower = (o == NO_INDEX || h < o) ? h : o;
        const Index la = h == lower ? l[k] : l[j], lb = h == lower ? l[j] : l[k];
        const double t = border_crossing(lower, la, lb);
        ep[k] = Curve_pieces::edge_curve_point(h, lower, t);
        m_pieces.edge_point(h, h == lower ? t : 1. - t, ex[k], ey[k]);
      }
      const bool three = l[0] != l[1] && l[1] != l[2] && l[2] != l[0];
      if(!three)
      {
        int odd = 0;
        for(int k = 0; k < 3; ++k)
          if(l[(k + 1) % 3] == l[(k + 2) % 3])
            odd = k;
        const int a = odd, b = (odd + 2) % 3;  // the edges odd -> odd+1 and odd+2 -> odd
        add_border_piece(f, c, l[odd], l[(odd + 1) % 3], set_index(l[odd], l[(odd + 1) % 3]),
                         ex[a], ey[a], ep[a], 2 * lower_of(m, 3 * f + a), ex[b], ey[b], ep[b], 2 * lower_of(m, 3 * f + b),
                         pieces);
        // the cells' areas: the polygon of the odd corner and the piece, the rest of the face
        const std::vector<Curve_point>& border = pieces.back().points;
        const double part = polygon_area(m, f, odd, border, nullptr), bound = m_tolerance * polyline_length(m, f, border);
        add_area(l[odd], part, bound);
        add_area(l[(odd + 1) % 3], face_area(m, f) - part, bound);
        continue;
      }
      // three cells: the junction where the three are equal
      double jx = (ex[0] + ex[1] + ex[2]) / 3., jy = (ey[0] + ey[1] + ey[2]) / 3.;
      m_pieces.junction(f, c, l, jx, jy);
      const Face_frame fr(m, f);
      const Curve_point jp = Curve_pieces::point_in_face(f, fr, jx, jy);
      for(int k = 0; k < 3; ++k)
        add_border_piece(f, c, l[k], l[(k + 1) % 3], set_index(l[k], l[(k + 1) % 3]), ex[k], ey[k], ep[k],
                         2 * lower_of(m, 3 * f + k), jx, jy, jp, 6 * m.nf + f, pieces);
      // the cells' areas: corner k, the piece of edge k to the junction, that of edge k + 2 back
      const std::size_t last = pieces.size();
      double bound = 0., sum = 0.;
      for(int k = 0; k < 3; ++k)
        bound += m_tolerance * polyline_length(m, f, pieces[last - 3 + static_cast<std::size_t>(k)].points);
      for(int k = 0; k < 3; ++k)
      {
        const double part = k < 2 ? polygon_area(m, f, k, pieces[last - 3 + static_cast<std::size_t>(k)].points,
                                                 &pieces[last - 3 + static_cast<std::size_t>((k + 2) % 3)].points)
                                  : face_area(m, f) - sum;
        sum += part;
        add_area(l[k], part, bound);
      }
    }
    return chain_pieces(pieces);
  }

private:
  static Index lower_of(const Mesh_arrays& m, Index h)
  {
    const Index o = m.opposite[h];
    return (o == NO_INDEX || h < o) ? h : o;
  }

  // the border of cells la (negative side) and lb on the lower half-edge c
  double border_crossing(Index c, Index la, Index lb)
  {
    auto value_of = [](Index label) {
      return [label](const std::vector<Curve_candidate>& cc, double x, double y) {
        return Curve_field::value(cc, x, y, label);
      };
    };
    const Curve_field& field = m_pieces.field();
    const Mesh_arrays& m = field.mesh();
    const Index o = m.opposite[c];
    field.candidates(Mesh_arrays::face(c), m_cf);
    if(o != NO_INDEX)
      field.candidates(Mesh_arrays::face(o), m_cg);
    else
      m_cg.clear();
    auto psi = [&](double t) {
      return m_pieces.edge_value(c, t, m_cf, m_cg, value_of(la)) - m_pieces.edge_value(c, t, m_cf, m_cg, value_of(lb));
    };
    const double f0 = psi(0.), f1 = psi(1.);
    if(!(f0 <= 0. && f1 >= 0.) || !std::isfinite(f0) || !std::isfinite(f1))
    {
      ++m_border_fallbacks;
      const double da = field.distance(m.source[c]), db = field.distance(m.target(c));
      const double length = m.geometry[c].length;
      return length > 0. ? (std::min)((std::max)((db - da + length) / (2. * length), 0.), 1.) : 0.5;
    }
    if(f0 == 0.)
      return 0.;
    if(f1 == 0.)
      return 1.;
    return bracketed_zero(psi, 0., 1., f0, f1, 1e-15);
  }

  void add_border_piece(Index f, const std::vector<Curve_candidate>& c, Index la, Index lb, Index set, double x0,
                        double y0, const Curve_point& p0, Index k0, double x1, double y1, const Curve_point& p1,
                        Index k1, std::vector<Curve_piece>& pieces)
  {
    auto psi = [la, lb](const std::vector<Curve_candidate>& cc, double px, double py, double dx, double dy, double u,
                        double& next) {
      const double x = px + u * dx, y = py + u * dy;
      next = std::numeric_limits<double>::quiet_NaN();
      return Curve_field::value(cc, x, y, la) - Curve_field::value(cc, x, y, lb);
    };
    Curve_piece piece;
    piece.set = set;
    piece.key[0] = k0;
    piece.key[1] = k1;
    piece.points.push_back(p0);
    const double r = (std::min)(Curve_field::value(c, x0, y0), Curve_field::value(c, x1, y1));
    m_pieces.interior(f, c, x0, y0, x1, y1, m_pieces.number_of_chords(std::hypot(x1 - x0, y1 - y0), r), psi,
                      piece.points);
    piece.points.push_back(p1);
    pieces.push_back(std::move(piece));
  }

  void add_area(Index label, double area, double bound)
  {
    const std::size_t i = static_cast<std::size_t>(label);
    if(areas.size() <= i)
    {
      areas.resize(i + 1, 0.);
      area_bounds.resize(i + 1, 0.);
    }
    areas[i] += area;
    area_bounds[i] += bound;
  }

  Curve_pieces m_pieces;
  double m_tolerance;
  struct Edge_crossings
  {
    int count;
    double t[4];
  };
  std::unordered_map<std::uint64_t, Edge_crossings> m_edge_crossings;  // (isolines(): key lower half-edge, set)
  std::vector<Curve_piece> m_trial, m_kept;  // (face_isoline(): the pieces of a face, the two ways to join)
  std::uint64_t m_number_of_sets = 1;
  std::vector<Curve_candidate> m_cf, m_cg;

public:
  // after borders(): per label, the area of its cell (engine unit) from the split of the faces by the borders,
  // and the tolerance times the length of its border (a bound of the area between the chords and the curve)
  std::vector<double> areas, area_bounds;

public:
  std::size_t m_border_fallbacks = 0;
  // after borders() from the kept field: the faces searched, of which with one corner label (a cell pokes into
  // them), and with more than three changes of label on their edges
  std::size_t border_faces = 0, poked_faces = 0, many_ends = 0;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_EXTRACTION_H
