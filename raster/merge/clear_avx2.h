// Rows of a clear (clear.cpp), stored around the cache for tiles no triangle of the pass
// reaches, whose texels nothing reads again in the pass. A plain store first reads each
// line for ownership; a streaming store does not, so such a tile costs half the memory
// traffic and leaves the cache to the tiles being drawn.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#endif

namespace raster::merge {

// Stores `bytes` bytes of the repeated 32-byte `pattern` at `row`; the pattern lines up
// with `row`'s first byte. `streaming`: around the cache, where the CPU can and the row is
// aligned for it.
inline void storeRow(unsigned char* row, const unsigned char (&pattern)[32], size_t bytes, bool streaming) {
  size_t i = 0;
#if RASTER_AVX2
  if (streaming && (reinterpret_cast<uintptr_t>(row) & 31u) == 0) {
    const __m256i value = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(pattern));
    for (; i + 32 <= bytes; i += 32) _mm256_stream_si256(reinterpret_cast<__m256i*>(row + i), value);
  }
#endif
  for (; i + 32 <= bytes; i += 32) std::memcpy(row + i, pattern, 32);
  std::memcpy(row + i, pattern, bytes - i);
}

// Orders the streaming stores before anything the thread does next (its next tile, the
// pass's end).
inline void endStreaming() {
#if RASTER_AVX2
  _mm_sfence();
#endif
}

}  // namespace raster::merge
