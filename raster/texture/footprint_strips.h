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
//   cache, and the lines are the time (docs/notes/2026-11-30-footprint-strips.md).
// The strips are 4/3 of the texture and hold every texel, so an uploaded texture keeps
// them instead of its rows (releaseRows): every reader of a texel then finds it through
// rgba8Texel below (the reference sampler, pixel history) or the same unit arithmetic in
// vector form (sample_rgba8_avx2.h, sample_rgba8_avx512.h). The copy is made at upload,
// and the rows come back (restoreRows) when the texture becomes a render target
// (backends/raster_backend.cpp), whose writers write rows. Keeping both had put the deferred
// scene's peak memory at 1920x1080 above llvmpipe's (docs/notes/2026-12-01-peak-memory.md).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>

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
  if (t.rgba8.empty()) return t.hasStripCopy();   // the strips hold the texels already
  t.strips8 = {};
  if (!wantsStripCopy(t)) return false;
  const size_t width = size_t(t.width), strips = stripCount(t.height);
  Texture::zeroedTexels(t.strips8, stripCopyBytes(t));
  for (size_t s = 0; s < strips; ++s)
    for (size_t j = 0; j < size_t(kStripRows) && s * kStripStep + j < size_t(t.height); ++j) {
      const uint8_t* row = &t.rgba8[(s * kStripStep + j) * width * 4];
      for (size_t x = 0; x < width; ++x)
        std::memcpy(&t.strips8[((s * width + x) * kStripRows + j) * 4], row + x * 4, 4);
    }
  return true;
}

// Whether t's texels are in its strip copy alone (releaseRows).
inline bool texelsInStripsOnly(const Texture& t) { return t.hasStripCopy() && t.rgba8.empty(); }

// The 4-byte unit of any texel (x, y) of the texture in the copy: in strip y / 3, or in the
// last strip for a last row that no strip starts at (row 3 of it).
inline size_t stripUnitOfTexel(int width, int height, int x, int y) {
  const size_t strip = std::min(size_t(y) / kStripStep, stripCount(height) - 1);
  return (strip * size_t(width) + size_t(x)) * kStripRows + (size_t(y) - strip * kStripStep);
}

// The four bytes of RGBA8 texel (x, y) of t, from its rows or its strips.
inline const uint8_t* rgba8Texel(const Texture& t, int x, int y) {
  if (!t.rgba8.empty()) return &t.rgba8[(size_t(y) * size_t(t.width) + size_t(x)) * 4];
  return &t.strips8[stripUnitOfTexel(t.width, t.height, x, y) * 4];
}

// Frees t's rows once its strip copy holds the texels; returns the bytes freed.
inline size_t releaseRows(Texture& t) {
  if (!t.hasStripCopy() || t.rgba8.empty()) return 0;
  const size_t bytes = t.rgba8.size();
  decltype(t.rgba8)().swap(t.rgba8);
  return bytes;
}

// Gives t its rows back from the strips, then drops the strips (a texture about to be
// drawn into). The rows take rgba8's bytes again; the caller reserves them first.
inline void restoreRows(Texture& t) {
  if (texelsInStripsOnly(t)) {
    decltype(t.rgba8) rows(size_t(t.width) * size_t(t.height) * 4);
    for (int y = 0; y < t.height; ++y)
      for (int x = 0; x < t.width; ++x)
        std::memcpy(&rows[(size_t(y) * size_t(t.width) + size_t(x)) * 4], rgba8Texel(t, x, y), 4);
    t.rgba8 = std::move(rows);
  }
  decltype(t.strips8)().swap(t.strips8);
}

}  // namespace raster
