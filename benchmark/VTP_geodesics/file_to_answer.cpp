// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the benchmarks of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// From the file to the answer: the mesh read from its OFF file as the tool reads it (vtp_support::read_input_mesh),
// the solver built, exact VTP from one source, in a fresh child process; the stages as the tool's --stats-json
// gives them (vtp_support::Stage_seconds), printed as one line per mesh beside the table of the propagations.

#include "vtp_benchmark.h"

#include <CGAL/property_map.h>
#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/parameters.h>

#include <vtp_support/read_mesh.h>
#include <vtp_support/statistics.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace vtp_benchmark {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// In the child: the stages, written to `fd` as the bytes of a Stage_seconds; exits.
[[noreturn]] void run_stages(int fd, const std::string& file, std::size_t source, int threads)
{
  vtp_support::Stage_seconds s;
  int code = 0;
  try
  {
    const auto start = std::chrono::steady_clock::now();
    vtp_support::Input_mesh input;
    vtp_support::read_input_mesh(file, input, threads);
    s.read = input.read_seconds;
    s.repair = input.repair_seconds;
    CGAL::VTP_geodesics::Geodesic_distance_solver<vtp_support::Mesh> solver(
      input.mesh, CGAL::VTP_geodesics::parameters::number_of_threads(threads));
    s.preprocessing = solver.preprocessing_seconds();
    solver.add_source(input.mesh_vertices_of(source).front());
    solver.compute(CGAL::Constant_property_map<vtp_support::Vertex_index, double>());
    s.propagation = solver.statistics().seconds;
    s.total = seconds_since(start);
  }
  catch(...)
  {
    code = 1;
  }
  const char* p = reinterpret_cast<const char*>(&s);
  std::size_t left = sizeof(s);
  while(code == 0 && left > 0)
  {
    const ssize_t w = ::write(fd, p, left);
    if(w <= 0)
      code = 1;
    else
    {
      p += w;
      left -= static_cast<std::size_t>(w);
    }
  }
  ::close(fd);
  ::_exit(code);
}

} // namespace

int default_threads() { return vtp_support::default_threads(); }

bool file_to_answer(const std::string& file, std::size_t source, int threads, vtp_support::Stage_seconds& stages)
{
  int fd = -1;
  const pid_t pid = fork_with_pipe(fd);
  if(pid == 0)
    run_stages(fd, file, source, threads);
  int status = 0;
  double peak_rss_mb = 0.;
  const std::string message = read_all_and_wait(fd, pid, status, peak_rss_mb);
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0 || message.size() != sizeof(stages))
    return false;
  std::memcpy(&stages, message.data(), sizeof(stages));
  return true;
}

void print_file_to_answer(const std::string& label, std::size_t source, int threads,
                          const vtp_support::Stage_seconds& s)
{
  std::printf("# %s: file to answer (OFF file, vtp from vertex %zu, %d preprocessing thread%s):", label.c_str(),
              source, threads, threads == 1 ? "" : "s");
  vtp_support::for_each_stage(s, [](const char* name, double value, vtp_support::Statistic_unit unit) {
    if(unit == vtp_support::Statistic_unit::seconds)
    {
      std::string n = name;
      n = n.substr(0, n.size() - std::strlen("_seconds"));
      std::printf(" %s %.3f s", n.c_str(), value);
    }
    else
      std::printf(", %s %.1f%%", name, 100. * value);
  });
  std::printf("\n");
}

} // namespace vtp_benchmark
