// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The picture (see picture.h): the overlay drawn with cairo on the mesh drawing (paths, markers, colour bar), and
// the PNG encoding with libpng.

#include "picture.h"
#include "colour_map.h"

#include <cairo.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace vtp_geodesics_app {

namespace {

constexpr double pi = 3.14159265358979323846;

void png_write_to_stream(png_structp png, png_bytep data, png_size_t length)
{
  std::ostream* os = static_cast<std::ostream*>(png_get_io_ptr(png));
  os->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
}
void png_flush_stream(png_structp png) { static_cast<std::ostream*>(png_get_io_ptr(png))->flush(); }

// Strokes the current path in dark red (of red component `red`), solid where it is `seen`, else dashed (`dash`:
// the lengths on and off).
void stroke_red(cairo_t* cr, bool seen, double red, double width, const std::array<double, 2>& dash)
{
  if(seen)
    cairo_set_dash(cr, nullptr, 0, 0.);
  else
    cairo_set_dash(cr, dash.data(), 2, 0.);
  cairo_set_source_rgb(cr, red, 0.05, 0.05);
  cairo_set_line_width(cr, width);
  cairo_stroke(cr);
}

} // namespace

// What the overlay draws, each from the picture's projection and visibility.
struct Distance_picture::Overlay
{
  static void markers(const Distance_picture& pic, cairo_t* cr)
  {
    for(const Vec3& p : pic.m_markers)
    {
      const std::array<double, 3> q = pic.project(p);
      const bool seen = pic.visible(q[0], q[1], q[2]);
      cairo_new_path(cr);
      cairo_arc(cr, q[0], q[1], 6.5, 0., 2. * pi);
      if(seen)
      {
        cairo_set_source_rgb(cr, 1., 1., 1.);
        cairo_fill_preserve(cr);
      }
      stroke_red(cr, seen, 0.8, 2.5, { 3., 2.5 });
      if(seen)
      {
        cairo_arc(cr, q[0], q[1], 2., 0., 2. * pi);
        cairo_fill(cr);
      }
    }
    cairo_set_dash(cr, nullptr, 0, 0.);
  }

  static void polylines(const Distance_picture& pic, cairo_t* cr)
  {
    for(const std::vector<Vec3>& line : pic.m_polylines)
    {
      // Sample each segment about every pixel; draw the runs of visible and hidden samples.
      std::vector<std::array<double, 3> > samples;
      std::vector<char> seen;
      for(std::size_t i = 0; i + 1 < line.size(); ++i)
      {
        const std::array<double, 3> a = pic.project(line[i]), b = pic.project(line[i + 1]);
        const int n = (std::max)(1, static_cast<int>(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]))));
        for(int k = (i == 0 ? 0 : 1); k <= n; ++k)
        {
          const double t = static_cast<double>(k) / n;
          const std::array<double, 3> q{ { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
                                           a[2] + t * (b[2] - a[2]) } };
          samples.push_back(q);
          seen.push_back(pic.visible(q[0], q[1], q[2]) ? 1 : 0);
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
        }
        stroke_red(cr, seen[begin + 1] != 0, 0.75, seen[begin + 1] ? 2.5 : 1.5, { 4., 3. });
        begin = end;
      }
    }
    cairo_set_dash(cr, nullptr, 0, 0.);
  }

  static void colour_bar(const Distance_picture& pic, cairo_t* cr)
  {
    using namespace picture_detail;
    const double bar_x = pic.m_margin + pic.m_mesh_width + pic.m_margin + 20.;
    const double bar_w = 26.;
    const double top = pic.m_margin + 40.;
    const double bottom = pic.m_height - pic.m_margin - 10.;
    const double h = bottom - top;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 14.);

    // Title.
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, bar_x - 10., pic.m_margin + 12.);
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
    if(!(pic.m_max_value > 0.) || !std::isfinite(pic.m_max_value))
    {
      label(0., "0", false);
      return;
    }
    // Isoline values (thin lines across the bar), labelled unless too close to the ends.
    if(pic.m_step > 0.)
    {
      const double min_gap = 18. / h; // in fractions of the bar
      for(int k = 1; k * pic.m_step < pic.m_max_value; ++k)
      {
        const double f = k * pic.m_step / pic.m_max_value;
        const double y = std::round(bottom - f * h) + 0.5;
        cairo_set_source_rgba(cr, 0., 0., 0., 0.55);
        cairo_move_to(cr, bar_x, y);
        cairo_line_to(cr, bar_x + bar_w, y);
        cairo_stroke(cr);
        if(f > min_gap && f < 1. - min_gap)
          label(f, label_text(k * pic.m_step, pic.m_step), false);
      }
    }
    label(0., "0", false);
    const double precision = pic.m_step > 0. ? pic.m_step / 100. : pic.m_max_value / 1000.;
    label(1., label_text(pic.m_max_value, precision) + " (max)", true);
  }
};

void Distance_picture::draw_overlay()
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

  Overlay::polylines(*this, cr);
  Overlay::markers(*this, cr);
  if(!m_angles.empty())
    draw_angle_wheel(cr);
  else if(m_labels.empty())
    Overlay::colour_bar(*this, cr);

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

void Distance_picture::encode_png(std::ostream& os) const
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
  png_set_write_fn(png, &os, png_write_to_stream, png_flush_stream);
  png_set_IHDR(png, info, static_cast<png_uint_32>(m_width), static_cast<png_uint_32>(m_height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 3);
  png_write_info(png, info);
  for(int y = 0; y < m_height; ++y)
    png_write_row(png, const_cast<png_bytep>(&m_pixels[3 * static_cast<std::size_t>(y) * m_width]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

} // namespace vtp_geodesics_app
