// Prefetches for lines that loads or stores will reach soon. A tile's rows, and the rows a
// fullscreen pass reads or stores a 4x4 block at a time, are short runs a whole target row
// apart, which the hardware prefetchers do not fetch far enough ahead: each load waited on
// its line, each plain store on its line's read for ownership
// (docs/notes/2026-11-21-what-made-it-faster.md). Callers prefetch a few rows, or a
// kilobyte, ahead.
//
// `asm volatile`, not __builtin_prefetch or _mm_prefetch: GCC 12 at -O3 deleted those from an
// inlined helper that picked the texel array by format (every prefetch gone, no warning).
// `prefetcht0` for stores too, not `prefetchw`: they measured the same, and every x86-64 has
// it. Elsewhere nothing (a hint only).
#pragma once

#include <cstddef>
#include <cstdint>

namespace raster::simd {

// How many rows ahead of its stores a tile's row-by-row writer (a plain clear, the depth
// codes that replace one) prefetches: 2 took the shadow-map pass from 0.84 to 0.77-0.80 ms
// and shadow at 1920x1080 from 2.05-2.10x to 2.17-2.23x llvmpipe (2 threads); 4 gained no
// more.
inline constexpr int kPrefetchRowsAhead = 2;

// How far to the right of a 4x4 block's texel rows a fullscreen pass prefetches the lines
// it will read or store, in texels (1 KiB of RGBA16F, 512 bytes of RGBA8): far enough that a
// line arrives before the blocks that reach it, in the next tile to the right while a tile's
// first block row is worked, ahead of the next block row for the rest. Measured on the
// reads of the first bloom downsample at 16, 32, 64, 128 and 256 texels: the gain stops
// growing at 128; the stores were measured at 128.
inline constexpr size_t kPrefetchTexelsAhead = 128;

// The 64-byte line holding `address`, into every cache level.
inline void prefetchLine(const void* address) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(address)));
#else
  (void)address;
#endif
}

// The 64-byte line holding `address`, into the level-2 cache and those below it, not level 1:
// for texture lookups' scattered footprints (texturePrefetch, sampler.h), fetched hundreds of
// cycles before their loads. On the AMD EPYC Zen 4 host the same prefetches into level 1
// bought a third as much: the deferred G-buffer pass 6.50 -> 5.40 ms with this hint against
// 6.05 ms with prefetcht0, its lighting pass (the environment map's lookups) 5.36 -> 5.06
// (640x480, 2 threads, 6 alternated rounds; docs/notes/2026-12-05-prefetch-to-l2.md).
inline void prefetchLineToL2(const void* address) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht1 %0" : : "m"(*static_cast<const char*>(address)));
#else
  (void)address;
#endif
}

// Every line that `bytes` bytes from `start` touch.
inline void prefetchLines(const void* start, size_t bytes) {
  if (bytes == 0) return;
  const uintptr_t first = reinterpret_cast<uintptr_t>(start), end = first + bytes;
  for (uintptr_t line = first & ~uintptr_t(63); line < end; line += 64)
    prefetchLine(static_cast<const char*>(start) + (line > first ? line - first : 0));
}

// For `rows` texel rows `stride` texels apart, the first starting at texel `first`, the
// line kPrefetchTexelsAhead texels to the right, clamped to texel `last`; four channels a
// texel.
template <class Channel>
inline void prefetchRowsAhead(const Channel* texels, size_t last, size_t first, size_t stride, int rows) {
  for (int r = 0; r < rows; ++r) {
    const size_t texel = first + size_t(r) * stride + kPrefetchTexelsAhead;
    prefetchLine(texels + (texel < last ? texel : last) * 4);
  }
}

}  // namespace raster::simd
