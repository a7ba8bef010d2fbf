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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_POLAR_PATCH_ROWS_H
#define CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_POLAR_PATCH_ROWS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Polar_patches.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/log_map/Tangent_frame.h>
#include <CGAL/VTP_geodesics/internal/propagation/Local_propagation.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/solver/Rows_on_threads.h>
#include <CGAL/VTP_geodesics/internal/log_map/Log_map_output.h>
#include <CGAL/VTP_geodesics/internal/solver/Settings_from_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The polar patches of Geodesic_distance_solver (Polar_patches.h): one local run of the log map per centre
// (propagation/Local_propagation.h), stopped at the radius, on per-thread workspaces; each patch is what the reached
// vertices within the radius give, sorted by vertex position, handed to a sink by one thread at a time.

// A centre, validated and prepared serially before any patch: its seed and its log map frame.
struct Patch_centre
{
  Seed seed;
  bool at_vertex = false;
  Log_map_source source;    // at a vertex
  double seed_angle = 0.;   // at a point (Direction_record::seed_angle)
};

// One entry of a patch being gathered.
struct Patch_entry
{
  std::uint32_t vertex;
  double rho, theta;
  bool operator<(const Patch_entry& e) const { return vertex < e.vertex; }
};

// The patch rows: sink(i, centres[i], vertices, rho, theta) for each centre (three const std::vector&, of
// std::uint32_t, double, double; valid during the call only), one call at a time, in any order of the rows.
// With CGAL::Parallel_tag, the centres are shared among number_of_threads(threads) threads dynamically. An exception
// of a row or of the sink stops the handing out of rows and is thrown again once the rows under way are done.
template <class ConcurrencyTag, class MeshIndex, class VertexPointMap, class CentreRange, class PatchSink,
          class NamedParameters>
void compute_patch_rows(const MeshIndex& mesh, VertexPointMap vpm, const CentreRange& centres, double radius,
                        PatchSink& sink, const NamedParameters& np,
                        std::vector<std::unique_ptr<Local_propagation> >& workspaces,
                        Propagation_statistics& statistics)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename std::iterator_traits<decltype(std::begin(centres))>::value_type Centre;
  if(!(radius >= 0.))
    throw Invalid_input_error("the radius of the polar patches must be >= 0 (+infinity for none), got "
                              + std::to_string(radius));
  if(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::initial_distances_t>::value)
    throw Invalid_input_error("polar patches take no initial_distances");
  int threads = 0;
  Propagation_settings settings = settings_from_parameters(np, mesh, threads);
  if(settings.virtual_sources || settings.reset_step < std::numeric_limits<double>::infinity())
    throw Invalid_input_error("polar patches need the exact method (VTP): the log map is refused by AVTP and VSP");
  settings.want_labels = false;
  settings.record_paths = false;
  settings.keep_field = false;
  settings.stop_at_targets = false;
  settings.limit = radius / mesh.length_scale;  // as maximum_distance(radius)
  settings.log_map = true;
  settings.log_map_strict = choose_parameter(get_parameter(np, internal_np::log_map_strict), false);

  // the centres, validated before any patch
  const std::vector<Centre> items(std::begin(centres), std::end(centres));
  std::vector<Patch_centre> prepared(items.size());
  Direction_record frames;
  std::vector<Seed> one(1);
  for(std::size_t i = 0; i < items.size(); ++i)
  {
    Patch_centre& p = prepared[i];
    p.seed = mesh.seed_of(items[i], 0, "centre", i);
    one[0] = p.seed;
    try
    {
      prepare_log_map(mesh, vpm, np, one, frames);
    }
    catch(const Invalid_input_error& e)
    {
      std::string message = e.what();
      const std::string suffix = " (source 0)";
      if(message.size() >= suffix.size() && message.compare(message.size() - suffix.size(), suffix.size(), suffix) == 0)
        message.erase(message.size() - suffix.size());
      throw Invalid_input_error("centre " + std::to_string(i) + ": " + message);
    }
    p.at_vertex = !frames.vertex_sources.empty();
    if(p.at_vertex)
      p.source = frames.vertex_sources[0];
    p.seed_angle = frames.seed_angle[0];
  }

  threads = is_parallel<ConcurrencyTag>() ? number_of_threads(threads) : 1;
  struct Thread_data
  {
    std::vector<Patch_entry> entries;
    std::vector<std::uint32_t> vertices;
    std::vector<double> rho, theta;
  };
  std::vector<Thread_data> per_thread(static_cast<std::size_t>(threads));
  statistics = Propagation_statistics();
  statistics.method = "vtp";
  statistics.vertices = static_cast<std::size_t>(mesh.arrays.nv);
  statistics.faces = static_cast<std::size_t>(mesh.arrays.nf);
  statistics.max_distance = radius;
  run_rows_on_threads(items.size(), threads, workspaces,
    [&](std::size_t i, Local_propagation& w, int t, Propagation_statistics& row) {
      const Patch_centre& p = prepared[i];
      Thread_data& data = per_thread[static_cast<std::size_t>(t)];
      Direction_record& direction = w.direction();
      direction.vertex_sources.clear();
      if(p.at_vertex)
        direction.vertex_sources.push_back(p.source);
      direction.seed_angle.assign(1, p.seed_angle);
      w.run(mesh.arrays, p.seed, settings);
      // the patch: the reached vertices within the cutoff, as the single run keeps them (apply_cutoff(), unit)
      const double cutoff = w.cutoff();
      const std::vector<double>& dist = w.distances();
      data.entries.clear();
      for(Index v : w.reached())
        if(dist[v] <= cutoff)
          data.entries.push_back(Patch_entry{static_cast<std::uint32_t>(mesh.position[static_cast<std::size_t>(v)]),
                                             settings.unit != 1. ? dist[v] * settings.unit : dist[v],
                                             angle_in_0_2pi(direction.theta[v])});
      std::sort(data.entries.begin(), data.entries.end());
      data.vertices.resize(data.entries.size());
      data.rho.resize(data.entries.size());
      data.theta.resize(data.entries.size());
      for(std::size_t k = 0; k < data.entries.size(); ++k)
      {
        data.vertices[k] = data.entries[k].vertex;
        data.rho[k] = data.entries[k].rho;
        data.theta[k] = data.entries[k].theta;
      }
      row.windows_created = w.windows_created();
      row.windows_propagated = w.windows_propagated();
      row.vertices_processed = w.vertices_processed();
      row.pseudo_sources = w.pseudo_sources();
      row.reached_vertices = data.entries.size();
      row.stopped_early = w.stopped_early();
    },
    [&](std::size_t i, int t) {
      const Thread_data& data = per_thread[static_cast<std::size_t>(t)];
      sink(i, items[i], static_cast<const std::vector<std::uint32_t>&>(data.vertices),
           static_cast<const std::vector<double>&>(data.rho), static_cast<const std::vector<double>&>(data.theta));
    },
    statistics);
}

