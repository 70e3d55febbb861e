// Coverage of straddled 4x4 blocks with vector compares (AVX2, and AVX-512 where built):
// WalkEdge8, the edge type of Float8 walks. Every bit equals coverage.h's.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include <algorithm>
#include <type_traits>

#include "raster/simd/intrinsics.h"
#include "raster/tile/coverage.h"

namespace raster {

#if RASTER_ZMM_PAIRS
// An edge's offsets from a 4x4 block's first pixel to each of its 16 (lane row * 4 + col):
// dcdy * row - dcdx * col, exact in 32 bits when the edge hasSmallSteps.
[[gnu::always_inline]] inline __m512i blockPixelOffsets16(const EdgeFunction& e) {
  const __m512i col = _mm512_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3);
  const __m512i row = _mm512_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3);
  return _mm512_sub_epi32(_mm512_mullo_epi32(_mm512_set1_epi32(int32_t(e.dcdy)), row),
                          _mm512_mullo_epi32(_mm512_set1_epi32(int32_t(e.dcdx)), col));
}
#endif

// A WalkEdge that also holds, for small steps, the offset from a block's first pixel to
// each of its 16 (bit row * 4 + col): -dcdx * col + dcdy * row, which then fits 32 bits.
struct WalkEdge8 : WalkEdge {
#if RASTER_ZMM_PAIRS
  __m512i pixel16;    // all 16 in one register (blockPixelOffsets16)
#else
  __m256i pixel[2];   // rows 0-1, rows 2-3
#endif
  explicit WalkEdge8(const EdgeFunction& e) : WalkEdge(e) {
    if (!smallSteps) return;
#if RASTER_ZMM_PAIRS
    pixel16 = blockPixelOffsets16(e);
#else
    const __m256i col = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
    const __m256i xTerm = _mm256_mullo_epi32(_mm256_set1_epi32(int32_t(e.dcdx)), col);
    for (int half = 0; half < 2; ++half) {
      const __m256i row = _mm256_add_epi32(_mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1), _mm256_set1_epi32(2 * half));
      pixel[half] = _mm256_sub_epi32(_mm256_mullo_epi32(_mm256_set1_epi32(int32_t(e.dcdy)), row), xTerm);
    }
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

// The bound on the edge values the small-step forms below keep in 32-bit lanes:
// blockCoverageSmallSteps clamps to +-2^30, walkSmallTriangleBlocks applies only within it,
// so a value plus a block's pixel offsets (below 3 * 2^28 with small steps) cannot overflow.
constexpr int64_t kEdgeValueLimit = int64_t(1) << 30;

// blockCoverage without a branch, when every edge has small steps, kept to the pixels of
// `within`: each edge's value at the block's first pixel is clamped to +-2^30 and compared
// with all 16 pixel offsets at once. The offsets stay below 3 * 2^28 in size, so beyond the
// clamp a block lies wholly on one side of the edge either way, and every bit is the one
// blockCoverage gives. With AVX-512 each edge's compare takes the last one's bits as its
// mask, so the three chain in mask registers.
[[gnu::always_inline]] inline uint32_t blockCoverageSmallSteps(const WalkEdge8 (&edges)[3], int blockX, int blockY,
                                                               uint32_t within) {
  auto threshold = [&](const WalkEdge8& e) {
    return int32_t(-std::clamp(e.f.at(blockX, blockY), -kEdgeValueLimit, kEdgeValueLimit));
  };
#if RASTER_ZMM_PAIRS
  __mmask16 mask = __mmask16(within);
  for (const WalkEdge8& e : edges) mask = _mm512_mask_cmpgt_epi32_mask(mask, e.pixel16, _mm512_set1_epi32(threshold(e)));
  return mask;
#else
  uint32_t mask = within;
  for (const WalkEdge8& e : edges) mask &= e.straddledCoverage(-int64_t(threshold(e)));
  return mask;
#endif
}

// The covered blocks of up to four block rows from (blockX0, blockY0), row by row, left to
// right: bit 16 * row + column of `covered` is set where coverage[16 * row + column], the
// block's pixel mask, has a pixel; each goes to visitBlock with the pixels inside the
// framebuffer, if any are.
template <class VisitBlock>
[[gnu::always_inline]] inline void visitCoveredBlocks(const uint16_t (&coverage)[64], uint64_t covered, int blockX0,
                                                      int blockY0, int width, int height, VisitBlock& visitBlock) {
  constexpr int kBlock = limits::kBlockSize;
  for (; covered; covered &= covered - 1) {
    const int bit = __builtin_ctzll(covered);
    const int blockX = blockX0 + (bit % 16) * kBlock, blockY = blockY0 + (bit / 16) * kBlock;
    const uint32_t inside = coverage[bit] & blockBounds(blockX, blockY, width, height);
    if (inside) visitBlock(blockX, blockY, inside);
  }
}

#if RASTER_ZMM_PAIRS
// walkSmallTriangleBlocks (coverage.h) for Float8: it applies where every edge has small
// steps and every edge value over the walked blocks' pixels lies within +-2^30.
//
// Each edge's values at a block's 16 pixels sit in one register, stepped by a vector add
// from block to block, so no value crosses from the integer registers per block. The
// coverage masks of up to four block rows are all found first, then their covered blocks
// visited: a branch per covered block instead of one per block whose outcome waits on the
// compares, and one loop exit per four rows (below). The values are exact
// in 32 bits, so every bit is blockCoverage's; the blocks and their order are the region
// walk's (walk.h), which visits the same blocks row by row, left to right.
template <class F, class VisitBlock>
  requires std::is_same_v<F, simd::Float8>
[[gnu::always_inline]] inline bool walkSmallTriangleBlocks(const EdgeFunction (&edges)[3], int x0, int y0, int x1, int y1,
                                                           int width, int height, VisitBlock&& visitBlock) {
  constexpr int kBlock = limits::kBlockSize;
  const int blockX0 = x0 & ~(kBlock - 1), blockY0 = y0 & ~(kBlock - 1);
  const int columns = (x1 - blockX0) / kBlock + 1, rows = (y1 - blockY0) / kBlock + 1;
  static_assert(limits::kTileSize / kBlock <= 16, "a row's masks are kept in 16 bits");
  __m512i value[3], stepX[3], stepY[3];
  for (int i = 0; i < 3; ++i) {
    const EdgeFunction& e = edges[i];
    if (!hasSmallSteps(e)) return false;
    const int64_t c00 = e.at(blockX0, blockY0);
    int64_t high, low;   // over every pixel of the blocks
    edgeExtremes(e, columns * kBlock - 1, rows * kBlock - 1, high, low);
    if (c00 + high >= kEdgeValueLimit || c00 + low <= -kEdgeValueLimit) return false;
    value[i] = _mm512_add_epi32(blockPixelOffsets16(e), _mm512_set1_epi32(int32_t(c00)));
    stepX[i] = _mm512_set1_epi32(int32_t(-e.dcdx * kBlock));
    stepY[i] = _mm512_set1_epi32(int32_t(e.dcdy * kBlock));
  }
  const __m512i zero = _mm512_setzero_si512();
  // Four block rows at a time: their coverage masks first, then one loop over the covered
  // blocks of all four (bit 16 * row + column), row by row, left to right. One loop exit to
  // mispredict a chunk instead of one a row: the hdr scene's visibility pass, 9 blocks a
  // triangle and tile, took 4-6% less time (docs/notes/2026-12-05-block-walk-and-cold-frames.md).
  for (int firstRow = 0; firstRow < rows; firstRow += 4) {
    const int chunkRows = std::min(4, rows - firstRow);
    uint16_t coverage[64];
    uint64_t covered = 0;
    for (int row = 0; row < chunkRows; ++row) {
      // Three named registers, not an array: at -O2 GCC kept an array's values on the
      // stack, each column's adds then waiting on the last one's stores.
      __m512i at0 = value[0], at1 = value[1], at2 = value[2];
      for (int column = 0; column < columns; ++column) {
        __mmask16 mask = _mm512_cmpgt_epi32_mask(at0, zero);
        mask = _mm512_mask_cmpgt_epi32_mask(mask, at1, zero);
        mask = _mm512_mask_cmpgt_epi32_mask(mask, at2, zero);
        coverage[16 * row + column] = mask;
        covered |= uint64_t(mask != 0) << (16 * row + column);
        at0 = _mm512_add_epi32(at0, stepX[0]), at1 = _mm512_add_epi32(at1, stepX[1]), at2 = _mm512_add_epi32(at2, stepX[2]);
      }
      for (int i = 0; i < 3; ++i) value[i] = _mm512_add_epi32(value[i], stepY[i]);
    }
    visitCoveredBlocks(coverage, covered, blockX0, blockY0 + firstRow * kBlock, width, height, visitBlock);
  }
  return true;
}
#else
// walkSmallTriangleBlocks (coverage.h) for Float8 with AVX2 alone: the AVX-512 walk above
// with each edge's 16 pixel values in two registers (rows 0-1, rows 2-3), held minus one so
// that "value > 0" is "sign bit clear": a block's pixels inside all three edges are the
// lanes whose three values, or-ed, have a clear sign bit (one or and one movemask a half
// where the compares took three compares and two ands). Values stay within +-2^30 (the same
// test as above) so subtracting one cannot overflow, and every bit is blockCoverage's.
// Without it every small triangle took the region walk: per block three 64-bit edge values,
// their clamps and broadcasts, on today's hosts without AVX-512.
template <class F, class VisitBlock>
  requires std::is_same_v<F, simd::Float8>
[[gnu::always_inline]] inline bool walkSmallTriangleBlocks(const EdgeFunction (&edges)[3], int x0, int y0, int x1, int y1,
                                                           int width, int height, VisitBlock&& visitBlock) {
  constexpr int kBlock = limits::kBlockSize;
  const int blockX0 = x0 & ~(kBlock - 1), blockY0 = y0 & ~(kBlock - 1);
  const int columns = (x1 - blockX0) / kBlock + 1, rows = (y1 - blockY0) / kBlock + 1;
  static_assert(limits::kTileSize / kBlock <= 16, "a row's masks are kept in 16 bits");
  __m256i top[3], bottom[3], stepX[3], stepY[3];
  for (int i = 0; i < 3; ++i) {
    const EdgeFunction& e = edges[i];
    if (!hasSmallSteps(e)) return false;
    const int64_t c00 = e.at(blockX0, blockY0);
    int64_t high, low;   // over every pixel of the blocks
    edgeExtremes(e, columns * kBlock - 1, rows * kBlock - 1, high, low);
    if (c00 + high >= kEdgeValueLimit || c00 + low <= -kEdgeValueLimit) return false;
    const __m256i col = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
    const __m256i row = _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1);
    const __m256i first = _mm256_add_epi32(_mm256_sub_epi32(_mm256_mullo_epi32(_mm256_set1_epi32(int32_t(e.dcdy)), row),
                                                            _mm256_mullo_epi32(_mm256_set1_epi32(int32_t(e.dcdx)), col)),
                                           _mm256_set1_epi32(int32_t(c00 - 1)));
    top[i] = first;
    bottom[i] = _mm256_add_epi32(first, _mm256_set1_epi32(int32_t(e.dcdy * 2)));
    stepX[i] = _mm256_set1_epi32(int32_t(-e.dcdx * kBlock));
    stepY[i] = _mm256_set1_epi32(int32_t(e.dcdy * kBlock));
  }
  // Four block rows at a time, as the AVX-512 walk above.
  for (int firstRow = 0; firstRow < rows; firstRow += 4) {
    const int chunkRows = std::min(4, rows - firstRow);
    uint16_t coverage[64];
    uint64_t covered = 0;
    for (int row = 0; row < chunkRows; ++row) {
      // Named registers, not arrays (as above: GCC kept an array's values on the stack).
      __m256i t0 = top[0], t1 = top[1], t2 = top[2], b0 = bottom[0], b1 = bottom[1], b2 = bottom[2];
      for (int column = 0; column < columns; ++column) {
        const uint32_t outTop = uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(t0, t1), t2))));
        const uint32_t outBottom =
            uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(b0, b1), b2))));
        const uint32_t mask = ~(outTop | outBottom << 8) & 0xFFFFu;
        coverage[16 * row + column] = uint16_t(mask);
        covered |= uint64_t(mask != 0) << (16 * row + column);
        t0 = _mm256_add_epi32(t0, stepX[0]), t1 = _mm256_add_epi32(t1, stepX[1]), t2 = _mm256_add_epi32(t2, stepX[2]);
        b0 = _mm256_add_epi32(b0, stepX[0]), b1 = _mm256_add_epi32(b1, stepX[1]), b2 = _mm256_add_epi32(b2, stepX[2]);
      }
      for (int i = 0; i < 3; ++i) top[i] = _mm256_add_epi32(top[i], stepY[i]), bottom[i] = _mm256_add_epi32(bottom[i], stepY[i]);
    }
    visitCoveredBlocks(coverage, covered, blockX0, blockY0 + firstRow * kBlock, width, height, visitBlock);
  }
  return true;
}
#endif

}  // namespace raster
#endif
