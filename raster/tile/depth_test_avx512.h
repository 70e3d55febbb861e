// The early depth test of a whole 4x4 block in one 512-bit register (AVX-512), for the tests
// that shade nothing and so need no quads: depth-only draws and the visibility pass. Each
// pixel gets the z, clamp and quantization depthTestGroup gives it, is tested against its
// stored code and written where it passes, so the same bits land.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include "raster/simd/intrinsics.h"
#include "raster/tile/coverage.h"
#include "raster/tile/depth_test.h"

namespace raster {

template <>
inline constexpr bool kDepthTestsInBlocks<simd::Float8> = true;

// depthCodes<Float8> and depthPasses for 16 lanes in one register: the same operations per
// lane; the passing lanes among `covered` as a mask.
inline __m512i depthCodes16(simd::Float8x2 z, TexelFormat format) {
  if (format == TexelFormat::Depth24) return _mm512_cvtps_epi32(_mm512_mul_ps(z.v, _mm512_set1_ps(16777215.0f)));
  const __m512 t = _mm512_add_ps(_mm512_mul_ps(z.v, _mm512_set1_ps(65535.0f / 65536.0f)), _mm512_set1_ps(128.0f));
  return _mm512_and_si512(_mm512_castps_si512(t), _mm512_set1_epi32(0xFFFF));
}
inline __mmask16 depthPasses16(__mmask16 covered, __m512i code, __m512i stored, bool lessEqual) {
  return lessEqual ? _mm512_mask_cmpgt_epi32_mask(covered, _mm512_add_epi32(stored, _mm512_set1_epi32(1)), code)
                   : _mm512_mask_cmpgt_epi32_mask(covered, stored, code);
}

// Four rows of 4 lanes as one register (row r in lanes 4r..4r + 3), and back.
inline __m512i joinRows(const __m128i (&rows)[4]) {
  const __m512i low = _mm512_inserti32x4(_mm512_castsi128_si512(rows[0]), rows[1], 1);
  return _mm512_inserti32x4(_mm512_inserti32x4(low, rows[2], 2), rows[3], 3);
}
inline void splitRows(__m512i v, __m128i (&rows)[4]) {
  rows[0] = _mm512_castsi512_si128(v);
  rows[1] = _mm512_extracti32x4_epi32(v, 1);
  rows[2] = _mm512_extracti32x4_epi32(v, 2);
  rows[3] = _mm512_extracti32x4_epi32(v, 3);
}

// The depth test of one 4x4 block in memory-row order (lane row * 4 + col) instead of two
// lane groups, for the blocks of one triangle (BlockDepthTest, depth_test.h): its z plane,
// the buffer and the test are held here, in registers across the blocks, as the buffer's
// stores (through __m128i, which may alias anything) would make the compiler load them from
// the triangle and the job again for every block. Returns the pixels that pass (bit row * 4
// + col).
template <>
class BlockDepthTest<simd::Float8> : BlockDepthState<simd::Float8x2> {
 public:
  using BlockDepthState<simd::Float8x2>::BlockDepthState;

