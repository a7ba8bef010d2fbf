// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_PICTURE_H
#define VTP_SUPPORT_PICTURE_H

// A headless picture of a scalar field on a triangle mesh (a distance field): the mesh, coloured by the field
// (colour_map.h), shaded, with isolines at round values, seen in orthographic projection from a direction that
// fits the whole mesh; a colour bar with the largest value written on it; marked points (the sources) and
// polylines (e.g. geodesic paths), hidden parts drawn dashed.
//
// The mesh is drawn by a small z-buffer rasterizer of our own (supersampled 2x2 for anti-aliasing): drawing
// millions of triangles is not what a 2D vector library is for. The overlay (colour bar, text, markers,
// polylines) is drawn with cairo, which does anti-aliased lines and text with the system fonts, and the PNG is
// encoded with libpng.
//
// Usage:
//   Distance_picture picture(options);
//   picture.set_mesh(nv, point_of, nf, face_of, values, max_value); // point_of(i) -> std::array<double, 3>,
//                                                                   // face_of(f) -> std::array<uint32_t, 3>
//   picture.add_marker(p);  picture.add_polyline(points);
//   (or, before set_mesh(), picture.set_labels(labels): each label, e.g. a nearest-source cell, in its own
//   colour with the borders between labels drawn, instead of the colour map, the isolines and the colour bar)
//   picture.write_png(stream);

#include <vtp_support/colour_map.h>
#include <vtp_support/number_format.h>

#include <cairo.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vtp_support {

struct Picture_options
{
  int isolines = 10;              // about this many isolines, at round values (0: none)
  bool has_view = false;          // else: along the shortest side of the bounding box
  std::array<double, 3> view = { { 0., 0., -1. } }; // viewing direction (from the eye into the scene)
  int max_mesh_width = 1100;      // size of the drawing of the mesh, in pixels
  int max_mesh_height = 850;
  int supersampling = 2;          // samples per pixel along each axis
};

namespace picture_detail {

typedef std::array<double, 3> Vec3;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return Vec3{ { a[0] - b[0], a[1] - b[1], a[2] - b[2] } }; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return Vec3{ { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}
inline Vec3 scaled(const Vec3& a, double s) { return Vec3{ { a[0] * s, a[1] * s, a[2] * s } }; }
inline Vec3 add(const Vec3& a, const Vec3& b) { return Vec3{ { a[0] + b[0], a[1] + b[1], a[2] + b[2] } }; }
inline Vec3 normalized(const Vec3& a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0. ? scaled(a, 1. / n) : a;
}

// A round step for about `n` isolines between 0 and `max_value`: 1, 2, 2.5 or 5 times a power of ten, the
// nearest to max_value / n (on a log scale).
inline double isoline_step(double max_value, int n)
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

// Short text of a value on the colour bar, with as many decimals as `step` needs.
inline std::string label_text(double x, double step)
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

inline void png_write_to_stream(png_structp png, png_bytep data, png_size_t length)
{
  std::ostream* os = static_cast<std::ostream*>(png_get_io_ptr(png));
  os->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
}
inline void png_flush_stream(png_structp png) { static_cast<std::ostream*>(png_get_io_ptr(png))->flush(); }

constexpr double pi = 3.14159265358979323846;

} // namespace picture_detail

class Distance_picture
{
public:
  explicit Distance_picture(const Picture_options& options = Picture_options()) : m_options(options) {}

  // Colours the mesh by `labels` (per vertex; negative: none, drawn grey) instead of the values: call before
  // set_mesh(). Inside a face whose corners have different labels, each point takes the label of the corner of
  // largest barycentric coordinate, and the border between two labels is drawn dark.
  void set_labels(std::vector<int> labels) { m_labels = std::move(labels); }

