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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_STEALING_RANGES_H
#define CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_STEALING_RANGES_H

#include <CGAL/license/VTP_geodesics.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The work items of one thread in one round, [front, back) of an array of items, with the number of the
// round (modulo 2^ROUND_BITS), packed in one atomic word on its own cache line: the owner takes items
// from the front, the other threads steal from the back; an item is taken only by a thread that names the
// round it belongs to (a thread that comes late to a round finished without it takes nothing from the
// next one; Round_team keeps a thread from naming a round 2^ROUND_BITS rounds old).
struct alignas(64) Stealing_range
{
  static const unsigned INDEX_BITS = 21;
  static const unsigned ROUND_BITS = 22;
  static const std::uint64_t INDEX_MASK = (std::uint64_t(1) << INDEX_BITS) - 1;
  static const std::uint64_t ROUND_MASK = (std::uint64_t(1) << ROUND_BITS) - 1;

  std::atomic<std::uint64_t> bounds{ 0 };

  // front, back <= INDEX_MASK
  void set(std::size_t front, std::size_t back, std::uint32_t round)
  {
    bounds.store(pack(round, back, front), std::memory_order_relaxed);
  }
  bool take_front(std::uint32_t round, std::size_t& i) { return take(false, round, i); }
  bool take_back(std::uint32_t round, std::size_t& i) { return take(true, round, i); }

private:
  static std::uint64_t pack(std::uint64_t round, std::uint64_t back, std::uint64_t front)
  {
    return ((round & ROUND_MASK) << (2 * INDEX_BITS)) | (back << INDEX_BITS) | front;
  }

  bool take(bool from_back, std::uint32_t round, std::size_t& i)
  {
    std::uint64_t b = bounds.load(std::memory_order_relaxed);
    for(;;)
    {
      if((b >> (2 * INDEX_BITS)) != (round & ROUND_MASK))
        return false;
      std::uint64_t front = b & INDEX_MASK, back = (b >> INDEX_BITS) & INDEX_MASK;
      if(front >= back)
        return false;
      i = static_cast<std::size_t>(from_back ? --back : front++);
      if(bounds.compare_exchange_weak(b, pack(round, back, front), std::memory_order_relaxed))
        return true;
    }
  }
};

// One range per thread of a team. Thread t takes the items of its own range, then steals from the
// back of the others' ranges (in the order t+1, t+2, ...). Which thread gets an item is a matter of
// timing: callers must make the result independent of it.
class Stealing_ranges
{
public:
  // the largest number of items of a round
  static const std::size_t MAX_ITEMS = Stealing_range::INDEX_MASK;

  void resize(std::size_t threads)
  {
    if(threads != m_size)
    {
      m_ranges.reset(new Stealing_range[threads]);
      m_size = threads;
    }
  }

  Stealing_range& operator[](std::size_t t) { return m_ranges[t]; }

  // Calls f(i) for every item of round `round` that thread t of a team of `team` threads takes.
  template <class F>
  void for_each_taken(std::size_t t, std::size_t team, std::uint32_t round, F&& f)
  {
    std::size_t i;
    while(m_ranges[t].take_front(round, i))
      f(i);
    for(std::size_t k = 1; k < team; ++k)
    {
      Stealing_range& r = m_ranges[(t + k) % team];
      while(r.take_back(round, i))
        f(i);
    }
  }

private:
  std::unique_ptr<Stealing_range[]> m_ranges;
  std::size_t m_size = 0;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_STEALING_RANGES_H
