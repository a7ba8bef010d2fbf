// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The registration of vtp_geodesics._core: its attributes and method table here, each topic's names in its
// file (see core_solver.h for which file holds what).

#include "core_solver.h"

#include <vtp_support/statistics.h>

namespace {

// The support layer's method table, one dict per method.
pybind11::list method_table()
{
  pybind11::list l;
  for(const vtp_support::Method_info* m = vtp_support::methods_begin(); m != vtp_support::methods_end(); ++m)
  {
    pybind11::dict d;
    d["name"] = m->name;
    d["parallel"] = m->parallel;
    d["approximate"] = m->approximate;
    d["description"] = m->description;
    d["available"] = vtp_support::method_available(*m);
    l.append(d);
  }
  return l;
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  namespace vp = vtp_python;
  m.doc() = "The compiled layer of vtp_geodesics (use the package vtp_geodesics, not this module).";
  pybind11::class_<vp::Core_solver> solver(m, "Solver");
  vp::define_solver(solver);
  vp::define_queries(solver);
  vp::define_matrices(solver);
  vp::define_sampling(solver);
  vp::define_straightest(solver);
  vp::define_log_map(solver);
  vp::define_curves(solver);
  vp::define_field(solver);
  vp::define_patches(solver);
  vp::define_source_curves(solver);
  vp::define_io(m);
  m.def("method_table", &method_table);
  m.attr("recommended_lambda") = vtp_support::default_lambda;
  m.attr("openmp") = vtp_support::parallel_methods_available();
  // the keys of Solver.statistics: the library's statistics, then the stages from the file to the answer, from
  // their one description (vtp_support/statistics.h), then the solver's own build time
  pybind11::list keys;
  const CGAL::VTP_geodesics::Propagation_statistics none;
  vtp_support::for_each_statistic(none, [&](const char* name, const auto&, vtp_support::Statistic_unit) {
    keys.append(name);
  });
  vtp_support::for_each_stage(vtp_support::Stage_seconds(), [&](const char* name, double, vtp_support::Statistic_unit) {
    keys.append(name);
  });
  keys.append("mesh_build_seconds");
  m.attr("statistics_keys") = pybind11::tuple(keys);
}
