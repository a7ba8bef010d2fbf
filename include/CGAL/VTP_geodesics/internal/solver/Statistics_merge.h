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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOLVER_STATISTICS_MERGE_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOLVER_STATISTICS_MERGE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <algorithm>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// Adds the counts of one propagation (a row of compute_each()) to a sum of rows: the counts add up, the
// peaks and the largest distance are maxima, and the sum stopped early if a row did.
inline void add_row_statistics(const Propagation_statistics& row, Propagation_statistics& sum)
{
  sum.windows_created += row.windows_created;
  sum.windows_propagated += row.windows_propagated;
  sum.peak_live_windows = (std::max)(sum.peak_live_windows, row.peak_live_windows);
  sum.peak_window_bytes = (std::max)(sum.peak_window_bytes, row.peak_window_bytes);
  sum.vertices_processed += row.vertices_processed;
  sum.pseudo_sources += row.pseudo_sources;
  sum.resets += row.resets;
  sum.reached_vertices += row.reached_vertices;
  sum.max_distance = (std::max)(sum.max_distance, row.max_distance);
  sum.stopped_early = sum.stopped_early || row.stopped_early;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOLVER_STATISTICS_MERGE_H
