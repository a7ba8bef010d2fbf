// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_PICTURE_H
#define VTP_GEODESICS_APP_PICTURE_H

// A headless picture of a scalar field on a triangle mesh (a distance field): the mesh, coloured by the field
// (colour_map.h), shaded, with isolines at round values, seen in orthographic projection from a direction that
// fits the whole mesh; a colour bar with the largest value written on it; marked points (the sources) and
// polylines (e.g. geodesic paths), hidden parts drawn dashed.
//
// The mesh is drawn by a small z-buffer rasterizer of our own (supersampled 2x2 for anti-aliasing): drawing
// millions of triangles is not what a 2D vector library is for. The overlay (colour bar, text, markers,
// polylines) is drawn with cairo, which does anti-aliased lines and text with the system fonts, and the PNG is
// encoded with libpng. The class is written in three files:
//   picture.cpp          the view (direction, projection, layout) and the visibility of points
//   picture_raster.cpp   the rasterizer: depth test, shading, isolines, label colours, downsampling
//   picture_curves.cpp   the curves given by set_curves() (the library's isolines and cell borders) in the samples
//   picture_overlay.cpp  the overlay (cairo) and the PNG encoding (libpng)
//   picture_angle.cpp    the colours of angles (the log map's theta) and their wheel
//
// Usage:
//   Distance_picture picture(options);
//   picture.set_mesh(nv, point_of, nf, face_of, values, max_value); // point_of(i) -> std::array<double, 3>,
//                                                                   // face_of(f) -> std::array<uint32_t, 3>
//   picture.add_marker(p);  picture.add_polyline(points);
//   (or, before set_mesh(), picture.set_labels(labels): each label, e.g. a nearest-source cell, in its own
//   colour with the borders between labels drawn, instead of the colour map, the isolines and the colour bar;
//   and picture.set_curves(curves): these curves drawn as the isolines, or as the borders of the labels)
//   picture.write_png(stream);

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

struct _cairo;  // cairo_t (picture_angle.cpp)

namespace vtp_geodesics_app {

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

// A round step for about `n` isolines between 0 and `max_value`: 1, 2, 2.5 or 5 times a power of ten, the
// nearest to max_value / n (on a log scale).
double isoline_step(double max_value, int n);

// Short text of a value on the colour bar, with as many decimals as `step` needs.
std::string label_text(double x, double step);

} // namespace picture_detail

class Distance_picture
{
public:
  typedef std::array<double, 3> Vec3;
  typedef std::array<std::uint32_t, 3> Triangle;
  typedef std::function<Vec3(std::size_t)> Point_of;
  typedef std::function<Triangle(std::size_t)> Face_of;

  explicit Distance_picture(const Picture_options& options = Picture_options()) : m_options(options) {}

  // Colours the mesh by `labels` (per vertex; negative: none, drawn grey) instead of the values: call before
  // set_mesh(). Inside a face whose corners have different labels, each point takes the label of the corner of
  // largest barycentric coordinate, and the border between two labels is drawn dark.
  void set_labels(std::vector<int> labels) { m_labels = std::move(labels); }

  // Colours the mesh by the angle of `xy` (per vertex: the log map's tangent coordinates, interpolated linearly
  // inside each face) on a hue wheel, keeping the isolines of the values; a wheel instead of the colour bar
  // (picture_angle.cpp). Call before set_mesh().
  void set_angles(std::vector<std::array<double, 2> > xy) { m_angles = std::move(xy); }

  // Draws `curves` (polylines on the surface, e.g. the isolines of the library at the picture's levels, or the
  // borders of its cells) instead of the isolines found by interpolating the values linearly inside the faces
  // (with set_labels(): instead of the borders between the labels of the corners), with the same width and
  // darkening, where they are seen (picture_curves.cpp). A closed curve repeats its first point at the end.
  // Call before set_mesh().
  void set_curves(std::vector<std::vector<Vec3> > curves)
  {
    m_curves = std::move(curves);
    m_has_curves = true;
  }

  // Draws the mesh: `point_of(i)` (i < nv) gives the point of vertex i, `face_of(f)` (f < nf) the three vertex
  // indices of face f, `values[i]` the value of vertex i (not finite: no value, drawn grey). Colours go from 0
  // to `max_value`.
  void set_mesh(std::size_t nv, const Point_of& point_of, std::size_t nf, const Face_of& face_of,
                const std::vector<double>& values, double max_value);

  // Marks a point (e.g. a source): a white disc with a dark ring; dashed ring if hidden by the surface.
  void add_marker(const Vec3& p) { m_markers.push_back(p); }

  // Draws a polyline (e.g. a geodesic path): dark red, dashed where hidden by the surface.
  void add_polyline(const std::vector<Vec3>& points) { m_polylines.push_back(points); }

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
  static constexpr std::uint32_t no_face = 0xffffffffu;
  static constexpr int no_label = -2147483647 - 1;  // (INT_MIN) m_sample_label: the rule of label_colour()
  static constexpr int lut_size = 1024;

  // picture.cpp: the view, and where points are on the picture.
  void set_view(std::size_t nv, const Point_of& point_of);
  std::array<double, 3> project(const Vec3& p) const;
  bool visible(double x, double y, double z) const;

  // picture_raster.cpp
  void rasterize(const std::vector<float>& sx, const std::vector<float>& sy, const std::vector<float>& sz,
                 const Triangle& t, std::uint32_t f);
  void shade(std::size_t s, const std::vector<float>& sx, const std::vector<float>& sy,
             const std::vector<std::array<float, 3> >& normals, const std::vector<double>& values,
             std::uint32_t face, const Triangle& t);
  void label_colour(const Triangle& t, const std::array<float, 3>& w, double& r, double& g, double& b,
                    double& line) const;
  void fill_colour_table();
  void downsample();

  // picture_curves.cpp: m_line from m_curves (after the depth test); with labels, m_sample_label
  void draw_curves();
  void fill_labels(std::size_t nf, const Face_of& face_of);

  // picture_angle.cpp
  void angle_colour(const Triangle& t, const std::array<float, 3>& w, double& r, double& g, double& b) const;
  void draw_angle_wheel(::_cairo* cr) const;

  // picture_overlay.cpp
  struct Overlay;
  void draw_overlay();
  void encode_png(std::ostream& os) const;

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
  std::vector<float> m_line;           // during set_mesh(), with set_curves(): how much each sample is on a curve
  std::vector<int> m_sample_label;     // during set_mesh(), with set_curves() and labels: the label of each sample
  std::array<std::array<float, 3>, lut_size> m_lut;  // the colour map, finely sampled
  std::vector<unsigned char> m_colour, m_pixels;
  std::vector<Vec3> m_markers;
  std::vector<std::vector<Vec3> > m_polylines;
  std::vector<int> m_labels;           // per vertex, if the picture colours labels (set_labels())
  std::vector<std::array<double, 2> > m_angles; // per vertex, if the picture colours angles (set_angles())
  std::vector<std::vector<Vec3> > m_curves;      // set_curves()
  bool m_has_curves = false;
};

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_PICTURE_H
