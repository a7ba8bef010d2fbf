// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The log map on the vertices of the file, and its text (see log_map_output.h).

#include "log_map_output.h"

#include <vtp_support/number_format.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace vtp_geodesics_app {

namespace {

constexpr double two_pi = 6.283185307179586476925286766559;

// The angle of (x, y) in [0, 2 pi) (0 at the origin).
double angle_of(double x, double y)
{
  double t = std::atan2(y, x);
  if(t < 0.)
    t += two_pi;
  return t < two_pi ? t : 0.;
}

} // namespace

Log_map_results log_map_on_file_vertices(const Arguments& args, const vtp_support::Input_mesh& input,
                                         const Run_result& run)
{
  Log_map_results r;
  if(run.log_map.empty())
    return r;
  const double infinity = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t nm = run.log_map.size();
  // per mesh vertex, then on the file's vertices through the copy nearest to a source (as the labels)
  std::vector<double> rho(nm), theta(nm);
  std::vector<long long> via(nm);
  for(std::size_t i = 0; i < nm; ++i)
  {
    const std::array<double, 2>& x = run.log_map[i];
    const bool reached = run.distances[i] < infinity;
    rho[i] = reached ? run.distances[i] : infinity;
    theta[i] = reached ? angle_of(x[0], x[1]) : nan;
    via[i] = reached && run.log_map_via[i] >= 0
               ? static_cast<long long>(input.file_vertex_of(vtp_support::Vertex_index(
                   static_cast<vtp_support::Mesh::size_type>(run.log_map_via[i]))))
               : -1;
  }
  if(input.direct)
  {
    r.rho = std::move(rho);
    r.theta = std::move(theta);
    r.via = std::move(via);
  }
  else
  {
    r.rho = input.labels_on_file_vertices(rho, run.distances, infinity);
    r.theta = input.labels_on_file_vertices(theta, run.distances, nan);
    r.via = input.labels_on_file_vertices(via, run.distances, -1LL);
  }
  for(std::size_t v : args.sources)  // a source vertex (even one in no face) is at 0, as in --output
  {
    r.rho[v] = 0.;
    r.theta[v] = 0.;
    r.via[v] = -1;
  }
  for(std::size_t i = 0; i < r.via.size(); ++i)
    r.behind_vertices += r.via[i] >= 0;
  return r;
}

void write_log_map(std::ostream& os, const Log_map_results& log_map)
{
  const std::size_t chunk = 4096;
  std::string text;
  text.reserve(chunk * (2 * vtp_support::max_double_chars + 24));
  char buffer[vtp_support::max_double_chars];
  for(std::size_t i = 0; i < log_map.rho.size(); ++i)
  {
    text.append(buffer, vtp_support::format_double(buffer, log_map.rho[i]));
    text += ' ';
    text.append(buffer, vtp_support::format_double(buffer, log_map.theta[i]));
    text += ' ';
    text += std::to_string(log_map.via[i]);
    text += '\n';
    if(text.size() > chunk * (2 * vtp_support::max_double_chars + 2))
    {
      os.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  }
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
}

} // namespace vtp_geodesics_app
