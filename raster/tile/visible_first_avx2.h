// TileTriangles for Float8 groups (visible_first.h), whose depth tests run a 4x4 block at a
// time (kDepthTestsInBlocks): a block's pixels marked from its depth test's mask with one
// load, blend and store of its line (AVX2: two halves), and a group's two rows of 4 entries,
// 8 entries of its block's line, read in one register. Same entries as the reference.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#include "raster/tile/visible_first.h"

namespace raster {

// The block's line is written without a branch, as a blend of its old line (GCC makes it
// one masked store with AVX-512; a branch on whether any pixel passed measured slower:
// docs/notes/2026-12-08-scene-pass-by-part.md). No group bits are kept (forEachVisible reads
// the entries themselves).
#if RASTER_ZMM_PAIRS
template <>
inline void TileTriangles<simd::Float8>::markBlock(int lx, int ly, uint32_t passed, uint32_t index) {
  __m512i* at = reinterpret_cast<__m512i*>(entries_ + entryIndex(lx, ly));
  _mm512_store_si512(at, _mm512_mask_blend_epi32(__mmask16(passed), _mm512_load_si512(at), _mm512_set1_epi32(int(index))));
}
#else
template <>
inline void TileTriangles<simd::Float8>::markBlock(int lx, int ly, uint32_t passed, uint32_t index) {
  // The AVX-512 form in two halves of the block's line (rows 0-1, rows 2-3).
  __m256i* at = reinterpret_cast<__m256i*>(entries_ + entryIndex(lx, ly));
  const __m256i value = _mm256_set1_epi32(int(index));
  for (int half = 0; half < 2; ++half) {
    const __m256i take = _mm256_castps_si256(simd::Mask8::fromBits(passed >> (8 * half) & 0xFFu).v);
    _mm256_store_si256(at + half, _mm256_blendv_epi8(_mm256_load_si256(at + half), value, take));
  }
}
#endif

namespace visible_first_detail {

// One Float8 group's entries, its two rows of four from `at`: shade(lx, ly, index,
// laneMask) once per triangle they name, the lanes in quad order.
template <class Shade>
[[gnu::always_inline]] inline void visitGroup(const uint32_t* at, __m256i toLanes, int lx, int ly, Shade&& shade) {
  alignas(32) uint32_t lanes[8];
  const __m256i rows = _mm256_load_si256(reinterpret_cast<const __m256i*>(at));
  const __m256i v = _mm256_permutevar8x32_epi32(rows, toLanes);
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), v);
  const __m256i none = _mm256_cmpeq_epi32(v, _mm256_set1_epi32(-1));
  unsigned remaining = ~unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(none))) & 0xFFu;
  while (remaining) {
    const uint32_t index = lanes[__builtin_ctz(remaining)];
    const __m256i same = _mm256_cmpeq_epi32(v, _mm256_set1_epi32(int(index)));
    const unsigned laneMask = unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(same)));
    remaining &= ~laneMask;
    shade(lx, ly, index, laneMask);
  }
}

}  // namespace visible_first_detail

namespace visible_first_detail {

// Which of a block's 16 entries (bit row * 4 + col) name a triangle, from its line at `at`.
[[gnu::always_inline]] inline uint32_t shownPixels(const uint32_t* at) {
#if RASTER_ZMM_PAIRS
  return _mm512_cmpneq_epi32_mask(_mm512_load_si512(at), _mm512_set1_epi32(-1));
#else
  const __m256i none = _mm256_set1_epi32(-1);
  const auto half = [&](int h) {
    const __m256i v = _mm256_load_si256(reinterpret_cast<const __m256i*>(at + 8 * h));
    return uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(v, none))));
  };
  return ~(half(0) | half(1) << 8) & 0xFFFFu;
#endif
}

// Whether all 16 entries of a block's line name the triangle its first one names.
[[gnu::always_inline]] inline bool oneTriangle(const uint32_t* at) {
#if RASTER_ZMM_PAIRS
  return _mm512_cmpneq_epi32_mask(_mm512_load_si512(at), _mm512_set1_epi32(int(at[0]))) == 0;
#else
  const __m256i first = _mm256_set1_epi32(int(at[0]));
  const __m256i same = _mm256_and_si256(_mm256_cmpeq_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(at)), first),
                                        _mm256_cmpeq_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(at + 8)), first));
  return _mm256_movemask_ps(_mm256_castsi256_ps(same)) == 0xFF;
#endif
}

}  // namespace visible_first_detail

// The blocks in rows, left to right; a block's groups, upper then lower. Which show a
// triangle is read from their entries (an entry other than kNone) rather than kept in
// marked_ by markBlock: that took two read-modify-writes of the bit words a tested block,
// and without them the hdr scene pass took 3% less time at 640x480 and 6% less at
// 1920x1080 (2 threads, two builds alternated: docs/notes/2026-12-08-scene-pass-by-part.md),
// for a compare a block when the tile is read.
template <>
template <class Shade, class Whole>
void TileTriangles<simd::Float8>::forEachVisible(Shade&& shade, Whole&& whole) const {
  using namespace visible_first_detail;
  const __m256i toLanes = simd::rowsToQuadLanes(flipY_);
  for (int ly = 0; ly < kTile; ly += kBlock) {
    for (int lx = 0; lx < kTile; lx += kBlock) {
      const uint32_t* at = entries_ + entryIndex(lx, ly);   // rows 0-1, then rows 2-3 (at + 8)
      const uint32_t shown = shownPixels(at);
      if (shown == 0) continue;
      if (shown == 0xFFFFu && oneTriangle(at) && whole(lx, ly, at[0])) continue;   // one triangle shows in all 16
      if (shown & 0xFFu) visitGroup(at, toLanes, lx, ly, shade);
      if (shown >> 8) visitGroup(at + 8, toLanes, lx, ly + 2, shade);
    }
  }
}

}  // namespace raster
#endif
