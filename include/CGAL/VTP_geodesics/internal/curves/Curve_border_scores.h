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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_SCORES_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_SCORES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/curves/Curve_border_geometry.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The scores of the ways to join the changes of label on the border of a face (Curve_border_face.h): the arcs
// of the face's border of one label that are one region for sure (witnesses: the straight segment between them
// has that label all along, exact), and how often a way gives another label than the field at probe points.
class Border_scores : public Border_geometry
{
public:
  Border_scores(Curve_pieces& pieces, double tolerance) : Border_geometry(pieces, tolerance) {}

protected:
  // The pairs of arcs of the face's border with one label that are one region for sure: the segment between
  // their middles (moved by 1% towards the middle of the face) has that label all along (Label_envelope).
  void find_witnesses(const Face_frame& fr)
  {
    const std::size_t n = crossings.size();
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
        const Index label = crossings[i].to;
        if(crossings[j].to != label)
          continue;
        const double x = m_middles[i].first, y = m_middles[i].second;
        const double scale = Curve_field::value(m_c, x, y) + size;
        if(has_one_label(m_c, x, y, m_middles[j].first - x, m_middles[j].second - y, label, scale))
          m_witnesses.emplace_back(i, j);
      }
  }

  // The probe points (the middle of the crossings, and the middles of two crossings on different edges, each
  // moved by 1% towards the middle of the face) where the label the plan gives (the region whose boundary winds
  // around the point) is not the field's, where the field's is clear.
  std::size_t disagreements(Index f, const Face_frame& fr, const Plan& plan)
  {
    CGAL_USE(f);
    const std::size_t n = crossings.size();
    const double cx = (fr.x[0] + fr.x[1] + fr.x[2]) / 3., cy = (fr.y[0] + fr.y[1] + fr.y[2]) / 3.;
    std::vector<std::pair<double, double> > probes;
    double mx = 0., my = 0.;
    for(std::size_t i = 0; i < n; ++i)
    {
      mx += nodes[i].x / static_cast<double>(n);
      my += nodes[i].y / static_cast<double>(n);
      for(std::size_t j = i + 1; j < n; ++j)
        if(crossings[i].edge != crossings[j].edge)
          probes.emplace_back(0.99 * 0.5 * (nodes[i].x + nodes[j].x) + 0.01 * cx,
                              0.99 * 0.5 * (nodes[i].y + nodes[j].y) + 0.01 * cy);
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
        const Index label = crossings[i].to;
        bool seen = false;
        for(std::size_t j = 0; j < i; ++j)
          seen = seen || crossings[j].to == label;
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
        add(crossings[i].to, a);
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

  std::vector<std::pair<Index, double> > m_winding;
  std::vector<std::pair<double, double> > m_middles;   // (find_witnesses(): per arc, its middle)
  std::vector<std::pair<std::size_t, std::size_t> > m_witnesses;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_BORDER_SCORES_H
