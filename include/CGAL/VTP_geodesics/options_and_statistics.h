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

#ifndef CGAL_VTP_GEODESICS_OPTIONS_AND_STATISTICS_H
#define CGAL_VTP_GEODESICS_OPTIONS_AND_STATISTICS_H

#include <CGAL/license/VTP_geodesics.h>

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// \brief exception thrown by the entry points of the package when the input cannot be processed:
/// a mesh that is not a triangle mesh, a source vertex that is not a vertex of the mesh,
/// non-finite coordinates, or invalid options.
///
/// The message is one line that says what is wrong.
class Invalid_input_error : public std::invalid_argument
{
public:
  explicit Invalid_input_error(const std::string& what)
    : std::invalid_argument(what)
  {}
};

/// \ingroup PkgVTPGeodesicsRef
/// \brief options of one propagation.
///
/// The default values give the exact algorithm (VTP, or PVTP with `CGAL::Parallel_tag`).
struct Propagation_options
{
  /// Window-reset period of the approximate variants (AVTP / PAVTP), in multiples of the mean
  /// edge length `h`. The default, `+infinity`, never resets windows: the result is exact.
  /// Must be `> 0` and not NaN.
  double lambda = std::numeric_limits<double>::infinity();

  /// The value of `lambda` we recommend for the approximate variants (used by the command-line
  /// program when none is given): on our benchmark meshes it keeps the mean relative error
  /// around 0.1% (see the benchmark section of the user manual).
  static constexpr double recommended_lambda = 8.;

  /// Guard band of the approximate variants, in multiples of `h`: at a reset, the windows next to
  /// wavefront vertices farther than `(R+1) lambda h + lambda_g h` are kept. Must be `>= 0`, not NaN.
  double lambda_g = 1.0;

  /// Number of threads of the parallel scheduling (`CGAL::Parallel_tag`); `0` means OpenMP's default.
  /// Ignored with `CGAL::Sequential_tag`.
  int number_of_threads = 0;

  /// Windows shorter than `minimum_window_length * (length of their edge)` are dropped.
  /// Such windows change distances by a second-order amount (below `1e-18` relative for the default).
  double minimum_window_length = 1e-9;
};

/// \ingroup PkgVTPGeodesicsRef
/// \brief statistics of one propagation, returned by every computation.
struct Propagation_statistics
{
  /// Number of vertices and faces of the mesh (as seen by the algorithm).
  std::size_t vertices = 0;
  std::size_t faces = 0;
  /// Name of the algorithm that ran: `"vtp"`, `"pvtp"`, `"avtp"` or `"pavtp"`.
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
  /// Number of window resets (approximate variants only).
  std::size_t resets = 0;
  /// Parallel scheduling only: propagation rounds (arrays of lists), and those run on several threads.
  std::size_t rounds = 0;
  std::size_t parallel_rounds = 0;
  /// Parallel scheduling only: seconds spent selecting vertices and lists (serial), propagating
  /// lists and storing their children (parallel), and in the serial tail of each round (lowering
  /// the distances, queueing the next lists; `merge_seconds`).
  double selection_seconds = 0.;
  double propagation_seconds = 0.;
  double merge_seconds = 0.;
  /// Vertices with a finite distance, and the largest finite distance.
  std::size_t reached_vertices = 0;
  double max_distance = 0.;
  /// Wall-clock seconds: propagation only (`seconds`), and writing the output map (`output_seconds`).
  double seconds = 0.;
  double output_seconds = 0.;
};

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_OPTIONS_AND_STATISTICS_H
