// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_APP_DISTANCE_PLY_H
#define VTP_GEODESICS_APP_DISTANCE_PLY_H

// A distance field as a PLY file: the mesh as read (the vertices of the file in file order, and its faces),
// with the per-vertex properties
//   double distance            the distance (inf for unreachable vertices)
//   int source                 the index of the nearest source (only when labels are given; -1: none)
//   uchar red, green, blue     the colour of the distance (see colour_map.h)
// in binary little-endian PLY, written with CGAL's PLY writer (the property writers behind
// CGAL::IO::write_PLY and CGAL::IO::write_PLY_with_properties). MeshLab, ParaView and Blender show the colours;
// ParaView also colours by `distance`. Written in distance_ply.cpp (CGAL's PLY writer is slow to compile).

#include <vtp_support/read_mesh.h>

#include <ostream>
#include <string>
#include <vector>

namespace vtp_geodesics_app {

// Writes the distance field of `input` (`distances` and, if not null, `labels`: one per vertex of the file) as a
// binary PLY file; the colours go from 0 to `max_distance`. `comment` lines go to the header.
void write_distance_ply(std::ostream& os, const vtp_support::Input_mesh& input, const std::vector<double>& distances,
                        const std::vector<int>* labels, double max_distance, const std::string& comment);

} // namespace vtp_geodesics_app

#endif // VTP_GEODESICS_APP_DISTANCE_PLY_H
