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

#ifndef CGAL_VTP_GEODESICS_INTERNAL_MEMORY_HUGE_PAGE_ALLOCATOR_H
#define CGAL_VTP_GEODESICS_INTERNAL_MEMORY_HUGE_PAGE_ALLOCATOR_H

#include <CGAL/license/VTP_geodesics.h>

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace VTP_geodesics {
namespace internal {

// An allocator for large per-vertex arrays written once per run: blocks of 4 MB and more are aligned on
// 2 MB and, on Linux, marked for transparent huge pages (madvise), so that a fresh array costs one page
// fault per 2 MB instead of one per 4 KB (on a virtual machine, about 12 us each: a fifth of a first VSP
// run at 150K vertices). Elsewhere, or where the system does not grant huge pages, it is plain memory.
template <class T>
struct Huge_page_allocator
{
  typedef T value_type;

  Huge_page_allocator() = default;
  template <class U>
  Huge_page_allocator(const Huge_page_allocator<U>&) {}

  static constexpr std::size_t huge_page = std::size_t(2) << 20;

  static bool is_large(std::size_t n)
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    return n >= 2 * huge_page / sizeof(T);
#else
    (void)n;
    return false;
#endif
  }

  T* allocate(std::size_t n)
  {
    if(n > static_cast<std::size_t>(-1) / sizeof(T))
      throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(is_large(n))
    {
      const std::size_t bytes = (n * sizeof(T) + huge_page - 1) / huge_page * huge_page;
      void* p = nullptr;
      if(posix_memalign(&p, huge_page, bytes) != 0 || p == nullptr)
        throw std::bad_alloc();
      madvise(p, bytes, MADV_HUGEPAGE);  // a hint: where it is refused, the memory is plain
      return static_cast<T*>(p);
    }
#endif
    return static_cast<T*>(::operator new(n * sizeof(T)));
  }

  void deallocate(T* p, std::size_t n)
  {
    if(is_large(n))
      std::free(p);
    else
      ::operator delete(p);
  }

  template <class U>
  bool operator==(const Huge_page_allocator<U>&) const { return true; }
  template <class U>
  bool operator!=(const Huge_page_allocator<U>&) const { return false; }
};

} // namespace internal
} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INTERNAL_MEMORY_HUGE_PAGE_ALLOCATOR_H
