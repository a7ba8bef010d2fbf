// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The picture (see picture.h): the colours of angles (the log map's theta, --picture-colour angle) on a hue
// wheel, and the wheel drawn instead of the colour bar.

#include "picture.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace vtp_geodesics_app {

namespace {

constexpr double pi = 3.14159265358979323846;

// The colour of angle `theta` (radians) on the hue wheel: red at 0, then yellow, green, cyan, blue, magenta
// counter-clockwise; a little less saturated than pure hues, so that the shading and the isolines show. In 0-1.
void hue_of_angle(double theta, double& r, double& g, double& b)
{
  double h = std::fmod(theta / (2. * pi), 1.);
  if(h < 0.)
    h += 1.;
  const double s = 0.72, v = 0.97;
  const double x = h * 6.;
  const int sector = static_cast<int>(x) % 6;
  const double f = x - std::floor(x);
  const double p = v * (1. - s), q = v * (1. - s * f), u = v * (1. - s * (1. - f));
  const double rgb[6][3] = { { v, u, p }, { q, v, p }, { p, v, u }, { p, q, v }, { u, p, v }, { v, p, q } };
  r = rgb[sector][0];
  g = rgb[sector][1];
  b = rgb[sector][2];
}

} // namespace

// The tangent coordinates of the corners of t interpolated with the weights w, and the hue of their angle (a
// point at the origin, the source itself, takes the hue of 0). In 0-255, as the colour map.
void Distance_picture::angle_colour(const Triangle& t, const std::array<float, 3>& w, double& r, double& g,
                                    double& b) const
{
  double x = 0., y = 0.;
  for(int k = 0; k < 3; ++k)
  {
    x += w[k] * m_angles[t[k]][0];
    y += w[k] * m_angles[t[k]][1];
  }
  if(!std::isfinite(x) || !std::isfinite(y))
    return;  // keep the colour given (a corner unreached is drawn grey before)
  hue_of_angle(std::atan2(y, x), r, g, b);
  r *= 255.;
  g *= 255.;
  b *= 255.;
}

// The wheel of the angles in the panel on the right: theta = 0 to the right, growing counter-clockwise (as
// seen from the side the faces' normals point to), with the isoline step below.
void Distance_picture::draw_angle_wheel(::_cairo* cr) const
{
  const double x0 = m_margin + m_mesh_width + m_margin;
  const double cx = x0 + m_panel / 2. - 10., cy = m_margin + 40. + 75., radius = 62.;
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 14.);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_move_to(cr, x0 + 10., m_margin + 12.);
  cairo_show_text(cr, "geodesic polar angle");

  // the wheel: a ring of thin sectors, angles counter-clockwise on the picture (its y axis points down)
  const int sectors = 360;
  const double inner = 0.5 * radius;
  for(int i = 0; i < sectors; ++i)
  {
    const double a0 = 2. * pi * i / sectors, a1 = 2. * pi * (i + 1.2) / sectors;
    double r, g, b;
    hue_of_angle(2. * pi * (i + 0.5) / sectors, r, g, b);
    cairo_set_source_rgb(cr, r, g, b);
    cairo_new_path(cr);
    cairo_arc_negative(cr, cx, cy, radius, -a0, -a1);
    cairo_arc(cr, cx, cy, inner, -a1, -a0);
    cairo_close_path(cr);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_line_width(cr, 1.);
  cairo_new_path(cr);
  cairo_arc(cr, cx, cy, radius, 0., 2. * pi);
  cairo_stroke(cr);
  cairo_new_path(cr);
  cairo_arc(cr, cx, cy, inner, 0., 2. * pi);
  cairo_stroke(cr);
  // theta = 0, and the sense in which it grows
  cairo_move_to(cr, cx + inner * 0.3, cy);
  cairo_line_to(cr, cx + inner * 0.9, cy);
  cairo_stroke(cr);
  cairo_new_path(cr);
  cairo_arc_negative(cr, cx, cy, inner * 0.6, -0.15, -1.2);
  cairo_stroke(cr);
  const double tip = -1.2;
  cairo_move_to(cr, cx + inner * 0.6 * std::cos(tip) - 6., cy + inner * 0.6 * std::sin(tip) - 1.);
  cairo_line_to(cr, cx + inner * 0.6 * std::cos(tip), cy + inner * 0.6 * std::sin(tip));
  cairo_line_to(cr, cx + inner * 0.6 * std::cos(tip) - 1., cy + inner * 0.6 * std::sin(tip) + 6.);
  cairo_stroke(cr);

  const char* names[4] = { "0", "\xcf\x80/2", "\xcf\x80", "3\xcf\x80/2" };
  for(int k = 0; k < 4; ++k)
  {
    const double a = 0.5 * pi * k;
    cairo_text_extents_t e;
    cairo_text_extents(cr, names[k], &e);
    const double tx = cx + (radius + 8. + 0.5 * e.width) * std::cos(a), ty = cy - (radius + 10.) * std::sin(a);
    cairo_move_to(cr, tx - e.width / 2. - e.x_bearing, ty - e.y_bearing - e.height / 2.);
    cairo_show_text(cr, names[k]);
  }

  // the isolines (of the distance)
  double y = cy + radius + 40.;
  cairo_move_to(cr, x0 + 10., y);
  cairo_show_text(cr, "isolines: distance");
  if(m_step > 0.)
  {
    y += 20.;
    const std::string text = "every " + picture_detail::label_text(m_step, m_step);
    cairo_move_to(cr, x0 + 10., y);
    cairo_show_text(cr, text.c_str());
  }
  y += 20.;
  const std::string largest = "largest " + picture_detail::label_text(m_max_value, m_step > 0. ? m_step / 10. : 0.);
  if(m_max_value > 0. && std::isfinite(m_max_value))
  {
    cairo_move_to(cr, x0 + 10., y);
    cairo_show_text(cr, largest.c_str());
  }
}

} // namespace vtp_geodesics_app
