// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_ARGUMENTS_H
#define VTP_GEODESICS_APP_ARGUMENTS_H

// The command line of vtp_geodesics: one table of options (`option_table()`, made with the command-line helper
// of the support layer, vtp_support/command_line.h), from which the parser and the help are made. To add an
// option: a field in `Arguments`, an entry in the table (arguments_table.cpp), and the checks of its combinations
// with other options in `check_arguments()` (arguments_checks.cpp). The parser and the help: arguments.cpp.

#include <vtp_support/command_line.h>

#include <array>
#include <cstddef>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace vtp_geodesics_app {

// Every error of the program: reported as one line "vtp_geodesics: error: ...", exit code 2.
using vtp_support::Tool_error;

struct Arguments
{
  std::string mesh;                       // empty: the default mesh
  // Sources: the vertices of --source (file order indices), then the points of --source-point, then the curves
  // of the --source-curve files (in the order of the files, each file's curves in its order), then the border
  // (--source-border); vertex 0 if none is given. Their order numbers the sources (the labels).
  std::vector<std::size_t> sources;
  std::vector<std::array<double, 3> > source_points;
  std::vector<std::string> source_curve_files;   // --source-curve FILE, in order
  // The curves of those files, read by parse_arguments() (a curve: its points, and its name for the messages,
  // "curve 2 of --source-curve file 'f' (lines 5-9)").
  struct Curve
  {
    std::string name;
    std::vector<std::array<double, 3> > points;
  };
  std::vector<Curve> source_curves;
  bool source_border = false;                    // --source-border
  bool signed_distance = false;                  // --signed
  std::string labels;                     // empty: none
  double max_distance = std::numeric_limits<double>::infinity();
  bool has_max_distance = false;
  // Targets: --target vertices, then --target-point points (the order of --target-output).
  std::vector<std::size_t> targets;
  std::vector<std::array<double, 3> > target_points;
  std::string target_output;              // empty: none
  // Paths: --path-to vertices, then --path-to-point points (the order of --path-output).
  std::vector<std::size_t> path_to;
  std::vector<std::array<double, 3> > path_to_points;
  std::string path_output;                // empty: none
  // Straightest geodesics (--trace V,X,Y,Z,LENGTH): from vertex V (file order) in the direction (X,Y,Z),
  // projected onto the tangent plane, for LENGTH; written to --path-output after the paths.
  struct Trace
  {
    std::size_t vertex = 0;
    std::array<double, 3> direction = { { 1., 0., 0. } };
    double length = 0.;
  };
  std::vector<Trace> traces;
  std::string output;                     // empty: none; "-": standard output
  std::string stats_json;                 // empty: none; "-": standard output
  std::string picture;                    // empty: none
  int isolines = 10;
  std::string curves_output;              // --curves-output: empty: none
  std::vector<double> levels;             // --levels (empty: those of --isolines)
  // The kept field (vtp, pvtp): --keep-field, and the points it answers for, --query-points FILE (one "X Y Z"
  // per line, located as --target-point) with --query-output FILE ("distance label" per point)
  bool keep_field = false;
  std::string query_points;               // empty: none
  std::string query_output;               // empty: none; "-": standard output
  bool has_view = false;
  std::array<double, 3> view = { { 0., 0., -1. } };
  bool check_cgal = false;
  bool through_pinches = false;           // --through-pinches
  std::string method = "vtp";
  int threads = 0;
  bool has_threads = false;
  double lambda = std::numeric_limits<double>::infinity();
  bool has_lambda = false;
  double lambda_g = 1.0;
  bool has_lambda_g = false;
  // Farthest-point sampling: --farthest-points K (0: none), --first V (file order), --radius R, and the
  // file of the samples; the samples are then the sources of every other output.
  std::size_t farthest_points = 0;
  std::size_t first = 0;
  bool has_first = false;
  double radius = 0.;
  bool has_radius = false;
  std::string samples_output;             // empty: none; "-": standard output
  bool colour_labels = false;             // --picture-colour labels
  bool colour_angle = false;              // --picture-colour angle (the log map's theta)
  bool has_picture_colour = false;        // --picture-colour given (it needs --picture)
  bool help = false;
  // The log map (log_map_output.h): --log-map-output FILE, --log-map-strict, --reference-direction X,Y,Z
  std::string log_map_output;             // empty: none; "-": standard output
  bool log_map_strict = false;
  bool has_reference_direction = false;
  std::array<double, 3> reference_direction = { { 1., 0., 0. } };
  bool wants_log_map() const { return !log_map_output.empty() || colour_angle; }
  // --keep-field, or implied by --query-points
  bool wants_field() const { return keep_field || !query_points.empty(); }

  bool has_curve_sources() const { return !source_curve_files.empty() || source_border; }
  // (the curves counted once the files are read; before, one per file)
  std::size_t number_of_sources() const
  {
    return sources.size() + source_points.size()
           + (source_curves.empty() ? source_curve_files.size() : source_curves.size()) + (source_border ? 1 : 0);
  }
  // several sources: the outputs tell the nearest one (the labels)
  bool several_sources() const { return number_of_sources() > 1 || farthest_points > 1; }
  bool has_targets() const { return !targets.empty() || !target_points.empty(); }
  bool has_paths() const { return !path_to.empty() || !path_to_points.empty(); }
  bool has_traces() const { return !traces.empty(); }
};

typedef vtp_support::Option<Arguments> Option;

const vtp_support::Option_table<Arguments>& option_table();

// Checks the combinations of options (the method's name, what an option needs or excludes, output files that
// must differ); throws Tool_error.
void check_arguments(const Arguments& a);

// Parses the command line, then check_arguments(); throws Tool_error. `--help` only sets `help`.
Arguments parse_arguments(int argc, char** argv);

// The help text; `default_mesh` is shown as the default of MESH.
void print_usage(std::ostream& os, const std::string& default_mesh);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_ARGUMENTS_H
