// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The picture (see picture.h): the curves given by set_curves() (the library's isolines and cell borders), drawn
// into the samples of the mesh drawing as the isolines of the values are: how much each sample lies on a curve,
// with the width and the anti-aliasing of those isolines, where the curve is seen.

#include "picture.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace vtp_geodesics_app {

namespace {

// A point of a curve in samples (x to the right, y down) and its depth.
struct Sample_point
{
  double x, y, z;
};

} // namespace

void Distance_picture::draw_curves()
{
  const int ss = (std::max)(1, m_options.supersampling);
  const double half_width = 0.55 * ss;  // as the isolines of the values (shade())
  const double reach = half_width + 0.5;
  m_line.assign(m_depth.size(), 0.f);
  const double limit = 1e8; // samples; keeps the conversions to int defined
  auto to_samples = [&](const Vec3& p) {
    const std::array<double, 3> q = project(p); // picture pixels, depth
    return Sample_point{ (q[0] - m_mesh_x) * ss, (q[1] - m_mesh_y) * ss, q[2] };
  };
  for(const std::vector<Vec3>& curve : m_curves)
    for(std::size_t i = 0; i + 1 < curve.size(); ++i)
    {
      const Sample_point a = to_samples(curve[i]), b = to_samples(curve[i + 1]);
      if(!(std::abs(a.x) < limit && std::abs(a.y) < limit && std::abs(b.x) < limit && std::abs(b.y) < limit))
        continue;
      const int x0 = (std::max)(static_cast<int>(std::floor((std::min)(a.x, b.x) - reach)), 0);
      const int x1 = (std::min)(static_cast<int>(std::ceil((std::max)(a.x, b.x) + reach)), m_sw - 1);
      const int y0 = (std::max)(static_cast<int>(std::floor((std::min)(a.y, b.y) - reach)), 0);
      const int y1 = (std::min)(static_cast<int>(std::ceil((std::max)(a.y, b.y) + reach)), m_sh - 1);
      const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
      for(int y = y0; y <= y1; ++y)
        for(int x = x0; x <= x1; ++x)
        {
          const std::size_t s = static_cast<std::size_t>(y) * m_sw + x;
          if(m_face[s] == no_face)
            continue;
          // the point of the segment nearest to the sample's centre (on screen)
          const double px = x + 0.5, py = y + 0.5;
          const double t = length2 > 0. ? std::clamp(((px - a.x) * dx + (py - a.y) * dy) / length2, 0., 1.) : 0.;
          const double qx = a.x + t * dx, qy = a.y + t * dy;
          const float cover = static_cast<float>(std::clamp(reach - std::hypot(px - qx, py - qy), 0., 1.));
          if(!(cover > m_line[s]))
            continue;
          // drawn where that point of the curve is seen (not behind the surface)
          if(visible(m_mesh_x + qx / ss, m_mesh_y + qy / ss, a.z + t * (b.z - a.z)))
            m_line[s] = cover;
        }
    }
}

// The labels of the samples of the faces whose corners have different labels (all reached), so that the colours
// of the cells meet on the borders drawn: each such sample takes the label of the samples of faces of one label
// that reach it, on screen, without crossing a curve (a breadth-first fill from them, from face to face through a
// shared corner, a label of the face's corners only). Samples it does not reach keep the rule of label_colour().
void Distance_picture::fill_labels(std::size_t nf, const Face_of& face_of)
{
  constexpr int mixed = INT_MIN + 1, partly_unreached = INT_MIN + 2;
  std::vector<int> face_label(nf);
  std::vector<Triangle> triangles(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const Triangle t = triangles[f] = face_of(f);
    const int a = m_labels[t[0]], b = m_labels[t[1]], c = m_labels[t[2]];
    face_label[f] = a == b && b == c ? a : ((std::min)({ a, b, c }) < 0 ? partly_unreached : mixed);
  }
  m_sample_label.assign(m_depth.size(), no_label);
  std::vector<std::size_t> queue;
  for(std::size_t s = 0; s < m_depth.size(); ++s)
    if(m_face[s] != no_face && face_label[m_face[s]] >= 0)
    {
      m_sample_label[s] = face_label[m_face[s]];
      if(m_line[s] < 1.f)
        queue.push_back(s);
    }
  auto shares_a_corner = [&](std::uint32_t f, std::uint32_t g) {
    if(f == g)
      return true;
    const Triangle& a = triangles[f];
    const Triangle& b = triangles[g];
    for(std::uint32_t u : a)
      for(std::uint32_t v : b)
        if(u == v)
          return true;
    return false;
  };
  for(std::size_t next = 0; next < queue.size(); ++next)
  {
    const std::size_t s = queue[next];
    const int x = static_cast<int>(s % m_sw), y = static_cast<int>(s / m_sw);
    const int label = m_sample_label[s];
    const int neighbours[4][2] = { { x - 1, y }, { x + 1, y }, { x, y - 1 }, { x, y + 1 } };
    for(const auto& q : neighbours)
    {
      if(q[0] < 0 || q[1] < 0 || q[0] >= m_sw || q[1] >= m_sh)
        continue;
      const std::size_t n = static_cast<std::size_t>(q[1]) * m_sw + q[0];
      const std::uint32_t f = m_face[n];
      if(f == no_face || face_label[f] != mixed || m_sample_label[n] != no_label || !shares_a_corner(m_face[s], f))
        continue;
      const Triangle& t = triangles[f];
      if(m_labels[t[0]] != label && m_labels[t[1]] != label && m_labels[t[2]] != label)
        continue;
      m_sample_label[n] = label;
      if(m_line[n] < 1.f)
        queue.push_back(n);
    }
  }
}

} // namespace vtp_geodesics_app
