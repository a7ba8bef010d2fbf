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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_FIELD_FIELD_QUERIES_H
#define CGAL_VTP_GEODESICS_INTERNAL_FIELD_FIELD_QUERIES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Face_frame.h>
#include <CGAL/VTP_geodesics/internal/mesh/Surface_point.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/field/Curve_field.h>

#include <CGAL/assertions.h>

#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The questions a kept field answers (keep_field): the distance and the nearest source at any point of the
// surface, and the field of the faces that the curves are drawn on (Curve_field.h). Built after a run that kept
// the field (or, for the curves, the trace-back record), from the engine, which must not run again while this
// is in use; in the engine's unit.
class Field_queries
{
public:
  Field_queries(const Mesh_arrays& m, const Propagation_engine& engine, double unit)
    : m_mesh(m), m_cutoff(engine.cutoff()), m_distances(engine.distances())
  {
    for(double& d : m_distances)
      d /= unit;
    const Kept_field& kept = engine.kept_field();
    m_field.reset(new Curve_field(m, engine.path_record(), engine.seeds(), m_distances, engine.labels(),
                                  kept.is_active() ? &kept : nullptr));
  }
  Field_queries(const Field_queries&) = delete;
  Field_queries& operator=(const Field_queries&) = delete;

  const Curve_field& field() const { return *m_field; }
  const std::vector<double>& distances() const { return m_distances; }

  // The distance (engine unit; +infinity where unreached or beyond the distance limit) and the label (NO_INDEX
  // there) at the point p of the surface: at a vertex, those of the run; elsewhere the least candidate of the
  // face (of the first face of an edge point: the field is continuous across the edge).
  std::pair<double, Index> at(const Surface_point& p) const
  {
    const double inf = std::numeric_limits<double>::infinity();
    if(p.kind == Surface_point::AT_VERTEX)
    {
      const double d = m_distances[static_cast<std::size_t>(p.element)];
      return std::make_pair(d, d < inf ? m_field->label(p.element) : NO_INDEX);
    }
    Index f;
    double x, y;
    if(p.kind == Surface_point::IN_FACE)
    {
      f = p.element;
      x = p.x;
      y = p.y;
    }
    else
    {
      f = Mesh_arrays::face(p.element);
      Face_frame(m_mesh, f).from_edge_frame(static_cast<int>(p.element % 3), p.x, 0., x, y);
    }
    m_field->candidates(f, m_candidates);
    int which = -1;
    const double d = Curve_field::value(m_candidates, x, y, NO_INDEX, which);
    if(which < 0 || !(d <= m_cutoff))
      return std::make_pair(inf, NO_INDEX);
    return std::make_pair(d, m_candidates[static_cast<std::size_t>(which)].label);
  }

private:
  const Mesh_arrays& m_mesh;
  double m_cutoff;
  std::vector<double> m_distances;
  std::unique_ptr<Curve_field> m_field;
  mutable std::vector<Curve_candidate> m_candidates;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_FIELD_FIELD_QUERIES_H
