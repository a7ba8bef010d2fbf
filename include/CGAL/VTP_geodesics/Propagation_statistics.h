// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the VTP_geodesics package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef CGAL_VTP_GEODESICS_PROPAGATION_STATISTICS_H
#define CGAL_VTP_GEODESICS_PROPAGATION_STATISTICS_H

#include <CGAL/license/VTP_geodesics.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// \brief statistics of one propagation: `Geodesic_distance_solver::statistics()`, or the named
/// parameter `statistics` of `compute_geodesic_distances()`.
struct Propagation_statistics
{
  /// Number of vertices and faces of the mesh (as seen by the algorithm).
  std::size_t vertices = 0;
  std::size_t faces = 0;
  /// Number of sources.
  std::size_t sources = 0;
  /// Name of the algorithm that ran: `"vtp"`, `"pvtp"`, `"avtp"`, `"pavtp"`, `"vsp"`, `"pvsp"`, `"vsp2"` or
  /// `"pvsp2"` (two virtual sources per vertex).
  std::string method = "vtp";
  /// Number of threads used (1 for the sequential scheduling).
  int threads = 1;
  /// Windows created (by triangle propagation and by sources / pseudo-sources).
  std::size_t windows_created = 0;
  /// Windows propagated across a triangle.
  std::size_t windows_propagated = 0;
  /// Largest number of windows alive at the same time.
  std::size_t peak_live_windows = 0;
  /// Largest number of bytes held by the window storage (including unused slots of its blocks).
  std::size_t peak_window_bytes = 0;
  /// Number of times a vertex was taken from the queue / buckets, and pseudo-source emissions.
  std::size_t vertices_processed = 0;
  std::size_t pseudo_sources = 0;
  /// With `keep_field(true)`: the pieces of the kept field (the windows that crossed a face) and the bytes it
  /// holds (0 without it).
  std::size_t field_pieces = 0;
  std::size_t field_bytes = 0;
  /// Number of window resets (approximate variants only).
  std::size_t resets = 0;
  /// Whether the propagation stopped before the end, at the distance limit or once every target was final.
  bool stopped_early = false;
  /// Parallel scheduling and virtual sources only: propagation rounds (arrays of lists; with
  /// `virtual_sources(true)`, buckets of vertices), and those run on several threads.
  std::size_t rounds = 0;
  std::size_t parallel_rounds = 0;
  /// Parallel scheduling only: seconds spent selecting vertices and lists (serial), propagating
  /// lists and storing their children (parallel), and in the serial tail of each round (lowering
  /// the distances, queueing the next lists; `merge_seconds`). With `virtual_sources(true)`:
  /// choosing the rounds, computing the offers (and applying them, in a round that one thread runs
  /// alone), and applying the offers of a round that the team runs (`merge_seconds`).
  double selection_seconds = 0.;
  double propagation_seconds = 0.;
  double merge_seconds = 0.;
  /// Vertices with a finite distance, and the largest finite distance.
  std::size_t reached_vertices = 0;
  double max_distance = 0.;
  /// Wall-clock seconds: propagation only (`seconds`), and writing the output maps (`output_seconds`).
  double seconds = 0.;
  double output_seconds = 0.;
};

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_PROPAGATION_STATISTICS_H
