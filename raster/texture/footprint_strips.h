// A read-only copy of an RGBA8 texture in overlapping row strips, the layout the 16-lane
// bilinear lookup reads (sample_rgba8_avx512.h).
//
// Strip s holds rows 3s..3s+3, four rows, column by column: the four texels of column x
// are 16 bytes, texel (x, 3s + j) at byte (s * width + x) * 16 + j * 4. Strips overlap by
// a row (row 3s+3 is also strip s+1's first), so the two rows of any bilinear footprint,
// y and y + 1, lie in one strip, s = y / 3. Then:
// - a footprint's column is one 8-byte load (its texel in row y, then in row y + 1), and
//   the footprint two such loads, as the row-major layout's two rows are;
// - a 64-byte cache line holds four columns of a strip, a 4x4 texel block, so a footprint
//   touches one line, or two where its columns straddle a block (x % 4 == 3): 1.25 lines
//   on average, against 2.1 for rows of the row-major layout. Minified without mipmaps, as
//   the G-buffer samples its 1K and 2K material maps, almost every footprint misses the
//   cache, and the lines are the time (BENCHMARKS.md, "Footprint strips").
// The copy is 4/3 of the texture. rgba8 stays whole and is what every writer, every other
// reader and the reference sampler use. The copy is made at upload and dropped when the
// texture becomes a render target (scenes/raster_backend.cpp), as the grey copy is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "raster/simd/isa.h"
#include "raster/texture/texture.h"

namespace raster {

// Whether this build's samplers read strip copies: the 16-lane RGBA8 lookup of AVX-512
// builds. Elsewhere a copy would only take memory, so none is made.
#if RASTER_ZMM_PAIRS && defined(__AVX512BW__)
inline constexpr bool kSamplersReadStrips = true;
#else
inline constexpr bool kSamplersReadStrips = false;
#endif

inline constexpr int kStripStep = 3;   // rows from one strip's first to the next's
inline constexpr int kStripRows = 4;   // rows a strip holds

// Strips of a texture this high: enough for every footprint of two rows y, y + 1 with
// y <= height - 2 (a one-row texture has no such footprint, and so no strips).
inline size_t stripCount(int height) { return height < 2 ? 0 : size_t(height - 2) / kStripStep + 1; }

// The 4-byte unit of texel (x, y) in the copy, for y <= height - 2 (the first row of a
// footprint).
inline size_t stripUnit(int width, int x, int y) {
  const size_t strip = size_t(y) / kStripStep, row = size_t(y) % kStripStep;
  return (strip * size_t(width) + size_t(x)) * kStripRows + row;
}

// Whether t takes a strip copy: RGBA8 texels sampled bilinearly, with no grey copy (that
// one is smaller still, texture.h), and at least two rows.
inline bool wantsStripCopy(const Texture& t) {
  return t.format == TexelFormat::RGBA8 && !t.rgba8.empty() && t.sampler.filter == Filter::Linear && !t.hasGreyCopy() &&
         stripCount(t.height) > 0;
}

// The bytes of t's strip copy, for reserving them before it is made.
inline size_t stripCopyBytes(const Texture& t) { return stripCount(t.height) * size_t(t.width) * kStripRows * 4; }

// Makes t's strip copy if it wants one; returns whether it did. Rows past the last of the
// texture, in the last strip, are zero and never read.
inline bool makeStripCopy(Texture& t) {
  t.strips8 = {};
  if (!wantsStripCopy(t)) return false;
  const size_t width = size_t(t.width), strips = stripCount(t.height);
  t.strips8.assign(stripCopyBytes(t), 0);
  for (size_t s = 0; s < strips; ++s)
    for (size_t j = 0; j < size_t(kStripRows) && s * kStripStep + j < size_t(t.height); ++j) {
      const uint8_t* row = &t.rgba8[(s * kStripStep + j) * width * 4];
      for (size_t x = 0; x < width; ++x)
        std::memcpy(&t.strips8[((s * width + x) * kStripRows + j) * 4], row + x * 4, 4);
    }
  return true;
}

inline void dropStripCopy(Texture& t) { t.strips8 = {}; }

}  // namespace raster
