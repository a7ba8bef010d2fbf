// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The checks of the combinations of options of vtp_geodesics (arguments.h), each with its error message: what
// an option needs, what it cannot go with, and output files that must differ.

#include "arguments.h"

#include <vtp_support/methods.h>

#include <string>

namespace vtp_geodesics_app {

namespace {

void check_sampling_arguments(const Arguments& a)
{
  if(a.farthest_points == 0)
  {
    if(a.has_first || a.has_radius || !a.samples_output.empty())
      throw Tool_error("--first, --radius and --samples-output need --farthest-points");
    return;
  }
  if(a.number_of_sources() > 0)
    throw Tool_error("--farthest-points chooses the sources: it takes no --source, --source-point, --source-curve "
                     "nor --source-border");
  if(a.has_targets() || a.has_paths() || a.has_traces() || a.has_max_distance)
    throw Tool_error("--farthest-points takes no --target, --target-point, --path-to, --path-to-point, "
                     "--straightest-geodesic nor --max-distance");
  if(a.check_cgal)
    throw Tool_error("--farthest-points takes no --check-cgal");
}

// The log map: exact methods, one run from the sources (no sampling, no joining runs).
void check_log_map_arguments(const Arguments& a, const vtp_support::Method_info& m)
{
  if(!a.wants_log_map())
  {
    if(a.log_map_strict || a.has_reference_direction)
      throw Tool_error("--log-map-strict and --reference-direction need --log-map-output or --picture-colour angle");
    return;
  }
  if(m.approximate || m.virtual_sources)
    throw Tool_error("the log map (--log-map-output, --picture-colour angle) needs --method vtp or pvtp, not "
                     + std::string(m.name) + " (its lines carry no direction)");
  if(a.farthest_points > 0 || a.through_pinches)
    throw Tool_error("the log map (--log-map-output, --picture-colour angle) takes no --farthest-points nor "
                     "--through-pinches");
  if(a.has_curve_sources())
    throw Tool_error("the log map (--log-map-output, --picture-colour angle) takes no --source-curve nor "
                     "--source-border (its sources are points)");
}

// Sources that are curves (--source-curve, --source-border) and --signed.
void check_curve_arguments(const Arguments& a, const vtp_support::Method_info& m)
{
  if(a.signed_distance && !a.has_curve_sources())
    throw Tool_error("--signed needs a source that is a curve (--source-curve or --source-border)");
  if(!a.has_curve_sources())
    return;
  if(m.virtual_sources)
    throw Tool_error("--source-curve and --source-border need --method vtp, pvtp, avtp or pavtp, not "
                     + std::string(m.name) + " (virtual sources stand for points only)");
  if(a.check_cgal)
    throw Tool_error("--check-cgal takes no --source-curve nor --source-border (CGAL's reference has point "
                     "sources only)");
  if(a.through_pinches)
    throw Tool_error("--source-curve and --source-border take no --through-pinches (curves are not joined through "
                     "the vertices that the repair split)");
}

// The kept field: exact methods, and a field that the last run keeps (the runs through the split vertices of
// --through-pinches start from known distances, which keep none); --query-points and --query-output go together.
void check_field_arguments(const Arguments& a, const vtp_support::Method_info& m)
{
  if(!a.query_output.empty() && a.query_points.empty())
    throw Tool_error("--query-output needs --query-points");
  if(!a.query_points.empty() && a.query_output.empty())
    throw Tool_error("--query-points needs --query-output");
  if(!a.wants_field())
    return;
  const std::string what = a.keep_field ? "--keep-field" : "--query-points (which keeps the field)";
  if(m.approximate || m.virtual_sources)
    throw Tool_error(what + " needs --method vtp or pvtp, not " + m.name + " (the field of an exact run)");
  if(a.through_pinches)
    throw Tool_error(what + " takes no --through-pinches");
}

} // namespace

void check_arguments(const Arguments& a)
{
  const vtp_support::Method_info* m = vtp_support::find_method(a.method);
  if(m == nullptr)
    throw Tool_error("unknown method '" + a.method + "' (expected " + vtp_support::method_names() + ")");
  check_sampling_arguments(a);
  check_log_map_arguments(a, *m);
  check_field_arguments(a, *m);
  check_curve_arguments(a, *m);
  if((a.has_lambda || a.has_lambda_g) && !m->approximate)
    throw Tool_error("--lambda and --lambda-g need --method avtp or pavtp");
  if(!a.target_output.empty() && !a.has_targets())
    throw Tool_error("--target-output needs --target or --target-point");
  if(!a.path_output.empty() && !a.has_paths() && !a.has_traces())
    throw Tool_error("--path-output needs --path-to, --path-to-point or --straightest-geodesic");
  if(a.has_traces() && a.path_output.empty())
    throw Tool_error("--straightest-geodesic (--trace) needs --path-output");
  if(a.through_pinches && (a.has_paths() || !a.target_points.empty() || a.farthest_points > 0 || a.check_cgal))
    throw Tool_error("--through-pinches takes no --path-to, --path-to-point, --target-point, --farthest-points nor "
                     "--check-cgal (whose reference runs on the cut surface)");
  if(!a.levels.empty() && a.curves_output.empty())
    throw Tool_error("--levels needs --curves-output");
  if(!a.curves_output.empty() && a.through_pinches)
    throw Tool_error("--curves-output takes no --through-pinches");
  if(a.has_picture_colour && a.picture.empty())
    throw Tool_error("--picture-colour needs --picture");
  if(a.has_paths() && a.path_output.empty() && a.picture.empty())
    throw Tool_error("--path-to and --path-to-point need --path-output (or --picture, which draws the paths)");
  const std::string* files[] = { &a.output, &a.stats_json, &a.picture, &a.labels, &a.target_output, &a.path_output,
                                 &a.samples_output, &a.log_map_output, &a.curves_output,
                                 &a.query_output };
  const char* names[] = { "--output", "--stats-json", "--picture", "--labels", "--target-output", "--path-output",
                          "--samples-output", "--log-map-output", "--curves-output",
                          "--query-output" };
  const int n = static_cast<int>(sizeof(names) / sizeof(names[0]));
  for(int i = 0; i < n; ++i)
    for(int j = i + 1; j < n; ++j)
      if(!files[i]->empty() && *files[i] == *files[j])
        throw Tool_error(std::string(names[i]) + " and " + names[j] + " must name different files");
}

} // namespace vtp_geodesics_app
