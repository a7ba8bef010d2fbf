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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_ROUND_TEAM_H
#define CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_ROUND_TEAM_H

#include <CGAL/license/VTP_geodesics.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>

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

// A hook for the tests: when set, each thread of a team (PVTP, PAVTP, PVSP) calls it with its number before
// each work item it takes, and the master before each round it publishes (with -1 - its number); a test
// makes a thread late with it (sleeps), and the results must not change.
inline std::atomic<void (*)(int)>& round_team_test_hook()
{
  static std::atomic<void (*)(int)> hook{ nullptr };
  return hook;
}

inline void call_round_team_test_hook(int t)
{
  if(void (*f)(int) = round_team_test_hook().load(std::memory_order_relaxed))
    f(t);
}

// The synchronisation of a team that works in rounds published by one thread (the master, thread 0),
// where no thread waits for another to arrive:
//  - the master prepares a round, then publishes it (a new round number, with release semantics);
//  - every thread, master included, takes work items of the current round (Stealing_ranges.h: an item can
//    only be taken with the round number it belongs to) and counts the items it finished;
//  - the round is over when the finished items add up to the round's items: the master then goes on.
// A thread that is not running (the machine is busy with other work) does not hold the others back,
// unless it stopped in the middle of an item; a thread that wakes up late finds the items taken, or
// joins the current round. Waiting threads spin with the pause hint, then sleep.
class Round_team
{
public:
  void reset(int threads)
  {
    m_threads = threads;
    m_finished.reset(new Counter[static_cast<std::size_t>(threads)]);
    m_taking.reset(new Counter32[static_cast<std::size_t>(threads)]);
    m_round.store(0, std::memory_order_relaxed);
    m_done.store(false, std::memory_order_relaxed);
    m_sleepers.store(0, std::memory_order_relaxed);
    m_target = 0;
  }

  // master: publishes round `round` (> the previous one, > 0) of `items` items, after writing everything
  // the items need. A thread still trying to take items of a round `horizon` rounds older (which could
  // then be mistaken for this one by tags of `horizon` values, see Stealing_range in Stealing_ranges.h) is waited for.
  void publish(std::uint32_t round, std::size_t items, std::uint32_t horizon)
  {
    for(int t = 1; t < m_threads; ++t)
      for(;;)
      {
        const std::uint32_t r = m_taking[static_cast<std::size_t>(t)].value.load(std::memory_order_acquire);
        if(r == 0 || round - r < horizon)
          break;
        std::this_thread::yield();
      }
    m_target += items;
    m_round.store(round, std::memory_order_seq_cst);
    wake_sleepers();
  }

  // master: the propagation is over
  void finish()
  {
    m_done.store(true, std::memory_order_seq_cst);
    wake_sleepers();
  }

  // a worker: waits for a round newer than `seen` (returns it), or for the end (returns 0)
  std::uint32_t wait_for_round(std::uint32_t seen)
  {
    for(int spins = 0; spins < 4096; ++spins)
    {
      const std::uint32_t r = m_round.load(std::memory_order_acquire);
      if(r != seen)
        return r;
      if(m_done.load(std::memory_order_acquire))
        return 0;
      spin_pause();
    }
    std::unique_lock<std::mutex> lock(m_mutex);
    m_sleepers.fetch_add(1, std::memory_order_seq_cst);
    for(;;)
    {
      const std::uint32_t r = m_round.load(std::memory_order_seq_cst);
      if(r != seen || m_done.load(std::memory_order_seq_cst))
      {
        m_sleepers.fetch_sub(1, std::memory_order_relaxed);
        return r != seen ? r : 0;
      }
      m_wake.wait(lock);
    }
  }

  // worker t: declares that it takes items of the round it waited for (`round`), and returns the round it
  // may take items of: the current one, once its declaration is known to precede any later publication
  std::uint32_t start_taking(int t, std::uint32_t round)
  {
    for(;;)
    {
      m_taking[static_cast<std::size_t>(t)].value.store(round, std::memory_order_seq_cst);
      const std::uint32_t now = m_round.load(std::memory_order_seq_cst);
      if(now == round)
        return round;
      round = now;
    }
  }

  // worker t: takes no more items
  void stop_taking(int t) { m_taking[static_cast<std::size_t>(t)].value.store(0, std::memory_order_release); }

