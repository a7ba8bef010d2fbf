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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_FIELD_KEPT_FIELD_H
#define CGAL_VTP_GEODESICS_INTERNAL_FIELD_KEPT_FIELD_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/memory/Huge_page_allocator.h>
#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// A piece of the kept field: a window that crossed a face. The list of `halfedge` propagated it across
// face(halfedge), after the list was trimmed by the vertices and pruned pairwise (List_filter.h). In the frame
// of `halfedge`: its image (sx, sy), its distance sigma, its interval [b0, b1]; `origin` as in Window.
struct Field_piece
{
  Index halfedge;
  Index origin;
  double sx, sy, sigma, b0, b1;
};

// A block of pieces: up to 6 MB, on transparent huge pages where the system grants them (one page fault per
// 2 MB instead of one per 4 KB).
typedef std::vector<Field_piece, Huge_page_allocator<Field_piece> > Field_piece_block;

// The pieces one thread records during a run, in blocks (no block is moved once written: no copy as the record
// grows, and the blocks of the threads are handed over by moving them). The first block of a run holds 4,096
// pieces and each next one twice as many, up to BLOCK: a small run takes little memory.
class Field_piece_buffer
{
public:
  static constexpr int BLOCK_BITS = 17;
  static constexpr std::size_t BLOCK = std::size_t(1) << BLOCK_BITS;

  void push(const Field_piece& p)
  {
    if(m_current.size() == m_capacity)
    {
      if(m_capacity > 0)
        m_full.push_back(std::move(m_current));
      m_capacity = m_capacity == 0 ? std::size_t(4096) : (std::min)(2 * m_capacity, BLOCK);
      m_current = Field_piece_block();
      m_current.reserve(m_capacity);
    }
    m_current.push_back(p);
  }
  void clear()
  {
    m_full.clear();
    m_current = Field_piece_block();
    m_capacity = 0;
  }
  // moves every block (full or not) to the end of `blocks`
  void hand_over(std::vector<Field_piece_block>& blocks)
  {
    for(auto& b : m_full)
      blocks.push_back(std::move(b));
    if(!m_current.empty())
      blocks.push_back(std::move(m_current));
    clear();
  }

private:
  std::vector<Field_piece_block> m_full;
  Field_piece_block m_current;
  std::size_t m_capacity = 0;  // of m_current
};

// The kept field (named parameter keep_field): every window that a list propagates across a face, indexed by
// face after the run. A recording policy like the path record (paths/Path_record.h): O(windows propagated),
// off unless asked for; exact methods only (VTP, PVTP: the resets of AVTP / PAVTP replace windows by fewer,
// approximate ones, and VSP has none).
//
// Why the field inside a face is exact from it: the geodesic to a point p inside face f enters f through a
// point x of an edge h of f (or comes from a corner, or from a source in f). The windows the lists of h carry
// across f give, together with the corners, the exact distance at every point of h: a window is cut (trimmed
// by a vertex, pruned by another window of its list, List_filter.h) only where a corner or another window of
// the same list offers as little or less at the same points of h, and such a path followed by the straight
// segment to p is at least as short as the cut one. Rule 1 (one angle, two sides) only limits the children on
// the far edges, not the windows that cross f. So the least, over the corners of f (their distance plus the
// segment), the sources in f, and the windows that crossed f (each one's distance at p, straight from its
// image when p is seen through its interval, else bent at the nearer end: a real path either way), is the
// distance at p. Windows shorter than the minimum window length are dropped (an error of that order).
//
// Why every crossing is kept, not only the lower envelope: a window that is the least candidate at a point
// of the face is the least at the point where its path enters (a part of a shortest path is one), so a window
// that is never the least on its own interval can be dropped (field/Field_envelope.h decides it); measured on
// the elephant and on camel Loop 2 (doc/VTP_geodesics/curves.txt), 97.6% and 99.2% of the windows that cross a
// face are the least somewhere on their interval, by 1e-7 to 1e-3 of the largest distance: the envelope is
// nearly all of them, and the test would cost more than it saves.
//
// Threads: each thread appends to its own buffer (Propagation_scratch::crossed), which the loops hand over with
// gather(); finish() indexes the pieces by face: in the order of the appends after a run of one thread (the
// same in every such run), by half-edge and values after a run of several, so that the field does not depend
// on the order of the threads.
class Kept_field
{
public:
  void start(bool active, Index number_of_faces = 0)
  {
    m_active = active;
    m_blocks.clear();
    m_blocks.shrink_to_fit();
    m_order.clear();
    m_order.shrink_to_fit();
    m_face_begin.clear();
    m_face_begin.shrink_to_fit();
    m_buffers = 0;
    m_faces = active ? number_of_faces : 0;
  }

