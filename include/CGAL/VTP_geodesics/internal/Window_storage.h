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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_WINDOW_STORAGE_H
#define CGAL_VTP_GEODESICS_INTERNAL_WINDOW_STORAGE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/Mesh_arrays.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A window on a half-edge h = (A -> B), in the frame of h (A = (0,0), B = (length,0), the face
// of h above the x-axis). It covers [b0, b1] on the edge and carries the geodesics that come,
// straight in the unfolding, from the (pseudo-)source image (sx, sy), sy <= 0, whose own
// distance to the source is sigma. The distance of a point (x, 0) of the window is
// sigma + sqrt((x - sx)^2 + sy^2). The window is waiting to be propagated into face(h).
struct Window
{
  double b0, b1;
  double sx, sy;
  double sigma;
};

// Window lists, one per half-edge, stored in fixed-size blocks taken from one pool (slabs of
// blocks linked by indices, with a free list): windows of a list are contiguous inside a block,
// there is no allocation per window, and memory is recycled as soon as a list is propagated.
// The pool grows slab by slab (never copied) and is released by reset().
class Window_storage
{
public:
  static const int BLOCK = 4;

  struct Block
  {
    Window w[BLOCK];
    Index next;
    Index count;
  };

  void reset(std::size_t number_of_halfedges)
  {
    m_head.assign(number_of_halfedges, NO_INDEX);
    m_tail.assign(number_of_halfedges, NO_INDEX);
    m_slabs.clear();
    m_number_of_blocks = 0;
    m_free = NO_INDEX;
    m_live = m_peak_live = 0;
    m_blocks_in_use = m_peak_blocks = 0;
  }

  bool empty(Index h) const { return m_head[h] == NO_INDEX; }

  void push(Index h, const Window& w)
  {
    Index t = m_tail[h];
    if(t == NO_INDEX || block(t).count == BLOCK)
    {
      const Index b = allocate();
      if(t == NO_INDEX)
        m_head[h] = b;
      else
        block(t).next = b;
      m_tail[h] = b;
      t = b;
    }
    Block& blk = block(t);
    blk.w[blk.count++] = w;
    if(++m_live > m_peak_live)
      m_peak_live = m_live;
  }

  // Moves the windows of the list of h to the end of `out` and empties the list.
  void take(Index h, std::vector<Window>& out)
  {
    Index b = m_head[h];
    while(b != NO_INDEX)
    {
      Block& blk = block(b);
      out.insert(out.end(), blk.w, blk.w + blk.count);
      m_live -= static_cast<std::size_t>(blk.count);
      const Index nb = blk.next;
      release(b);
      b = nb;
    }
    m_head[h] = m_tail[h] = NO_INDEX;
  }

  // Appends the windows of the list of h to `out`, leaving the list as it is. Only reads the
  // storage, so that several threads may copy different lists at the same time.
  void copy(Index h, std::vector<Window>& out) const
  {
    for(Index b = m_head[h]; b != NO_INDEX; b = block(b).next)
    {
      const Block& blk = block(b);
      out.insert(out.end(), blk.w, blk.w + blk.count);
    }
  }

  // Deletes the windows of the list of h.
  void clear(Index h)
  {
    Index b = m_head[h];
    while(b != NO_INDEX)
    {
      m_live -= static_cast<std::size_t>(block(b).count);
      const Index nb = block(b).next;
      release(b);
      b = nb;
    }
    m_head[h] = m_tail[h] = NO_INDEX;
  }

  std::size_t live_windows() const { return m_live; }
  std::size_t peak_live_windows() const { return m_peak_live; }
  // bytes held by the pool (whole slabs), i.e. the peak of this run since the pool never shrinks
  std::size_t peak_bytes() const { return m_slabs.size() * SLAB * sizeof(Block); }
  std::size_t peak_blocks() const { return m_peak_blocks; }

private:
  Index allocate()
  {
    Index b;
    if(m_free != NO_INDEX)
    {
      b = m_free;
      m_free = block(b).next;
    }
    else
    {
      if(m_number_of_blocks == m_slabs.size() * SLAB)
        m_slabs.emplace_back(new Block[SLAB]);
      b = static_cast<Index>(m_number_of_blocks++);
    }
    block(b).next = NO_INDEX;
    block(b).count = 0;
    if(++m_blocks_in_use > m_peak_blocks)
      m_peak_blocks = m_blocks_in_use;
    return b;
  }

  void release(Index b)
  {
    block(b).next = m_free;
    m_free = b;
    --m_blocks_in_use;
  }

  static const std::size_t SLAB = 512;
  Block& block(Index b) { return m_slabs[static_cast<std::size_t>(b) / SLAB][static_cast<std::size_t>(b) % SLAB]; }
  const Block& block(Index b) const { return m_slabs[static_cast<std::size_t>(b) / SLAB][static_cast<std::size_t>(b) % SLAB]; }

  std::vector<std::unique_ptr<Block[]> > m_slabs;
  std::size_t m_number_of_blocks = 0;
  std::vector<Index> m_head, m_tail;
  Index m_free = NO_INDEX;
  std::size_t m_live = 0, m_peak_live = 0;
  std::size_t m_blocks_in_use = 0, m_peak_blocks = 0;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_WINDOW_STORAGE_H
