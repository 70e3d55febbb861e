// TileTriangles for Float8 groups (visible_first.h): a group's two rows of 4 entries, 8
// entries of its block's line, marked and read in one register each way, and (AVX-512) a
// 4x4 block's pixels marked from its depth test's mask with one load, blend and store. Same
// entries as the reference.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#include "raster/tile/visible_first.h"

namespace raster {

template <>
inline void TileTriangles<simd::Float8>::mark(int lx, int ly, unsigned passed, uint32_t index) {
  __m256i* at = reinterpret_cast<__m256i*>(entries_ + entryIndex(lx, ly));
  markGroup(lx, ly, passed != 0);
  // The group's two rows of four, read, blended, written.
  const __m256i old = _mm256_load_si256(at);
  const __m256i lanes = _mm256_castps_si256(simd::Mask8::fromBits(passed).v);
  const __m256i rows = _mm256_permutevar8x32_epi32(lanes, simd::quadLanesToRows(flipY_));
  _mm256_store_si256(at, _mm256_blendv_epi8(old, _mm256_set1_epi32(int(index)), rows));
}

#if RASTER_ZMM_PAIRS
template <>
inline void TileTriangles<simd::Float8>::markBlock(int lx, int ly, uint32_t passed, uint32_t index) {
  // mark() for the block's upper group and its lower one, without a branch: a block none of
  // whose pixels passed writes its line back as it was (read, blended and written: masked
  // stores are slow).
  for (int half = 0; half < 2; ++half) markGroup(lx, ly + 2 * half, (passed >> (8 * half) & 0xFFu) != 0);
  __m512i* at = reinterpret_cast<__m512i*>(entries_ + entryIndex(lx, ly));
  _mm512_store_si512(at, _mm512_mask_blend_epi32(__mmask16(passed), _mm512_load_si512(at), _mm512_set1_epi32(int(index))));
}
#else
template <>
inline void TileTriangles<simd::Float8>::markBlock(int lx, int ly, uint32_t passed, uint32_t index) {
  // The AVX-512 form in two halves of the block's line (rows 0-1, rows 2-3), read, blended
  // and written without a branch.
  for (int half = 0; half < 2; ++half) markGroup(lx, ly + 2 * half, (passed >> (8 * half) & 0xFFu) != 0);
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

template <>
template <class Shade>
void TileTriangles<simd::Float8>::forEachVisible(Shade&& shade) const {
  const __m256i toLanes = simd::rowsToQuadLanes(flipY_);
  for (int row = 0; row < kTile / 2; ++row) {
    for (uint32_t bits = marked_[row]; bits; bits &= bits - 1) {
      const int lx = __builtin_ctz(bits) * kGroupWidth, ly = row * 2;
      visible_first_detail::visitGroup(entries_ + entryIndex(lx, ly), toLanes, lx, ly, shade);
    }
  }
}

template <>
template <class Shade, class Whole>
void TileTriangles<simd::Float8>::forEachVisible(Shade&& shade, Whole&& whole) const {
  const __m256i toLanes = simd::rowsToQuadLanes(flipY_);
  for (int blockRow = 0; blockRow < kTile / 4; ++blockRow) {
    const uint32_t upper = marked_[2 * blockRow], lower = marked_[2 * blockRow + 1];
    const int ly = 4 * blockRow;
    for (uint32_t bits = upper | lower; bits; bits &= bits - 1) {
      const uint32_t bit = bits & (0u - bits);
      const int lx = __builtin_ctz(bits) * kGroupWidth;
      if (upper & lower & bit) {   // both groups marked: does one triangle show in all 16?
        const uint32_t* at = entries_ + entryIndex(lx, ly);
#if RASTER_ZMM_PAIRS
        const __m512i block = _mm512_load_si512(at);
        if (at[0] != kNone && _mm512_cmpneq_epi32_mask(block, _mm512_set1_epi32(int(at[0]))) == 0 && whole(lx, ly, at[0]))
          continue;
#else
        const __m256i first = _mm256_set1_epi32(int(at[0]));
        const __m256i same = _mm256_and_si256(_mm256_cmpeq_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(at)), first),
                                              _mm256_cmpeq_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(at + 8)), first));
        if (at[0] != kNone && _mm256_movemask_ps(_mm256_castsi256_ps(same)) == 0xFF && whole(lx, ly, at[0])) continue;
#endif
      }
      if (upper & bit) visible_first_detail::visitGroup(entries_ + entryIndex(lx, ly), toLanes, lx, ly, shade);
      if (lower & bit) visible_first_detail::visitGroup(entries_ + entryIndex(lx, ly + 2), toLanes, lx, ly + 2, shade);
    }
  }
}

}  // namespace raster
#endif
