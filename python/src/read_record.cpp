// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The record of the last read_mesh(): its faces and the seconds it read and checked them, taken by the first
// Solver(V, F) on the same arrays (see take_read() in core_solver.h).

#include "core_solver.h"

#include <algorithm>
#include <chrono>
#include <mutex>

namespace vtp_python {

// ---------------------------------------------------------------------------------------------------------------
// The record of the last read_mesh()
// ---------------------------------------------------------------------------------------------------------------
namespace {

struct Last_read
{
  std::mutex mutex;
  std::size_t n = 0;
  std::vector<vtp_support::fast_off_detail::Triangle> triangles;
  Read_record record;
  bool valid = false;
};

Last_read& last_read()
{
  static Last_read r;
  return r;
}

} // namespace

void remember_read(std::size_t n, std::vector<vtp_support::fast_off_detail::Triangle>&& triangles,
                   Read_record&& record)
{
  Last_read& last = last_read();
  std::lock_guard<std::mutex> lock(last.mutex);
  last.n = n;
  last.triangles = std::move(triangles);
  last.record = std::move(record);
  last.valid = true;
}

bool take_read(std::size_t n, const std::vector<vtp_support::fast_off_detail::Triangle>& triangles,
               Read_record& record)
{
  Last_read& last = last_read();
  std::lock_guard<std::mutex> lock(last.mutex);
  if(!last.valid || last.n != n || last.triangles != triangles)
    return false;
  record = std::move(last.record);
  last.record = Read_record();
  std::vector<vtp_support::fast_off_detail::Triangle>().swap(last.triangles);
  last.valid = false;
  return true;
}

void forget_read()
{
  Last_read& last = last_read();
  std::lock_guard<std::mutex> lock(last.mutex);
  std::vector<vtp_support::fast_off_detail::Triangle>().swap(last.triangles);
  last.record = Read_record();
  last.valid = false;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The record of a read by read_input_mesh() (no tables: the Solver checks the faces), returning n vertices and the
// m faces f; the time since t0 less the reader's checks and repairs is the reading.
void remember_other_read(std::size_t n, const std::int64_t* f, std::size_t m, const vtp_support::Input_mesh& input,
                         std::chrono::steady_clock::time_point t0)
{
  std::vector<vtp_support::fast_off_detail::Triangle> triangles(m);
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t k = 0; k < 3; ++k)
      triangles[j][k] = static_cast<std::uint32_t>(f[3 * j + k]);
  Read_record record;
  record.check_seconds = input.repair_seconds;
  record.read_seconds = (std::max)(0., seconds_since(t0) - input.repair_seconds);
  remember_read(n, std::move(triangles), std::move(record));
}

} // namespace vtp_python
