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

#ifndef CGAL_VTP_GEODESICS_POLAR_PATCHES_H
#define CGAL_VTP_GEODESICS_POLAR_PATCHES_H

#include <CGAL/license/VTP_geodesics.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// \brief polar patches: for each of many centres, every vertex within a radius of it with its geodesic
/// polar coordinates `(rho, theta)`, in compressed sparse rows (CSR), as
/// `Geodesic_distance_solver::polar_patches()` returns them.
///
/// Patch `i` (the centre of index `i` in the range given) is the entries `offsets[i]` to `offsets[i + 1] - 1`
/// of `vertices`, `rho` and `theta`, ordered by vertex index (`Geodesic_distance_solver::vertex_id()`),
/// ascending: the row offsets, column indices and values of a CSR matrix with one row per centre and one column
/// per vertex (two value arrays, `rho` and `theta`, sharing the same structure). A patch holds every vertex
/// whose geodesic distance to the centre is at most the radius, the centre itself (a vertex centre) with
/// `rho = 0` and `theta = 0`.
///
/// `rho` and `theta` are those of the log map from the centre alone (`compute()` with `log_map()`, the
/// sequential scheduling and `maximum_distance(radius)`), bit for bit: `rho` the distance, `theta` the angle
/// of its tangent coordinates, reduced to `[0, 2 pi)` (`log_map()` writes `rho (cos theta, sin theta)` with the
/// same `theta` before the reduction). So the tangent frame is that of the log map (the manual's section
/// on the log map: at a vertex centre, the reference edge and the scaling by 2 pi / the sum of the corner
/// angles; at a face location, `halfedge(f)`; `reference_direction` if given), and by default the coordinates
/// go on behind saddle and border vertices, or with `log_map_strict(true)` take the strict polyhedral angle.
///
/// `Geodesic_distance_solver::polar_patches<ConcurrencyTag>(centres, radius, np)` computes them for a range of
/// centres (`vertex_descriptor`s or face locations, as sources are given); `compute_each_polar_patch<ConcurrencyTag>(
/// centres, radius, sink, np)` hands each patch to `sink(i, centre, vertices, rho, theta)` instead (three
/// `const std::vector&` of `std::uint32_t`, `double` and `double`, a row as above, valid during the call only),
/// as `compute_each()` hands its rows: one call at a time, in any order of the centres; an exception of the
/// sink or of a run stops the handing out of patches and is thrown again once those under way are done.
/// With `CGAL::Parallel_tag`, the centres are shared among `number_of_threads` threads (OpenMP, dynamic
/// schedule), each run with the sequential scheduling in a workspace of its thread; the result does not
/// depend on the number of threads. A run costs what its patch reaches, not the mesh: it stops at the radius,
/// and its workspace puts back only what it touched before the next run (the first run of each thread's
/// workspace sets it up, O(V) once). Memory: one workspace (O(V)) per thread, and the patches; `polar_patches()`
/// gathers the patches as they come and, if they came out of order, copies them once into the order of the
/// centres (twice the result for a moment).
///
/// Named parameters: `log_map_strict`, `reference_direction` (of the log map), `minimum_window_length`,
/// `number_of_threads`; the radius replaces `maximum_distance`. Errors (`Invalid_input_error`, before any
/// patch is computed): a centre that is not a vertex or a point of the mesh, or a vertex whose faces do not
/// form one fan around it ("centre N ..."), a negative or NaN radius (`+infinity`: whole log maps), `lambda` or
/// `virtual_sources` (the log map needs the exact method), `initial_distances`. `statistics()` afterwards sums
/// the runs (`reached_vertices`: the number of entries).
///
/// Index widths: a vertex index is a `std::uint32_t` because the solver takes at most 2^31 - 1 vertices (its
/// constructor throws `Invalid_input_error` beyond, "the mesh is too large"), so every vertex index fits, and an
/// entry then takes 20 bytes instead of 24 (patches of a large mesh hold billions of entries). The offsets are
/// `std::size_t`: the number of entries of all patches is not bounded by 2^31 (nor 2^32), only by memory.
struct Polar_patches
{
  std::vector<std::size_t> offsets;     ///< `number_of_patches() + 1` row offsets; `offsets[0] = 0`
  std::vector<std::uint32_t> vertices;  ///< the vertex index of each entry, ascending within a patch (32 bits:
                                        ///< see above)
  std::vector<double> rho;              ///< the geodesic distance of each entry to its centre
  std::vector<double> theta;            ///< the angle of each entry at its centre, in `[0, 2 pi)`

  /// the number of patches (of centres).
  std::size_t number_of_patches() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  /// the number of (patch, vertex) entries of all patches.
  std::size_t number_of_entries() const { return vertices.size(); }
};

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_POLAR_PATCHES_H
