// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The option table of vtp_geodesics (arguments.h): every option with its help and how it stores its value, with
// the checks of a single value (a list, a number's range, a direction). The checks of combinations of options
// are in arguments_checks.cpp.

#include "arguments.h"


#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace vtp_geodesics_app {

namespace {

using vtp_support::parse_double;
using vtp_support::parse_index;
using vtp_support::parse_index_list;
using vtp_support::parse_point;

void append(std::vector<std::size_t>& list, const std::vector<std::size_t>& more)
{
  list.insert(list.end(), more.begin(), more.end());
}

std::string file_name(const std::string& option, const std::string& s)
{
  if(s.empty())
    throw Tool_error("empty file name for " + option);
  return s;
}

// "V,X,Y,Z,LENGTH" of --straightest-geodesic (or its alias --trace): a vertex, a direction (finite, not zero) and a length (finite, >= 0).
Arguments::Trace parse_trace(const std::string& option, const std::string& s)
{
  const std::vector<std::string> parts = vtp_support::split(s, ',');
  if(parts.size() != 5)
    throw Tool_error("invalid value '" + s + "' for " + option + " (expected V,X,Y,Z,LENGTH)");
  Arguments::Trace t;
  t.vertex = vtp_support::parse_index(option, parts[0]);
  for(std::size_t k = 0; k < 3; ++k)
    t.direction[k] = vtp_support::parse_double(option, parts[k + 1]);
  t.length = vtp_support::parse_double(option, parts[4]);
  const double n = t.direction[0] * t.direction[0] + t.direction[1] * t.direction[1] + t.direction[2] * t.direction[2];
  if(!std::isfinite(n) || !(n > 0.))
    throw Tool_error("invalid value '" + s + "' for " + option + " (the direction must be finite and not zero)");
  if(!std::isfinite(t.length) || !(t.length >= 0.))
    throw Tool_error("invalid value '" + s + "' for " + option + " (the length must be finite and >= 0)");
  return t;
}

// "X,Y,Z" of a direction (--view, --reference-direction): not zero.
std::array<double, 3> parse_direction(const std::string& option, const std::string& s)
{
  const std::array<double, 3> d = parse_point(option, s);
  if(d[0] == 0. && d[1] == 0. && d[2] == 0.)
    throw Tool_error("the direction given to " + option + " is zero");
  return d;
}

} // namespace

