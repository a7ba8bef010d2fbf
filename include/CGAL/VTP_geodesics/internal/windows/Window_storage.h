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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_WINDOW_STORAGE_H
#define CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_WINDOW_STORAGE_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/internal/mesh/Mesh_arrays.h>
#include <CGAL/VTP_geodesics/internal/windows/Window.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// Window lists, one per half-edge, stored in fixed-size blocks linked by indices: windows of a
// list are contiguous inside a block, there is no allocation per window, and memory is recycled
// as soon as a list is propagated. Blocks come from pools (one per thread of the parallel
// scheduling; the sequential scheduling uses pool 0): a pool grows slab by slab (never copied)
// and keeps a free list, so that threads touching different lists never share allocator state.
// A freed block goes to the free list of the pool of the thread that frees it. Everything is
// released by reset(). A half-edge holds only the index of the first block of its list, which
// knows the last one. Blocks hold 8 windows: lists on meshes with many saddle vertices (scans,
// smooth subdivisions, remeshed surfaces) hold about 30 windows, read one block after another.
class Window_storage
{
public:
  static const int BLOCK = 8;

  struct Block
  {
    Window w[BLOCK];
    Index next;
    Index count;
    Index tail;   // in the first block of a list: the last block of the list
  };

  void reset(std::size_t number_of_halfedges, std::size_t number_of_pools = 1)
  {
    CGAL_precondition(number_of_pools >= 1 && number_of_pools <= MAX_POOLS);
    m_head.assign(number_of_halfedges, NO_INDEX);
    m_pools.clear();
    m_pools.resize(number_of_pools);
    m_peak_live = 0;
  }

  // Starts another run when every list is empty (the previous run consumed them all): O(pools), the blocks
  // are kept for reuse; the peak starts again.
  void restart(std::size_t number_of_pools)
  {
    CGAL_precondition(number_of_pools >= 1 && number_of_pools <= MAX_POOLS);
    flush_returns();
    CGAL_assertion_code(long long live = 0; long long in_use = 0;)
    CGAL_assertion_code(for(const Pool& p : m_pools) { live += p.live; in_use += p.in_use; })
    CGAL_assertion(live == 0 && in_use == 0);
    if(m_pools.size() != number_of_pools)
    {
      m_pools.clear();
      m_pools.resize(number_of_pools);
    }
    m_peak_live = 0;
  }

  std::size_t number_of_pools() const { return m_pools.size(); }

  bool empty(Index h) const { return m_head[h] == NO_INDEX; }

  // Appends w to the list of h, with blocks from pool p.
  void push(Index h, const Window& w, std::size_t p = 0) { push(h, &w, &w + 1, p); }

  // Appends the windows [begin, end) to the list of h, with blocks from pool p.
  void push(Index h, const Window* begin, const Window* end, std::size_t p = 0)
  {
    if(begin == end)
      return;
    Index head = m_head[h];
    if(head == NO_INDEX)
    {
      head = allocate(p);
      m_head[h] = head;
      block(head).tail = head;
    }
    Index t = block(head).tail;
    m_pools[p].live += static_cast<long long>(end - begin);
    for(;;)
    {
      Block* blk = &block(t);
      if(blk->count == BLOCK)
      {
        const Index b = allocate(p);
        blk->next = b;
        block(head).tail = b;
        t = b;
        blk = &block(b);
      }
      const std::ptrdiff_t room = BLOCK - blk->count;
      const std::ptrdiff_t n = (std::min)(room, end - begin);
      std::copy(begin, begin + n, blk->w + blk->count);
      blk->count += static_cast<Index>(n);
      begin += n;
      if(begin == end)
        return;
    }
  }

  // Moves the windows of the list of h to the end of `out` and empties the list.
  void take(Index h, std::vector<Window>& out, std::size_t p = 0) { take_chain(detach(h), out, p); }

  // Deletes the windows of the list of h, from the thread that owns pool p.
  void clear(Index h, std::size_t p = 0) { free_chain(detach(h), p); }

  // Detaches the windows of the list of h (the list is empty afterwards) and returns the chain
  // of blocks that holds them, to be read and freed by take_chain().
  Index detach(Index h)
  {
    const Index b = m_head[h];
    m_head[h] = NO_INDEX;
    return b;
  }

  // The pool a chain's first block comes from (the thread that wrote it); `fallback` if empty.
  static std::size_t pool_of_chain(Index chain, std::size_t fallback)
  {
    return chain == NO_INDEX ? fallback : static_cast<std::size_t>(chain) >> POOL_SHIFT;
  }

  // Appends the windows of a detached chain to `out` and frees its blocks (from pool p).
  void take_chain(Index chain, std::vector<Window>& out, std::size_t p)
  {
    for(Index b = chain; b != NO_INDEX;)
    {
      const Block& blk = block(b);
      out.insert(out.end(), blk.w, blk.w + blk.count);
      const Index next = blk.next;
      free_block(b, p);
      b = next;
    }
  }

