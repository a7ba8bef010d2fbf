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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOLVER_MANY_SOURCES_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOLVER_MANY_SOURCES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/solver/Settings_from_parameters.h>
#include <CGAL/VTP_geodesics/internal/solver/Rows_on_threads.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The rows of Geodesic_distance_solver::compute_each(): one propagation per seed, each with the
// sequential scheduling in the workspace of its thread (`workspaces` grows to one engine per thread),
// handed to `sink(i, items[i], distances)` by one thread at a time. With `parallel`, the seeds are
// shared among number_of_threads(threads) threads (at most one per seed), dynamically; else one after
// the other. An exception of a propagation or of the sink stops the handing out of rows and is thrown
// again once the rows under way are done. `statistics` receives the sum of the rows.
// A row reaches the sink in the order of vertices(tm) (`position`: per vertex index, its place in the row).
template <class Item, class RowSink>
void compute_rows(const Mesh_arrays& arrays, const std::vector<Index>& position, const std::vector<Item>& items,
                  const std::vector<Seed>& seeds, RowSink& sink, const Propagation_settings& settings, bool parallel,
                  int threads, std::vector<std::unique_ptr<Propagation_engine> >& workspaces,
                  Propagation_statistics& statistics)
{
  CGAL_precondition(items.size() == seeds.size());
  threads = parallel ? number_of_threads(threads) : 1;
  std::vector<std::vector<double> > rows(static_cast<std::size_t>(threads));  // per thread
  statistics = Propagation_statistics();
  statistics.vertices = static_cast<std::size_t>(arrays.nv);
  statistics.faces = static_cast<std::size_t>(arrays.nf);
  statistics.method = settings.reset_step < std::numeric_limits<double>::infinity() ? "avtp" : "vtp";
  run_rows_on_threads(seeds.size(), threads, workspaces,
    [&](std::size_t i, Propagation_engine& workspace, int t, Propagation_statistics& st) {
      workspace.template run<CGAL::Sequential_tag>(arrays, std::vector<Seed>(1, seeds[i]), std::vector<Target>(),
                                                   settings, 1, st);
      std::vector<double>& row = rows[static_cast<std::size_t>(t)];
      const std::vector<double>& d = workspace.distances();
      row.resize(d.size());
      for(std::size_t v = 0; v < d.size(); ++v)
        row[static_cast<std::size_t>(position[v])] = d[v];
    },
    [&](std::size_t i, int t) {
      sink(i, items[i], static_cast<const std::vector<double>&>(rows[static_cast<std::size_t>(t)]));
    },
    statistics);
}

// Geodesic_distance_solver::compute_each() on the solver's mesh (Mesh_index `mesh`): the sources validated
// (serially, before any row), the settings of `np` (no labels, paths nor targets; no initial distances; no log
// map: refused when compiling), then the rows.
template <class MeshIndex, class SourceRange, class RowSink, class NamedParameters>
void compute_each_row(const MeshIndex& mesh, const SourceRange& sources, RowSink& sink, const NamedParameters& np,
                      bool parallel, std::vector<std::unique_ptr<Propagation_engine> >& workspaces,
                      Propagation_statistics& statistics)
{
  static_assert(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::log_map_t>::value
                  && CGAL::parameters::is_default_parameter<NamedParameters, internal_np::log_map_via_t>::value,
                "compute_each() computes no log map: call compute() with log_map() for each source");
  typedef typename std::iterator_traits<decltype(std::begin(sources))>::value_type Source;
  const std::vector<Source> items(std::begin(sources), std::end(sources));
  std::vector<Seed> seeds;
  seeds.reserve(items.size());
  for(const Source& item : items)
    seeds.push_back(mesh.seed_of(item, static_cast<Index>(seeds.size())));
  if(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::initial_distances_t>::value)
    throw Invalid_input_error("compute_each() takes no initial_distances");
  int threads = 0;
  Propagation_settings settings = settings_from_parameters(np, mesh, threads);
  settings.want_labels = false;
  settings.record_paths = false;
  settings.keep_field = false;  // (a row keeps no field)
  settings.stop_at_targets = false;
  compute_rows(mesh.arrays, mesh.position, items, seeds, sink, settings, parallel, threads, workspaces, statistics);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOLVER_MANY_SOURCES_H
