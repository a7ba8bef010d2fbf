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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_LIST_FILTER_H
#define CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_LIST_FILTER_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Pair_pruning.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// The filtering of one window list before it crosses its face (filter_list()): the trimming of each
// window by the distances of the two ends of its edge (ICH), and the pairwise pruning of the windows of
// the list (Rule 2). Pure functions of their arguments, as the propagation of Triangle_propagation.h.

// Pointwise domination by the endpoint vertices (the ICH filter, applied as trimming): on an edge
// X -> Y of length L, the part of the window where sigma + |S q| > d(X) + |X q| (a prefix, since
// |S q| - |X q| does not increase away from X) or sigma + |S q| > d(Y) + |Y q| (a suffix) carries
// no shortest path: every point beyond is reached at least as fast through X or Y. A line window offers
// sigma + sx q, |sx| < 1: the same holds, and the ends are roots of linear equations.
// Returns false when nothing is left; otherwise `e` holds the distances at the new ends.
template <bool line>
inline bool trim_by_vertices_of(Window& w, Window_ends& e, double L, double dX, double dY)
{
  e.f0 = distance_of<line>(w, w.b0);
  e.f1 = distance_of<line>(w, w.b1);
  // prefix dominated by X
  if(e.f1 > dX + w.b1)
    return false;
  if(e.f0 > dX + w.b0)
  {
    const double D = dX - w.sigma;
    const double den = line ? 1. - w.sx : 2. * (w.sx + D);
    double t = !(den > 0.) ? w.b0 : line ? -D / den : (w.sx * w.sx + w.sy * w.sy - D * D) / den;
    if(!(t > w.b0)) t = w.b0;
    if(t > w.b1) t = w.b1;
    if(t != w.b0)
    {
      w.b0 = t;
      e.f0 = distance_of<line>(w, t);
    }
  }
  // suffix dominated by Y
  if(e.f0 > dY + (L - w.b0))
    return false;
  if(e.f1 > dY + (L - w.b1))
  {
    double nb1;
    if constexpr(line)
    {
      // sigma + sx x > dY + L - x beyond (dY + L - sigma) / (1 + sx)
      const double den = 1. + w.sx;
      nb1 = den > 0. ? (dY + L - w.sigma) / den : w.b1;
    }
    else
    {
      const double rx = L - w.sx;
      const double D = dY - w.sigma;
      const double den = 2. * (rx + D);
      const double t = (den > 0.) ? (rx * rx + w.sy * w.sy - D * D) / den : (L - w.b1);
      nb1 = L - t;
    }
    if(!(nb1 < w.b1)) nb1 = w.b1;
    if(nb1 < w.b0) nb1 = w.b0;
    if(nb1 != w.b1)
    {
      w.b1 = nb1;
      e.f1 = distance_of<line>(w, nb1);
    }
  }
  return w.b1 > w.b0;
}

// (the kind of w tested once)
inline bool trim_by_vertices(Window& w, Window_ends& e, double L, double dX, double dY)
{
  return is_line(w) ? trim_by_vertices_of<true>(w, e, L, dX, dY) : trim_by_vertices_of<false>(w, e, L, dX, dY);
}

inline bool trim_by_vertices(Window& w, double L, double dX, double dY)
{
  Window_ends e;
  return trim_by_vertices(w, e, L, dX, dY);
}

// Whether a window of a list being filtered is still alive (filter_list() marks the windows
// it cuts away by making them shorter than `min_length`).
inline bool is_alive(const Window& w, double min_length) { return w.b1 - w.b0 > min_length; }

// Scratch memory of filter_list() and propagate_list(), kept from list to list (one per thread).
struct List_scratch
{
  std::vector<Window_ends> ends;
  std::vector<Index> active;
  std::vector<double> xc;
  std::vector<Window> buffer;
  std::vector<Window_piece> pieces;
};

