// NEAREST lookups of RGBA8 and depth textures for Float8x2 lanes held in one 512-bit
// register, sixteen lanes at a time: pbr's SSAO reads its depth texture 65 times a pixel
// through sampler2D, and its blur an RGBA8 target 9 times. Inline, so that a port's lookup
// costs no call and no trip of four channel planes through memory, and the shader's compiler
// drops the channels it never reads (both read r only). The wraps and conversions are the
// 8-lane sampler's (sample_color_avx2.cpp: sampleRgba8, sampleRgba8Float and its depth
// branch) on 16 lanes at once, so every value is the same:
//   - RGBA8: each channel as unorm8 * float(1/255). The fixed-point path floors before its
//     CLAMP_TO_EDGE clamp and the float path truncates; the clamp to [0, size - 1] makes the
//     two the same index for every float, NaN included, so wrapNearest16 serves both. A grey
//     copy's texels are the rgba8 texels' r, with a = 255, so rows read as it reads.
//   - depth: code * depthCodeScale in r, (0, 0, 1) in gba (sample_color.cpp's
//     depthTexelChannel).
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include "raster/simd/intrinsics.h"
#include "raster/texture/lane_loads_avx512.h"
#include "raster/texture/lookup_filter.h"
#include "raster/texture/sample_half_avx512.h"
#include "raster/texture/sampler.h"
#include "raster/texture/texture.h"
#include "raster/tile/lane_layout.h"

namespace raster::sampling {

// Whether sampleNearest32Pair is this texture's lookup: a depth texture, or an RGBA8 one
// that keeps its rows (a strip copy alone holds an uploaded LINEAR texture's texels; under
// `lookup=nearest` that texture takes sampleColor8x2).
inline bool isNearest32(const Texture& t) {
  if (lookupFilter(t) != Filter::Nearest) return false;
  return t.isDepth() || (t.format == TexelFormat::RGBA8 && !t.rgba8.empty());
}

// Each lane's texel offset from lane 0's where the sixteen lanes read a 4x4 block of texels
// as raster/tile/lane_layout.h lays a block's pixels out (two 8-lane groups, quads of 2x2,
// memory rows upward): what a post pass reads at its own pixel, or at one a whole number of
// texels away, in an offscreen target.
[[gnu::always_inline]] inline __m512i blockOffsets16(int width) {
  struct Lanes {
    alignas(64) int dx[16];
    alignas(64) int dy[16];
  };
  static constexpr Lanes kLanes = [] {
    Lanes lanes{};
    for (int lane = 0; lane < 16; ++lane) {
      lanes.dx[lane] = LaneLayout<simd::Float8>::originX(lane / 8) + laneDx(lane % 8);
      lanes.dy[lane] = LaneLayout<simd::Float8>::originY(lane / 8) + laneDy(lane % 8);
    }
    return lanes;
  }();
  const __m512i dx = _mm512_load_si512(kLanes.dx), dy = _mm512_load_si512(kLanes.dy);
  return _mm512_add_epi32(_mm512_mullo_epi32(dy, _mm512_set1_epi32(width)), dx);
}

// The 32-bit texels at base[index[lane]], in lane order. Where the lanes read a 4x4 block
// (blockOffsets16), four 16-byte row loads and two shuffles a half take the place of
// sixteen loads: the blur's lookups all do, SSAO's own-pixel lookups too. Every texel of
// the block is some lane's, so the row loads stay inside the texture.
[[gnu::always_inline]] inline __m512i loadTexels32(const uint32_t* base, __m512i index, int width) {
  const int first = _mm_cvtsi128_si32(_mm512_castsi512_si128(index));
  if (_mm512_cmpeq_epi32_mask(index, _mm512_add_epi32(_mm512_set1_epi32(first), blockOffsets16(width))) == 0xFFFF) {
    const uint32_t* block = base + first;
    auto row = [&](int r) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(block + ptrdiff_t(r) * width)); };
    // Rows r and r + 1 in one half's lane order: [r c0, r c1, r+1 c0, r+1 c1, r c2, r c3, r+1 c2, r+1 c3].
    auto half = [&](int r) {
      const __m128i top = row(r), bottom = row(r + 1);
      return _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_unpacklo_epi64(top, bottom)), _mm_unpackhi_epi64(top, bottom), 1);
    };
    return _mm512_inserti64x4(_mm512_castsi256_si512(half(0)), half(2), 1);
  }
  alignas(64) int at[16];
  storeLaneIndices16(index, at);
  return loadSixteenLanes32(base, at);
}

// One 32-bit texel a lane (an RGBA8 texel or a depth code) as float channels.
[[gnu::always_inline]] inline void sampleNearest32Pair(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc,
                                                       simd::Float8x2 out[4]) {
  const __m512i x = wrapNearest16(s.v, t.width, t.sampler.wrapS);
  const __m512i y = wrapNearest16(tc.v, t.height, t.sampler.wrapT);
  const __m512i index = _mm512_add_epi32(_mm512_mullo_epi32(y, _mm512_set1_epi32(t.width)), x);
  if (t.isDepth()) {
    const __m512i code = loadTexels32(t.depth.data(), index, t.width);
    out[0] = simd::Float8x2(_mm512_mul_ps(_mm512_cvtepi32_ps(code), _mm512_set1_ps(depthCodeScale(t))));
    out[1] = out[2] = simd::Float8x2(0.0f);
    out[3] = simd::Float8x2(1.0f);
    return;
  }
  const __m512i texel = loadTexels32(reinterpret_cast<const uint32_t*>(t.rgba8.data()), index, t.width);
  const __m512 kUnorm8 = _mm512_set1_ps(float(1.0 / 255.0));
  for (int c = 0; c < 4; ++c) {
    const __m512i value = _mm512_and_si512(_mm512_srli_epi32(texel, 8 * c), _mm512_set1_epi32(0xFF));
    out[c] = simd::Float8x2(_mm512_mul_ps(_mm512_cvtepi32_ps(value), kUnorm8));
  }
}

}  // namespace raster::sampling
#endif
