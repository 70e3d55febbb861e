// An allocator whose value-less construct() default-initialises, so that a std::vector of a
// trivial type grows by resize() without zeroing what it adds.
//
// The renderer sizes the pass's lists for a large draw before its setup chunks write their
// windows of them in parallel (renderer.cpp, geometry/setup.h). A plain vector would first
// zero those megabytes on one thread, only for the chunks to overwrite them (at 2 threads
// such zeroing was 0.13 ms of a 5.4 ms hdr frame), and would touch the pages of the holes
// culled primitives leave, which nothing reads. Every element that is read is written first.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace raster {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// A vector whose resize() leaves new elements default-initialised (for a trivial T:
// unwritten), for lists that are grown and then filled.
template <class T>
using GrowableList = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace raster
