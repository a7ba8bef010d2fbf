// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_METHODS_H
#define VTP_SUPPORT_METHODS_H

// The table of the package's methods, shared by the command-line tools, the benchmark and the Python module:
// each method is one choice of scheduling (sequential or parallel), of front (windows, or virtual sources per
// vertex) and of window resets (exact or approximate). It is also the one dispatch from a method to a call of
// the library: with_method() turns a method, its lambda and its threads into the concurrency tag and the named
// parameters of the call (a new method is one more row of the table, and nothing else).

#include <CGAL/VTP_geodesics/parameters.h>

#include <CGAL/tags.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace vtp_support {

struct Method_info
{
  const char* name;         // as typed on a command line: "vtp", "pvtp", "avtp", "pavtp", "vsp", "pvsp", ...
  bool parallel;            // CGAL::Parallel_tag scheduling (OpenMP threads)
  bool approximate;         // window resets every lambda * h (AVTP / PAVTP)
  const char* description;  // one line, for --help texts
  bool virtual_sources;     // virtual sources per vertex (VSP / PVSP): approximate, an upper bound
  int per_vertex;           // with virtual_sources: one or two per vertex (vsp2, pvsp2: more accurate, slower)
};

inline const Method_info* methods_begin()
{
  static const Method_info table[] = {
    { "vtp",   false, false, "exact, sequential", false, 1 },
    { "pvtp",  true,  false, "exact, parallel", false, 1 },
    { "avtp",  false, true,  "approximate, sequential", false, 1 },
    { "pavtp", true,  true,  "approximate, parallel", false, 1 },
    { "vsp",   false, false, "approximate (one virtual source per vertex, upper bound), sequential", true, 1 },
    { "pvsp",  true,  false, "as vsp, on T threads (the same distances, bit for bit)", true, 1 },
    { "vsp2",  false, false, "as vsp with two virtual sources per vertex: half the error, 1.3-2x the time", true, 2 },
    { "pvsp2", true,  false, "as vsp2, on T threads (the same distances, bit for bit)", true, 2 },
  };
  return table;
}
inline const Method_info* methods_end() { return methods_begin() + 8; }

// The method called `name`, or nullptr.
inline const Method_info* find_method(const std::string& name)
{
  for(const Method_info* m = methods_begin(); m != methods_end(); ++m)
    if(name == m->name)
      return m;
  return nullptr;
}

// "vtp, pvtp, avtp or pavtp"
inline std::string method_names(const char* last_separator = " or ")
{
  std::string s;
  for(const Method_info* m = methods_begin(); m != methods_end(); ++m)
  {
    if(m != methods_begin())
      s += (m + 1 == methods_end()) ? last_separator : ", ";
    s += m->name;
  }
  return s;
}

// Whether the parallel methods can run: this translation unit is compiled with OpenMP (the program
// links CGAL::VTP_geodesics_OpenMP_support).
inline bool parallel_methods_available()
{
#ifdef _OPENMP
  return true;
#else
  return false;
#endif
}

inline bool method_available(const Method_info& m) { return !m.parallel || parallel_methods_available(); }

// The reset period of the approximate methods when none is given (the library's recommendation).
constexpr double default_lambda = CGAL::VTP_geodesics::recommended_lambda;

// The named parameters that make the library run `m`: `lambda` (used by the approximate methods only, +inf for
// the others), `threads` (number_of_threads: the team of a parallel method, the preprocessing's and the batches'
// threads; 0: OpenMP's default), and the front (virtual sources, and how many per vertex). A call adds its own
// parameters to the chain (maximum_distance, targets, ...).
inline auto method_parameters(const Method_info& m, double lambda, int threads)
{
  return CGAL::VTP_geodesics::parameters::number_of_threads(threads)
    .lambda(m.approximate ? lambda : std::numeric_limits<double>::infinity())
    .virtual_sources(m.virtual_sources)
    .virtual_sources_per_vertex(m.per_vertex);
}

// Thrown by with_method() for a parallel method in a program built without OpenMP (clients check
// method_available() first and say so in their own words; this is the safety net).
struct Method_unavailable : std::invalid_argument
{
  explicit Method_unavailable(const Method_info& m)
    : std::invalid_argument(std::string("method ") + m.name + " needs OpenMP, and this program was built without it")
  {}
};

// The one dispatch: returns call(tag, np), with `tag` the concurrency tag of `m` (CGAL::Sequential_tag or
// CGAL::Parallel_tag) and `np` its named parameters (method_parameters()). For example
//   with_method(m, lambda, threads, [&](auto tag, const auto& np) {
//     solver.template compute<decltype(tag)>(distance_map, np.maximum_distance(r)); });
template <class Call>
decltype(auto) with_method(const Method_info& m, double lambda, int threads, Call&& call)
{
  const auto np = method_parameters(m, lambda, threads);
  if(!m.parallel)
    return std::forward<Call>(call)(CGAL::Sequential_tag(), np);
#ifdef _OPENMP
  return std::forward<Call>(call)(CGAL::Parallel_tag(), np);
#else
  throw Method_unavailable(m);
#endif
}

// The concurrency tag of work spread over rows, one row per thread (compute_each(), compute_each_polar_patch(),
// straightest_geodesics()): CGAL::Parallel_tag in a program built with OpenMP, else CGAL::Sequential_tag (the
// rows one after another). The one place outside the library that chooses between the two tags.
#ifdef _OPENMP
typedef CGAL::Parallel_tag Rows_tag;
constexpr bool rows_on_threads = true;
#else
typedef CGAL::Sequential_tag Rows_tag;
constexpr bool rows_on_threads = false;
#endif

// The number of threads when none is asked for: OpenMP's default (omp_get_max_threads(): OMP_NUM_THREADS, or the
// number of processors), 1 in a program built without OpenMP.
inline int default_threads()
{
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// The batches: solver.compute_each(sources, sink, np), one row per source, the rows on the threads of `np` (each
// row on one thread, whatever the method: compute_each() runs the sequential scheduling of each row; its
// Parallel_tag is that of the rows), or one after another in a program built without OpenMP.
template <class Solver, class Sources, class Sink, class NamedParameters>
void compute_each_on_threads(Solver& solver, const Sources& sources, Sink&& sink, const NamedParameters& np)
{
  solver.template compute_each<Rows_tag>(sources, std::forward<Sink>(sink), np);
}

} // namespace vtp_support

#endif // VTP_SUPPORT_METHODS_H
