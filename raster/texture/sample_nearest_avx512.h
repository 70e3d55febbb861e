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
#include "raster/texture/lookup_filter.h"
#include "raster/texture/sample_half_avx512.h"
#include "raster/texture/sampler.h"
#include "raster/texture/texture.h"

namespace raster::sampling {

// Whether sampleNearest32Pair is this texture's lookup: a depth texture, or an RGBA8 one
// that keeps its rows (a strip copy alone holds an uploaded LINEAR texture's texels; under
// `lookup=nearest` that texture takes sampleColor8x2).
inline bool isNearest32(const Texture& t) {
  if (lookupFilter(t) != Filter::Nearest) return false;
  return t.isDepth() || (t.format == TexelFormat::RGBA8 && !t.rgba8.empty());
}

// One 32-bit texel a lane (an RGBA8 texel or a depth code), gathered, as float channels.
[[gnu::always_inline]] inline void sampleNearest32Pair(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc,
                                                       simd::Float8x2 out[4]) {
  const __m512i x = wrapNearest16(s.v, t.width, t.sampler.wrapS);
  const __m512i y = wrapNearest16(tc.v, t.height, t.sampler.wrapT);
  const __m512i index = _mm512_add_epi32(_mm512_mullo_epi32(y, _mm512_set1_epi32(t.width)), x);
  if (t.isDepth()) {
    const __m512i code = _mm512_i32gather_epi32(index, t.depth.data(), 4);
    out[0] = simd::Float8x2(_mm512_mul_ps(_mm512_cvtepi32_ps(code), _mm512_set1_ps(depthCodeScale(t))));
    out[1] = out[2] = simd::Float8x2(0.0f);
    out[3] = simd::Float8x2(1.0f);
    return;
  }
  const __m512i texel = _mm512_i32gather_epi32(index, t.rgba8.data(), 4);
  const __m512 kUnorm8 = _mm512_set1_ps(float(1.0 / 255.0));
  for (int c = 0; c < 4; ++c) {
    const __m512i value = _mm512_and_si512(_mm512_srli_epi32(texel, 8 * c), _mm512_set1_epi32(0xFF));
    out[c] = simd::Float8x2(_mm512_mul_ps(_mm512_cvtepi32_ps(value), kUnorm8));
  }
}

}  // namespace raster::sampling
#endif
