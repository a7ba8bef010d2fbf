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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_ENGINE_FACE_CROSSINGS_H
#define CGAL_VTP_GEODESICS_INTERNAL_ENGINE_FACE_CROSSINGS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/List_filter.h>
#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/Window.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A window that crossed a face: the list of `halfedge` propagated it across face(halfedge), after the list
// was trimmed by the vertices and pruned pairwise (List_filter.h). In the frame of `halfedge`: its image
// (sx, sy), its distance sigma, its interval [b0, b1]; `origin` as in Window.
struct Face_crossing
{
  Index halfedge;
  Index origin;
  double sx, sy, sigma, b0, b1;
};

// The record of the curves (internal/curves/Curve_field.h): every window a list propagates across a face
// (a recording policy like the path record, Path_record.h, but O(windows propagated), off unless asked for).
//
// Why it makes the field inside a face exact: the geodesic to a point p inside face f enters f through a
// point x of an edge h of f (or comes from a corner, or from a source in f). The windows the lists of h carry
// across f give, together with the corners, the exact distance at every point of h: a window is cut
// (trimmed by a vertex, pruned by another window) only where a corner or another window of the same list
// offers less at the same points of h, and such a path followed by the straight segment to p is at least as
// short as the cut one. Rule 1 (one angle, two sides) only limits the children on the far edges, not the
// windows that cross f. So the least, over the corners of f (their distance plus the segment), the sources
// in f, and the windows that crossed f (each one's distance at p, straight from its image when p is seen
// through its interval, else bent at the nearer end: a real path either way), is the distance at p. Windows
// shorter than the minimum window length are dropped (an error of that order). The tests check it against
// exact targeted runs (test_curves.cpp).
//
// Dominance: a window whose least distance on its interval is above the largest distance over the face of a
// corner (its distance, an upper bound at that time, plus its farthest point of the face) or of a window recorded
// before (its largest value at the three corners: it is convex) is nowhere the least in the face: not recorded.
//
// Filter: with levels (in the engine's unit), a window is kept only if the range of its distance over the
// face may hold one of them: at least its least distance on its interval (sigma - sy if the foot of its image is
// inside, else the lesser of its distances at the ends), at most its largest value over the face (at a corner:
// it is convex) and the face's bound. A face crossed by the isoline at level L keeps every window whose distance
// reaches L inside it, and a window whose whole range is below L there means the face is not crossed. So the
// isolines at those levels come out the same as without the filter (test_curves.cpp checks it).
//
// The bound of each face (the least largest value over the face of its corners, of the windows recorded, and
// of those found below a level all over it: an upper bound of the distance everywhere in the face) is kept
// after the run (bound()): the extraction does not look for a rise of the field above a level in a face that
// is below it all over.
//
// Threads: each thread appends to its own buffer (Propagation_scratch::crossed), which the loops hand over
// with gather() (the sequential loop once, at the end); finish() orders the crossings by face: in the order of
// the appends after a run of one thread (the same in every such run), by half-edge and values after a run of
// several, so that the record does not depend on the order of the threads.
class Face_crossing_record
{
public:
  void start(bool active, const std::vector<double>& levels, Index number_of_faces = 0)
  {
    m_active = active;
    if(active)
      m_face.assign(static_cast<std::size_t>(number_of_faces), Face_state{std::numeric_limits<double>::infinity(), 0});
    else
      m_face.clear();
    m_levels = levels;
    std::sort(m_levels.begin(), m_levels.end());
    m_crossings.clear();
    m_face_begin.clear();
    m_buffers = 0;
  }

  bool is_active() const { return m_active; }
  bool is_filtered() const { return !m_levels.empty(); }
  // the levels of the filter (sorted; empty: every window is kept)
  const std::vector<double>& levels() const { return m_levels; }

