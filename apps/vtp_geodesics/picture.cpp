// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The picture (see picture.h): the view (direction, projection, layout), the drawing of the mesh in samples, and
// the visibility of points.

#include "picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace vtp_geodesics_app {

namespace picture_detail {

double isoline_step(double max_value, int n)
{
  if(!(max_value > 0.) || !std::isfinite(max_value) || n <= 0)
    return 0.;
  const double raw = max_value / n;
  const double p = std::pow(10., std::floor(std::log10(raw)));
  double best = p;
  for(double m : { 1., 2., 2.5, 5., 10. })
    if(std::abs(std::log(m * p / raw)) < std::abs(std::log(best / raw)))
      best = m * p;
  return best;
}

std::string label_text(double x, double step)
{
  char buffer[64];
  if(x != 0. && (std::abs(x) >= 1e6 || std::abs(x) < 1e-4))
  {
    std::snprintf(buffer, sizeof(buffer), "%.3g", x);
    return buffer;
  }
  int decimals = 0;
  if(step > 0.)
    while(decimals < 8)
    {
      const double scaled_step = step * std::pow(10., decimals);
      if(std::abs(scaled_step - std::round(scaled_step)) <= 1e-6 * scaled_step)
        break;
      ++decimals;
    }
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, x);
  return buffer;
}

} // namespace picture_detail

namespace {

typedef Distance_picture::Vec3 Vec3;

Vec3 sub(const Vec3& a, const Vec3& b) { return Vec3{ { a[0] - b[0], a[1] - b[1], a[2] - b[2] } }; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b)
{
  return Vec3{ { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}
Vec3 scaled(const Vec3& a, double s) { return Vec3{ { a[0] * s, a[1] * s, a[2] * s } }; }
Vec3 add(const Vec3& a, const Vec3& b) { return Vec3{ { a[0] + b[0], a[1] + b[1], a[2] + b[2] } }; }
Vec3 normalized(const Vec3& a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0. ? scaled(a, 1. / n) : a;
}

} // namespace

// The viewing direction, the projection and the layout of the picture, and the samples of the mesh drawing.
void Distance_picture::set_view(std::size_t nv, const Point_of& point_of)
{
  // Bounding box, and the viewing direction.
  Vec3 lo{ { std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity() } };
  Vec3 hi = scaled(lo, -1.);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const Vec3 p = point_of(i);
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = (std::min)(lo[k], p[k]);
      hi[k] = (std::max)(hi[k], p[k]);
    }
  }
  if(nv == 0)
    lo = hi = Vec3{ { 0., 0., 0. } };
  m_center = scaled(add(lo, hi), 0.5);
  Vec3 forward;
  if(m_options.has_view)
    forward = normalized(m_options.view);
  else
  {
    int shortest = 0;
    for(int k = 1; k < 3; ++k)
      if(hi[k] - lo[k] < hi[shortest] - lo[shortest])
        shortest = k;
    forward = Vec3{ { 0., 0., 0. } };
    forward[shortest] = -1.; // look at the mesh from the positive side of its thinnest axis
  }
  // Up: the y axis, or z if the view is (nearly) along y.
  Vec3 up_hint{ { 0., 1., 0. } };
  if(std::abs(forward[1]) > 0.9)
    up_hint = Vec3{ { 0., 0., forward[1] > 0. ? 1. : -1. } };
  m_forward = forward;
  m_right = normalized(cross(forward, up_hint));
  m_up = cross(m_right, forward);

  // Projected extent, and the layout of the picture.
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0, z0 = x0, z1 = -x0;
  for(std::size_t i = 0; i < nv; ++i)
  {
    const Vec3 q = sub(point_of(i), m_center);
    const double x = dot(q, m_right), y = dot(q, m_up), z = dot(q, m_forward);
    x0 = (std::min)(x0, x); x1 = (std::max)(x1, x);
    y0 = (std::min)(y0, y); y1 = (std::max)(y1, y);
    z0 = (std::min)(z0, z); z1 = (std::max)(z1, z);
  }
  if(nv == 0)
    x0 = x1 = y0 = y1 = z0 = z1 = 0.;
  const double ex = (std::max)(x1 - x0, 1e-300), ey = (std::max)(y1 - y0, 1e-300);
  double scale = (std::min)(m_options.max_mesh_width / ex, m_options.max_mesh_height / ey);
  if(!std::isfinite(scale) || !(x1 - x0 > 0. || y1 - y0 > 0.))
    scale = 1.; // a single point, or a mesh seen edge-on along a segment: nothing sensible to fit
  m_mesh_width = (std::max)(1, static_cast<int>(std::ceil(ex * scale)));
  m_mesh_height = (std::max)(1, static_cast<int>(std::ceil(ey * scale)));
  m_margin = 30;
  m_panel = 190;
  m_width = m_margin + m_mesh_width + m_margin + m_panel;
  m_height = (std::max)(m_mesh_height, 380) + 2 * m_margin;
  m_mesh_x = m_margin;
  m_mesh_y = (m_height - m_mesh_height) / 2;
  m_scale = scale;
  m_x0 = x0;
  m_y1 = y1;
  m_depth_range = (std::max)(z1 - z0, 1e-300);

