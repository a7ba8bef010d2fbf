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

#ifndef CGAL_VTP_GEODESICS_GEODESIC_CURVES_H
#define CGAL_VTP_GEODESICS_GEODESIC_CURVES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Surface_polyline.h>
#include <CGAL/VTP_geodesics/geodesic_voronoi_cells.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_extraction.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_refinement.h>
#include <CGAL/VTP_geodesics/internal/solver/Settings_from_parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// A curve on the surface: an isoline of the distance (`level`) or a border between two geodesic Voronoi
/// cells (`cells`). It is a `Surface_polyline` (`points` and their face `locations`, as the solver takes them):
/// two consecutive points lie in a common face (they are joined by a chord of the curve inside it). A closed
/// curve does not repeat its first point.
template <class FaceDescriptor, class Point>
struct Geodesic_curve : Surface_polyline<FaceDescriptor, Point>
{
  /// whether the curve is closed (its last point is joined to its first)
  bool closed = false;
  /// the level of an isoline (NaN for a border)
  double level = std::numeric_limits<double>::quiet_NaN();
  /// the two labels (source indices) of a border, the smaller first (`no_source` for an isoline)
  std::array<std::size_t, 2> cells = { { no_source, no_source } };
};

/// \ingroup PkgVTPGeodesicsRef
/// What the extraction of curves could not place from the field of the faces: an extra result of
/// `geodesic_isolines()` and `geodesic_cell_borders()`, asked for as `statistics` is, with the named parameter
/// `curves_report(r)` (`r` a `Geodesic_curves_report&` that the function fills).
struct Geodesic_curves_report
{
  std::size_t points = 0;           ///< points written
  std::size_t undecided = 0;        ///< points inside faces left on the chord (no sign change across it)
  std::size_t edge_fallbacks = 0;   ///< edge points placed by interpolation of the vertex values (borders from
                                    ///< the kept field: edges whose exact search of the changes gave up)
  std::size_t junction_fallbacks = 0; ///< junctions of three cells not solved inside their face
  /// with `exact_refinement(n)`: the largest |exact distance - level| of the points before the moves of the
  /// last refinement run (NaN without refinement)
  double residual = std::numeric_limits<double>::quiet_NaN();
};