  // Gives the blocks of a chain back, from the thread that owns pool p. A block goes back to
  // the free list of the pool it came from: directly if that is pool p, otherwise through a
  // return bin of pool p, emptied by flush_returns() at the next sequential step. So no pool
  // keeps growing while another one hoards free blocks.
  void free_chain(Index b, std::size_t p)
  {
    while(b != NO_INDEX)
    {
      const Index next = block(b).next;
      free_block(b, p);
      b = next;
    }
  }

  // Gives the blocks in the return bins back to their pools (call when no other thread works).
  void flush_returns()
  {
    for(Pool& pool : m_pools)
      for(std::size_t owner = 0; owner < m_pools.size(); ++owner)
      {
        Bin& bin = pool.returns[owner];
        if(bin.head == NO_INDEX)
          continue;
        block(bin.tail).next = m_pools[owner].free;
        m_pools[owner].free = bin.head;
        bin.head = bin.tail = NO_INDEX;
      }
  }

  // Number of windows alive; records the peak. The sequential scheduling calls it after every
  // list, the parallel one after every round (its peak is sampled at round boundaries).
  std::size_t update_peaks()
  {
    long long live = 0;
    for(const Pool& p : m_pools)
      live += p.live;
    if(live > static_cast<long long>(m_peak_live))
      m_peak_live = static_cast<std::size_t>(live);
    return static_cast<std::size_t>(live);
  }

  std::size_t peak_live_windows() const { return m_peak_live; }
  // bytes held by the pools (whole slabs), i.e. the peak of this run since pools never shrink
  std::size_t peak_bytes() const
  {
    std::size_t slabs = 0;
    for(const Pool& p : m_pools)
      slabs += p.number_of_slabs;
    return slabs * SLAB * sizeof(Block);
  }

private:
  static const std::size_t SLAB = 512;
  static const std::size_t POOL_SHIFT = 24;  // 16M blocks (2.7 GB) per pool
  static const std::size_t MAX_POOLS = 127;

  static const std::size_t MAX_SLABS = (std::size_t(1) << POOL_SHIFT) / SLAB;

  struct Bin
  {
    Index head = NO_INDEX, tail = NO_INDEX;
  };

  // The table of slabs of a pool has a fixed size, so that adding a slab never moves the
  // pointers that other threads read to reach blocks of this pool.
  struct alignas(64) Pool
  {
    // read by every thread (block()); the counters below, written by the owner, are on other lines
    std::unique_ptr<std::unique_ptr<Block[]>[]> slabs{ new std::unique_ptr<Block[]>[MAX_SLABS] };
    alignas(64) std::size_t number_of_slabs = 0;
    std::size_t number_of_blocks = 0;
    Index free = NO_INDEX;
    long long live = 0;    // may be negative in one pool: blocks can be freed by another thread
    long long in_use = 0;
    Bin returns[MAX_POOLS];  // blocks of other pools freed by this pool's thread (kept in the pool:
                             // a separate allocation could share a cache line with another pool's)
  };

  Block& block(Index b)
  {
    const std::size_t u = static_cast<std::size_t>(b);
    const std::size_t local = u & ((std::size_t(1) << POOL_SHIFT) - 1);
    return m_pools[u >> POOL_SHIFT].slabs[local / SLAB][local % SLAB];
  }
  const Block& block(Index b) const
  {
    const std::size_t u = static_cast<std::size_t>(b);
    const std::size_t local = u & ((std::size_t(1) << POOL_SHIFT) - 1);
    return m_pools[u >> POOL_SHIFT].slabs[local / SLAB][local % SLAB];
  }

  // Gives block b back (see free_chain()).
  void free_block(Index b, std::size_t p)
  {
    Pool& pool = m_pools[p];
    Block& blk = block(b);
    pool.live -= static_cast<long long>(blk.count);
    --pool.in_use;
    const std::size_t owner = static_cast<std::size_t>(b) >> POOL_SHIFT;
    if(owner == p)
    {
      blk.next = pool.free;
      pool.free = b;
    }
    else
    {
      Bin& bin = pool.returns[owner];
      blk.next = bin.head;
      if(bin.head == NO_INDEX)
        bin.tail = b;
      bin.head = b;
    }
  }

  Index allocate(std::size_t p)
  {
    Pool& pool = m_pools[p];
    Index b;
    if(pool.free != NO_INDEX)
    {
      b = pool.free;
      pool.free = block(b).next;
    }
    else
    {
      CGAL_assertion(pool.number_of_blocks < (std::size_t(1) << POOL_SHIFT));
      if(pool.number_of_blocks == pool.number_of_slabs * SLAB)
        pool.slabs[pool.number_of_slabs++].reset(new Block[SLAB]);
      b = static_cast<Index>((p << POOL_SHIFT) | pool.number_of_blocks++);
    }
    Block& blk = block(b);
    blk.next = NO_INDEX;
    blk.count = 0;
    ++pool.in_use;
    return b;
  }

  std::vector<Pool> m_pools;
  std::vector<Index> m_head;   // per half-edge: the first block of its list
  std::size_t m_peak_live = 0;
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_WINDOWS_WINDOW_STORAGE_H
