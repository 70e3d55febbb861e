// Coverage of straddled 4x4 blocks with vector compares (AVX2, and AVX-512 where built):
// WalkEdge8, the edge type of Float8 walks. Every bit equals coverage.h's.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#include "raster/tile/coverage.h"

namespace raster {

// A WalkEdge that also holds, for small steps, the offset from a block's first pixel to
// each of its 16 (bit row * 4 + col): -dcdx * col + dcdy * row, which then fits 32 bits.
struct WalkEdge8 : WalkEdge {
  __m256i pixel[2];   // rows 0-1, rows 2-3
#if RASTER_ZMM_PAIRS
  __m512i pixel16;    // both in one register
#endif
  explicit WalkEdge8(const EdgeFunction& e) : WalkEdge(e) {
    if (!smallSteps) return;
    const __m256i col = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
    const __m256i xTerm = _mm256_mullo_epi32(_mm256_set1_epi32(int32_t(e.dcdx)), col);
    for (int half = 0; half < 2; ++half) {
      const __m256i row = _mm256_add_epi32(_mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1), _mm256_set1_epi32(2 * half));
      pixel[half] = _mm256_sub_epi32(_mm256_mullo_epi32(_mm256_set1_epi32(int32_t(e.dcdy)), row), xTerm);
    }
#if RASTER_ZMM_PAIRS
    pixel16 = _mm512_inserti64x4(_mm512_castsi256_si512(pixel[0]), pixel[1], 1);
#endif
  }

  uint32_t straddledCoverage(int64_t c00) const {
    if (!smallSteps) return WalkEdge::straddledCoverage(c00);
    // Straddling: |c00| < 3 * 2^28, so -c00 fits 32 bits too.
#if RASTER_ZMM_PAIRS
    return _mm512_cmpgt_epi32_mask(pixel16, _mm512_set1_epi32(int32_t(-c00)));
#else
    const __m256i threshold = _mm256_set1_epi32(int32_t(-c00));
    auto rows = [&](int half) {
      return uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpgt_epi32(pixel[half], threshold))));
    };
    return rows(0) | rows(1) << 8;
#endif
  }
};

template <>
struct EdgeWalkOf<simd::Float8> {
  using type = WalkEdge8;
};

// blockCoverage without a branch, when every edge has small steps: each edge's value at the
// block's first pixel is clamped to +-2^30 and compared with all 16 pixel offsets at once.
// The offsets stay below 3 * 2^28 in size, so beyond the clamp a block lies wholly on one
// side of the edge either way, and every bit is the one blockCoverage gives.
[[gnu::always_inline]] inline uint32_t blockCoverageSmallSteps(const WalkEdge8 (&edges)[3], int blockX, int blockY) {
  constexpr int64_t kLimit = int64_t(1) << 30;
  uint32_t mask = 0xFFFFu;
  for (const WalkEdge8& e : edges) mask &= e.straddledCoverage(std::clamp(e.f.at(blockX, blockY), -kLimit, kLimit));
  return mask;
}

}  // namespace raster
#endif
