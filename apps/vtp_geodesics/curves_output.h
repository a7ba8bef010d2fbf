// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_CURVES_OUTPUT_H
#define VTP_GEODESICS_APP_CURVES_OUTPUT_H

// --curves-output: the isolines (and, with several sources, the borders of their cells) of the run as curves of
// the library (geodesic_curves.h), written as OBJ polylines: 'v' lines, then one 'l' line per curve (a closed
// curve repeats its first vertex at the end), one group per set of curves, 'g level_<value>' (the shortest
// text that reads back as the level) or 'g border_<i>_<j>' (the two source labels of the command line, i < j).
// The picture draws curves of the same extraction (at its own levels, or the borders of its label colouring).

#include <vtp_support/read_mesh.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace vtp_geodesics_app {

struct Curve_set
{
  std::string name;                                            // level_<value> or border_<i>_<j>
  std::vector<std::vector<std::array<double, 3> > > curves;   // points in order
  std::vector<char> closed;
  bool in_output = true;                                       // written by --curves-output
  bool in_picture = false;                                     // drawn by --picture
};

typedef CGAL::VTP_geodesics::Geodesic_distance_solver<vtp_support::Mesh> Curve_solver;

// The levels of --curves-output: `given` if not empty, else about `isolines` round values up to the largest
// finite distance of the solver's last run (that one included).
std::vector<double> curve_levels(const Curve_solver& solver, const std::vector<double>& given, int isolines);

// The levels of the picture's isolines: those round values below the largest finite distance (picture.h).
std::vector<double> picture_levels(const Curve_solver& solver, int isolines);

// What curves to extract from the solver's last run (which kept its field, or recorded its paths): the isolines
// at the levels of --curves-output and of the picture, the borders of the cells for either (with several
// sources).
struct Curve_request
{
  std::vector<double> output_levels, picture_levels;
  bool output_borders = false, picture_borders = false;
};

// The curves of `request` in one extraction (a level of both is extracted once, a set then in both), the labels of
// the borders mapped by `label_of_source` (empty: the library's); the sets of the output first, in its order.
std::vector<Curve_set> extract_curve_sets(const Curve_solver& solver, const Curve_request& request,
                                          const std::vector<std::size_t>& label_of_source);

// Writes the sets `in_output`.
void write_curves_obj(std::ostream& os, const std::vector<Curve_set>& sets);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_CURVES_OUTPUT_H