/// \cond SKIP_IN_MANUAL
namespace internal {

template <class Solver, class NP>
std::vector<Geodesic_curve<typename Solver::face_descriptor, typename Solver::Point_3> >
extract_curves(const Solver& solver, const std::vector<double>* levels, const NP& np, Geodesic_curves_report* report,
               Voronoi_cell_areas* cell_areas = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Geodesic_curve<typename Solver::face_descriptor, typename Solver::Point_3> Curve;
  report = choose_parameter(get_parameter(np, internal_np::curves_report), report);
  const auto& index = solver.mesh_index();
  const Propagation_engine& engine = solver.engine();
  if(!engine.path_record().is_active() && !engine.kept_field().is_active())
    throw Invalid_input_error("curves need the field of the last computation: compute with keep_field(true) "
                              "(exact), or record_paths(true)");
  if(has_segments(engine.seeds()) && (levels == nullptr || !engine.kept_field().is_active()))
    throw Invalid_input_error("from sources that are curves, the isolines (their offset curves) only, from the kept "
                              "field (keep_field(true)); no cell borders yet");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, index.tm));
  const double scale = index.length_scale;
  const double tolerance = choose_parameter(get_parameter(np, internal_np::chord_tolerance),
                                            1e-3 * solver.mean_edge_length());
  if(!(tolerance > 0.) || !std::isfinite(tolerance))
    throw Invalid_input_error("the chord tolerance must be positive and finite");
  const Mesh_arrays& m = index.arrays;
  const Curve_field& field = solver.field_queries().field();
  Curve_extraction extraction(field, tolerance / scale);
  std::vector<Extracted_curve> curves;
  std::vector<std::pair<Index, Index> > pairs;
  if(levels != nullptr)
  {
    std::vector<double> scaled(*levels);
    for(double& l : scaled)
      l /= scale;
    curves = extraction.isolines(scaled);
    const int runs = choose_parameter(get_parameter(np, internal_np::exact_refinement), 0);
    if(runs < 0 || runs > 10)
      throw Invalid_input_error("exact_refinement must be between 0 and 10 runs");
    if(runs > 0)
    {
      int threads = 1;
      const Propagation_settings settings = settings_from_parameters(parameters::default_values(), index, threads);
      const double residual = refine_isolines(m, engine.seeds(), scaled, settings, runs, curves);
      if(report != nullptr)
        report->residual = residual * scale;
    }
  }
  else
    curves = extraction.borders(pairs);
  if(cell_areas != nullptr)
  {
    std::size_t cells = 0;
    for(const Seed& s : engine.seeds())
      cells = (std::max)(cells, static_cast<std::size_t>(s.label) + 1);
    cell_areas->areas.assign(cells, 0.);
    cell_areas->uncertainty.assign(cells, 0.);
    for(std::size_t i = 0; i < extraction.areas.size() && i < cells; ++i)
    {
      cell_areas->areas[i] = extraction.areas[i] * scale * scale;
      cell_areas->uncertainty[i] = extraction.area_bounds[i] * scale * scale;
    }
  }
  std::vector<Curve> out(curves.size());
  std::size_t points = 0;
  for(std::size_t i = 0; i < curves.size(); ++i)
  {
    const Extracted_curve& c = curves[i];
    Curve& r = out[i];
    r.closed = c.closed;
    if(levels != nullptr)
      r.level = (*levels)[static_cast<std::size_t>(c.set)];
    else
      r.cells = { { static_cast<std::size_t>(pairs[static_cast<std::size_t>(c.set)].first),
                    static_cast<std::size_t>(pairs[static_cast<std::size_t>(c.set)].second) } };
    for(const Curve_point& p : c.points)
    {
      double xyz[3] = { 0., 0., 0. };
      for(int k = 0; k < 3; ++k)
      {
        const auto& q = get(vpm, index.vertices[static_cast<std::size_t>(m.source[3 * p.face + k])]);
        xyz[0] += p.b[k] * CGAL::to_double(q.x());
        xyz[1] += p.b[k] * CGAL::to_double(q.y());
        xyz[2] += p.b[k] * CGAL::to_double(q.z());
      }
      r.points.push_back(typename Solver::Point_3(xyz[0], xyz[1], xyz[2]));
      r.locations.emplace_back(index.faces[static_cast<std::size_t>(p.face)],
                               std::array<double, 3>{ { p.b[0], p.b[1], p.b[2] } });
    }
    points += c.points.size();
  }
  if(report != nullptr)
  {
    report->points = points;
    report->undecided = extraction.pieces().undecided;
    report->edge_fallbacks = extraction.pieces().edge_fallbacks + extraction.m_border_fallbacks;
    report->junction_fallbacks = extraction.pieces().junction_fallbacks;
  }
  return out;
}

} // namespace internal
/// \endcond

/// \ingroup PkgVTPGeodesicsRef
/// The isolines of the distance of the last computation of `solver` at `levels`, as connected curves: one
/// curve per connected component of each level set, closed, or open with its ends on the border of the mesh
/// (or where a face has an unreached corner). Curves are ordered by level (in the order of `levels`).
///
/// Which edges an isoline crosses is decided by the vertex distances (a vertex at the level counts as above
/// it). Where it crosses an edge and how it runs inside a face come from the field inside the faces: each face
/// has candidates (its corners, the sources in it, and with the kept field every window that crossed it) and the
/// distance at a point is the least candidate distance (arcs of circles meeting where candidates switch),
/// sampled so that the chords are within `chord_tolerance` of the arcs. With the kept field this is the exact
/// distance; from the trace-back record only (`record_paths(true)`), the candidates are the images through
/// which the corners were reached, which is not exact everywhere (see the manual, curves).
///
/// \param solver a `Geodesic_distance_solver` whose last computation kept its field (`keep_field(true)`: exact
///   at every level, and the borders) or recorded its paths (`record_paths(true)`: per vertex only, also after
///   the approximate methods)
/// \param levels the levels, in the unit of the mesh
/// \param np optional: `chord_tolerance` (the largest distance of a chord to its arc, default 1e-3 times
///   the mean edge length), `vertex_point_map` (default: that of the mesh), `exact_refinement` (a number of
///   runs, default 0, at most 10: each is an exact run (VTP) from the same sources with every point as a
///   target, after which each point moves onto its level along the circle of the exact image that reaches it;
///   each costs about one distance run), `curves_report` (a `Geodesic_curves_report&` that receives what could
///   not be placed from the field of the faces; the one way of the package to return an extra result, as
///   `statistics`)
/// \param report deprecated alias of the named parameter `curves_report` (a pointer, or `nullptr`; the named
///   parameter wins if both are given)
/// \throws Invalid_input_error if a level is negative or not a number, the tolerance is not positive, or the
/// last computation kept neither its field nor its paths.
template <class Solver, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Geodesic_curve<typename Solver::face_descriptor, typename Solver::Point_3> >
geodesic_isolines(const Solver& solver, const std::vector<double>& levels,
                  const NamedParameters& np = parameters::default_values(), Geodesic_curves_report* report = nullptr)
{
  for(std::size_t i = 0; i < levels.size(); ++i)
    if(!(levels[i] >= 0.) || !std::isfinite(levels[i]))
      throw Invalid_input_error("level " + std::to_string(i) + " is negative, infinite or not a number");
  return internal::extract_curves(solver, &levels, np, report);
}