  // worker t (1 ... T-1), until finish(): for each round published, `take(round)` takes the items it can of it
  template <class Take>
  void serve(int t, Take&& take)
  {
    std::uint32_t seen = 0;
    for(;;)
    {
      std::uint32_t round = wait_for_round(seen);
      if(round == 0)
        return;
      round = start_taking(t, round);
      take(round);
      stop_taking(t);
      seen = round;
    }
  }

  // thread t finished one item (with release semantics: its results are visible to the master)
  void item_finished(int t)
  {
    Counter& c = m_finished[static_cast<std::size_t>(t)];
    c.value.store(c.value.load(std::memory_order_relaxed) + 1, std::memory_order_release);
  }

  // master: waits until every item published so far is finished
  void wait_for_items()
  {
    for(long spins = 0;; ++spins)
    {
      std::size_t finished = 0;
      for(int t = 0; t < m_threads; ++t)
        finished += m_finished[static_cast<std::size_t>(t)].value.load(std::memory_order_acquire);
      if(finished == m_target)
        return;
      if(spins < 4096)
        spin_pause();
      else
        std::this_thread::yield(); // the thread holding an item may need this processor
    }
  }

private:
  void wake_sleepers()
  {
    if(m_sleepers.load(std::memory_order_seq_cst) > 0)
    {
      { std::lock_guard<std::mutex> lock(m_mutex); }
      m_wake.notify_all();
    }
  }

  struct alignas(64) Counter
  {
    std::atomic<std::size_t> value{ 0 };
  };
  struct alignas(64) Counter32
  {
    std::atomic<std::uint32_t> value{ 0 };
  };

  int m_threads = 1;
  std::unique_ptr<Counter[]> m_finished;               // per thread: items finished, cumulative
  std::unique_ptr<Counter32[]> m_taking;               // per worker: the round it takes items of, or 0
  std::size_t m_target = 0;                             // master: items published, cumulative
  alignas(64) std::atomic<std::uint32_t> m_round{ 0 };
  std::atomic<bool> m_done{ false };
  alignas(64) std::atomic<int> m_sleepers{ 0 };
  std::mutex m_mutex;
  std::condition_variable m_wake;
};

// Whether the master of a team runs the rounds with the team or alone, chosen by the throughput measured:
// the work done per second (windows created by PVTP, vertices taken by PVSP: any count of the same work in
// both ways) in windows of `window` seconds (20 ms: several time slices of the system's scheduler). After a window with the way believed best, one window the other way (a probe);
// the faster becomes the best; the best stays for 1, 2, 4 ... up to 32 windows while probes confirm it.
// On an idle machine the team wins and a probe costs at most 1/33 of the time at the speed of one thread;
// when the machine is busy with other work (a thread descheduled, a core taken), the master alone is faster
// than a team waiting for its late members, and it is chosen. Which thread runs a round changes no result.
class Team_choice
{
public:
  typedef std::chrono::steady_clock Clock;

  void reset(Clock::time_point now)
  {
    m_team = m_best_team = true;
    m_probing = false;
    m_stay = m_left = 1;
    m_start = now;
    m_work = m_best_rate = 0.;
  }

  // whether the rounds are run by the team now
  bool team() const { return m_team; }

  // the master finished `work` units of work (a round), at `now`
  void record(double work, Clock::time_point now)
  {
    m_work += work;
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    if(elapsed < window)
      return;
    const double rate = m_work / elapsed;
    m_start = now;
    m_work = 0.;
    if(m_probing)
    {
      if(rate > m_best_rate)
      {
        m_best_team = m_team;
        m_stay = 1;
      }
      else
        m_stay = (std::min)(32, 2 * m_stay);
      m_team = m_best_team;
      m_probing = false;
      m_left = m_stay;
      return;
    }
    m_best_rate = rate;
    if(--m_left <= 0)
    {
      m_team = !m_best_team;
      m_probing = true;
    }
  }

  static constexpr double window = 0.02;

private:
  bool m_team = true, m_best_team = true, m_probing = false;
  int m_stay = 1, m_left = 1;
  Clock::time_point m_start;
  double m_work = 0., m_best_rate = 0.;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_ROUND_TEAM_H
