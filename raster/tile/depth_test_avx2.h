// The early depth test for Float8 groups (AVX2): a group's two memory rows of 4 codes
// loaded, tested and stored at once, and depth-only regions filled 8 pixels a step. Every
// bit equals depth_test.h's.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/simd/intrinsics.h"
#include "raster/tile/depth_test.h"

namespace raster {

template <>
inline void depthCodes<simd::Float8>(simd::Float8 z, TexelFormat format, uint32_t* codes) {
  __m256i result;
  if (format == TexelFormat::Depth24) {
    // z * 16777215.0f, cvtps2dq (round to nearest even); z in [0, 1] cannot overflow.
    result = _mm256_cvtps_epi32(_mm256_mul_ps(z.v, _mm256_set1_ps(16777215.0f)));
  } else {
    // z * (65535/65536)f + 128.0f, low 16 bits of the float.
    const __m256 t = _mm256_add_ps(_mm256_mul_ps(z.v, _mm256_set1_ps(65535.0f / 65536.0f)), _mm256_set1_ps(128.0f));
    result = _mm256_and_si256(_mm256_castps_si256(t), _mm256_set1_epi32(0xFFFF));
  }
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(codes), result);
}

// The test on 8 codes against 8 stored codes: all bits set where the fragment passes.
// Codes are below 2^24, so signed compares are exact and stored + 1 cannot overflow.
// LESS: stored > code; LEQUAL: stored + 1 > code. (LEQUAL written as NOT(code > stored) is
// miscompiled by GCC 12 with AVX-512VL: the NOT, folded into the blend that consumes the
// mask, was dropped in depthOnlyRegion, and raster_vs_gl's depth-only cases failed.)
inline __m256i depthPasses(__m256i code, __m256i stored, bool lessEqual) {
  return lessEqual ? _mm256_cmpgt_epi32(_mm256_add_epi32(stored, _mm256_set1_epi32(1)), code)
                   : _mm256_cmpgt_epi32(stored, code);
}

// The two memory rows of an 8-lane group's depth codes.
struct GroupRows {
  uint32_t* top;      // the group's first memory row
  uint32_t* bottom;   // the next (the same as top on a last odd row: all its lanes are off)
  // All 8 pixels lie inside the framebuffer: then both rows are loaded and stored whole,
  // failing and uncovered lanes storing back what they read (the rows belong to the tile of
  // the calling thread). At the right or top edge, masked loads and stores touch only
  // covered lanes (AMD cores run masked stores as slow microcode, so they are kept for edges).
  bool whole;
  bool flipped;       // the quads' rows are swapped (window-system buffers)
};

// depthTest for an 8-lane group in its two memory rows. Returns the lanes that pass.
inline unsigned depthTestRows(const uint32_t* codes, const GroupRows& rows, unsigned laneMask, const RasterState& state) {
  const bool lessEqual = state.depthFunc == DepthFunc::Lequal;
  const __m256i toRows = simd::quadLanesToRows(rows.flipped), toQuads = simd::rowsToQuadLanes(rows.flipped);
  const __m256i covered = _mm256_permutevar8x32_epi32(_mm256_castps_si256(simd::Mask8::fromBits(laneMask).v), toRows);
  const __m256i code = _mm256_permutevar8x32_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(codes)), toRows);
  const __m128i maskTop = _mm256_castsi256_si128(covered), maskBottom = _mm256_extracti128_si256(covered, 1);
  const __m256i stored =
      rows.whole ? _mm256_setr_m128i(_mm_loadu_si128(reinterpret_cast<const __m128i*>(rows.top)),
                                     _mm_loadu_si128(reinterpret_cast<const __m128i*>(rows.bottom)))
                 : _mm256_setr_m128i(_mm_maskload_epi32(reinterpret_cast<const int*>(rows.top), maskTop),
                                     _mm_maskload_epi32(reinterpret_cast<const int*>(rows.bottom), maskBottom));
  const __m256i pass = _mm256_and_si256(depthPasses(code, stored, lessEqual), covered);
  if (state.depthWrite && rows.whole) {
    const __m256i merged = _mm256_blendv_epi8(stored, code, pass);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(rows.top), _mm256_castsi256_si128(merged));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(rows.bottom), _mm256_extracti128_si256(merged, 1));
  } else if (state.depthWrite) {
    _mm_maskstore_epi32(reinterpret_cast<int*>(rows.top), _mm256_castsi256_si128(pass), _mm256_castsi256_si128(code));
    _mm_maskstore_epi32(reinterpret_cast<int*>(rows.bottom), _mm256_extracti128_si256(pass, 1),
                        _mm256_extracti128_si256(code, 1));
  }
  return unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_permutevar8x32_epi32(pass, toQuads))));
}