  bool is_active() const { return m_active; }

  // hook: the (filtered) list `ws` of h crosses face(h) (may run on several threads: writes only to `buffer`,
  // the caller's)
  void on_list_crossing(Index h, const std::vector<Window>& ws, Field_piece_buffer& buffer) const
  {
    if(!m_active)
      return;
    for(const Window& w : ws)
      buffer.push(Field_piece{ h, w.origin, w.sx, w.sy, w.sigma, w.b0, w.b1 });
  }

  // hands over the buffer of a thread (serial; the sequential loop once, at the end of the run)
  void gather(Field_piece_buffer& buffer)
  {
    if(m_active)
    {
      const std::size_t before = m_blocks.size();
      buffer.hand_over(m_blocks);
      if(m_blocks.size() > before)
        ++m_buffers;
    }
    else
      buffer.clear();
  }

  // After the run: indexes the pieces by face (in the order they were recorded, the same in every run of one
  // thread; after a run of several, by half-edge and values, so that the order of the threads does not matter).
  void finish()
  {
    if(!m_active)
      return;
    std::size_t total = 0;
    for(const auto& b : m_blocks)
      total += b.size();
    CGAL_precondition(m_blocks.size() < (std::size_t(1) << (32 - Field_piece_buffer::BLOCK_BITS)));
    m_face_begin.assign(static_cast<std::size_t>(m_faces) + 1, 0);
    for(const auto& b : m_blocks)
      for(const Field_piece& p : b)
        ++m_face_begin[static_cast<std::size_t>(Mesh_arrays::face(p.halfedge)) + 1];
    for(std::size_t f = 0; f < static_cast<std::size_t>(m_faces); ++f)
      m_face_begin[f + 1] += m_face_begin[f];
    CGAL_assertion(m_face_begin.back() == total);
    m_order.resize(total);
    std::vector<std::size_t> next(m_face_begin.begin(), m_face_begin.end() - 1);
    for(std::size_t i = 0; i < m_blocks.size(); ++i)
      for(std::size_t j = 0; j < m_blocks[i].size(); ++j)
        m_order[next[static_cast<std::size_t>(Mesh_arrays::face(m_blocks[i][j].halfedge))]++]
          = static_cast<std::uint32_t>((i << Field_piece_buffer::BLOCK_BITS) | j);
    if(m_buffers > 1)
      for(std::size_t f = 0; f < static_cast<std::size_t>(m_faces); ++f)
        std::sort(m_order.begin() + static_cast<std::ptrdiff_t>(m_face_begin[f]),
                  m_order.begin() + static_cast<std::ptrdiff_t>(m_face_begin[f + 1]),
                  [this](std::uint32_t i, std::uint32_t j) {
                    const Field_piece& a = piece(i);
                    const Field_piece& b = piece(j);
                    return std::tie(a.halfedge, a.sigma, a.sx, a.sy, a.b0, a.b1, a.origin)
                         < std::tie(b.halfedge, b.sigma, b.sx, b.sy, b.b0, b.b1, b.origin);
                  });
  }

  // the pieces of face f (after finish()): piece(order()[i]) for i in [first(f), last(f))
  std::size_t first(Index f) const { return m_face_begin[static_cast<std::size_t>(f)]; }
  std::size_t last(Index f) const { return m_face_begin[static_cast<std::size_t>(f) + 1]; }
  const Field_piece& piece_of_face(std::size_t i) const { return piece(m_order[i]); }
  std::size_t size() const { return m_order.size(); }
  std::size_t number_of_faces() const { return static_cast<std::size_t>(m_faces); }
  // the bytes the field holds (its pieces, their order and the index by face)
  std::size_t bytes() const
  {
    std::size_t b = m_order.capacity() * sizeof(std::uint32_t) + m_face_begin.capacity() * sizeof(std::size_t);
    for(const auto& block : m_blocks)
      b += block.capacity() * sizeof(Field_piece);
    return b;
  }

private:
  const Field_piece& piece(std::uint32_t i) const
  {
    return m_blocks[i >> Field_piece_buffer::BLOCK_BITS][i & (Field_piece_buffer::BLOCK - 1)];
  }

  bool m_active = false;
  Index m_faces = 0;
  int m_buffers = 0;                                // the threads' buffers that held pieces
  std::vector<Field_piece_block> m_blocks;  // the pieces, in blocks of at most Field_piece_buffer::BLOCK
  std::vector<std::uint32_t, Huge_page_allocator<std::uint32_t> > m_order;  // block << BLOCK_BITS | position, by face
  std::vector<std::size_t> m_face_begin;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_FIELD_KEPT_FIELD_H
