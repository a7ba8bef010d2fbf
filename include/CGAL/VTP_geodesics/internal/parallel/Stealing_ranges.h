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

// The work items of one thread, [front, back) of an array of items, packed in one atomic word on its
// own cache line: the owner takes items from the front, the other threads steal from the back.
struct alignas(64) Stealing_range
{
  std::atomic<std::uint64_t> bounds{ 0 };

  void set(std::size_t front, std::size_t back)
  {
    bounds.store((std::uint64_t(back) << 32) | std::uint64_t(front), std::memory_order_relaxed);
  }
  bool take_front(std::size_t& i) { return take(false, i); }
  bool take_back(std::size_t& i) { return take(true, i); }

private:
  bool take(bool from_back, std::size_t& i)
  {
    std::uint64_t b = bounds.load(std::memory_order_relaxed);
    for(;;)
    {
      std::uint64_t front = b & 0xffffffffu, back = b >> 32;
      if(front >= back)
        return false;
      i = static_cast<std::size_t>(from_back ? --back : front++);
      if(bounds.compare_exchange_weak(b, (back << 32) | front, std::memory_order_relaxed))
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
  void resize(std::size_t threads)
  {
    if(threads != m_size)
    {
      m_ranges.reset(new Stealing_range[threads]);
      m_size = threads;
    }
  }

  Stealing_range& operator[](std::size_t t) { return m_ranges[t]; }

  // Calls f(i) for every item that thread t of a team of `team` threads takes.
  template <class F>
  void for_each_taken(std::size_t t, std::size_t team, F&& f)
  {
    std::size_t i;
    while(m_ranges[t].take_front(i))
      f(i);
    for(std::size_t k = 1; k < team; ++k)
    {
      Stealing_range& r = m_ranges[(t + k) % team];
      while(r.take_back(i))
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
