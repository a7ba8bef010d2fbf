// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The picture (see picture.h): the rasterizer of the mesh (depth test, shading, isolines, label colours) and the
// downsampling of its samples into pixels.

#include "picture.h"
#include "colour_map.h"

#include <algorithm>
#include <cmath>

namespace vtp_geodesics_app {

namespace {

// A colour per label: hues spread by the golden ratio, alternating lightness, so that neighbouring cells
// (consecutive samples of a farthest-point sampling are far apart, but any labels may meet) differ.
void colour_of_label(int label, double& r, double& g, double& b)
{
  const double hue = std::fmod(0.13 + 0.6180339887498949 * label, 1.) * 6.;
  const double saturation = label % 2 == 0 ? 0.55 : 0.4;
  const double value = label % 3 == 0 ? 0.95 : (label % 3 == 1 ? 0.82 : 0.7);
  const int sector = static_cast<int>(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = value * (1. - saturation), q = value * (1. - saturation * f);
  const double u = value * (1. - saturation * (1. - f));
  const double rgb[6][3] = { { value, u, p }, { q, value, p }, { p, value, u },
                             { p, q, value }, { u, p, value }, { value, p, q } };
  r = 255. * rgb[sector][0];
  g = 255. * rgb[sector][1];
  b = 255. * rgb[sector][2];
}

} // namespace

// Depth test of face `f` at the samples it covers (edges shared by two faces are covered by both).
void Distance_picture::rasterize(const std::vector<float>& sx, const std::vector<float>& sy,
                                 const std::vector<float>& sz, const Triangle& t, std::uint32_t f)
{
  const float x0 = sx[t[0]], y0 = sy[t[0]], x1 = sx[t[1]], y1 = sy[t[1]], x2 = sx[t[2]], y2 = sy[t[2]];
  const float area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  if(!(std::abs(area) > 1e-12f) || !std::isfinite(area))
    return;
  const float limit = 1e8f; // samples; keeps the conversions to int defined
  for(float c : { x0, y0, x1, y1, x2, y2 })
    if(!(std::abs(c) < limit))
      return;
  const int bx0 = (std::max)(static_cast<int>(std::floor((std::min)({ x0, x1, x2 }))), 0);
  const int bx1 = (std::min)(static_cast<int>(std::ceil((std::max)({ x0, x1, x2 }))), m_sw - 1);
  const int by0 = (std::max)(static_cast<int>(std::floor((std::min)({ y0, y1, y2 }))), 0);
  const int by1 = (std::min)(static_cast<int>(std::ceil((std::max)({ y0, y1, y2 }))), m_sh - 1);
  if(bx0 > bx1 || by0 > by1)
    return;
  const float inv_area = 1.f / area;
  const float z0 = sz[t[0]], z1 = sz[t[1]], z2 = sz[t[2]];
  for(int y = by0; y <= by1; ++y)
  {
    const float py = y + 0.5f;
    for(int x = bx0; x <= bx1; ++x)
    {
      const float px = x + 0.5f;
      const float w0 = ((x1 - px) * (y2 - py) - (x2 - px) * (y1 - py)) * inv_area;
      const float w1 = ((x2 - px) * (y0 - py) - (x0 - px) * (y2 - py)) * inv_area;
      const float w2 = 1.f - w0 - w1;
      if(w0 < 0.f || w1 < 0.f || w2 < 0.f)
        continue;
      const float z = w0 * z0 + w1 * z1 + w2 * z2;
      const std::size_t s = static_cast<std::size_t>(y) * m_sw + x;
      if(!(z < m_depth[s]))
        continue;
      m_depth[s] = z;
      m_face[s] = f;
      m_bary[2 * s] = w0;
      m_bary[2 * s + 1] = w1;
    }
  }
}

// The colour of sample `s`, on face `t`: the colour of the interpolated value, shaded, darkened on isolines.
void Distance_picture::shade(std::size_t s, const std::vector<float>& sx, const std::vector<float>& sy,
                             const std::vector<std::array<float, 3> >& normals, const std::vector<double>& values,
                             std::uint32_t face, const Triangle& t)
{
  const float w0 = m_bary[2 * s], w1 = m_bary[2 * s + 1], w2 = 1.f - w0 - w1;

  // Shading: the normal facing the viewer; back faces, seen through holes, are darker and greyer.
  float n[3];
  for(int k = 0; k < 3; ++k)
    n[k] = w0 * normals[t[0]][k] + w1 * normals[t[1]][k] + w2 * normals[t[2]][k];
  const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double light = 1.;
  bool back = false;
  if(len > 0.f)
  {
    double nx = n[0] / len, ny = n[1] / len, nz = n[2] / len;
    back = nz > 0.; // camera z points into the scene: a front face has its normal towards -z
    if(back)
    {
      nx = -nx;
      ny = -ny;
      nz = -nz;
    }
    // A head light (from the viewer) and a key light from the upper left: every visible face gets some
    // light, faces seen at a grazing angle get less, and the key light shows the relief.
    const double lx = -0.4, ly = 0.5, lz = -0.768;
    const double head = -nz, key = (std::max)(0., nx * lx + ny * ly + nz * lz);
    light = 0.4 + 0.6 * (0.55 * head + 0.45 * key);
  }

  const double v0 = values[t[0]], v1 = values[t[1]], v2 = values[t[2]];
  const Rgb grey = unreachable_colour();
  double r = grey.r, g = grey.g, b = grey.b;
  double line = 0.;
  if(!m_labels.empty())
  {
    if(m_has_curves && m_sample_label[s] != no_label)
    {
      if(m_sample_label[s] >= 0)
        colour_of_label(m_sample_label[s], r, g, b);
    }
    else
      label_colour(t, { { w0, w1, w2 } }, r, g, b, line);
    if(m_has_curves)
      line = m_line[s];  // the borders given, not those between the corners' labels
  }
  else if(std::isfinite(v0) && std::isfinite(v1) && std::isfinite(v2))
  {
    const double v = w0 * v0 + w1 * v1 + w2 * v2;
    const double fraction = m_max_value > 0. ? std::clamp(v / m_max_value, 0., 1.) : 0.;
    const std::array<float, 3>& c = m_lut[static_cast<int>(fraction * (lut_size - 1) + 0.5)];
    r = c[0];
    g = c[1];
    b = c[2];
    if(!m_angles.empty())
      angle_colour(t, { { w0, w1, w2 } }, r, g, b);
    if(m_has_curves)
      line = m_line[s];
    else if(m_step > 0.)
    {
      const double k = std::round(v / m_step);
      if(k >= 1. && k * m_step < m_max_value)
      {
        // Screen-space gradient of the value on the face (per sample), for isolines of constant width.
        float& gradient = m_face_gradient[face];
        if(gradient < 0.f)
        {
          const float x0 = sx[t[0]], y0 = sy[t[0]], x1 = sx[t[1]], y1 = sy[t[1]], x2 = sx[t[2]], y2 = sy[t[2]];
          const double area = double(x1 - x0) * (y2 - y0) - double(x2 - x0) * (y1 - y0);
          const double gx = ((v1 - v0) * (y2 - y0) - (v2 - v0) * (y1 - y0)) / area;
          const double gy = ((v2 - v0) * (x1 - x0) - (v1 - v0) * (x2 - x0)) / area;
          gradient = static_cast<float>(std::sqrt(gx * gx + gy * gy));
        }
        if(gradient > 0.f)
        {
          const double half_width = 0.55 * (std::max)(1, m_options.supersampling);
          const double d = std::abs(v - k * m_step) / gradient; // samples to the isoline
          line = std::clamp(half_width + 0.5 - d, 0., 1.);
        }
      }
    }
  }
  if(back)
  {
    const double grey = 0.3 * r + 0.59 * g + 0.11 * b;
    r = 0.5 * (r + grey);
    g = 0.5 * (g + grey);
    b = 0.5 * (b + grey);
    light *= 0.7;
  }
  const double f = light * (1. - 0.78 * line);
  unsigned char* out = &m_colour[3 * s];
  out[0] = static_cast<unsigned char>((std::min)(255., r * f + 0.5));
  out[1] = static_cast<unsigned char>((std::min)(255., g * f + 0.5));
  out[2] = static_cast<unsigned char>((std::min)(255., b * f + 0.5));
}

// The colour of a sample of face t (corner labels, barycentric weights w) in the label colouring, and how
// much it lies on a border (line, 0 to 1).
void Distance_picture::label_colour(const Triangle& t, const std::array<float, 3>& w, double& r, double& g,
                                      double& b, double& line) const
{
  int best = 0;
  for(int k = 1; k < 3; ++k)
    if(w[k] > w[best])
      best = k;
  const int label = m_labels[t[best]];
  if(label >= 0)
    colour_of_label(label, r, g, b);
  // the border: where the weight of a corner of another label comes close to the largest one
  float other = -1.f;
  for(int k = 0; k < 3; ++k)
    if(m_labels[t[k]] != label)
      other = (std::max)(other, w[k]);
  if(other >= 0.f)
    line = std::clamp(1. - (w[best] - other) / 0.06, 0., 1.);
}

void Distance_picture::downsample()
{
  const int ss = (std::max)(1, m_options.supersampling);
  m_pixels.assign(static_cast<std::size_t>(m_width) * m_height * 3, 255);
  for(int y = 0; y < m_mesh_height; ++y)
    for(int x = 0; x < m_mesh_width; ++x)
    {
      unsigned sum[3] = { 0, 0, 0 };
      for(int j = 0; j < ss; ++j)
        for(int i = 0; i < ss; ++i)
        {
          const std::size_t s = static_cast<std::size_t>(y * ss + j) * m_sw + (x * ss + i);
          for(int k = 0; k < 3; ++k)
            sum[k] += m_colour[3 * s + k];
        }
      unsigned char* out = &m_pixels[3 * (static_cast<std::size_t>(m_mesh_y + y) * m_width + m_mesh_x + x)];
      for(int k = 0; k < 3; ++k)
        out[k] = static_cast<unsigned char>((sum[k] + ss * ss / 2) / (ss * ss));
    }
}

void Distance_picture::fill_colour_table()
{
  for(int i = 0; i < lut_size; ++i)
  {
    const Rgb c = colour_of_fraction(static_cast<double>(i) / (lut_size - 1));
    m_lut[i] = std::array<float, 3>{ { float(c.r), float(c.g), float(c.b) } };
  }
}

} // namespace vtp_geodesics_app
