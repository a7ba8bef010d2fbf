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

// The table of the package's methods, shared by the command-line tools and the benchmark: each method
// is one choice of scheduling (sequential or parallel) and of window resets (exact or approximate).

#include <cstddef>
#include <string>

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

} // namespace vtp_support

#endif // VTP_SUPPORT_METHODS_H