  // Draws the mesh: `point_of(i)` (i < nv) gives the point of vertex i as std::array<double, 3>, `face_of(f)`
  // (f < nf) the three vertex indices of face f, `values[i]` the value of vertex i (not finite: no value, drawn
  // grey). Colours go from 0 to `max_value`.
  template <class PointOf, class FaceOf>
  void set_mesh(std::size_t nv, const PointOf& point_of, std::size_t nf, const FaceOf& face_of,
                const std::vector<double>& values, double max_value)
  {
    using namespace picture_detail;
    m_max_value = max_value;
    m_step = picture_detail::isoline_step(max_value, m_options.isolines);

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

    // Vertices on screen (in samples) and normals.
    std::vector<float> sx(nv), sy(nv), sz(nv);
    for(std::size_t i = 0; i < nv; ++i)
    {
      const Vec3 q = sub(point_of(i), m_center);
      sx[i] = static_cast<float>((dot(q, m_right) - x0) * scale * ss);
      sy[i] = static_cast<float>((y1 - dot(q, m_up)) * scale * ss);
      sz[i] = static_cast<float>(dot(q, m_forward));
    }
    std::vector<std::array<float, 3> > normals(nv, std::array<float, 3>{ { 0.f, 0.f, 0.f } });
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::array<std::uint32_t, 3> t = face_of(f);
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
    for(int i = 0; i < lut_size; ++i)
    {
      const Rgb c = colour_of_fraction(static_cast<double>(i) / (lut_size - 1));
      m_lut[i] = std::array<float, 3>{ { float(c.r), float(c.g), float(c.b) } };
    }
    for(std::size_t f = 0; f < nf; ++f)
      rasterize(sx, sy, sz, face_of(f), static_cast<std::uint32_t>(f));
    for(std::size_t s = 0; s < m_depth.size(); ++s)
      if(m_face[s] != no_face)
        shade(s, sx, sy, normals, values, m_face[s], face_of(m_face[s]));
    std::vector<std::uint32_t>().swap(m_face);
    std::vector<float>().swap(m_bary);
    std::vector<float>().swap(m_face_gradient);
  }

  // Marks a point (e.g. a source): a white disc with a dark ring; dashed ring if hidden by the surface.
  void add_marker(const std::array<double, 3>& p) { m_markers.push_back(p); }

  // Draws a polyline (e.g. a geodesic path): dark red, dashed where hidden by the surface.
  void add_polyline(const std::vector<std::array<double, 3> >& points) { m_polylines.push_back(points); }

  int width() const { return m_width; }
  int height() const { return m_height; }
  double isoline_step() const { return m_step; }

  // The final picture, RGB, row by row (after `render()`).
  const std::vector<unsigned char>& pixels() const { return m_pixels; }

  // Composes the picture: the mesh (downsampled), then the overlay.
  void render()
  {
    downsample();
    draw_overlay();
  }

  // Renders and writes the picture as PNG to `os`. Throws std::runtime_error on failure.
  void write_png(std::ostream& os)
  {
    render();
    encode_png(os);
  }

private:
  typedef picture_detail::Vec3 Vec3;

  static constexpr std::uint32_t no_face = 0xffffffffu;

