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


#ifndef CGAL_VTP_GEODESICS_GEODESIC_VORONOI_CELLS_H
#define CGAL_VTP_GEODESICS_GEODESIC_VORONOI_CELLS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// The areas of geodesic Voronoi cells, as both `geodesic_voronoi_cell_areas()` give them: from a
/// nearest-source labelling of the vertices (geodesic_voronoi_cells.h) or from the field of a solver
/// (geodesic_curves.h).
struct Voronoi_cell_areas
{
  /// `areas[i]`: the area of the part of the surface nearest to source (sample) `i`.
  std::vector<double> areas;
  /// `uncertainty[i]`: a bound of |`areas[i]` - the true area of cell `i`|, which holds under the condition that
  /// the function that computed it states (one meaning for both): from the labels of the vertices, the total area
  /// of the split faces (faces whose corners have different labels) with a corner in cell `i`, a bound when the
  /// cell meets no face without a corner in it; from the field of a solver, the chord tolerance times the length
  /// of the border of cell `i` (the area between its chords and its arcs), a bound where the borders are exact.
  std::vector<double> uncertainty;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

inline double triangle_area(const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const std::array<double, 3>& c)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
  return 0.5 * std::sqrt(x * x + y * y + z * z);
}

// The point of edge (p, q) where the distances of the cells of p and of q, each extended straight along the
// edge from its end (dp + t L and dq + (1 - t) L), are equal: p + t (q - p), t clamped to [0, 1].
inline double border_parameter(double dp, double dq, double length)
{
  if(!(length > 0.))
    return 0.5;
  const double t = (dq - dp + length) / (2. * length);
  return t < 0. ? 0. : (t > 1. ? 1. : (t == t ? t : 0.5));
}

inline std::array<double, 3> lerp(const std::array<double, 3>& p, const std::array<double, 3>& q, double t)
{
  return { p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2]) };
}

} // namespace internal
/// \endcond

/// \ingroup PkgVTPGeodesicsRef
/// The area of each geodesic Voronoi cell of a nearest-source labelling of the vertices of `tm` (for
/// example the labels and distances of `farthest_point_sampling()`, or of `compute_geodesic_distances()`
/// with `nearest_source_map`). A face whose three corners have the same label belongs to that cell. A face
/// whose corners have different labels is split: on each edge between two cells, the border is placed where
/// the two distances, each extended straight along the edge from its end, are equal, and it is straight in
/// between (through the mean of the three edge points when the three labels differ). This is exact when
/// the two nearest sources are seen along the edge and only an estimate otherwise: the area of every face
/// so split is counted (once) in `uncertainty` of each cell that has a corner in it, a bound of |`areas[i]` -
/// the true area| when cell `i` meets no face without a corner labelled `i` (no cell pokes across an edge
/// whose two vertices are in another cell; refining the mesh makes the bound small). A corner without a label (unreached) takes its share of the
/// face out of every cell. The areas of the cells and of the unreached part add up to the area of `tm`.
///
/// \param tm the triangle mesh
/// \param number_of_cells the number of sources (labels are in `[0, number_of_cells)` or `no_source`)
/// \param labels per vertex, in the order of `vertices(tm)`: the index of its nearest source, or `no_source`
/// \param distances per vertex, in the same order: its distance to its nearest source
/// \param np optional named parameters: `vertex_point_map`
/// \throws Invalid_input_error if a label is out of range, the vectors do not have one entry per vertex, a
/// face is not a triangle, or a distance of a labelled vertex is not finite.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Voronoi_cell_areas geodesic_voronoi_cell_areas(const TriangleMesh& tm, std::size_t number_of_cells,
                                               const std::vector<std::size_t>& labels,
                                               const std::vector<double>& distances,
                                               const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const std::size_t nv = static_cast<std::size_t>(num_vertices(tm));
  if(labels.size() != nv || distances.size() != nv)
    throw Invalid_input_error("geodesic_voronoi_cell_areas: " + std::to_string(labels.size()) + " labels and "
                              + std::to_string(distances.size()) + " distances for " + std::to_string(nv)
                              + " vertices");
  auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t n = 0;
  for(vertex_descriptor v : vertices(tm))
  {
    const std::size_t l = labels[n];
    if(l != no_source && l >= number_of_cells)
      throw Invalid_input_error("the label of vertex " + std::to_string(n) + " is " + std::to_string(l)
                                + ", not below the number of cells " + std::to_string(number_of_cells));
    if(l != no_source && !std::isfinite(distances[n]))
      throw Invalid_input_error("the distance of vertex " + std::to_string(n) + " is not finite");
    put(vid, v, n++);
  }

  Voronoi_cell_areas r;
  r.areas.assign(number_of_cells, 0.);
  r.uncertainty.assign(number_of_cells, 0.);
  std::size_t f_index = 0;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      throw Invalid_input_error("face " + std::to_string(f_index) + " is not a triangle");
    ++f_index;
    std::array<std::array<double, 3>, 3> p;
    std::size_t l[3];
    double d[3];
    auto g = h;
    for(int k = 0; k < 3; ++k, g = next(g, tm))
    {
      const vertex_descriptor v = source(g, tm);
      const auto& q = get(vpm, v);
      p[k] = { CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()) };
      const std::size_t i = get(vid, v);
      l[k] = labels[i];
      d[k] = distances[i];
    }
    const double area = internal::triangle_area(p[0], p[1], p[2]);
    if(l[0] == l[1] && l[1] == l[2])
    {
      if(l[0] != no_source)
        r.areas[l[0]] += area;
      continue;
    }
    for(int k = 0; k < 3; ++k)
      if(l[k] != no_source)
        r.uncertainty[l[k]] += (k == 0 || (l[k] != l[0] && (k == 1 || l[k] != l[1]))) ? area : 0.;
    // the edge points between corners of different labels
    auto edge_point = [&](int i, int j) {
      const double length = std::sqrt((p[j][0] - p[i][0]) * (p[j][0] - p[i][0]) + (p[j][1] - p[i][1]) * (p[j][1] - p[i][1])
                                      + (p[j][2] - p[i][2]) * (p[j][2] - p[i][2]));
      return internal::lerp(p[i], p[j], internal::border_parameter(d[i], d[j], length));
    };
    int odd = -1;  // two labels: the corner whose label the two others share
    for(int k = 0; k < 3; ++k)
      if(l[(k + 1) % 3] == l[(k + 2) % 3])
        odd = k;
    if(odd >= 0)
    {
      const int a = (odd + 1) % 3, b = (odd + 2) % 3;
      const double part = internal::triangle_area(p[odd], edge_point(odd, a), edge_point(odd, b));
      if(l[odd] != no_source)
        r.areas[l[odd]] += part;
      if(l[a] != no_source)
        r.areas[l[a]] += area - part;
      continue;
    }
    const std::array<double, 3> e[3] = { edge_point(0, 1), edge_point(1, 2), edge_point(2, 0) };
    const std::array<double, 3> c = { (e[0][0] + e[1][0] + e[2][0]) / 3., (e[0][1] + e[1][1] + e[2][1]) / 3.,
                                      (e[0][2] + e[1][2] + e[2][2]) / 3. };
    for(int k = 0; k < 3; ++k)
      if(l[k] != no_source)
        r.areas[l[k]] += internal::triangle_area(p[k], e[k], c) + internal::triangle_area(p[k], c, e[(k + 2) % 3]);
  }
  return r;
}

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_GEODESIC_VORONOI_CELLS_H