/// \ingroup PkgVTPGeodesicsRef
/// The levels `step`, `2 step`, ... up to the largest finite distance of the last computation of `solver`.
/// \throws Invalid_input_error if `step` is not positive and finite, or there would be more than 10^6 levels.
template <class Solver>
std::vector<double> geodesic_isoline_levels(const Solver& solver, double step)
{
  if(!(step > 0.) || !std::isfinite(step))
    throw Invalid_input_error("the isoline step must be positive and finite");
  double largest = 0.;
  for(double d : solver.distances())
    if(d < std::numeric_limits<double>::infinity() && d > largest)
      largest = d;
  if(largest / step > 1e6)
    throw Invalid_input_error("the isoline step gives more than 10^6 levels");
  std::vector<double> levels;
  for(double l = step; l <= largest; l = step * static_cast<double>(levels.size() + 1))
    levels.push_back(l);
  return levels;
}

/// \ingroup PkgVTPGeodesicsRef
/// The borders between the geodesic Voronoi cells of the sources of the last computation of `solver`, as
/// connected curves (`cells`: the two labels), each closed or open with its ends on the border of the mesh
/// or at a junction of three cells. A point of a border is where the least candidate distances of the two
/// labels are equal and least of all (the candidates of the faces, as `geodesic_isolines()`). With the kept
/// field (`keep_field(true)`: exact) the borders follow every change of the nearest source, found exactly on
/// the edges (also where a cell pokes across an edge whose two vertices are in another cell), the junctions of
/// three cells where the three are equal, and the points inside faces where the two labels change along lines
/// across the chords, added where a border bends away from its chords by more than the tolerance; from the
/// per-vertex record (`record_paths(true)`), which edges a border crosses is decided by the nearest-source
/// labels of the vertices. Parameters (`curves_report`, and the deprecated trailing `report`) and exceptions as
/// `geodesic_isolines()`.
template <class Solver, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Geodesic_curve<typename Solver::face_descriptor, typename Solver::Point_3> >
geodesic_cell_borders(const Solver& solver, const NamedParameters& np = parameters::default_values(),
                      Geodesic_curves_report* report = nullptr)
{
  return internal::extract_curves(solver, nullptr, np, report);
}

/// \ingroup PkgVTPGeodesicsRef
/// The area of the geodesic Voronoi cell of each source of the last computation of `solver` (which used
/// `keep_field(true)`, or `record_paths(true)`), from the split of the faces by the borders of
/// `geodesic_cell_borders()`: a face that no border enters is in the cell of its corners; a face that borders
/// enter is cut along their pieces (per cell, the area enclosed by its arcs of the face's boundary and the
/// pieces beside it). The areas add up to the area of the faces whose corners are all reached (to rounding).
/// `uncertainty[i]` (a bound of |`areas[i]` - the true area|, see `Voronoi_cell_areas`): the chord tolerance times
/// the length of the border of cell i, which bounds the area between the chords and the borders; a bound where
/// the borders are exact (with the kept field; see the manual, curves).
/// \param solver a solver whose last computation kept its field or its paths, from several sources.
/// \param np optional: `chord_tolerance`, `vertex_point_map` (as `geodesic_isolines()`)
/// \throws Invalid_input_error as `geodesic_cell_borders()`.
template <class Solver, class NamedParameters = CGAL::parameters::Default_named_parameters>
Voronoi_cell_areas geodesic_voronoi_cell_areas(const Solver& solver,
                                               const NamedParameters& np = parameters::default_values())
{
  Voronoi_cell_areas r;
  internal::extract_curves(solver, nullptr, np, nullptr, &r);
  return r;
}

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_GEODESIC_CURVES_H