  // Depth test of face `f` at the samples it covers (edges shared by two faces are covered by both).
  void rasterize(const std::vector<float>& sx, const std::vector<float>& sy, const std::vector<float>& sz,
                 const std::array<std::uint32_t, 3>& t, std::uint32_t f)
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
  void shade(std::size_t s, const std::vector<float>& sx, const std::vector<float>& sy,
             const std::vector<std::array<float, 3> >& normals, const std::vector<double>& values,
             std::uint32_t face, const std::array<std::uint32_t, 3>& t)
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
      label_colour(t, { { w0, w1, w2 } }, r, g, b, line);
    else if(std::isfinite(v0) && std::isfinite(v1) && std::isfinite(v2))
    {
      const double v = w0 * v0 + w1 * v1 + w2 * v2;
      const double fraction = m_max_value > 0. ? std::clamp(v / m_max_value, 0., 1.) : 0.;
      const std::array<float, 3>& c = m_lut[static_cast<int>(fraction * (lut_size - 1) + 0.5)];
      r = c[0];
      g = c[1];
      b = c[2];
      if(m_step > 0.)
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

  // A colour per label: hues spread by the golden ratio, alternating lightness, so that neighbouring cells
  // (consecutive samples of a farthest-point sampling are far apart, but any labels may meet) differ.
  static void colour_of_label(int label, double& r, double& g, double& b)
  {
    const double hue = std::fmod(0.13 + 0.6180339887498949 * label, 1.) * 6.;
    const double saturation = label % 2 == 0 ? 0.55 : 0.4, value = label % 3 == 0 ? 0.95 : (label % 3 == 1 ? 0.82 : 0.7);
    const int sector = static_cast<int>(hue) % 6;
    const double f = hue - std::floor(hue);
    const double p = value * (1. - saturation), q = value * (1. - saturation * f), u = value * (1. - saturation * (1. - f));
    const double rgb[6][3] = { { value, u, p }, { q, value, p }, { p, value, u }, { p, q, value }, { u, p, value }, { value, p, q } };
    r = 255. * rgb[sector][0];
    g = 255. * rgb[sector][1];
    b = 255. * rgb[sector][2];
  }

  // The colour of a sample of face t (corner labels, barycentric weights w) in the label colouring, and how
  // much it lies on a border (line, 0 to 1).
  void label_colour(const std::array<std::uint32_t, 3>& t, const std::array<float, 3>& w, double& r, double& g,
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

  void downsample()
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

  // Position of a point in picture pixels (x, y) and its depth.
  std::array<double, 3> project(const Vec3& p) const
  {
    using namespace picture_detail;
    const Vec3 q = sub(p, m_center);
    return std::array<double, 3>{ { m_mesh_x + (dot(q, m_right) - m_x0) * m_scale,
                                    m_mesh_y + (m_y1 - dot(q, m_up)) * m_scale, dot(q, m_forward) } };
  }

  // Whether a point at picture position (x, y) and depth z is in front of the surface (within a tolerance). A
  // point on the surface has a depth between those of the samples around it, whatever the slope of the surface:
  // it is visible unless it lies behind every sample of the 3 x 3 samples around it (background samples do not
  // hide anything).
  bool visible(double x, double y, double z) const
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

  void draw_overlay()
  {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, m_width, m_height);
    if(cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    {
      cairo_surface_destroy(surface);
      throw std::runtime_error("cannot create a picture of " + std::to_string(m_width) + " x "
                               + std::to_string(m_height) + " pixels");
    }
    // Copy the mesh drawing in (cairo's RGB24: 32-bit words 0x00RRGGBB).
    cairo_surface_flush(surface);
    unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for(int y = 0; y < m_height; ++y)
    {
      std::uint32_t* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
      const unsigned char* in = &m_pixels[3 * static_cast<std::size_t>(y) * m_width];
      for(int x = 0; x < m_width; ++x)
        row[x] = (std::uint32_t(in[3 * x]) << 16) | (std::uint32_t(in[3 * x + 1]) << 8) | std::uint32_t(in[3 * x + 2]);
    }
    cairo_surface_mark_dirty(surface);
    cairo_t* cr = cairo_create(surface);

    draw_polylines(cr);
    draw_markers(cr);
    if(m_labels.empty())
      draw_colour_bar(cr);

    cairo_destroy(cr);
    cairo_surface_flush(surface);
    for(int y = 0; y < m_height; ++y)
    {
      const std::uint32_t* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
      unsigned char* out = &m_pixels[3 * static_cast<std::size_t>(y) * m_width];
      for(int x = 0; x < m_width; ++x)
      {
        out[3 * x] = static_cast<unsigned char>(row[x] >> 16);
        out[3 * x + 1] = static_cast<unsigned char>(row[x] >> 8);
        out[3 * x + 2] = static_cast<unsigned char>(row[x]);
      }
    }
    cairo_surface_destroy(surface);
  }

  void draw_markers(cairo_t* cr) const
  {
    for(const Vec3& p : m_markers)
    {
      const std::array<double, 3> q = project(p);
      const bool seen = visible(q[0], q[1], q[2]);
      cairo_new_path(cr);
      cairo_arc(cr, q[0], q[1], 6.5, 0., 2. * picture_detail::pi);
      if(seen)
      {
        cairo_set_source_rgb(cr, 1., 1., 1.);
        cairo_fill_preserve(cr);
        cairo_set_dash(cr, nullptr, 0, 0.);
      }
      else
      {
        const double dash[] = { 3., 2.5 };
        cairo_set_dash(cr, dash, 2, 0.);
      }
      cairo_set_source_rgb(cr, 0.8, 0.05, 0.05);
      cairo_set_line_width(cr, 2.5);
      cairo_stroke(cr);
      if(seen)
      {
        cairo_arc(cr, q[0], q[1], 2., 0., 2. * picture_detail::pi);
        cairo_fill(cr);
      }
    }
    cairo_set_dash(cr, nullptr, 0, 0.);
  }

  void draw_polylines(cairo_t* cr) const
  {
    for(const std::vector<Vec3>& line : m_polylines)
    {
      // Sample each segment about every pixel; draw the runs of visible and hidden samples.
      std::vector<std::array<double, 3> > samples;
      std::vector<char> seen;
      for(std::size_t i = 0; i + 1 < line.size(); ++i)
      {
        const std::array<double, 3> a = project(line[i]), b = project(line[i + 1]);
        const int n = (std::max)(1, static_cast<int>(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]))));
        for(int k = (i == 0 ? 0 : 1); k <= n; ++k)
        {
          const double t = static_cast<double>(k) / n;
          const std::array<double, 3> q{ { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
                                           a[2] + t * (b[2] - a[2]) } };
          samples.push_back(q);
          seen.push_back(visible(q[0], q[1], q[2]) ? 1 : 0);
        }
      }
      std::size_t begin = 0;
      while(begin + 1 < samples.size())
      {
        std::size_t end = begin + 1;
        while(end + 1 < samples.size() && seen[end + 1] == seen[begin + 1])
          ++end;
        cairo_new_path(cr);
        cairo_move_to(cr, samples[begin][0], samples[begin][1]);
        for(std::size_t k = begin + 1; k <= end; ++k)
          cairo_line_to(cr, samples[k][0], samples[k][1]);
        if(seen[begin + 1])
        {
          cairo_set_dash(cr, nullptr, 0, 0.);
          cairo_set_source_rgb(cr, 1., 1., 1.);
          cairo_set_line_width(cr, 4.5);
          cairo_stroke_preserve(cr);
          cairo_set_source_rgb(cr, 0.75, 0.05, 0.05);
          cairo_set_line_width(cr, 2.5);
          cairo_stroke(cr);
        }
        else
        {
          const double dash[] = { 4., 3. };
          cairo_set_dash(cr, dash, 2, 0.);
          cairo_set_source_rgb(cr, 0.75, 0.05, 0.05);
          cairo_set_line_width(cr, 1.5);
          cairo_stroke(cr);
        }
        begin = end;
      }
    }
    cairo_set_dash(cr, nullptr, 0, 0.);
  }