// The polar patches of `centres` in CSR form (Polar_patches.h), from compute_patch_rows(): the rows are
// appended as they come, then put in the order of the centres (moved as they are if they came in order).
template <class ConcurrencyTag, class MeshIndex, class VertexPointMap, class CentreRange, class NamedParameters>
Polar_patches polar_patches_of(const MeshIndex& mesh, VertexPointMap vpm, const CentreRange& centres, double radius,
                               const NamedParameters& np,
                               std::vector<std::unique_ptr<Local_propagation> >& workspaces,
                               Propagation_statistics& statistics)
{
  const std::size_t n = static_cast<std::size_t>(std::distance(std::begin(centres), std::end(centres)));
  std::vector<std::size_t> start(n, 0), count(n, 0);
  Polar_patches got;
  bool in_order = true;
  std::size_t next = 0;
  auto sink = [&](std::size_t i, const auto&, const std::vector<std::uint32_t>& v, const std::vector<double>& r,
                  const std::vector<double>& t) {
    in_order = in_order && i == next;
    ++next;
    start[i] = got.vertices.size();
    count[i] = v.size();
    got.vertices.insert(got.vertices.end(), v.begin(), v.end());
    got.rho.insert(got.rho.end(), r.begin(), r.end());
    got.theta.insert(got.theta.end(), t.begin(), t.end());
  };
  compute_patch_rows<ConcurrencyTag>(mesh, vpm, centres, radius, sink, np, workspaces, statistics);
  Polar_patches out;
  out.offsets.assign(n + 1, 0);
  for(std::size_t i = 0; i < n; ++i)
    out.offsets[i + 1] = out.offsets[i] + count[i];
  if(in_order)
  {
    out.vertices.swap(got.vertices);
    out.rho.swap(got.rho);
    out.theta.swap(got.theta);
    return out;
  }
  const std::size_t total = out.offsets[n];
  out.vertices.resize(total);
  out.rho.resize(total);
  out.theta.resize(total);
  for(std::size_t i = 0; i < n; ++i)
  {
    std::copy_n(got.vertices.begin() + static_cast<std::ptrdiff_t>(start[i]), count[i],
                out.vertices.begin() + static_cast<std::ptrdiff_t>(out.offsets[i]));
    std::copy_n(got.rho.begin() + static_cast<std::ptrdiff_t>(start[i]), count[i],
                out.rho.begin() + static_cast<std::ptrdiff_t>(out.offsets[i]));
    std::copy_n(got.theta.begin() + static_cast<std::ptrdiff_t>(start[i]), count[i],
                out.theta.begin() + static_cast<std::ptrdiff_t>(out.offsets[i]));
  }
  return out;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_LOG_MAP_POLAR_PATCH_ROWS_H
