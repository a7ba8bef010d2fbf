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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_REFINEMENT_H
#define CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_REFINEMENT_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/internal/curves/Curve_extraction.h>
#include <CGAL/VTP_geodesics/internal/engine/Propagation_engine.h>
#include <CGAL/VTP_geodesics/internal/propagation/Targets.h>

#include <CGAL/tags.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The refinement of isoline points by exact runs (named parameter `exact_refinement`): one run of the engine
// from the same seeds has every point of the curves as a target, recording the offer of each, that is the exact
// image through which its geodesic comes; each point then moves onto the level along that image's circle: inside
// its face along the ray from the image, on an edge along the edge (so the point stays where the curve crosses
// the edge). The image is exact at the point; it stays so at the moved point unless the move leaves the window
// (then the next run corrects it again). Returns the largest |distance - level| seen by the last run (engine
// unit), measured before its moves.
inline double refine_isolines(const Mesh_arrays& m, const std::vector<Seed>& seeds, const std::vector<double>& levels,
                              Propagation_settings settings, int runs, std::vector<Extracted_curve>& curves)
{
  double residual = 0.;
  Propagation_engine engine;
  settings.record_paths = true;
  settings.want_labels = false;
  settings.stop_at_targets = false;
  for(int run = 0; run < runs; ++run)
  {
    std::vector<Target> targets;
    for(const Extracted_curve& c : curves)
      for(const Curve_point& p : c.points)
        targets.push_back(target_from_barycentric(m, p.face, p.b[0], p.b[1], p.b[2]));
    Propagation_statistics unused;
    engine.run<CGAL::Sequential_tag>(m, seeds, std::move(targets), settings, 1, unused);
    const Path_record& record = engine.path_record();
    residual = 0.;
    std::size_t t = 0;
    for(Extracted_curve& c : curves)
    {
      const double level = levels[static_cast<std::size_t>(c.set)];
      for(Curve_point& p : c.points)
      {
        const Offer& o = record.target[t];
        const Target& target = engine.targets()[t++];
        if(!(o.distance < std::numeric_limits<double>::infinity()) || target.vertex != NO_INDEX)
          continue;
        residual = (std::max)(residual, std::abs(o.distance - level));
        const Face_frame fr(m, p.face);
        const double px = target.x[0], py = target.y[0];
        // the image in the frame of the face
        double ix, iy;
        if(o.halfedge == NO_INDEX)
        {
          if(o.origin >= m.nv)
          {
            const Seed& s = seeds[static_cast<std::size_t>(o.origin - m.nv)];
            if(s.kind == Seed::IN_FACE && !s.segment && s.element == p.face)  // (a piece of a curve: no image)
            {
              ix = s.x;
              iy = s.y;
            }
            else
              continue;
          }
          else
          {
            int k = 0;
            while(k < 3 && m.source[3 * p.face + k] != o.origin)
              ++k;
            if(k == 3)
              continue;
            ix = fr.x[k];
            iy = fr.y[k];
          }
        }
        else if(Mesh_arrays::face(o.halfedge) == p.face)
        {
          const bool bent = o.bend == o.bend;
          if(!bent && o.sy > 0.)
            continue;  // a line window (a piece of a curve): no image, the point stays
          fr.from_edge_frame(static_cast<int>(o.halfedge % 3), bent ? o.bend : o.sx, bent ? 0. : o.sy, ix, iy);
        }
        else
          continue;
        const double r = std::hypot(px - ix, py - iy);
        const double base = o.distance - r, radius = level - base;
        if(!(r > 0.) || !(radius > 0.))
          continue;
        int zero = -1;
        for(int k = 0; k < 3; ++k)
          if(p.b[k] == 0.)
            zero = k;
        if(zero < 0)
        {
          const double qx = ix + (px - ix) * radius / r, qy = iy + (py - iy) * radius / r;
          const Curve_point q = Curve_pieces::point_in_face(p.face, fr, qx, qy);
          if(q.b[0] >= 0. && q.b[1] >= 0. && q.b[2] >= 0.)
            p = q;
          continue;
        }
        // on the edge from corner a = zero + 1 to b = zero + 2: |a + s (b - a) - image| = radius, s near p's
        const int a = (zero + 1) % 3, b = (zero + 2) % 3;
        const double ex = fr.x[b] - fr.x[a], ey = fr.y[b] - fr.y[a], wx = fr.x[a] - ix, wy = fr.y[a] - iy;
        const double qa = ex * ex + ey * ey, qb = 2. * (ex * wx + ey * wy), qc = wx * wx + wy * wy - radius * radius;
        const double disc = qb * qb - 4. * qa * qc;
        if(!(qa > 0.) || !(disc >= 0.))
          continue;
        const double s0 = (-qb - std::sqrt(disc)) / (2. * qa), s1 = (-qb + std::sqrt(disc)) / (2. * qa);
        const double now = p.b[b];
        const double s = std::abs(s0 - now) < std::abs(s1 - now) ? s0 : s1;
        if(s >= 0. && s <= 1.)
        {
          p.b[a] = 1. - s;
          p.b[b] = s;
        }
      }
    }
  }
  return residual;
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_CURVES_CURVE_REFINEMENT_H