  void draw_colour_bar(cairo_t* cr) const
  {
    using namespace picture_detail;
    const double bar_x = m_margin + m_mesh_width + m_margin + 20.;
    const double bar_w = 26.;
    const double top = m_margin + 40.;
    const double bottom = m_height - m_margin - 10.;
    const double h = bottom - top;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 14.);

    // Title.
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, bar_x - 10., m_margin + 12.);
    cairo_show_text(cr, "geodesic distance");

    // The colours, bottom (0) to top (largest value).
    const int rows = static_cast<int>(std::ceil(h));
    for(int i = 0; i < rows; ++i)
    {
      const Rgb c = colour_of_fraction(1. - (i + 0.5) / rows);
      cairo_set_source_rgb(cr, c.r / 255., c.g / 255., c.b / 255.);
      cairo_rectangle(cr, bar_x, top + i * h / rows, bar_w, h / rows + 0.5);
      cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1.);
    cairo_rectangle(cr, bar_x + 0.5, top + 0.5, bar_w - 1., h - 1.);
    cairo_stroke(cr);

    auto label = [&](double fraction, const std::string& text, bool bold) {
      const double y = bottom - fraction * h;
      cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
      cairo_set_line_width(cr, 1.);
      cairo_move_to(cr, bar_x + bar_w, std::round(y) + 0.5);
      cairo_line_to(cr, bar_x + bar_w + 6., std::round(y) + 0.5);
      cairo_stroke(cr);
      cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                             bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
      cairo_text_extents_t e;
      cairo_text_extents(cr, text.c_str(), &e);
      cairo_move_to(cr, bar_x + bar_w + 10., y - e.y_bearing - e.height / 2.);
      cairo_show_text(cr, text.c_str());
    };
    if(!(m_max_value > 0.) || !std::isfinite(m_max_value))
    {
      label(0., "0", false);
      return;
    }
    // Isoline values (thin lines across the bar), labelled unless too close to the ends.
    if(m_step > 0.)
    {
      const double min_gap = 18. / h; // in fractions of the bar
      for(int k = 1; k * m_step < m_max_value; ++k)
      {
        const double f = k * m_step / m_max_value;
        const double y = std::round(bottom - f * h) + 0.5;
        cairo_set_source_rgba(cr, 0., 0., 0., 0.55);
        cairo_move_to(cr, bar_x, y);
        cairo_line_to(cr, bar_x + bar_w, y);
        cairo_stroke(cr);
        if(f > min_gap && f < 1. - min_gap)
          label(f, label_text(k * m_step, m_step), false);
      }
    }
    label(0., "0", false);
    label(1., label_text(m_max_value, m_step > 0. ? m_step / 100. : m_max_value / 1000.) + " (max)", true);
  }

  void encode_png(std::ostream& os) const
  {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if(png == nullptr)
      throw std::runtime_error("cannot encode the picture (libpng)");
    png_infop info = png_create_info_struct(png);
    if(info == nullptr)
    {
      png_destroy_write_struct(&png, nullptr);
      throw std::runtime_error("cannot encode the picture (libpng)");
    }
    if(setjmp(png_jmpbuf(png)))
    {
      png_destroy_write_struct(&png, &info);
      throw std::runtime_error("cannot encode the picture (libpng)");
    }
    png_set_write_fn(png, &os, picture_detail::png_write_to_stream, picture_detail::png_flush_stream);
    png_set_IHDR(png, info, static_cast<png_uint_32>(m_width), static_cast<png_uint_32>(m_height), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 3);
    png_write_info(png, info);
    for(int y = 0; y < m_height; ++y)
      png_write_row(png, const_cast<png_bytep>(&m_pixels[3 * static_cast<std::size_t>(y) * m_width]));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
  }

  Picture_options m_options;
  double m_max_value = 0., m_step = 0.;
  Vec3 m_center{ { 0., 0., 0. } }, m_forward{ { 0., 0., -1. } }, m_right{ { 1., 0., 0. } }, m_up{ { 0., 1., 0. } };
  double m_scale = 1., m_x0 = 0., m_y1 = 0., m_depth_range = 1.;
  int m_mesh_width = 1, m_mesh_height = 1, m_margin = 30, m_panel = 190, m_width = 1, m_height = 1;
  int m_mesh_x = 0, m_mesh_y = 0, m_sw = 1, m_sh = 1;
  std::vector<float> m_depth;
  std::vector<std::uint32_t> m_face;   // during set_mesh(): the face seen at each sample
  std::vector<float> m_bary;           // during set_mesh(): its first two barycentric coordinates there
  std::vector<float> m_face_gradient;  // during set_mesh(): screen gradient of the value per face (-1: not yet)
  static constexpr int lut_size = 1024;
  std::array<std::array<float, 3>, lut_size> m_lut;  // the colour map, finely sampled
  std::vector<unsigned char> m_colour, m_pixels;
  std::vector<Vec3> m_markers;
  std::vector<std::vector<Vec3> > m_polylines;
  std::vector<int> m_labels;           // per vertex, if the picture colours labels (set_labels())
};

} // namespace vtp_support

#endif // VTP_SUPPORT_PICTURE_H
