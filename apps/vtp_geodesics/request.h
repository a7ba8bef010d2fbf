// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_REQUEST_H
#define VTP_GEODESICS_APP_REQUEST_H

// The request made from the command line: the arguments, which name vertices of the file and points of space,
// turned into the run of the library on the mesh of the computation (mesh vertices and face locations), with
// what the results need to be put back in the file's terms (file_results.h). The vertices go from the file to
// the mesh through the correspondence that the reading keeps (vtp_support::Input_mesh::mesh_vertices_of()).

#include "arguments.h"
#include "locate.h"
#include "run.h"

#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>

#include <array>
#include <vector>

namespace vtp_geodesics_app {

struct Request
{
  Run_request run;
  std::vector<Located_point> source_points;  // --source-point, located on the mesh
  // the points of each curve of --source-curve, located on the mesh (the picture draws them)
  std::vector<std::vector<Located_point> > source_curves;
  // The paths of --path-output, in its order (the --path-to vertices, then the --path-to-point points): a path
  // to a source vertex is its single point, given here; the others are traced by the run, path k being
  // run.paths[traced[k]] (traced[k] is -1 for a path given here).
  std::vector<std::vector<std::array<double, 3> > > paths;
  std::vector<long long> traced;
};

// Checks the vertices of the arguments against the file, locates the points of the arguments on the mesh and
// makes the request. Throws Tool_error (a vertex out of range, a point that cannot be located, a point of a
// --source-curve farther from the surface than 1e-6 of the diagonal of the mesh's bounding box, a path from or a
// first sample at a vertex in no face).
Request make_request(const Arguments& args, const vtp_support::Method_info& method,
                     const vtp_support::Input_mesh& input);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_REQUEST_H