  // hook: the (filtered) list `ws` of h, with the distances at the ends of its windows, crosses face(h) = (A, B,
  // C), whose corners are at distances dA, dB, dC now (upper bounds of the final ones)
  // (may run on several threads: writes only to `buffer`, the caller's, and to the bound of face(h), whose
  // lists are propagated by one thread at a time)
  void on_list_crossing(const Halfedge_geometry& g, Index h, const std::vector<Window>& ws,
                        const std::vector<Window_ends>& ends, double dA, double dB, double dC,
                        std::vector<Face_crossing>& buffer)
  {
    if(!m_active)
      return;
    const double L = g.length;
    const double longest = (std::max)(L, (std::max)(g.l_prev, g.l_next));
    if(!m_levels.empty())
    {
      // first the whole list (one pass): its least distance on the edge, and that plus the longest edge, hold no
      // level? (a window's least distance is at least sigma - sy, its image to the line of the edge)
      double least = std::numeric_limits<double>::infinity(), lowest = least, highest = 0.;
      const std::size_t n = ws.size();
      for(std::size_t i = 0; i < n; ++i)
      {
        const double c = (std::min)(ends[i].f0, ends[i].f1);
        least = (std::min)(least, c);
        highest = (std::max)(highest, c);
        lowest = (std::min)(lowest, ws[i].sigma - ws[i].sy);
      }
      lowest = (std::min)(lowest, least);
      const auto it = std::lower_bound(m_levels.begin(), m_levels.end(), lowest);
      if(it == m_levels.end())
        return;
      if(!(*it <= highest + longest))
      {
        // the list is below the level *it all over the face (at most its least value plus the longest edge):
        // where that level is near, the bound tells the extraction that the field does not rise to it in the
        // face (between vertices below it)
        if(*it <= least + 2. * longest)
        {
          double& bound = m_face[static_cast<std::size_t>(Mesh_arrays::face(h))].bound;
          bound = (std::min)(bound, least + longest);
        }
        return;
      }
    }
    Face_state& face = m_face[static_cast<std::size_t>(Mesh_arrays::face(h))];
    double& bound = face.bound;
    // a corner k bounds the distance in the face by its distance plus its farthest point (an edge at k)
    bound = (std::min)({ bound, dA + (std::max)(L, g.l_prev), dB + (std::max)(L, g.l_next),
                         dC + (std::max)(g.l_prev, g.l_next) });
    for(std::size_t i = 0; i < ws.size(); ++i)
    {
      const Window& w = ws[i];
      const double closest = (std::min)(ends[i].f0, ends[i].f1);
      const double lo = w.sx >= w.b0 && w.sx <= w.b1 ? w.sigma - w.sy : closest;
      if(lo > bound * (1. + 1e-12))
        continue;  // above a corner or an earlier window everywhere in the face
      std::vector<double>::const_iterator level;
      if(!m_levels.empty())
      {
        level = std::lower_bound(m_levels.begin(), m_levels.end(), lo);
        if(level == m_levels.end())
          continue;
        if(!(*level <= closest + longest))
        {
          bound = (std::min)(bound, closest + longest);  // (below the level all over the face: as above)
          continue;
        }
      }
      // the window's distance is convex over the face: its largest value is at a corner
      const double high = (std::max)({ ends[i].f0 + w.b0, ends[i].f1 + (L - w.b1), window_distance_at(w, g.cx, g.cy) });
      bound = (std::min)(bound, high);
      if(!m_levels.empty() && !(*level <= bound * (1. + 1e-12)))
        continue;  // (its range over the face, below the bound, holds no level)
      ++face.count;
      buffer.push_back(Face_crossing{h, w.origin, w.sx, w.sy, w.sigma, w.b0, w.b1});
    }
  }

  // hands over the buffer of a thread (serial; the sequential loop once, at the end of the run)
  void gather(std::vector<Face_crossing>& buffer)
  {
    if(m_active)
    {
      ++m_buffers;
      if(m_crossings.empty())
        m_crossings.swap(buffer);
      else
        m_crossings.insert(m_crossings.end(), buffer.begin(), buffer.end());
    }
    buffer.clear();
  }

  // After the run: orders the crossings by face (in the order they were recorded: the same in every run
  // of one thread; of several, by half-edge and values, so that the order of the threads does not matter)
  // and indexes them by face.
  void finish(Index number_of_faces)
  {
    if(!m_active)
      return;
    m_face_begin.assign(static_cast<std::size_t>(number_of_faces) + 1, 0);
    for(std::size_t f = 0; f < m_face.size(); ++f)
      m_face_begin[f + 1] = m_face_begin[f] + m_face[f].count;
    CGAL_assertion(m_face_begin.back() == m_crossings.size());
    std::vector<Face_crossing> sorted(m_crossings.size());
    for(std::size_t f = 0; f < m_face.size(); ++f)
      m_face[f].count = static_cast<std::uint32_t>(m_face_begin[f]);  // (from here: where the next one goes)
    for(const Face_crossing& c : m_crossings)
      sorted[m_face[static_cast<std::size_t>(Mesh_arrays::face(c.halfedge))].count++] = c;
    m_crossings.swap(sorted);
    std::vector<Face_crossing>().swap(sorted);
    for(std::size_t f = 0; f < m_face.size(); ++f)
      m_face[f].count = 0;
    if(m_buffers > 1)
      for(std::size_t f = 0; f + 1 < m_face_begin.size(); ++f)
        std::sort(m_crossings.begin() + static_cast<std::ptrdiff_t>(m_face_begin[f]),
                  m_crossings.begin() + static_cast<std::ptrdiff_t>(m_face_begin[f + 1]),
                  [](const Face_crossing& a, const Face_crossing& b) {
                    return std::tie(a.halfedge, a.sigma, a.sx, a.sy, a.b0, a.b1, a.origin)
                         < std::tie(b.halfedge, b.sigma, b.sx, b.sy, b.b0, b.b1, b.origin);
                  });
  }

  // An upper bound of the distance all over face f (after the run): below it, no curve crosses the face.
  // (+infinity where unknown: a face no list crossed near a level)
  double bound(Index f) const
  {
    return static_cast<std::size_t>(f) < m_face.size() ? m_face[static_cast<std::size_t>(f)].bound
                                                       : std::numeric_limits<double>::infinity();
  }

  // the crossings of face f (after finish())
  const Face_crossing* begin(Index f) const { return m_crossings.data() + m_face_begin[static_cast<std::size_t>(f)]; }
  const Face_crossing* end(Index f) const { return m_crossings.data() + m_face_begin[static_cast<std::size_t>(f) + 1]; }
  std::size_t size() const { return m_crossings.size(); }
  std::size_t bytes() const
  {
    return m_crossings.capacity() * sizeof(Face_crossing) + m_face_begin.capacity() * sizeof(std::size_t);
  }

private:
  bool m_active = false;
  std::vector<double> m_levels;
  struct Face_state
  {
    double bound;         // the least largest value over the face of its corners and recorded windows
    std::uint32_t count;  // the windows recorded
  };
  std::vector<Face_state> m_face;  // during the run
  int m_buffers = 0;               // the buffers gathered
  std::vector<Face_crossing> m_crossings;
  std::vector<std::size_t> m_face_begin;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_ENGINE_FACE_CROSSINGS_H
