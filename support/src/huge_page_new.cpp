// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The global operator new and delete of the programs that link the object library VTP_geodesics_huge_pages (the
// command-line tools): blocks of 4 MB or more are aligned on 2 MB and advised to the kernel as transparent huge
// pages (madvise(MADV_HUGEPAGE); Linux's default THP mode, "madvise", gives huge pages only to such regions).
//
// Why: from a file to the answer, the tool fills about 100 bytes of fresh arrays per vertex (the mesh, the
// checks, the solver's arrays, the propagation's workspace), and on 4 KB pages each 4 KB is a page fault. On a
// virtual machine a page fault costs several microseconds: on a 253K-vertex mesh, 35,000 faults took more
// time than reading the file (doc/VTP_geodesics/performance.txt, "From file to answer"). With 2 MB pages
// there are 512 times fewer. Smaller blocks are malloc()'s, as before; every block is freed by free() (that of
// posix_memalign() too). Where the kernel refuses the advice (no THP, other systems), the memory is plain.
//
// Not linked into sanitizer builds (the sanitizers replace these functions themselves).

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace {

constexpr std::size_t huge_page = std::size_t(2) << 20;
constexpr std::size_t large_block = 2 * huge_page;

void* allocate(std::size_t n)
{
  if(n == 0)
    n = 1;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if(n >= large_block)
  {
    void* p = nullptr;
    if(posix_memalign(&p, huge_page, n) != 0)
      return nullptr;
    // a hint (where it is refused, the memory is plain), on the whole huge pages of the block only: its last,
    // partly used 2 MB stay on small pages, which the resident memory counts only as they are touched
    madvise(p, n / huge_page * huge_page, MADV_HUGEPAGE);
    return p;
  }
#endif
  return std::malloc(n);
}

void* allocate_or_throw(std::size_t n)
{
  for(;;)
  {
    if(void* p = allocate(n))
      return p;
    const std::new_handler handler = std::get_new_handler();
    if(handler == nullptr)
      throw std::bad_alloc();
    handler();
  }
}

} // namespace

// (the nothrow forms of libstdc++ call these; its aligned forms use aligned_alloc() and free(), which agree)
void* operator new(std::size_t n) { return allocate_or_throw(n); }
void* operator new[](std::size_t n) { return allocate_or_throw(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
