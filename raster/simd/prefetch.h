// Prefetches for lines that stores will write soon: a tile's rows, and the rows a fullscreen
// pass stores a block at a time, are short runs a whole target row apart, which the hardware
// prefetchers do not fetch ahead, so each plain store waited on its line's read for
// ownership (BENCHMARKS.md, "What made it faster"). Callers prefetch a few rows, or a
// kilobyte, ahead of their stores.
//
// `asm volatile`, not __builtin_prefetch or _mm_prefetch: GCC 12 at -O3 deleted those from an
// inlined helper that picked the texel array by format (every prefetch gone, no warning).
// `prefetcht0`, not `prefetchw`: they measured the same, and every x86-64 has it. Elsewhere
// nothing (a hint only).
#pragma once

#include <cstddef>

namespace raster::simd {

// How many rows ahead of its stores a tile's row-by-row writer (a plain clear, the depth
// codes that replace one) prefetches: 2 took the shadow-map pass from 0.84 to 0.77-0.80 ms
// and shadow at 1920x1080 from 2.05-2.10x to 2.17-2.23x llvmpipe (2 threads); 4 gained no
// more.
inline constexpr int kPrefetchRowsAhead = 2;

inline void prefetchForWrite(const void* line) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(line)));
#else
  (void)line;
#endif
}

// Every 64-byte line of `bytes` bytes from `start`.
inline void prefetchLinesForWrite(const void* start, size_t bytes) {
  for (size_t i = 0; i < bytes; i += 64) prefetchForWrite(static_cast<const char*>(start) + i);
}

}  // namespace raster::simd