  // Samples.
  const int ss = (std::max)(1, m_options.supersampling);
  m_sw = m_mesh_width * ss;
  m_sh = m_mesh_height * ss;
  m_depth.assign(static_cast<std::size_t>(m_sw) * m_sh, std::numeric_limits<float>::infinity());
  m_colour.assign(static_cast<std::size_t>(m_sw) * m_sh * 3, 255);
}

void Distance_picture::set_mesh(std::size_t nv, const Point_of& point_of, std::size_t nf, const Face_of& face_of,
                                const std::vector<double>& values, double max_value)
{
  m_max_value = max_value;
  m_step = picture_detail::isoline_step(max_value, m_options.isolines);
  set_view(nv, point_of);

  // Vertices on screen (in samples) and normals.
  const int ss = (std::max)(1, m_options.supersampling);
  std::vector<float> sx(nv), sy(nv), sz(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const Vec3 q = sub(point_of(i), m_center);
    sx[i] = static_cast<float>((dot(q, m_right) - m_x0) * m_scale * ss);
    sy[i] = static_cast<float>((m_y1 - dot(q, m_up)) * m_scale * ss);
    sz[i] = static_cast<float>(dot(q, m_forward));
  }
  std::vector<std::array<float, 3> > normals(nv, std::array<float, 3>{ { 0.f, 0.f, 0.f } });
  for(std::size_t f = 0; f < nf; ++f)
  {
    const Triangle t = face_of(f);
    const Vec3 a = point_of(t[0]), b = point_of(t[1]), c = point_of(t[2]);
    const Vec3 n = cross(sub(b, a), sub(c, a)); // area-weighted
    for(std::uint32_t v : t)
      for(int k = 0; k < 3; ++k)
        normals[v][k] += static_cast<float>(n[k]);
  }
  // Normals in camera coordinates (x right, y up, z forward), normalized.
  for(std::size_t i = 0; i < nv; ++i)
  {
    const Vec3 n{ { normals[i][0], normals[i][1], normals[i][2] } };
    const Vec3 c = normalized(Vec3{ { dot(n, m_right), dot(n, m_up), dot(n, m_forward) } });
    normals[i] = std::array<float, 3>{ { static_cast<float>(c[0]), static_cast<float>(c[1]),
                                         static_cast<float>(c[2]) } };
  }

  // Visibility: the nearest face and the barycentric coordinates at each sample; then one shading per sample.
  m_face.assign(m_depth.size(), no_face);
  m_bary.assign(2 * m_depth.size(), 0.f);
  m_face_gradient.assign(nf, -1.f); // computed when first needed
  fill_colour_table();
  for(std::size_t f = 0; f < nf; ++f)
    rasterize(sx, sy, sz, face_of(f), static_cast<std::uint32_t>(f));
  if(m_has_curves)
  {
    draw_curves();
    if(!m_labels.empty())
      fill_labels(nf, face_of);
  }
  for(std::size_t s = 0; s < m_depth.size(); ++s)
    if(m_face[s] != no_face)
      shade(s, sx, sy, normals, values, m_face[s], face_of(m_face[s]));
  std::vector<std::uint32_t>().swap(m_face);
  std::vector<float>().swap(m_bary);
  std::vector<float>().swap(m_face_gradient);
  std::vector<float>().swap(m_line);
  std::vector<int>().swap(m_sample_label);
}

// Position of a point in picture pixels (x, y) and its depth.
std::array<double, 3> Distance_picture::project(const Vec3& p) const
{
  const Vec3 q = sub(p, m_center);
  return std::array<double, 3>{ { m_mesh_x + (dot(q, m_right) - m_x0) * m_scale,
                                  m_mesh_y + (m_y1 - dot(q, m_up)) * m_scale, dot(q, m_forward) } };
}

// Whether a point at picture position (x, y) and depth z is in front of the surface (within a tolerance). A
// point on the surface has a depth between those of the samples around it, whatever the slope of the surface:
// it is visible unless it lies behind every sample of the 3 x 3 samples around it (background samples do not
// hide anything).
bool Distance_picture::visible(double x, double y, double z) const
{
  const int ss = (std::max)(1, m_options.supersampling);
  const double fx = (x - m_mesh_x) * ss, fy = (y - m_mesh_y) * ss;
  if(!(std::abs(fx) < 1e8) || !(std::abs(fy) < 1e8))
    return true; // far outside the drawing: nothing hides it
  const int cx = static_cast<int>(std::floor(fx));
  const int cy = static_cast<int>(std::floor(fy));
  const double tolerance = 2e-3 * m_depth_range;
  float farthest = -std::numeric_limits<float>::infinity();
  bool covered = false;
  for(int j = cy - 1; j <= cy + 1; ++j)
    for(int i = cx - 1; i <= cx + 1; ++i)
      if(i >= 0 && j >= 0 && i < m_sw && j < m_sh)
      {
        const float d = m_depth[static_cast<std::size_t>(j) * m_sw + i];
        if(d < std::numeric_limits<float>::infinity())
        {
          farthest = (std::max)(farthest, d);
          covered = true;
        }
      }
  return !covered || z <= farthest + tolerance;
}

} // namespace vtp_geodesics_app