  [[gnu::always_inline]] uint32_t operator()(int blockX, int blockY, uint32_t coverage) const {
    if (!tests_) return coverage;
    using simd::Float8x2;
    const Float8x2 px(_mm512_add_ps(_mm512_set1_ps(float(blockX)), _mm512_setr_ps(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3)));
    const Float8x2 py(_mm512_add_ps(_mm512_set1_ps(float(blockY)), _mm512_setr_ps(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3)));
    // fragmentDepth and clampDepth, the same operations, less clampDepth's min(z, 1):
    // fragmentDepth's z is already at most 1, and not NaN, so that min changes no bit.
    const Float8x2 z = simd::min(simd::fma(dady_, py, simd::fma(dadx_, px, a0_)) + depthOffset_, Float8x2(1.0f));
    const __m512i code = depthCodes16(simd::max(z, Float8x2(0.0f)), format_);
    // The block's four memory rows, read whole and written back blended, as masked stores are
    // slow. This case goes first, straight from memory to registers and back: through the
    // row arrays below, GCC at -O2 kept the rows on the stack.
    if (blockX + 4 <= width_ && blockY + 4 <= height_) {
      uint32_t* const first = buffer_ + size_t(blockY) * size_t(width_) + size_t(blockX);
      const size_t stride = size_t(width_);
      const auto row = [&](int r) { return reinterpret_cast<__m128i*>(first + size_t(r) * stride); };
      const __m512i stored = joinRows({_mm_loadu_si128(row(0)), _mm_loadu_si128(row(1)), _mm_loadu_si128(row(2)),
                                       _mm_loadu_si128(row(3))});
      const __mmask16 pass = depthPasses16(__mmask16(coverage), code, stored, lessEqual_);
      // Written back even where no pixel passed (the same codes then): whether one did is a
      // branch no predictor learns in the visibility pass, where half the blocks fail whole.
      if (writes_) {
        const __m512i blended = _mm512_mask_blend_epi32(pass, stored, code);
        _mm_storeu_si128(row(0), _mm512_castsi512_si128(blended));
        _mm_storeu_si128(row(1), _mm512_extracti32x4_epi32(blended, 1));
        _mm_storeu_si128(row(2), _mm512_extracti32x4_epi32(blended, 2));
        _mm_storeu_si128(row(3), _mm512_extracti32x4_epi32(blended, 3));
      }
      return pass;
    }
    // Where the block sticks out of the framebuffer, rows and pixels outside it (never
    // covered) are neither read nor written.
    uint32_t* rows[4];
    __m128i rowCodes[4];
    for (int r = 0; r < 4; ++r) {
      const __mmask8 covered = __mmask8(coverage >> (4 * r) & 0xFu);
      rows[r] = covered ? buffer_ + size_t(blockY + r) * size_t(width_) + size_t(blockX) : nullptr;
      rowCodes[r] = covered ? _mm_maskz_loadu_epi32(covered, rows[r]) : _mm_setzero_si128();
    }
    const __m512i stored = joinRows(rowCodes);
    const __mmask16 pass = depthPasses16(__mmask16(coverage), code, stored, lessEqual_);
    if (writes_ && pass) {
      splitRows(_mm512_mask_blend_epi32(pass, stored, code), rowCodes);
      for (int r = 0; r < 4; ++r)
        if (rows[r]) _mm_mask_storeu_epi32(rows[r], __mmask8(pass >> (4 * r) & 0xFu), rowCodes[r]);
    }
    return pass;
  }

