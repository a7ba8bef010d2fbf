// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The command line of vtp_geodesics (arguments.h): the parser and the help. The option table is in
// arguments_table.cpp, the checks of combinations of options in arguments_checks.cpp.

#include "arguments.h"
#include "query_points.h"

#include <vtp_support/methods.h>
#include <vtp_support/mesh_formats.h>

#include <string>

namespace vtp_geodesics_app {

namespace {

std::string methods_help()
{
  std::string s;
  for(const vtp_support::Method_info* m = vtp_support::methods_begin(); m != vtp_support::methods_end(); ++m)
    s += std::string(m == vtp_support::methods_begin() ? "" : "\n") + m->name + ": " + m->description
         + (m == vtp_support::methods_begin() ? " (default)" : "");
  return s;
}

} // namespace

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  bool has_mesh = false;
  vtp_support::parse_command_line(argc, argv, option_table(), a, [&has_mesh](Arguments& a, const std::string& arg) {
    if(arg.empty() || arg == "-")
      throw Tool_error("invalid mesh file name '" + arg + "'");
    if(has_mesh)
      throw Tool_error("more than one mesh file given ('" + a.mesh + "' and '" + arg + "')");
    a.mesh = arg;
    has_mesh = true;
  });
  if(!a.help)
  {
    check_arguments(a);
    // the curves of the --source-curve files (before the mesh is read: a bad file fails at once)
    for(const std::string& file : a.source_curve_files)
    {
      const std::vector<Point_file_curve> curves = read_curve_file(file);
      for(std::size_t k = 0; k < curves.size(); ++k)
      {
        Arguments::Curve c;
        c.name = "curve " + std::to_string(k + 1) + " of --source-curve file '" + file + "' (lines "
                 + std::to_string(curves[k].first_line) + "-" + std::to_string(curves[k].last_line) + ")";
        c.points = curves[k].points;
        a.source_curves.push_back(c);
      }
    }
  }
  if(a.sources.empty() && a.source_points.empty() && !a.has_curve_sources() && a.farthest_points == 0)
    a.sources.push_back(0);
  return a;
}

void print_usage(std::ostream& os, const std::string& default_mesh)
{
  os << "usage: vtp_geodesics [MESH] [options]\n"
        "\n"
        "Computes exact geodesic distances from sources (vertices, points of the surface, curves\n"
        "drawn on it, its border) to all vertices of a triangle mesh by vertex-oriented triangle\n"
        "propagation (VTP): the distance of a vertex is its distance to the nearest source (signed\n"
        "with --signed: negative on the left of the curves). Optionally: the nearest source of\n"
        "each vertex, a distance limit, distances at targets, geodesic paths, farthest-point\n"
        "sampling with its geodesic Voronoi cells, geodesic polar coordinates (the log map), and\n"
        "the exact distance and nearest source at any points of the surface (--query-points),\n"
        "from the field that the run keeps.\n"
        "\n";
  const std::size_t column = 25;
  vtp_support::print_help_item(os, "MESH", "mesh file: " + vtp_support::readable_extensions_text() + "\n(default: "
                                             + default_mesh + ")", column);
  for(const Option& o : option_table())
    vtp_support::print_help_item(os, std::string(o.name) + (o.value != nullptr ? std::string(" ") + o.value : ""),
                                 o.help != nullptr ? std::string(o.help) : methods_help(), column);
  os << "\n"
        "Input that is not a triangle mesh is repaired, and one line \"vtp_geodesics: note: ...\"\n"
        "on stderr says what was done:\n"
        "  - faces with more than three vertices (quads, polygons) are triangulated, without\n"
        "    adding vertices;\n"
        "  - a polygon soup that is not a valid mesh (non-manifold vertices or edges, faces with\n"
        "    repeated or coincident points, duplicate faces, inconsistent orientation) is repaired\n"
        "    with CGAL::Polygon_mesh_processing::repair_polygon_soup and orient_polygon_soup:\n"
        "    coincident points are merged, degenerate and duplicate faces removed, and the surface\n"
        "    is cut at non-manifold vertices and edges, which duplicates their vertices.\n"
        "The distances are then computed on the repaired surface (a shortest path does not go from\n"
        "one side of a cut to the other; with --through-pinches, it may pass through the vertices\n"
        "the cut split) and mapped back to the vertices of the file: a duplicated\n"
        "vertex gets the smallest distance over its copies (and the nearest source of that copy;\n"
        "as a source or a target, all its copies are; a path starts from its nearest copy), merged\n"
        "points share their distance, and a vertex left in no face is unreachable (\"inf\", label\n"
        "-1) unless it is a source itself. Points (--source-point, --target-point, --path-to-point)\n"
        "are located on the repaired surface. Outputs always have one value per vertex of the\n"
        "file, in file order.\n"
        "Input that cannot be repaired (no face left, faces that cannot be triangulated, bad\n"
        "indices, non-finite coordinates) is refused.\n"
        "\n"
        "Output files are never left half-written: a regular file is written to a temporary file\n"
        "in the same folder, then renamed over the target (a symbolic link is followed and stays);\n"
        "standard output (-, /dev/stdout), pipes and devices are written directly.\n"
        "\n"
        "Without --output and --stats-json, a short summary is printed. On error (a bad index or\n"
        "list, a point that cannot be located, a path to a vertex or point that no source reaches\n"
        "or that lies beyond --max-distance, ...), one line \"vtp_geodesics: error: ...\" is\n"
        "printed on stderr, no output file is written, and the exit code is 2.\n";
}

} // namespace vtp_geodesics_app