// depthTestGroup for Float8 groups, in memory rows.
[[gnu::always_inline]] inline unsigned depthTestGroup(const TileJob& job, const SetupTriangle& tri,
                                                     const LaneLayout<simd::Float8>& layout, GroupAt at, simd::Float8& z) {
  using simd::Float8;
  const Framebuffer& fb = *job.framebuffer;
  const Float8 px = Float8(float(at.x)) + layout.dxLanes;
  const Float8 py = Float8(float(at.y)) + layout.dyLanes;
  z = fragmentDepth(tri, px, py);
  const RasterState& state = job.draws[tri.drawIndex].state;
  if (!state.depthTest || !fb.depth) return at.laneMask;
  uint32_t codes[8];
  depthCodes(clampDepth(z), fb.depth->format, codes);
  uint32_t* top = fb.depth->depth.data() + size_t(at.y) * size_t(fb.width) + size_t(at.x);
  // On a last odd row the second row's lanes are all masked off: no pointer past the buffer.
  const GroupRows rows{top, at.y + 1 < fb.height ? top + fb.width : top, at.x + 4 <= fb.width && at.y + 1 < fb.height,
                       fb.flipY};
  return depthTestRows(codes, rows, at.laneMask, state);
}

#if !RASTER_ZMM_PAIRS   // with AVX-512, one register a block (depth_test_avx512.h)
// Whole 4x4 blocks for AVX2 too: the visibility pass and depth-only draws then test a
// block as two halves in memory-row order (rows 0-1, rows 2-3) with no permutes to and from
// the quads' lane order, and walk blocks instead of groups.
template <>
inline constexpr bool kDepthTestsInBlocks<simd::Float8> = true;

// BlockDepthTest (depth_test.h) in two 8-lane halves: the AVX-512 form's operations, the
// z plane, the buffer and the test held across the triangle's blocks, so the same bits.
template <>
class BlockDepthTest<simd::Float8> : BlockDepthState<simd::Float8> {
 public:
  using BlockDepthState<simd::Float8>::BlockDepthState;

