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
};

typedef CGAL::VTP_geodesics::Geodesic_distance_solver<vtp_support::Mesh> Curve_solver;

// The levels: `given` if not empty, else those of the picture's isolines (about `isolines` round values up to the
// largest finite distance of the solver's last run).
std::vector<double> curve_levels(const Curve_solver& solver, const std::vector<double>& given, int isolines);

// The isolines at `levels` and, with `borders`, the borders of the cells (labels mapped by `label_of_source`)
// of the solver's last run (which recorded paths).
std::vector<Curve_set> extract_curve_sets(const Curve_solver& solver, const std::vector<double>& levels, bool borders,
                                          const std::vector<std::size_t>& label_of_source);

void write_curves_obj(std::ostream& os, const std::vector<Curve_set>& sets);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_CURVES_OUTPUT_H
