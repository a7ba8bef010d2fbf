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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_TEAM_BARRIER_H
#define CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_TEAM_BARRIER_H

#include <CGAL/license/VTP_geodesics.h>

#include <atomic>
#include <condition_variable>
#include <mutex>

#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
#include <intrin.h>
#endif

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The processor's spin-wait hint: leaves the core's resources to a hardware sibling and lets a
// hypervisor see that the thread spins.
inline void spin_pause()
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __builtin_ia32_pause();
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
  _mm_pause();
#endif
}

// A barrier for a team of threads. Most waits are short (a few microseconds of sequential work by one
// thread), so a waiting thread first spins with the pause hint; after about a hundred microseconds it
// sleeps on a condition variable, so that a long wait, or a machine busy with other work, does not cost
// a processor to the thread it waits for.
class alignas(64) Team_barrier
{
public:
  void reset(int n)
  {
    m_n = n;
    m_count.store(0, std::memory_order_relaxed);
    m_generation.store(0, std::memory_order_relaxed);
    m_sleepers.store(0, std::memory_order_relaxed);
  }

  void wait()
  {
    const unsigned generation = m_generation.load(std::memory_order_acquire);
    if(m_count.fetch_add(1, std::memory_order_acq_rel) + 1 == m_n)
    {
      m_count.store(0, std::memory_order_relaxed);
      m_generation.fetch_add(1, std::memory_order_seq_cst);
      if(m_sleepers.load(std::memory_order_seq_cst) > 0)
      {
        { std::lock_guard<std::mutex> lock(m_mutex); }
        m_wake.notify_all();
      }
      return;
    }
    for(int spins = 0; spins < 4096; ++spins)
    {
      if(m_generation.load(std::memory_order_acquire) != generation)
        return;
      spin_pause();
    }
    std::unique_lock<std::mutex> lock(m_mutex);
    m_sleepers.fetch_add(1, std::memory_order_seq_cst);
    while(m_generation.load(std::memory_order_seq_cst) == generation)
      m_wake.wait(lock);
    m_sleepers.fetch_sub(1, std::memory_order_relaxed);
  }

private:
  int m_n = 1;
  std::atomic<int> m_count{ 0 };
  std::atomic<unsigned> m_generation{ 0 };
  std::atomic<int> m_sleepers{ 0 };
  std::mutex m_mutex;
  std::condition_variable m_wake;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_TEAM_BARRIER_H
