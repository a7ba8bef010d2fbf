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
#ifndef CGAL_VTP_GEODESICS_INTERNAL_SOLVER_ROWS_ON_THREADS_H
#define CGAL_VTP_GEODESICS_INTERNAL_SOLVER_ROWS_ON_THREADS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/parallel/Parallel_for.h>
#include <CGAL/VTP_geodesics/internal/solver/Statistics_merge.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The rows of the batch queries (compute_each(), the polar patches): `count` rows, each computed in the workspace
// of its thread by compute(i, workspace, t, row_statistics), then handed on by deliver(i, t), one row at a time
// (under a lock), in any order. The rows are shared dynamically among `threads` threads (at least 1, at most one
// per row; `workspaces` grows to one per thread and is kept for the next batch). An exception of compute or
// deliver stops the handing out of rows and is thrown again once the rows under way are done. `statistics`,
// whose description of the mesh and the method the caller has set, receives the threads, the number of rows as
// its sources, the sum of the rows' statistics (add_row_statistics()) and the seconds of the batch.
template <class Workspace, class Compute, class Deliver>
void run_rows_on_threads(std::size_t count, int threads, std::vector<std::unique_ptr<Workspace> >& workspaces,
                         Compute&& compute, Deliver&& deliver, Propagation_statistics& statistics)
{
  threads = (std::max)(1, (std::min)(threads, static_cast<int>((std::max)(std::size_t(1), count))));
  while(workspaces.size() < static_cast<std::size_t>(threads))
    workspaces.emplace_back(new Workspace());
  std::vector<Propagation_statistics> per_thread(static_cast<std::size_t>(threads));

  const auto t0 = std::chrono::steady_clock::now();
  Parallel_for loop(threads, Parallel_for::DYNAMIC);
  std::mutex deliver_mutex;
  bool deliver_failed = false;  // under deliver_mutex
  loop.run(static_cast<long long>(count), [&](long long il, int t) {
    const std::size_t i = static_cast<std::size_t>(il);
    Propagation_statistics row;
    compute(i, *workspaces[static_cast<std::size_t>(t)], t, row);
    add_row_statistics(row, per_thread[static_cast<std::size_t>(t)]);
    std::lock_guard<std::mutex> lock(deliver_mutex);
    if(deliver_failed || loop.failed())
      return;
    try
    {
      deliver(i, t);
    }
    catch(...)
    {
      deliver_failed = true;
      throw;
    }
  }, /* rethrow */ false);
  statistics.threads = threads;
  statistics.sources = count;
  for(const Propagation_statistics& st : per_thread)
    add_row_statistics(st, statistics);
  statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  loop.rethrow();
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_SOLVER_ROWS_ON_THREADS_H