  [[gnu::always_inline]] uint32_t operator()(int blockX, int blockY, uint32_t coverage) const {
    if (!tests_) return coverage;
    using simd::Float8;
    const Float8 px(_mm256_add_ps(_mm256_set1_ps(float(blockX)), _mm256_setr_ps(0, 1, 2, 3, 0, 1, 2, 3)));
    const Float8 pyTop(_mm256_add_ps(_mm256_set1_ps(float(blockY)), _mm256_setr_ps(0, 0, 0, 0, 1, 1, 1, 1)));
    const Float8 pyBottom = pyTop + Float8(2.0f);
    // fragmentDepth and clampDepth, less clampDepth's min(z, 1), as the AVX-512 form.
    const auto code = [&](Float8 py) {
      const Float8 z = simd::min(simd::fma(dady_, py, simd::fma(dadx_, px, a0_)) + depthOffset_, Float8(1.0f));
      return codes(simd::max(z, Float8(0.0f)));
    };
    const __m256i codeTop = code(pyTop), codeBottom = code(pyBottom);
    const __m256i coveredTop = _mm256_castps_si256(simd::Mask8::fromBits(coverage & 0xFFu).v);
    const __m256i coveredBottom = _mm256_castps_si256(simd::Mask8::fromBits(coverage >> 8 & 0xFFu).v);
    uint32_t* const first = buffer_ + size_t(blockY) * size_t(width_) + size_t(blockX);
    const size_t stride = size_t(width_);
    const auto row = [&](int r) { return reinterpret_cast<__m128i*>(first + size_t(r) * stride); };
    if (blockX + 4 <= width_ && blockY + 4 <= height_) {
      // Read whole and written back blended, even where nothing passed (a branch no
      // predictor learns in the visibility pass), as masked stores are slow.
      const __m256i storedTop = _mm256_setr_m128i(_mm_loadu_si128(row(0)), _mm_loadu_si128(row(1)));
      const __m256i storedBottom = _mm256_setr_m128i(_mm_loadu_si128(row(2)), _mm_loadu_si128(row(3)));
      const __m256i passTop = _mm256_and_si256(depthPasses(codeTop, storedTop, lessEqual_), coveredTop);
      const __m256i passBottom = _mm256_and_si256(depthPasses(codeBottom, storedBottom, lessEqual_), coveredBottom);
      if (writes_) {
        const __m256i top = _mm256_blendv_epi8(storedTop, codeTop, passTop);
        const __m256i bottom = _mm256_blendv_epi8(storedBottom, codeBottom, passBottom);
        _mm_storeu_si128(row(0), _mm256_castsi256_si128(top));
        _mm_storeu_si128(row(1), _mm256_extracti128_si256(top, 1));
        _mm_storeu_si128(row(2), _mm256_castsi256_si128(bottom));
        _mm_storeu_si128(row(3), _mm256_extracti128_si256(bottom, 1));
      }
      return bits(passTop) | bits(passBottom) << 8;
    }
    // Where the block sticks out of the framebuffer, rows outside it (never covered) are
    // neither read nor written, and pixels outside it only through masked loads and stores.
    __m128i rowCodes[4], rowMasks[4];
    const __m128i codeRows[4] = {_mm256_castsi256_si128(codeTop), _mm256_extracti128_si256(codeTop, 1),
                                 _mm256_castsi256_si128(codeBottom), _mm256_extracti128_si256(codeBottom, 1)};
    const __m128i maskRows[4] = {_mm256_castsi256_si128(coveredTop), _mm256_extracti128_si256(coveredTop, 1),
                                 _mm256_castsi256_si128(coveredBottom), _mm256_extracti128_si256(coveredBottom, 1)};
    uint32_t passed = 0;
    for (int r = 0; r < 4; ++r) {
      if (!(coverage >> (4 * r) & 0xFu)) continue;
      rowCodes[r] = _mm_maskload_epi32(reinterpret_cast<const int*>(row(r)), maskRows[r]);
      const __m128i pass = _mm_and_si128(
          lessEqual_ ? _mm_cmpgt_epi32(_mm_add_epi32(rowCodes[r], _mm_set1_epi32(1)), codeRows[r])
                     : _mm_cmpgt_epi32(rowCodes[r], codeRows[r]),
          maskRows[r]);
      rowMasks[r] = pass;
      passed |= uint32_t(_mm_movemask_ps(_mm_castsi128_ps(pass))) << (4 * r);
      if (writes_) _mm_maskstore_epi32(reinterpret_cast<int*>(row(r)), rowMasks[r], codeRows[r]);
    }
    return passed;
  }

 private:
  // depthCodes<Float8>, kept in a register.
  [[gnu::always_inline]] __m256i codes(simd::Float8 z) const {
    if (format_ == TexelFormat::Depth24) return _mm256_cvtps_epi32(_mm256_mul_ps(z.v, _mm256_set1_ps(16777215.0f)));
    const __m256 t = _mm256_add_ps(_mm256_mul_ps(z.v, _mm256_set1_ps(65535.0f / 65536.0f)), _mm256_set1_ps(128.0f));
    return _mm256_and_si256(_mm256_castps_si256(t), _mm256_set1_epi32(0xFFFF));
  }
  static uint32_t bits(__m256i pass) { return uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(pass))); }

};

template <>
[[gnu::noinline]] inline void depthOnlyRegion<simd::Float8>(const SetupTriangle& tri, const RasterState& state, Texture& depth, int width,
                                          int x, int y) {
  using simd::Float8;
  const Float8 columns(_mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7));
  for (int row = 0; row < limits::kRegionSize; ++row) {
    const Float8 py(float(y + row));
    uint32_t* dst = depth.depth.data() + size_t(y + row) * size_t(width) + size_t(x);
    for (int column = 0; column < limits::kRegionSize; column += 8) {
      const Float8 px = Float8(float(x + column)) + columns;
      alignas(32) uint32_t codes[8];
      depthCodes(clampDepth(fragmentDepth(tri, px, py)), depth.format, codes);
      const __m256i code = _mm256_load_si256(reinterpret_cast<const __m256i*>(codes));
      __m256i* stored = reinterpret_cast<__m256i*>(dst + column);
      const __m256i old = _mm256_loadu_si256(stored);
      const __m256i pass = depthPasses(code, old, state.depthFunc == DepthFunc::Lequal);
      _mm256_storeu_si256(stored, _mm256_blendv_epi8(old, code, pass));
    }
  }
}
#endif

}  // namespace raster
#endif
