// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_STATISTICS_H
#define VTP_SUPPORT_STATISTICS_H

// The one description of the library's statistics (CGAL::VTP_geodesics::Propagation_statistics): its fields, each
// with the name the outputs give it and its unit. The tool's JSON, the benchmark's CSV, the Python dict and the
// reports are all written from it: a new statistic is one more line of for_each_statistic(), and nothing else.
//
// The names are the fields' names, but for the parallel rounds' stages, whose `propagation_seconds` would clash
// with the whole propagation's time in the tools' outputs: they are "round_selection_seconds",
// "round_propagation_seconds" and "round_merge_seconds". The whole propagation's wall-clock time is "seconds".

#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <vtp_support/number_format.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <ostream>
#include <string>
#include <type_traits>

namespace vtp_support {

// The unit of a statistic.
enum class Statistic_unit
{
  count,    // a number of things (vertices, windows, threads, ...)
  bytes,
  seconds,  // wall-clock
  length,   // in the mesh's units
  flag,     // a bool
  text,     // a std::string
  ratio     // a quotient of two quantities of the same unit
};

// Calls f(name, field, unit) for each field of `s`, in the order the outputs list them. `field` is a reference
// to the field (const when `s` is): std::size_t, int, bool, double or std::string. Works on a const statistics
// object (to write it) and on a mutable one (to read it back, as the benchmark does from its child processes).
template <class Statistics, class F>
void for_each_statistic(Statistics& s, F&& f)
{
  static_assert(std::is_same<typename std::remove_const<Statistics>::type,
                             CGAL::VTP_geodesics::Propagation_statistics>::value,
                "for_each_statistic() describes CGAL::VTP_geodesics::Propagation_statistics");
  typedef Statistic_unit U;
  f("method", s.method, U::text);
  f("threads", s.threads, U::count);
  f("vertices", s.vertices, U::count);
  f("faces", s.faces, U::count);
  f("sources", s.sources, U::count);
  f("windows_created", s.windows_created, U::count);
  f("windows_propagated", s.windows_propagated, U::count);
  f("peak_live_windows", s.peak_live_windows, U::count);
  f("peak_window_bytes", s.peak_window_bytes, U::bytes);
  f("field_pieces", s.field_pieces, U::count);
  f("field_bytes", s.field_bytes, U::bytes);
  f("vertices_processed", s.vertices_processed, U::count);
  f("pseudo_sources", s.pseudo_sources, U::count);
  f("resets", s.resets, U::count);
  f("stopped_early", s.stopped_early, U::flag);
  f("rounds", s.rounds, U::count);
  f("parallel_rounds", s.parallel_rounds, U::count);
  f("round_selection_seconds", s.selection_seconds, U::seconds);
  f("round_propagation_seconds", s.propagation_seconds, U::seconds);
  f("round_merge_seconds", s.merge_seconds, U::seconds);
  f("reached_vertices", s.reached_vertices, U::count);
  f("max_distance", s.max_distance, U::length);
  f("seconds", s.seconds, U::seconds);
  f("output_seconds", s.output_seconds, U::seconds);
}

// The stages of a computation from a mesh file to its answer, wall-clock seconds: what a user waits for, of
// which the propagation is only a part. The tool fills them all; the benchmark's file-to-answer run and the
// Python module fill those they go through (0 for the others).
struct Stage_seconds
{
  double read = 0.;           // parsing the file
  double repair = 0.;         // checking the mesh, repairing it if needed, building its halfedge structure
  double preprocessing = 0.;  // the solver's per-mesh arrays (numbering, lengths, angles)
  double propagation = 0.;    // the computation asked for (the library's statistics' `seconds`)
  double write = 0.;          // the output files
  double total = 0.;          // from the start to the answer (at least the sum of the stages above)

  // the time not in one of the named stages (arguments, sources, results put back in the file's order)
  double other() const
  {
    const double rest = total - (read + repair + preprocessing + propagation + write);
    return rest > 0. ? rest : 0.;
  }
  // the time outside the propagation, relative to the propagation (the bar of the file-to-answer time)
  double outside_propagation_ratio() const
  {
    return propagation > 0. ? (total - propagation) / propagation : 0.;
  }
};

// Calls f(name, value, unit) for each stage of `s`, then for the time not in a named stage ("other_seconds")
// and for the time outside the propagation over the propagation ("outside_propagation_ratio"), in the order the
// outputs list them: the tool's JSON, the benchmark's file-to-answer line and the Python statistics are written
// from it. A new stage is one more line here (and one more field above).
template <class F>
void for_each_stage(const Stage_seconds& s, F&& f)
{
  typedef Statistic_unit U;
  f("read_seconds", s.read, U::seconds);
  f("repair_seconds", s.repair, U::seconds);
  f("preprocessing_seconds", s.preprocessing, U::seconds);
  f("propagation_seconds", s.propagation, U::seconds);
  f("write_seconds", s.write, U::seconds);
  f("other_seconds", s.other(), U::seconds);
  f("total_seconds", s.total, U::seconds);
  f("outside_propagation_ratio", s.outside_propagation_ratio(), U::ratio);
}

// A statistic as JSON text: numbers as numbers (non-finite ones as null), flags as true / false, text quoted.
inline std::string json_value(const std::string& s)
{
  std::string r = "\"";
  for(char c : s)
  {
    if(c == '"' || c == '\\')
      r += '\\';
    if(static_cast<unsigned char>(c) < 0x20)
    {
      static const char hex[] = "0123456789abcdef";
      r += "\\u00";
      r += hex[(c >> 4) & 0xf];
      r += hex[c & 0xf];
      continue;
    }
    r += c;
  }
  return r + "\"";
}
inline std::string json_value(bool b) { return b ? "true" : "false"; }
inline std::string json_value(double x) { return std::isfinite(x) ? double_to_string(x) : std::string("null"); }
inline std::string json_value(int x) { return std::to_string(x); }
inline std::string json_value(std::size_t x) { return std::to_string(x); }

// The statistics as the members of a JSON object: `"name": value` pairs separated by ", ", the first preceded by
// `first_separator` (so that they can follow other members: pass ", "). The statistics named in `except` are
// left out (a client that writes a member of that name itself, with its own meaning).
inline void write_statistics_json(std::ostream& os, const CGAL::VTP_geodesics::Propagation_statistics& s,
                                  const char* first_separator = "", std::initializer_list<const char*> except = {})
{
  const char* separator = first_separator;
  for_each_statistic(s, [&](const char* name, const auto& value, Statistic_unit) {
    for(const char* e : except)
      if(std::strcmp(name, e) == 0)
        return;
    os << separator << '"' << name << "\": " << json_value(value);
    separator = ", ";
  });
}

// The stages as the members of a JSON object (see write_statistics_json()).
inline void write_stages_json(std::ostream& os, const Stage_seconds& s, const char* first_separator = "")
{
  const char* separator = first_separator;
  for_each_stage(s, [&](const char* name, double value, Statistic_unit) {
    os << separator << '"' << name << "\": " << json_value(value);
    separator = ", ";
  });
}

} // namespace vtp_support

#endif // VTP_SUPPORT_STATISTICS_H
