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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_VERTEX_SCHEDULE_H
#define CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_VERTEX_SCHEDULE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The vertices waiting to be processed, with the distance they were reached at. Two orderings
// behind one interface:
//  - a binary heap (the sequential scheduling, VTP): pop() gives the nearest vertex;
//  - buckets of a fixed width (the parallel scheduling, PVTP, Du et al. 2020, Section 4): pop() gives
//    the entries of the nearest non-empty bucket, in the order they were pushed.
// A vertex can be pushed several times (each time its distance is lowered); the caller recognizes
// stale entries. The buckets also count, for the adaptive selection of PVTP (Eq. 5), how many
// entries were pushed beyond and within the current round limit.
class Vertex_schedule
{
public:
  typedef std::pair<double, Index> Entry;

  void start_heap()
  {
    m_buckets_mode = false;
    m_heap.clear();
  }

  // Buckets of width 1 / inverse_width.
  void start_buckets(double inverse_width)
  {
    CGAL_precondition(inverse_width > 0.);
    m_buckets_mode = true;
    m_inv_width = inverse_width;
    for(std::vector<Entry>& b : m_buckets)
      b.clear();
    m_buckets.clear();
    m_read.clear();
    m_current = 0;
    m_pending = 0;
    m_round_limit = std::numeric_limits<double>::infinity();
    m_pushed_beyond = m_pushed_within = 0;
  }

  void push(Index v, double value)
  {
    if(!m_buckets_mode)
    {
      m_heap.push_back(Entry(value, v));
      std::push_heap(m_heap.begin(), m_heap.end(), std::greater<Entry>());
      return;
    }
    const double b = value * m_inv_width;
    const double max_bucket = double(std::size_t(1) << 26);
    std::size_t i = static_cast<std::size_t>((std::min)(b, max_bucket));
    if(i < m_current)
      i = m_current;
    if(i >= m_buckets.size())
    {
      m_buckets.resize(i + 1);
      m_read.resize(i + 1, 0);
    }
    m_buckets[i].push_back(Entry(value, v));
    ++m_pending;
    if(value > m_round_limit)
      ++m_pushed_beyond;
    else
      ++m_pushed_within;
  }

  bool empty() const { return m_buckets_mode ? m_pending == 0 : m_heap.empty(); }

  bool pop(Entry& e)
  {
    if(!m_buckets_mode)
    {
      if(m_heap.empty())
        return false;
      std::pop_heap(m_heap.begin(), m_heap.end(), std::greater<Entry>());
      e = m_heap.back();
      m_heap.pop_back();
      return true;
    }
    while(m_current < m_buckets.size())
    {
      std::vector<Entry>& b = m_buckets[m_current];
      std::size_t& r = m_read[m_current];
      if(r < b.size())
      {
        e = b[r++];
        --m_pending;
        return true;
      }
      b.clear();
      r = 0;
      ++m_current;
    }
    return false;
  }

  // Buckets only: puts back the entry that pop() just returned.
  void unpop()
  {
    CGAL_precondition(m_buckets_mode && m_current < m_buckets.size() && m_read[m_current] > 0);
    --m_read[m_current];
    ++m_pending;
  }

  // A value no waiting entry is below: the top of the heap; with buckets, the smallest entry left in the
  // current bucket (an entry below the current bucket is put into it) or the start of the next one.
  double lower_bound() const
  {
    if(!m_buckets_mode)
      return m_heap.empty() ? std::numeric_limits<double>::infinity() : m_heap.front().first;
    if(m_pending == 0)
      return std::numeric_limits<double>::infinity();
    double low = double(m_current + 1) / m_inv_width;
    if(m_current < m_buckets.size())
      for(std::size_t i = m_read[m_current]; i < m_buckets[m_current].size(); ++i)
        low = (std::min)(low, m_buckets[m_current][i].first);
    return low;
  }

  // Calls f(entry) for every waiting entry (stale ones included).
  template <class F>
  void for_each_waiting(F&& f) const
  {
    if(!m_buckets_mode)
    {
      for(const Entry& e : m_heap)
        f(e);
      return;
    }
    for(std::size_t b = m_current; b < m_buckets.size(); ++b)
      for(std::size_t i = m_read[b]; i < m_buckets[b].size(); ++i)
        f(m_buckets[b][i]);
  }

  // Buckets only: the end of the bucket of `value` (the round limit of Eq. 5).
  double end_of_bucket(double value) const { return (std::floor(value * m_inv_width) + 1.) / m_inv_width; }

  // Buckets only: entries pushed from now on are counted as beyond or within `limit`.
  void set_round_limit(double limit) { m_round_limit = limit; }
  void reset_push_counts() { m_pushed_beyond = m_pushed_within = 0; }
  std::size_t pushed_beyond() const { return m_pushed_beyond; }
  std::size_t pushed_within() const { return m_pushed_within; }

private:
  bool m_buckets_mode = false;
  std::vector<Entry> m_heap;
  std::vector<std::vector<Entry> > m_buckets;
  std::vector<std::size_t> m_read;      // per bucket, the next entry to pop
  std::size_t m_current = 0;            // the first bucket that may hold entries
  std::size_t m_pending = 0;            // entries not popped yet
  double m_inv_width = 1.;
  double m_round_limit = std::numeric_limits<double>::infinity();
  std::size_t m_pushed_beyond = 0, m_pushed_within = 0;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PROPAGATION_VERTEX_SCHEDULE_H
