// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// How the lsolid process allocates. The mesh stages make and drop large
// vectors on every union and pass (a surface of 1.7 million triangles on
// blog tree B: its triangles, boxes, cells and pairs), and glibc maps blocks
// from 128 KiB up afresh and unmaps them when freed, so each is touched page
// by page again, which a virtual machine makes dear: blog tree B's build
// spent 11.6 s of its 181 s of CPU in the kernel.
#include "memory.hpp"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

namespace lsolid::cli {

void keep_freed_memory() {
  // Blocks up to glibc's largest threshold (32 MiB) come from the heap, and
  // up to 1 GiB freed at its top stays there for the next. The bush of ABOP
  // fig. 1.25 at n = 7, with MALLOC_MMAP_THRESHOLD_ at 32 MiB and
  // MALLOC_TRIM_THRESHOLD_ at 4 GiB in the environment: 13.3 s against
  // 12.6 s (medians of three, alternating), the same peak memory.
  constexpr int kLargestHeapBlock = 32 << 20;
  constexpr int kKeptAtTop = 1 << 30;
  ::mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  ::mallopt(M_TRIM_THRESHOLD, kKeptAtTop);
}

}  // namespace lsolid::cli

// AddressSanitizer brings its own allocation functions, which check that
// what new allocated delete frees: the replacement below is left out there.
#if defined(__SANITIZE_ADDRESS__)
#define LSOLID_OWN_NEW 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LSOLID_OWN_NEW 0
#endif
#endif
#ifndef LSOLID_OWN_NEW
#define LSOLID_OWN_NEW 1
#endif

#if LSOLID_OWN_NEW
namespace {

// Blocks larger than the heap's come from their own mapping; the kernel
// backs such a block with 2 MiB pages where it is asked to (transparent
// huge pages, "madvise" mode as Debian ships it): a fault for every 2 MiB
// instead of every 4 KiB.
constexpr std::size_t kHugePageBlock = std::size_t{32} << 20;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;

void advise_huge_pages(void* block, std::size_t size) {
  const auto begin = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + size) & ~(kHugePage - 1);
  // Advice only: a kernel without huge pages refuses it, and nothing is
  // lost but the speed.
  if (last > first) {
    static_cast<void>(
        ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE));
  }
}

}  // namespace

// The replaceable global allocation function ([new.delete.single]): as the
// standard library's, through malloc, with huge pages asked for large
// blocks. The other forms of new and every delete are the library's, which
// call this one or free.
void* operator new(std::size_t size) {
  for (;;) {
    if (void* block = std::malloc(size == 0 ? 1 : size)) {
      if (size >= kHugePageBlock) advise_huge_pages(block, size);
      return block;
    }
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}
#endif
