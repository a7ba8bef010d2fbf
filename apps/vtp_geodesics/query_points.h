// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_QUERY_POINTS_H
#define VTP_GEODESICS_APP_QUERY_POINTS_H

// The files of points: --query-points FILE and --query-output FILE: points of space, read from a text file, located
// on the surface (as --target-point locates its point: locate.h), and answered from the kept field of the run
// (run.cpp): their distance and nearest source, one line each; and --source-curve FILE, curves of points of space
// (located as --source-point locates its point, request.cpp).

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace vtp_geodesics_app {

// The points of `file`: one point per line, three finite numbers "X Y Z" separated by spaces or tabs (blanks
// around them and a final '\r' are allowed). Throws Tool_error, naming the file and the line (from 1), on the first
// line that is not such a point, or if the file cannot be read.
std::vector<std::array<double, 3> > read_query_points(const std::string& file);

// A curve of a --source-curve file: its points and the lines (from 1) of its first and last points.
struct Point_file_curve
{
  std::vector<std::array<double, 3> > points;
  std::size_t first_line = 0, last_line = 0;
};

// The curves of `file` (--source-curve): one point per line, as read_query_points() reads it; a blank line (or
// one of blanks) ends a curve, so that the next point starts another (blank lines before the first point, after
// the last and several in a row separate nothing more). Throws Tool_error, naming the file and the line, on a
// line that is neither a point nor blank, on a curve of one point, and if the file has no point or cannot be
// read.
std::vector<Point_file_curve> read_curve_file(const std::string& file);

// One line per point: "distance label", the distance as the text of --output ("inf" if infinite) and the label
// (-1: none).
void write_query_results(std::ostream& os, const std::vector<double>& distances, const std::vector<int>& labels);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_QUERY_POINTS_H
