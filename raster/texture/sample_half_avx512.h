// NEAREST lookups of RGBA16F textures for Float8x2 lanes held in one 512-bit register: the
// G-buffer reads of SSAO and lighting, sixteen lanes at a time. Inline, so that a port's
// lookup costs no call and the shader's compiler drops the channels it never reads (SSAO
// uses xyz); with the lookups of sample_color_avx2.cpp the SSAO pass took 13% longer.
// The wraps and the F16C conversion are the 8-lane sampler's (sample_color_avx2.cpp,
// sampleHalfNearest) on 16 lanes at once, so every value is the same.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include "raster/simd/intrinsics.h"
#include "raster/texture/texture.h"

namespace raster::sampling {

// The texel index along one axis for NEAREST, as the 8-lane wrapNearest of the float path
// (no floor before the CLAMP_TO_EDGE clamp): REPEAT of a power-of-two size masks the
// floored coordinate, of another size scales the fraction (at most 0.99999994, NaN too);
// both clamp a truncated index to [0, size - 1].
[[gnu::always_inline]] inline __m512i wrapNearest16(__m512 coord, int size, Wrap wrap) {
  const __m512 sizeF = _mm512_set1_ps(float(size));
  const __m512i last = _mm512_set1_epi32(size - 1);
  if (wrap == Wrap::Repeat && size > 0 && (size & (size - 1)) == 0)
    return _mm512_and_si512(_mm512_cvttps_epi32(_mm512_floor_ps(_mm512_mul_ps(coord, sizeF))), last);
  if (wrap == Wrap::Repeat) {
    const __m512 fraction = _mm512_min_ps(_mm512_sub_ps(coord, _mm512_floor_ps(coord)), _mm512_set1_ps(0.99999994f));
    coord = fraction;
  }
  const __m512i index = _mm512_cvttps_epi32(_mm512_mul_ps(coord, sizeF));
  return _mm512_min_epi32(_mm512_max_epi32(index, _mm512_setzero_si512()), last);
}

// sampleHalfNearest for two groups at once: one gather of eight 64-bit texels per group
// (masked by `live`: dead lanes read as zero), converted and transposed straight into
// Float8x2 planes, with about a third of the shuffles that transposing each group and
// joining the halves takes. The texture must be RGBA16F.
[[gnu::always_inline]] inline void sampleHalfNearestPair(const Texture& t, simd::Float8x2 s, simd::Float8x2 tc,
                                                         __mmask16 live, simd::Float8x2 out[4]) {
  const __m512i x = wrapNearest16(s.v, t.width, t.sampler.wrapS);
  const __m512i y = wrapNearest16(tc.v, t.height, t.sampler.wrapT);
  const __m512i index = _mm512_add_epi32(_mm512_mullo_epi32(y, _mm512_set1_epi32(t.width)), x);
  const long long* texels = reinterpret_cast<const long long*>(t.half.data());
  const __m256i halves[2] = {_mm512_castsi512_si256(index), _mm512_extracti64x4_epi64(index, 1)};   // lanes 0-7, 8-15
  __m512 v[4];   // texels of lanes 4k..4k + 3, r g b a each
  for (int h = 0; h < 2; ++h) {
    const __m512i texel =
        _mm512_mask_i32gather_epi64(_mm512_setzero_si512(), __mmask8(live >> (8 * h)), halves[h], texels, 8);
    v[2 * h] = _mm512_cvtph_ps(_mm512_castsi512_si256(texel));
    v[2 * h + 1] = _mm512_cvtph_ps(_mm512_extracti64x4_epi64(texel, 1));
  }
  // [r of lanes 0-7 | g of lanes 0-7] from v[0] and v[1], [b | a] likewise, and the same
  // for lanes 8-15; then each channel's two halves joined.
  const __m512i redGreen = _mm512_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28, 1, 5, 9, 13, 17, 21, 25, 29);
  const __m512i blueAlpha = _mm512_setr_epi32(2, 6, 10, 14, 18, 22, 26, 30, 3, 7, 11, 15, 19, 23, 27, 31);
  const __m512 rg0 = _mm512_permutex2var_ps(v[0], redGreen, v[1]), rg1 = _mm512_permutex2var_ps(v[2], redGreen, v[3]);
  const __m512 ba0 = _mm512_permutex2var_ps(v[0], blueAlpha, v[1]), ba1 = _mm512_permutex2var_ps(v[2], blueAlpha, v[3]);
  out[0] = simd::Float8x2(_mm512_shuffle_f32x4(rg0, rg1, _MM_SHUFFLE(1, 0, 1, 0)));
  out[1] = simd::Float8x2(_mm512_shuffle_f32x4(rg0, rg1, _MM_SHUFFLE(3, 2, 3, 2)));
  out[2] = simd::Float8x2(_mm512_shuffle_f32x4(ba0, ba1, _MM_SHUFFLE(1, 0, 1, 0)));
  out[3] = simd::Float8x2(_mm512_shuffle_f32x4(ba0, ba1, _MM_SHUFFLE(3, 2, 3, 2)));
}

// Whether sampleHalfNearestPair is this texture's lookup.
inline bool isHalfNearest(const Texture& t) {
  return t.format == TexelFormat::RGBA16F && t.sampler.filter == Filter::Nearest;
}

}  // namespace raster::sampling
#endif
