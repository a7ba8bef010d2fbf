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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_PARALLEL_FOR_H
#define CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_PARALLEL_FOR_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <type_traits>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The threading of the library: the preprocessing of the solver and of the mesh arrays, and the rows of
// compute_each() (Parallel_for); the team of a parallel propagation (run_team(), whose rounds the engine
// schedules itself). The propagation takes its number of threads from number_of_threads() too.

// Whether `ConcurrencyTag` asks for the parallel variants; Parallel_tag needs OpenMP.
template <class ConcurrencyTag>
constexpr bool is_parallel()
{
#ifndef _OPENMP
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but OpenMP is unavailable "
                "(link CGAL::VTP_geodesics_OpenMP_support, or compile with -fopenmp).");
#endif
  return std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
}

// The number of threads that the named parameter `number_of_threads` stands for: a positive value is
// itself; `threads <= 0` means OpenMP's default (omp_get_max_threads(): the OMP_NUM_THREADS environment
// variable, or the number of processors). Without OpenMP, always 1.
inline int number_of_threads(int requested)
{
#ifdef _OPENMP
  if(requested <= 0)
    requested = omp_get_max_threads();
  return (std::max)(1, requested);
#else
  (void)requested;
  return 1;
#endif
}

// The first exception thrown by work done on several threads, kept to be thrown again once they are done
// (an exception cannot leave an OpenMP region). run(f) calls f() unless an exception was already caught.
class Exception_capture
{
public:
  void reset()
  {
    m_failed.store(false, std::memory_order_relaxed);
    m_error = nullptr;
  }

  // whether some work has thrown (work still running may check it to stop early)
  bool failed() const { return m_failed.load(std::memory_order_relaxed); }

  template <class F>
  void run(const F& f)
  {
    if(failed())
      return;
    try
    {
      f();
    }
    catch(...)
    {
#ifdef _OPENMP
#pragma omp critical(vtp_geodesics_exception_capture)
#endif
      {
        if(!m_error)
          m_error = std::current_exception();
        m_failed.store(true, std::memory_order_relaxed);
      }
    }
  }

  // throws the first exception caught again, if there was one
  void rethrow() const
  {
    if(m_error)
      std::rethrow_exception(m_error);
  }

private:
  std::atomic<bool> m_failed{ false };
  std::exception_ptr m_error;  // written in the critical section only
};

// Runs body(t) on each thread t of a team of `threads` OpenMP threads (on the calling thread alone, t = 0, when
// threads <= 1 or without OpenMP), after start(team) on one of them, which the others wait for: `team` is the
// number of threads the runtime gave (it may give fewer than asked for). Returns it. The team of a whole
// propagation (propagation/Parallel_loop.h, virtual_sources/Virtual_source_rounds.h): start and body must not
// throw (an exception cannot leave an OpenMP region: see Exception_capture).
template <class Start, class Body>
int run_team(int threads, const Start& start, const Body& body)
{
  int team = 1;
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if(threads > 1)
  {
#pragma omp single
    {
      team = omp_get_num_threads();
      start(team);
    }
    body(omp_get_thread_num());
  }
#else
  (void)threads;
  start(team);
  body(0);
#endif
  return team;
}

// A loop whose iterations are shared among `threads` OpenMP threads (on the calling thread alone when
// threads <= 1 or without OpenMP). An exception cannot leave an OpenMP region: one thrown by an
// iteration is caught there, the iterations not begun yet are skipped, and the first exception is thrown
// again by run() once the iterations under way are done (or kept for rethrow(), when the caller has
// something to finish first).
class Parallel_for
{
public:
  enum Schedule { STATIC, DYNAMIC };  // OpenMP's schedule(static) or schedule(dynamic, 1)

  explicit Parallel_for(int threads, Schedule schedule = STATIC)
    : m_threads((std::max)(1, threads)), m_schedule(schedule)
  {}

  int threads() const { return m_threads; }

  // whether an iteration has thrown (iterations still running may check it to stop early)
  bool failed() const { return m_capture.failed(); }

  // Calls body(i, t) for i = 0, ..., n - 1, t being the number of the calling thread (0 <= t < threads()).
  template <class Body>
  void run(long long n, const Body& body, bool rethrow_now = true)
  {
    m_capture.reset();
#ifdef _OPENMP
    const int threads = m_threads;
    if(m_schedule == DYNAMIC)
    {
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) if(threads > 1)
      for(long long i = 0; i < n; ++i)
        iteration(i, omp_get_thread_num(), body);
    }
    else
    {
#pragma omp parallel for schedule(static) num_threads(threads) if(threads > 1)
      for(long long i = 0; i < n; ++i)
        iteration(i, omp_get_thread_num(), body);
    }
#else
    for(long long i = 0; i < n; ++i)
      iteration(i, 0, body);
#endif
    if(rethrow_now)
      rethrow();
  }

  // throws the first exception of the last run() again, if there was one
  void rethrow() const { m_capture.rethrow(); }

private:
  template <class Body>
  void iteration(long long i, int t, const Body& body)
  {
    m_capture.run([&] { body(i, t); });
  }

  int m_threads;
  Schedule m_schedule;
  Exception_capture m_capture;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_PARALLEL_PARALLEL_FOR_H
