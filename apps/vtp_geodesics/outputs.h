// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_OUTPUTS_H
#define VTP_GEODESICS_APP_OUTPUTS_H

// What vtp_geodesics writes: the distances (text or PLY, by file name), the labels, the samples, the paths, the
// picture (the statistics and the summary for people: report.h).

#include "arguments.h"
#include "file_results.h"
#include "output_file.h"
#include "request.h"
#include "run.h"

#include <vtp_support/read_mesh.h>

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace vtp_geodesics_app {

enum class Distance_format { TEXT, PLY };

// The format of `--output FILE`: PLY for a .ply extension, else text.
Distance_format distance_format(const std::string& file);

// Writes the distances (one per vertex of the file) in `format`; `labels` (nearest source per file vertex) may
// be null.
void write_distances(std::ostream& os, Distance_format format, const vtp_support::Input_mesh& input,
                     const std::vector<double>& distances, const std::vector<int>* labels, double max_distance);

// One value per line: the nearest source of each vertex of the file (-1: none).
void write_labels(std::ostream& os, const std::vector<int>& labels);

enum class Path_format { POLYLINES, OBJ };

// The format of `--path-output FILE`: OBJ for a .obj extension, else CGAL's polylines text.
Path_format path_format(const std::string& file);

// Writes geodesic paths (each: its points, target first), then the straightest geodesics of `traces` (the last
// traces.size() polylines of `paths`, each from its start), as CGAL's polylines text (one polyline per line:
// N x1 y1 z1 ... xN yN zN) or as OBJ (a header comment saying what each polyline is, 'v' lines, then one 'l' line
// per polyline; a polyline of one point is 'l i i').
void write_paths(std::ostream& os, Path_format format, const std::vector<std::vector<std::array<double, 3> > >& paths,
                 const std::vector<Arguments::Trace>& traces = std::vector<Arguments::Trace>());

struct Picture_request
{
  int isolines = 10;
  bool has_view = false;
  std::array<double, 3> view = { { 0., 0., -1. } };
  std::vector<std::array<double, 3> > markers;                // the sources
  std::vector<std::vector<std::array<double, 3> > > polylines; // the paths
  const std::vector<int>* labels = nullptr;                   // per mesh vertex: colour the labels instead
  const std::vector<std::array<double, 2> >* angles = nullptr; // per mesh vertex: colour the log map's theta
  // the curves to draw, those `in_picture` (the library's, instead of interpolating the isolines or the borders)
  const std::vector<Curve_set>* curves = nullptr;
};

// Draws the distance field on the mesh of the computation (`mesh_distances`: per mesh vertex) as a PNG picture.
void write_picture(std::ostream& os, const vtp_support::Mesh& mesh, const std::vector<double>& mesh_distances,
                   double max_distance, const Picture_request& request);

// Writes the samples of a farthest-point sampling (file vertex indices, in order) and the covering radius after
// each: a '#' header line, then "V R" per line (R: shortest text that reads back exactly, "inf" if infinite).
void write_samples(std::ostream& os, const std::vector<std::size_t>& samples, const std::vector<double>& radii);

// Writes the files that the arguments ask for (but --stats-json), in `files`: the distances, the labels, the
// distances of the targets, the samples, the paths, the log map, the curves, the answers at the query points, the
// picture.
void write_outputs(Output_files& files, const Arguments& args, const vtp_support::Input_mesh& input,
                   const Request& request, const Run_result& run, const File_results& results);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_OUTPUTS_H