 private:
};

// depthOnlyRegion (depth_test.h) a 16-pixel region row at a time: its codes, test and
// write in one register each, as BlockDepthTest makes them.
template <>
[[gnu::noinline]] inline void depthOnlyRegion<simd::Float8>(const SetupTriangle& tri, const RasterState& state, Texture& depth,
                                                           int width, int x, int y) {
  using simd::Float8x2;
  static_assert(limits::kRegionSize == 16, "a region row is one register");
  const Float8x2 px = Float8x2(float(x)) + Float8x2(_mm512_setr_ps(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
  const bool lessEqual = state.depthFunc == DepthFunc::Lequal;
  for (int row = 0; row < limits::kRegionSize; ++row) {
    const __m512i code = depthCodes16(clampDepth(fragmentDepth(tri, px, Float8x2(float(y + row)))), depth.format);
    uint32_t* stored = depth.depth.data() + size_t(y + row) * size_t(width) + size_t(x);
    const __m512i old = _mm512_loadu_si512(stored);
    _mm512_storeu_si512(stored, _mm512_mask_blend_epi32(depthPasses16(0xFFFF, code, old, lessEqual), old, code));
  }
}

// depthOnlyStraddledRegion (depth_test.h) a 16-pixel row at a time. Each edge's values at a
// row's 16 pixel centres sit in two registers of 64-bit lanes, stepped by a vector add from
// row to row: exact, as a long edge's values across a region outgrow 32 bits, so the
// coverage bits are blockCoverage's. An edge the whole region lies inside is left out. A
// row's codes, test and write are depthOnlyRegion's, kept to the covered pixels; rows with
// none are not touched unless the region takes its pending clear here. A triangle touches
// each pixel once, so the order does not matter and the same bits land as the block walk's.
template <>
inline constexpr bool kDepthRowsInRegions<simd::Float8> = true;
template <>
[[gnu::noinline]] inline bool depthOnlyStraddledRegion<simd::Float8>(const SetupTriangle& tri, const RasterState& state,
                                                                    Texture& depth, int width, int x, int y,
                                                                    const uint32_t* pendingClear) {
  using simd::Float8x2;
  static_assert(limits::kRegionSize == 16, "a region row is two registers of 64-bit lanes");
  constexpr int kLast = limits::kRegionSize - 1;
  const __m512i lanesLow = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7), lanesHigh = _mm512_setr_epi64(8, 9, 10, 11, 12, 13, 14, 15);
  __m512i low[3], high[3], stepY[3];
  int straddling = 0;
  for (const EdgeFunction& e : tri.edge) {
    // The steps must fit the signed 32-bit multiply below (they do for small steps).
    if (!hasSmallSteps(e)) return false;
    const int64_t c00 = e.at(x, y);
    int64_t most, least;   // over the region's pixels
    edgeExtremes(e, kLast, kLast, most, least);
    if (c00 + least > 0) continue;   // every pixel centre inside this edge
    // c00 - dcdx * lane, with 32 x 32 -> 64-bit products.
    const __m512i dcdx = _mm512_set1_epi64(e.dcdx), start = _mm512_set1_epi64(c00);
    low[straddling] = _mm512_sub_epi64(start, _mm512_mul_epi32(dcdx, lanesLow));
    high[straddling] = _mm512_sub_epi64(start, _mm512_mul_epi32(dcdx, lanesHigh));
    stepY[straddling] = _mm512_set1_epi64(e.dcdy);
    ++straddling;
  }
  const Float8x2 px = Float8x2(float(x)) + Float8x2(_mm512_setr_ps(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
  const bool lessEqual = state.depthFunc == DepthFunc::Lequal;
  const __m512i zero = _mm512_setzero_si512();
  const __m512i clearCodes = _mm512_set1_epi32(int32_t(pendingClear ? *pendingClear : 0));
  for (int row = 0; row < limits::kRegionSize; ++row) {
    __mmask16 covered = 0xFFFF;
    for (int k = 0; k < straddling; ++k) {
      covered &= _mm512_kunpackb(_mm512_cmpgt_epi64_mask(high[k], zero), _mm512_cmpgt_epi64_mask(low[k], zero));
      low[k] = _mm512_add_epi64(low[k], stepY[k]), high[k] = _mm512_add_epi64(high[k], stepY[k]);
    }
    uint32_t* stored = depth.depth.data() + size_t(y + row) * size_t(width) + size_t(x);
    if (!covered) {
      if (pendingClear) _mm512_storeu_si512(stored, clearCodes);
      continue;
    }
    const __m512i code = depthCodes16(clampDepth(fragmentDepth(tri, px, Float8x2(float(y + row)))), depth.format);
    const __m512i old = pendingClear ? clearCodes : _mm512_loadu_si512(stored);
    _mm512_storeu_si512(stored, _mm512_mask_blend_epi32(depthPasses16(covered, code, old, lessEqual), old, code));
  }
  return true;
}

// storeDepthCodes (depth_test.h) sixteen pixels of a row at a time, each code computed as
// BlockDepthTest computes it (the pixels are exact small integers in any lane) and stored
// straight from its register: the 8-lane form went through the stack and a copy.
template <>
inline void storeDepthCodes<simd::Float8>(const SetupTriangle& tri, Texture& depth, int width, const TileBounds& rect) {
  using simd::Float8x2;
  const Float8x2 columns(_mm512_setr_ps(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
  const size_t rowBytes = size_t(rect.x1 + 1 - rect.x0) * sizeof(uint32_t);
  for (int y = rect.y0; y <= rect.y1; ++y) {
    if (y + simd::kPrefetchRowsAhead <= rect.y1)
      simd::prefetchLines(depth.depth.data() + size_t(y + simd::kPrefetchRowsAhead) * size_t(width) + size_t(rect.x0),
                          rowBytes);
    const Float8x2 py = Float8x2(float(y));
    uint32_t* row = depth.depth.data() + size_t(y) * size_t(width);
    for (int x = rect.x0; x <= rect.x1; x += 16) {
      const __m512i codes = depthCodes16(clampDepth(fragmentDepth(tri, Float8x2(float(x)) + columns, py)), depth.format);
      const int left = rect.x1 + 1 - x;
      if (left >= 16) _mm512_storeu_si512(row + x, codes);
      else _mm512_mask_storeu_epi32(row + x, __mmask16((1u << left) - 1u), codes);
    }
  }
}

}  // namespace raster
#endif
