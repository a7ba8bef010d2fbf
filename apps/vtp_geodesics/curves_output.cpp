// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#include "curves_output.h"

#include "picture.h"

#include <CGAL/VTP_geodesics/geodesic_curves.h>

#include <vtp_support/number_format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <utility>

namespace vtp_geodesics_app {

namespace VTP = CGAL::VTP_geodesics;

namespace {

// About `isolines` round levels up to the largest finite distance of the solver's last run (that one included if
// `largest_included`).
std::vector<double> round_levels(const Curve_solver& solver, int isolines, bool largest_included)
{
  double largest = 0.;
  for(double d : solver.distances())
    if(d < std::numeric_limits<double>::infinity())
      largest = (std::max)(largest, d);
  std::vector<double> levels;
  if(isolines <= 0 || !(largest > 0.))
    return levels;
  const double step = picture_detail::isoline_step(largest, isolines);
  for(int k = 1; (largest_included ? step * k <= largest : step * k < largest) && k <= 100000; ++k)
  {
    // k times the round step, rounded to 12 significant digits (0.6, not 0.6000000000000001)
    char text[32];
    std::snprintf(text, sizeof(text), "%.12g", step * k);
    levels.push_back(std::strtod(text, nullptr));
  }
  return levels;
}

std::string number_text(double x)
{
  char buffer[vtp_support::max_double_chars];
  return std::string(buffer, vtp_support::format_double(buffer, x));
}

} // namespace

std::vector<double> curve_levels(const Curve_solver& solver, const std::vector<double>& given, int isolines)
{
  return given.empty() ? round_levels(solver, isolines, true) : given;
}

std::vector<double> picture_levels(const Curve_solver& solver, int isolines)
{
  return round_levels(solver, isolines, false);
}

std::vector<Curve_set> extract_curve_sets(const Curve_solver& solver, const Curve_request& request,
                                          const std::vector<std::size_t>& label_of_source)
{
  // the levels of the output, then those of the picture that it has not
  std::vector<double> levels = request.output_levels;
  for(double l : request.picture_levels)
    if(std::find(levels.begin(), levels.end(), l) == levels.end())
      levels.push_back(l);
  auto in = [](const std::vector<double>& list, double l) {
    return std::find(list.begin(), list.end(), l) != list.end();
  };
  std::vector<Curve_set> sets;
  std::map<double, std::size_t> level_set;
  for(const auto& c : VTP::geodesic_isolines(solver, levels))
  {
    auto it = level_set.find(c.level);
    if(it == level_set.end())
    {
      it = level_set.emplace(c.level, sets.size()).first;
      sets.push_back(Curve_set());
      sets.back().name = "level_" + number_text(c.level);
      sets.back().in_output = in(request.output_levels, c.level);
      sets.back().in_picture = in(request.picture_levels, c.level);
    }
    Curve_set& s = sets[it->second];
    s.curves.emplace_back();
    for(const auto& p : c.points)
      s.curves.back().push_back({ { p.x(), p.y(), p.z() } });
    s.closed.push_back(c.closed ? 1 : 0);
  }
  if(!request.output_borders && !request.picture_borders)
    return sets;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> border_set;
  for(const auto& c : VTP::geodesic_cell_borders(solver))
  {
    std::size_t a = label_of_source.empty() ? c.cells[0] : label_of_source[c.cells[0]];
    std::size_t b = label_of_source.empty() ? c.cells[1] : label_of_source[c.cells[1]];
    if(a == b)
      continue;  // (copies of one vertex)
    if(b < a)
      std::swap(a, b);
    auto it = border_set.find(std::make_pair(a, b));
    if(it == border_set.end())
    {
      it = border_set.emplace(std::make_pair(a, b), sets.size()).first;
      sets.push_back(Curve_set());
      sets.back().name = "border_" + std::to_string(a) + "_" + std::to_string(b);
      sets.back().in_output = request.output_borders;
      sets.back().in_picture = request.picture_borders;
    }
    Curve_set& s = sets[it->second];
    s.curves.emplace_back();
    for(const auto& p : c.points)
      s.curves.back().push_back({ { p.x(), p.y(), p.z() } });
    s.closed.push_back(c.closed ? 1 : 0);
  }
  return sets;
}

void write_curves_obj(std::ostream& os, const std::vector<Curve_set>& sets)
{
  std::string text = "# VTP_geodesics: isolines (g level_<value>) and cell borders (g border_<i>_<j>)\n";
  char buffer[vtp_support::max_double_chars];
  std::size_t next = 1;  // OBJ vertices are numbered from 1
  for(const Curve_set& s : sets)
  {
    if(!s.in_output)
      continue;
    text += "g " + s.name + "\n";
    for(std::size_t i = 0; i < s.curves.size(); ++i)
    {
      const std::vector<std::array<double, 3> >& c = s.curves[i];
      for(const std::array<double, 3>& p : c)
      {
        text += 'v';
        for(double x : p)
        {
          text += ' ';
          text.append(buffer, vtp_support::format_double(buffer, x));
        }
        text += '\n';
      }
      text += 'l';
      for(std::size_t k = 0; k < c.size(); ++k)
        text += ' ' + std::to_string(next + k);
      if(s.closed[i] && !c.empty())
        text += ' ' + std::to_string(next);
      text += '\n';
      next += c.size();
    }
  }
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
}

} // namespace vtp_geodesics_app