const vtp_support::Option_table<Arguments>& option_table()
{
  static const vtp_support::Option_table<Arguments> table = {
    { "--source", "V[,V...]",
      "source vertices: indices in file order, separated by commas\n"
      "(default: 0, unless --source-point, --source-curve or\n"
      "--source-border is given); may be repeated\n"
      "(the lists are joined). The distance of a vertex is to its\n"
      "nearest source",
      [](Arguments& a, const std::string& n, const std::string& v) { append(a.sources, parse_index_list(n, v)); } },
    { "--source-point", "X,Y,Z",
      "adds as a source the point of the surface nearest to (X,Y,Z),\n"
      "located with CGAL's locate_with_AABB_tree; may be repeated",
      [](Arguments& a, const std::string& n, const std::string& v) { a.source_points.push_back(parse_point(n, v)); } },
    { "--source-curve", "FILE",
      "adds as sources the curves of FILE: one point \"X Y Z\" per line\n"
      "(blanks between the numbers), each located on the surface as\n"
      "--source-point locates its point (a point farther from the\n"
      "surface than 1e-6 of the diagonal of the mesh's bounding box is\n"
      "an error); a blank line starts another curve; a curve whose last\n"
      "point repeats its first is closed. Consecutive points in one face\n"
      "are joined straight, others by the shortest geodesic between them.\n"
      "Each curve is one source (one label); may be repeated (the files'\n"
      "curves in the order of the files). A line that is not three finite\n"
      "numbers, a curve of one point, an empty file: an error",
      [](Arguments& a, const std::string& n, const std::string& v) { a.source_curve_files.push_back(file_name(n, v)); } },
    { "--source-border", nullptr,
      "adds the border of the mesh (every border loop) as one source,\n"
      "after the others (its label is the last); a mesh without border\n"
      "is an error",
      [](Arguments& a, const std::string&, const std::string&) { a.source_border = true; } },
    { "--signed", nullptr,
      "signed distances (needs --source-curve or --source-border):\n"
      "negative on the left of the curves (left: face normal x direction\n"
      "of travel; inside a counter-clockwise loop on the plane z = 0 seen\n"
      "from above; the border runs with the surface on its left: all\n"
      "distances are <= 0). Closed curves that do not bound consistently\n"
      "oriented parts of the surface are an error; the sign for open\n"
      "curves: see the manual (tools, --signed)",
      [](Arguments& a, const std::string&, const std::string&) { a.signed_distance = true; } },
    { "--output", "FILE",
      "write the distances; the format follows the extension of FILE:\n"
      "  .ply: the mesh as read (file vertex order) with per-vertex\n"
      "        properties 'distance' (double, inf if unreachable),\n"
      "        with several sources 'source' (int, as --labels), and\n"
      "        red/green/blue colours (viridis; grey: unreachable),\n"
      "        binary little-endian\n"
      "  anything else (.txt): one distance per line, in file vertex\n"
      "        order (shortest text that reads back exactly; \"inf\" if\n"
      "        unreachable)\n"
      "  -: the text format on standard output",
      [](Arguments& a, const std::string& n, const std::string& v) { a.output = file_name(n, v); } },
    { "--labels", "FILE",
      "write, one line per vertex of the file, the index of its nearest\n"
      "source (0-based: the --source vertices first, in their order, then\n"
      "each --source-point, then each curve of the --source-curve files,\n"
      "then --source-border, whatever the order of the options), or -1\n"
      "where the distance is inf",
      [](Arguments& a, const std::string& n, const std::string& v) { a.labels = file_name(n, v); } },
    { "--max-distance", "R",
      "distance limit (>= 0): every vertex at distance <= R gets its\n"
      "exact distance, every other vertex inf (as if unreachable); the\n"
      "propagation stops there, its work is that of the region within R",
      vtp_support::apply_distance_limit<Arguments, &Arguments::max_distance, &Arguments::has_max_distance> },
    { "--target", "V[,V...]",
      "target vertices (file order; may be repeated): the propagation\n"
      "stops as soon as the distance of every target is final; the\n"
      "other outputs then have the exact distance where it is final,\n"
      "inf elsewhere",
      [](Arguments& a, const std::string& n, const std::string& v) { append(a.targets, parse_index_list(n, v)); } },
    { "--target-point", "X,Y,Z",
      "adds as a target the point of the surface nearest to (X,Y,Z)\n"
      "(its exact distance, inside its face); may be repeated",
      [](Arguments& a, const std::string& n, const std::string& v) { a.target_points.push_back(parse_point(n, v)); } },
    { "--target-output", "FILE",
      "write the distance of each target, one per line, in this order:\n"
      "the --target vertices in their list order, then each\n"
      "--target-point; the text of --output (inf if unreachable or\n"
      "beyond --max-distance); - for standard output",
      [](Arguments& a, const std::string& n, const std::string& v) { a.target_output = file_name(n, v); } },
    { "--path-to", "V[,V...]",
      "geodesic path from vertex V (file order) back to its nearest\n"
      "source; may be repeated",
      [](Arguments& a, const std::string& n, const std::string& v) { append(a.path_to, parse_index_list(n, v)); } },
    { "--path-to-point", "X,Y,Z",
      "geodesic path from the point of the surface nearest to (X,Y,Z)\n"
      "back to its nearest source; may be repeated",
      [](Arguments& a, const std::string& n, const std::string& v) { a.path_to_points.push_back(parse_point(n, v)); } },
    { "--path-output", "FILE",
      "write the paths (the --path-to vertices in their list order, then\n"
      "each --path-to-point), from the target to the source, then the\n"
      "--straightest-geodesic polylines, from their start; by name:\n"
      "  .obj: OBJ 'v' lines (the points of all paths), then one 'l'\n"
      "        line per path (a path of one point: 'l i i')\n"
      "  anything else: CGAL's polylines text, one path per line,\n"
      "        N x1 y1 z1 ... xN yN zN (shortest text that reads back\n"
      "        exactly)\n"
      "A path to a source itself is the single point. A vertex or point\n"
      "that no source reaches (or beyond --max-distance) is an error",
      [](Arguments& a, const std::string& n, const std::string& v) { a.path_output = file_name(n, v); } },
    { "--straightest-geodesic", "V,X,Y,Z,LENGTH",
      "straightest geodesic (the exp map) from vertex V (file order) in\n"
      "the direction (X,Y,Z), projected onto the tangent plane at V,\n"
      "for LENGTH (>= 0): straight across the faces, through a vertex\n"
      "with half its angle sum on each side, ending on the border if it\n"
      "gets there; may be repeated. The polylines go to --path-output,\n"
      "after the paths, from V to the end",
      [](Arguments& a, const std::string& n, const std::string& v) { a.traces.push_back(parse_trace(n, v)); } },
    { "--trace", "V,X,Y,Z,LENGTH",
      "the same as --straightest-geodesic (its former name, kept)",
      [](Arguments& a, const std::string& n, const std::string& v) { a.traces.push_back(parse_trace(n, v)); } },
    { "--farthest-points", "K",
      "farthest-point sampling: takes K sample vertices, each the vertex\n"
      "farthest from the samples before it (the distances of --method:\n"
      "exact with vtp / pvtp, upper bounds with avtp / pavtp and the vsp\n"
      "family; ties: the lowest index), which then are the sources of\n"
      "--output, --labels (the geodesic Voronoi cells), --picture and\n"
      "--stats-json (the cells' areas: with vtp / pvtp from their exact\n"
      "borders, one more run that keeps its field). Not with --source,\n"
      "--source-point, targets, paths nor --max-distance",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.farthest_points = parse_index(n, v);
        if(a.farthest_points == 0)
          throw Tool_error(n + " must be at least 1");
      } },
    { "--first", "V",
      "the first sample of --farthest-points (file order; default: the\n"
      "vertex farthest from vertex 0)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.first = parse_index(n, v);
        a.has_first = true;
      } },
    { "--radius", "R",
      "stop --farthest-points before K samples once every vertex is within\n"
      "R of a sample (R >= 0)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.radius = parse_double(n, v);
        if(!(a.radius >= 0.))
          throw Tool_error(n + " must be >= 0");
        a.has_radius = true;
      } },
    { "--samples-output", "FILE",
      "write the samples of --farthest-points, one line each, in the order\n"
      "they were taken: the vertex index (file order) and the covering\n"
      "radius once it is taken (the largest distance of a vertex to its\n"
      "nearest sample so far; inf while a component has no sample),\n"
      "after a '#' header line; - for standard output",
      [](Arguments& a, const std::string& n, const std::string& v) { a.samples_output = file_name(n, v); } },
    { "--picture", "FILE",
      "draw the distances as a PNG picture: the mesh coloured by distance\n"
      "(viridis), shaded, with isolines, a colour bar, the sources marked\n"
      "and the paths drawn",
      [](Arguments& a, const std::string& n, const std::string& v) { a.picture = file_name(n, v); } },
    { "--picture-colour", "C",
      "what --picture colours: distances (the default), labels (each\n"
      "nearest-source cell in its own colour, the borders between cells\n"
      "drawn; with --farthest-points: the geodesic Voronoi cells) or\n"
      "angle (theta of the log map on a hue wheel, with the distance\n"
      "isolines; as --log-map-output); needs --picture",
      [](Arguments& a, const std::string& n, const std::string& v) {
        if(v != "distances" && v != "labels" && v != "angle")
          throw Tool_error("unknown value '" + v + "' for " + n + " (expected distances, labels or angle)");
        a.colour_labels = v == "labels";
        a.colour_angle = v == "angle";
        a.has_picture_colour = true;
      } },
    { "--isolines", "N", "about N isolines on the picture, at round distances (default: 10;\n0: none)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        const std::size_t k = parse_index(n, v);
        if(k > 1000)
          throw Tool_error("too many isolines for " + n + " (at most 1000)");
        a.isolines = static_cast<int>(k);
      } },
    { "--curves-output", "FILE",
      "write the isolines as curves on the exact distance (the levels of\n"
      "--isolines, or --levels) and, with several sources or\n"
      "--farthest-points, the borders of their cells, as OBJ polylines:\n"
      "'v' and 'l' lines, one group per level ('g level_<value>') and per\n"
      "pair of neighbour cells ('g border_<i>_<j>'); see the manual (curves);\n"
      "from a --source-curve, the isolines are its offset curves (no cell\n"
      "borders from sources that are curves yet)",
      [](Arguments& a, const std::string& n, const std::string& v) { a.curves_output = file_name(n, v); } },
    { "--levels", "A,B,...",
      "the levels of --curves-output (each >= 0), instead of those of\n"
      "--isolines",
      [](Arguments& a, const std::string& n, const std::string& v) {
        std::size_t start = 0;
        a.levels.clear();
        while(start <= v.size())
        {
          const std::size_t end = std::min(v.find(',', start), v.size());
          const double x = parse_double(n, v.substr(start, end - start));
          if(!(x >= 0.) || std::isinf(x))
            throw Tool_error(n + ": every level must be finite and >= 0");
          a.levels.push_back(x);
          start = end + 1;
        }
      } },
    { "--keep-field", nullptr,
      "keep every window that crossed a face (--method vtp or pvtp only):\n"
      "after the run, the exact distance and nearest source at any point\n"
      "of the surface (--query-points), and the curves at any level\n"
      "(memory: about the windows propagated, field_bytes of\n"
      "--stats-json). With vtp and pvtp, the curves of --picture and\n"
      "--curves-output come from the kept field anyway: one run gives\n"
      "the distances and the curves",
      [](Arguments& a, const std::string&, const std::string&) { a.keep_field = true; } },
    { "--query-points", "FILE",
      "points, one \"X Y Z\" per line, each located on the surface as\n"
      "--target-point locates its point (the nearest point of the\n"
      "surface); their exact distances and nearest sources, from the\n"
      "kept field, go to --query-output. A line that is not three finite\n"
      "numbers is an error (which names it). Implies --keep-field",
      [](Arguments& a, const std::string& n, const std::string& v) { a.query_points = file_name(n, v); } },
    { "--query-output", "FILE",
      "write one line per point of --query-points, in its order:\n"
      "\"distance label\", the distance as the text of --output and the\n"
      "nearest source numbered as --labels (with --farthest-points: the\n"
      "sample); \"inf -1\" where no source reaches the point (or beyond\n"
      "--max-distance); - for standard output",
      [](Arguments& a, const std::string& n, const std::string& v) { a.query_output = file_name(n, v); } },
    { "--view", "X,Y,Z",
      "viewing direction of the picture (default: along the shortest side\n"
      "of the bounding box)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.view = parse_direction(n, v);
        a.has_view = true;
      } },
    { "--log-map-output", "FILE",
      "write the log map (geodesic polar coordinates around the nearest\n"
      "source), one line per vertex of the file: \"rho theta via\"; rho\n"
      "the distance, theta in [0, 2 pi) the angle at which the geodesic\n"
      "leaves the source (counter-clockwise seen from the faces' side,\n"
      "from the reference direction), via the last vertex (file order)\n"
      "the geodesic passes through, -1 if none; \"inf nan -1\" where\n"
      "unreached; - for standard output. Methods vtp and pvtp only",
      [](Arguments& a, const std::string& n, const std::string& v) { a.log_map_output = file_name(n, v); } },
    { "--log-map-strict", nullptr,
      "the strict polyhedral theta: a vertex behind a saddle or border\n"
      "vertex s gets the theta of s (default: the coordinates go on from\n"
      "those of s, turned at s as a straightest geodesic)",
      [](Arguments& a, const std::string&, const std::string&) { a.log_map_strict = true; } },
    { "--reference-direction", "X,Y,Z",
      "the log map's theta = 0: (X,Y,Z) projected\n"
      "onto the tangent plane of each source (default: at a vertex the\n"
      "edge to source(halfedge(v)), at a point the first edge of its\n"
      "face)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.reference_direction = parse_direction(n, v);
        a.has_reference_direction = true;
      } },
    { "--stats-json", "FILE|-", "write statistics as one JSON object to FILE, or to stdout with \"-\"",
      [](Arguments& a, const std::string& n, const std::string& v) { a.stats_json = file_name(n, v); } },
    { "--check-cgal", nullptr,
      "also run CGAL::Surface_mesh_shortest_path from the same sources and\n"
      "report the largest absolute and relative differences (with\n"
      "--max-distance, its distances beyond the limit count as inf; with\n"
      "--target, only the vertices whose distance is final are compared)",
      [](Arguments& a, const std::string&, const std::string&) { a.check_cgal = true; } },
    { "--through-pinches", nullptr,
      "let shortest paths pass through the vertices that the repair of\n"
      "the input split (non-manifold vertices, ends of non-manifold\n"
      "edges): the copies of each are joined (default: they are apart);\n"
      "one more run per such vertex reached. Not with --path-to,\n"
      "--path-to-point, --target-point, --farthest-points nor\n"
      "--check-cgal",
      [](Arguments& a, const std::string&, const std::string&) { a.through_pinches = true; } },
    { "--method", "M", nullptr, // help made from the table of methods in print_usage()
      [](Arguments& a, const std::string&, const std::string& v) { a.method = v; } },
    { "--threads", "T",
      "number of threads of the parallel methods, and of building the mesh\n"
      "and its arrays for every method (0, the default: OpenMP's default)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        const std::size_t t = parse_index(n, v);
        if(t > 4096)
          throw Tool_error("too many threads for " + n);
        a.threads = static_cast<int>(t);
        a.has_threads = true;
      } },
    { "--lambda", "L",
      "window-reset period of avtp / pavtp, in mean edge lengths (> 0,\n"
      "default 8)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.lambda = parse_double(n, v);
        if(!(a.lambda > 0.))
          throw Tool_error(n + " must be > 0");
        a.has_lambda = true;
      } },
    { "--lambda-g", "G", "guard band of avtp / pavtp, in mean edge lengths (>= 0, default 1)",
      [](Arguments& a, const std::string& n, const std::string& v) {
        a.lambda_g = parse_double(n, v);
        if(!(a.lambda_g >= 0.) || std::isinf(a.lambda_g))
          throw Tool_error(n + " must be finite and >= 0");
        a.has_lambda_g = true;
      } },
    { "--help", nullptr, "print this help and exit",
      [](Arguments& a, const std::string&, const std::string&) { a.help = true; } },
  };
  return table;
}

} // namespace vtp_geodesics_app
