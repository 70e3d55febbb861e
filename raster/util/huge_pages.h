// An allocator for large texel arrays that asks the kernel for 2 MiB pages.
//
// Sampling a large texture far apart (minified 2K JPEGs, G-buffers read around each pixel)
// touches a new 4 KiB page on most lookups, so address translation misses as often as the
// cache does. With transparent huge pages set to "madvise" (Debian's default) memory gets
// 2 MiB pages only when asked, before its first touch: this allocator aligns blocks of
// 2 MiB or more to 2 MiB and asks. Where the kernel declines, memory stays in 4 KiB pages
// and nothing else changes.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>

#include <sys/mman.h>

namespace raster {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr size_t kHugePage = size_t(2) << 20;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) {
      if (void* p = std::malloc(bytes ? bytes : 1)) return static_cast<T*>(p);
      throw std::bad_alloc();
    }
    const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (!p) throw std::bad_alloc();
    madvise(p, rounded, MADV_HUGEPAGE);   // advice only: failure leaves 4 KiB pages
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t) { std::free(p); }
  // resize() and the size constructor default-initialise (for texels: leave unwritten), so
  // that a texture's storage is zeroed by one memset (zeroedTexels, texture.h) rather than
  // texel by texel: the -O1 builds (the sanitizers', SIMD off) do not turn that loop into a
  // memset, and under ThreadSanitizer its byte stores were a quarter of the determinism
  // suite. Constructing with a value (assign(n, v), resize(n, v)) is unchanged.
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const { return true; }
};

}  // namespace raster
