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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_BUCKETS_H
#define CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_BUCKETS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The vertices waiting in virtual source propagation (Virtual_source_rounds.h): buckets of distances of a
// fixed width (half a short edge length, see short_edge_length()), a ring of them per thread of the team (a
// thread puts the vertices it lowered in its own ring). A vertex waits in the bucket of the distance it was
// offered, and may wait in several (each time it is lowered): the rounds recognise the stale entries.
//
// An offer of a vertex u goes to a vertex y at most `reach` edges away (a neighbour, or the third vertex of
// a face beyond the faces around u), so it is at most d(u) plus `reach` longest edges (d(root) + |s - y| <=
// d(root) + |s - u| + |u - y|) and at least d(u) minus as much: the buckets in use span twice that length,
// and a ring of buckets suffices. An offer below the next bucket waits in the next bucket.
class Virtual_source_buckets
{
public:
  typedef std::pair<double, Index> Entry;  // a distance and its vertex

  // The bucket width, in short edge lengths (short_edge_length()).
  static constexpr double bucket_width = 0.5;
  // How many edges away from a vertex its offers go (Virtual_source_walks::reach_beyond()).
  static constexpr double reach = 2.;

  // the buckets of one thread
  struct Ring
  {
    std::vector<std::vector<Entry>> slots;
    std::size_t pending = 0, peak_entries = 0;
  };

  // Prepares the rings of a team of `team` threads for a run on `m`, empty, and puts the `seeded` vertices
  // in the first ring (the current bucket is the one before the least of them). With `keep_width`, the run
  // is on the mesh of the last one (its short edge length is then not measured again).
  void start(const Mesh_arrays& m, bool keep_width, int team, const std::vector<Entry>& seeded)
  {
    if(!keep_width || !(m_short_edge > 0.))
      m_short_edge = short_edge_length(m);
    m_width = bucket_width * m_short_edge;
    if(!(m_width > 0.) || !std::isfinite(m_width))
      m_width = 1.;
    // the ring: the offers 2 reach longest edges around the current bucket, plus rounding; at most 2^16
    // buckets (wider ones on meshes whose longest edge is that many times the bucket width)
    const double max_ring = 65536.;
    m_span = 2. * reach * m.max_edge_length;
    if(!(m_span / m_width < max_ring - 4.))
      m_width = m_span / (max_ring - 4.);
    m_ring = static_cast<long long>(std::floor(m_span / m_width)) + 4;
    m_rings.resize(static_cast<std::size_t>(team));
    for(Ring& r : m_rings)
    {
      r.slots.resize(static_cast<std::size_t>(m_ring));
      for(std::vector<Entry>& s : r.slots)
        s.clear();
      r.pending = r.peak_entries = 0;
    }
    m_current = (std::numeric_limits<long long>::max)();
    for(const Entry& e : seeded)
      m_current = (std::min)(m_current, index(e.first) - 1);
    for(const Entry& e : seeded)
      push(m_rings[0], e.second, e.first);
  }

  // the distances that the buckets in use span (2 reach longest edges)
  double span() const { return m_span; }

  // the ring of thread t
  Ring& ring(int t) { return m_rings[static_cast<std::size_t>(t)]; }

  // a vertex waits in the bucket of its distance, after the current one, and within the ring
  void push(Ring& r, Index v, double d) const
  {
    const long long b = (std::min)((std::max)(index(d), m_current + 1), m_current + m_ring - 1);
    r.slots[static_cast<std::size_t>(b % m_ring)].emplace_back(d, v);
    ++r.pending;
    r.peak_entries = (std::max)(r.peak_entries, r.pending);
  }

  // the number of entries waiting
  std::size_t pending() const
  {
    std::size_t n = 0;
    for(const Ring& r : m_rings)
      n += r.pending;
    return n;
  }

  // Moves on to the next bucket; returns its least distance.
  double next_bucket()
  {
    ++m_current;
    return static_cast<double>(m_current) * m_width;
  }

  // Calls f(e) for each entry of the current bucket, ring after ring (thread 0 first), in the order they were
  // put there, and empties it.
  template <class F>
  void empty_current(const F& f)
  {
    const std::size_t slot_index = static_cast<std::size_t>(m_current % m_ring);
    for(Ring& r : m_rings)
    {
      std::vector<Entry>& slot = r.slots[slot_index];
      for(const Entry& e : slot)
        f(e);
      r.pending -= slot.size();
      slot.clear();
    }
  }

  // whether some entry e of some bucket has f(e)
  template <class F>
  bool any_of(const F& f) const
  {
    for(const Ring& r : m_rings)
      for(const std::vector<Entry>& slot : r.slots)
        for(const Entry& e : slot)
          if(f(e))
            return true;
    return false;
  }

  // the bytes of the rings at their peak
  std::size_t peak_bytes() const
  {
    std::size_t bytes = 0;
    for(const Ring& r : m_rings)
      bytes += r.peak_entries * sizeof(Entry) + r.slots.capacity() * sizeof(std::vector<Entry>);
    return bytes;
  }

private:
  // A short edge length of the mesh (the first decile of the lengths of at most 4096 half-edges taken at
  // a regular stride, zero lengths left out): on meshes of varying density, the buckets are those of the
  // fine regions, where vertices of one round would otherwise be many edges apart.
  static double short_edge_length(const Mesh_arrays& m)
  {
    const std::size_t nh = static_cast<std::size_t>(m.nf) * 3;
    const std::size_t stride = (std::max)(std::size_t(1), nh / 4096);
    std::vector<double> lengths;
    lengths.reserve(nh / stride + 1);
    for(std::size_t h = 0; h < nh; h += stride)
    {
      const double l = m.geometry.faces[h / 3].length[h % 3];
      if(l > 0.)
        lengths.push_back(l);
    }
    if(lengths.empty())
      return m.mean_edge_length;
    const std::size_t k = lengths.size() / 10;
    std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(k), lengths.end());
    return lengths[k];
  }

  long long index(double d) const
  {
    const double b = std::floor(d / m_width);
    return b < 9e18 ? static_cast<long long>(b) : (std::numeric_limits<long long>::max)() / 2;
  }

  std::vector<Ring> m_rings;  // one per thread
  long long m_current = 0, m_ring = 1;
  double m_width = 1., m_span = 0., m_short_edge = 0.;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_VIRTUAL_SOURCES_VIRTUAL_SOURCE_BUCKETS_H
