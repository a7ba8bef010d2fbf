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

// The command line of vtp_geodesics: one table of options (`option_table()`), from which the parser and the
// help are made. To add an option: a field in `Arguments`, an entry in the table (arguments.cpp), and its
// checks in `check_arguments()`.

#include <array>
#include <cstddef>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vtp_geodesics_app {

// Every error of the program: reported as one line "vtp_geodesics: error: ...", exit code 2.
struct Tool_error : std::runtime_error
{
  explicit Tool_error(const std::string& what) : std::runtime_error(what) {}
};

struct Arguments
{
  std::string mesh;                       // empty: the default mesh
  std::size_t source = 0;                 // source vertex, in file order
  std::string output;                     // empty: none; "-": standard output
  std::string stats_json;                 // empty: none; "-": standard output
  std::string picture;                    // empty: none
  int isolines = 10;
  bool has_view = false;
  std::array<double, 3> view = { { 0., 0., -1. } };
  bool check_cgal = false;
  std::string method = "vtp";
  int threads = 0;
  bool has_threads = false;
  double lambda = std::numeric_limits<double>::infinity();
  bool has_lambda = false;
  double lambda_g = 1.0;
  bool has_lambda_g = false;
  bool help = false;
};

struct Option
{
  const char* name;        // "--source"
  const char* value;       // name of the value in the help ("V"), or nullptr for a flag
  const char* help;        // lines separated by '\n'
  // Stores the value; `value` is empty for a flag. Throws Tool_error on a bad value.
  void (*apply)(Arguments& a, const std::string& name, const std::string& value);
};

const std::vector<Option>& option_table();

// Parses the command line; throws Tool_error. `--help` only sets `help`.
Arguments parse_arguments(int argc, char** argv);

// The help text; `default_mesh` is shown as the default of MESH.
void print_usage(std::ostream& os, const std::string& default_mesh);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_ARGUMENTS_H