// Sorts a list by the starts of its windows. A list is made of a few batches of children, each
// in the order of the starts already (geodesics do not cross): a list of one or two such runs is
// merged in linear time.
inline void sort_by_start(std::vector<Window>& ws, std::vector<Window>& buffer)
{
  const std::size_t n = ws.size();
  std::size_t m = 1;
  while(m < n && !(ws[m].b0 < ws[m - 1].b0))
    ++m;
  if(m >= n)
    return;
  std::size_t e = m + 1;
  while(e < n && !(ws[e].b0 < ws[e - 1].b0))
    ++e;
  const auto by_start = [](const Window& x, const Window& y) { return x.b0 < y.b0; };
  if(e < n)
  {
    std::sort(ws.begin(), ws.end(), by_start);
    return;
  }
  buffer.resize(n);
  std::merge(ws.begin(), ws.begin() + static_cast<std::ptrdiff_t>(m),
             ws.begin() + static_cast<std::ptrdiff_t>(m), ws.end(), buffer.begin(), by_start);
  ws.swap(buffer);
}

// Filters a list before propagation: vertex trimming (ICH), tiny windows, pairwise pruning. The
// list is left sorted by the starts (up to the few starts that trimming moves), followed by the
// right parts of the windows cut in two (sorted too), with the distances at the ends of its
// windows in scratch.ends. During the filtering, a window that is cut away
// stays in place, shorter than `min_length` (see is_alive()); it is dropped at the end.
// (`mixed`: the list may hold line windows; a list of point windows only is filtered without testing their kind)
template <bool mixed>
inline void filter_list_of(std::vector<Window>& ws, double L, double dA, double dB, double min_length,
                           List_scratch& scratch)
{
  const std::size_t n = ws.size();
  sort_by_start(ws, scratch.buffer);
  std::vector<Window_ends>& ends = scratch.ends;
  ends.resize(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    Window& w = ws[i];
    const bool kept = mixed ? trim_by_vertices(w, ends[i], L, dA, dB) : trim_by_vertices_of<false>(w, ends[i], L, dA, dB);
    if(!kept || !is_alive(w, min_length))
      w.b1 = w.b0 - 1.;
  }
  // Sweep in the order of the starts (trimming may have moved a few of them: skipping a pair is
  // always safe, pruning only removes redundant coverage), with the windows that still reach
  // beyond the current start: most lists are nearly disjoint, so few pairs are examined.
  // The right parts of windows cut in two are appended to the list when the sweep reaches their
  // start.
  std::vector<Index>& active = scratch.active;
  std::vector<Window_piece>& pieces = scratch.pieces;
  active.clear();
  pieces.clear();
  for(std::size_t next = 0;;)
  {
    std::size_t i;
    if(!pieces.empty() && (next == n || !(ws[next].b0 < pieces.front().w.b0)))
    {
      std::pop_heap(pieces.begin(), pieces.end(), starts_later);
      ws.push_back(pieces.back().w);
      ends.push_back(pieces.back().e);
      pieces.pop_back();
      i = ws.size() - 1;
    }
    else if(next < n)
      i = next++;
    else
      break;
    Window& w = ws[i];
    if(!(w.b1 > w.b0))
      continue;
    Window_ends& ew = ends[i];
    std::size_t kept = 0;
    for(std::size_t j = 0; j < active.size(); ++j)
    {
      const Index a = active[j];
      Window& v = ws[static_cast<std::size_t>(a)];
      if(w.b1 > w.b0 && v.b1 > w.b0)
        prune_pair<mixed>(v, ends[static_cast<std::size_t>(a)], w, ew, pieces);
      if(v.b1 > v.b0 && v.b1 > w.b0)
        active[kept++] = a;
    }
    active.resize(kept);
    if(w.b1 > w.b0)
      active.push_back(static_cast<Index>(i));
  }
  // drop the windows cut away (most lists lose none)
  std::size_t k = 0;
  const std::size_t total = ws.size();
  while(k < total && is_alive(ws[k], min_length))
    ++k;
  for(std::size_t i = k; i < total; ++i)
    if(is_alive(ws[i], min_length))
    {
      ws[k] = ws[i];
      ends[k] = ends[i];
      ++k;
    }
  ws.resize(k);
  ends.resize(k);
}

// (`lines`: the list may hold line windows, i.e. a source of the run is a curve)
inline void filter_list(std::vector<Window>& ws, double L, double dA, double dB, double min_length,
                        List_scratch& scratch, bool lines = true)
{
  if(lines)
    filter_list_of<true>(ws, L, dA, dB, min_length, scratch);
  else
    filter_list_of<false>(ws, L, dA, dB, min_length, scratch);
}

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_LIST_FILTER_H
