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


#ifndef CGAL_VTP_GEODESICS_INTERNAL_SAMPLING_FARTHEST_POINT_SAMPLER_H
#define CGAL_VTP_GEODESICS_INTERNAL_SAMPLING_FARTHEST_POINT_SAMPLER_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Farthest_point_samples.h>
#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/solver/Settings_from_parameters.h>
#include <CGAL/VTP_geodesics/internal/solver/Statistics_merge.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// Farthest-point sampling above the engine: each new sample is added to the field of the samples so far by a
// run from known distances (Propagation_engine::run_again()), whose work and resetting are those of the
// region the sample wins; the farthest vertex is the top of a max-heap of the vertices (larger distance
// first, then lower index) whose vertices lowered by a run sift down, so that no step costs O(V) and the
// heap takes 8 bytes per vertex.
class Farthest_point_sampler
{
public:
  // Indices: samples, radii and the field, in the engine's unit.
  std::vector<Index> samples;
  std::vector<double> radii;
  Propagation_statistics statistics;

  // Takes up to k samples on `m` (first: NO_INDEX for the vertex farthest from the first vertex), stopping
  // once the covering radius is <= `radius` (engine unit); `settings` as for a computation (labels are
  // always kept). `rank`: per vertex index, its place in the order of the ties (that of vertices(tm)); the
  // first vertex is that of rank 0.
  template <class ConcurrencyTag>
  void run(const Mesh_arrays& m, const std::vector<Index>& rank, std::size_t k, Index first, double radius,
           Propagation_settings settings, int threads)
  {
    CGAL_precondition(rank.size() == static_cast<std::size_t>(m.nv));
    m_rank = &rank;
    const auto t0 = std::chrono::steady_clock::now();
    samples.clear();
    radii.clear();
    statistics = Propagation_statistics();
    if(m.nv == 0 || k == 0)
      return;
    settings.want_labels = true;
    settings.known_distances = true;
    settings.unit = 1.;
    if(first == NO_INDEX)
      first = farthest_from_first_vertex<ConcurrencyTag>(m, rank, settings, threads);
    Index next = first;
    for(;;)
    {
      Seed seed;
      seed.kind = Seed::AT_VERTEX;
      seed.element = next;
      seed.label = static_cast<Index>(samples.size());
      Propagation_statistics st;
      m_engine->template run_again<ConcurrencyTag>(m, seed, settings, threads, st);
      add_row_statistics(st, statistics);
      statistics.method = st.method;
      statistics.threads = st.threads;
      samples.push_back(next);
      if(samples.size() == 1)
        build_heap(m.nv);
      else
      {
        // the lowered vertices sift down from the deepest place up (as a heap is built): each then sifts
        // through a subtree that is already a heap
        m_lowered.clear();
        for(Index v : m_engine->touched())
          if(m_engine->was_lowered(v))
            m_lowered.push_back(m_position[static_cast<std::size_t>(v)]);
        std::sort(m_lowered.begin(), m_lowered.end(), std::greater<Index>());
        for(Index i : m_lowered)
          sift_down(i);
      }
      const Index top = m_heap.front();
      const double farthest = m_engine->distances()[static_cast<std::size_t>(top)];
      radii.push_back(farthest);
      if(samples.size() >= k || !(farthest > radius))
        break;
      next = top;
    }
    statistics.sources = samples.size();
    statistics.vertices = static_cast<std::size_t>(m.nv);
    statistics.faces = static_cast<std::size_t>(m.nf);
    statistics.max_distance = radii.back();
    statistics.reached_vertices = 0;
    for(double d : m_engine->distances())  // (the field of the runs: taken after them, see Propagation_engine)
      statistics.reached_vertices += d < std::numeric_limits<double>::infinity() ? 1 : 0;
    statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  // Moves the final field out (the distances and, per vertex, the index of the nearest sample or NO_INDEX),
  // and frees the rest.
  void release_field(std::vector<double>& distances, std::vector<Index>& labels)
  {
    m_engine->release_field(distances, labels);
    m_engine.reset();
    std::vector<Index>().swap(m_heap);
    std::vector<Index>().swap(m_position);
  }

private:
  // the heap order: a before b if a is farther, or as far with a lower rank
  bool before(Index a, Index b) const
  {
    const double da = m_engine->distances()[static_cast<std::size_t>(a)];
    const double db = m_engine->distances()[static_cast<std::size_t>(b)];
    return da > db || (da == db && (*m_rank)[static_cast<std::size_t>(a)] < (*m_rank)[static_cast<std::size_t>(b)]);
  }

  void place(std::size_t i, Index v)
  {
    m_heap[i] = v;
    m_position[static_cast<std::size_t>(v)] = static_cast<Index>(i);
  }

  // the vertex at place i went farther down the order (its distance was lowered)
  void sift_down(Index place_of_vertex)
  {
    std::size_t i = static_cast<std::size_t>(place_of_vertex);
    const Index v = m_heap[i];
    const std::size_t n = m_heap.size();
    for(;;)
    {
      std::size_t child = 2 * i + 1;
      if(child >= n)
        break;
      if(child + 1 < n && before(m_heap[child + 1], m_heap[child]))
        ++child;
      if(!before(m_heap[child], v))
        break;
      place(i, m_heap[child]);
      i = child;
    }
    place(i, v);
  }

  void build_heap(Index nv)
  {
    m_heap.resize(static_cast<std::size_t>(nv));
    m_position.resize(static_cast<std::size_t>(nv));
    for(Index v = 0; v < nv; ++v)
      place(static_cast<std::size_t>(v), v);
    for(std::size_t i = m_heap.size() / 2; i-- > 0;)
      sift_down(static_cast<Index>(i));
  }

  // The default first sample: the vertex farthest from the vertex of rank 0 (ties: the lowest rank), in a
  // workspace freed before the sampling starts.
  template <class ConcurrencyTag>
  static Index farthest_from_first_vertex(const Mesh_arrays& m, const std::vector<Index>& rank,
                                          const Propagation_settings& settings, int threads)
  {
    const Index first = static_cast<Index>(std::find(rank.begin(), rank.end(), Index(0)) - rank.begin());
    Propagation_engine engine;
    Propagation_settings s = settings;
    s.known_distances = false;
    s.want_labels = false;
    Seed seed;
    seed.kind = Seed::AT_VERTEX;
    seed.element = first;
    Propagation_statistics st;
    engine.template run<ConcurrencyTag>(m, std::vector<Seed>(1, seed), std::vector<Target>(), s, threads, st);
    const std::vector<double>& d = engine.distances();
    Index best = first;
    for(Index v = 0; v < m.nv; ++v)
    {
      const double dv = d[static_cast<std::size_t>(v)], db = d[static_cast<std::size_t>(best)];
      if(dv > db || (dv == db && rank[static_cast<std::size_t>(v)] < rank[static_cast<std::size_t>(best)]))
        best = v;
    }
    return best;
  }

  std::unique_ptr<Propagation_engine> m_engine{ new Propagation_engine() };
  const std::vector<Index>* m_rank = nullptr;
  std::vector<Index> m_heap;      // vertices
  std::vector<Index> m_position;  // per vertex, its place in m_heap
  std::vector<Index> m_lowered;   // places of the vertices lowered by a run
};

template <class MeshIndex>
Index first_sample_index(const MeshIndex&, CGAL::internal_np::Param_not_found)
{
  return NO_INDEX;
}

template <class MeshIndex>
Index first_sample_index(const MeshIndex& mesh, typename MeshIndex::vertex_descriptor v)
{
  return mesh.seed_of(v, 0, "first_sample", MeshIndex::no_position).element;
}

// The farthest-point sampling of the solver's mesh (Mesh_index `mesh`) with the named parameters `np`
// (first_sample, sampling_radius, and those of a computation).
template <class ConcurrencyTag, class MeshIndex, class NamedParameters>
Farthest_point_samples<typename MeshIndex::vertex_descriptor>
farthest_point_samples_of(const MeshIndex& mesh, std::size_t k, const NamedParameters& np)
{
  int threads = 0;
  const Propagation_settings settings = settings_from_parameters(np, mesh, threads);
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef typename MeshIndex::vertex_descriptor vertex_descriptor;
  if(settings.limit < std::numeric_limits<double>::infinity() || settings.record_paths || settings.keep_field
     || !is_default_parameter<NamedParameters, internal_np::targets_t>::value
     || !is_default_parameter<NamedParameters, internal_np::initial_distances_t>::value)
    throw Invalid_input_error("farthest_point_sampling() takes no maximum_distance, targets, record_paths, "
                              "keep_field nor initial_distances");
  const Index first = first_sample_index(mesh, get_parameter(np, internal_np::first_sample));
  const double radius = choose_parameter(get_parameter(np, internal_np::sampling_radius), 0.);
  if(!(radius >= 0.))
    throw Invalid_input_error("the sampling radius must be >= 0, got " + std::to_string(radius));

  Farthest_point_sampler sampler;
  sampler.template run<ConcurrencyTag>(mesh.arrays, mesh.position, k, first, radius / mesh.length_scale, settings, threads);
  Farthest_point_samples<vertex_descriptor> r;
  const double unit = mesh.length_scale;
  for(Index v : sampler.samples)
    r.samples.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
  for(double d : sampler.radii)
    r.radii.push_back(d * unit);
  r.statistics = sampler.statistics;
  r.statistics.max_distance *= unit;
  std::vector<Index> labels;
  std::vector<double> distances;
  sampler.release_field(distances, labels);  // the workspace is freed before the labels are widened
  if(!distances.empty())  // in the order of vertices(tm)
  {
    mesh.to_positions(distances, r.distances);
    std::vector<double>().swap(distances);
    for(double& d : r.distances)
      d *= unit;
    r.labels.resize(labels.size());
    for(std::size_t i = 0; i < labels.size(); ++i)
    {
      const Index l = labels[i];
      r.labels[mesh.position_of(static_cast<Index>(i))] = l == NO_INDEX ? no_source : static_cast<std::size_t>(l);
    }
  }
  if(r.distances.size() != mesh.vertices.size())  // no sample
  {
    r.distances.assign(mesh.vertices.size(), std::numeric_limits<double>::infinity());
    r.labels.assign(mesh.vertices.size(), no_source);
  }
  return r;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SAMPLING_FARTHEST_POINT_SAMPLER_H
