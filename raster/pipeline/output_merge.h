// Stage 6 helpers, the output merge's conversions for a whole lane group at once:
// depth quantization, and colour packing to RGBA8 or RGBA16F texels.
//
// Each function has a plain per-lane version (the reference: the scalar conversions of
// format/conversions.h lane by lane) and, for Float8, an AVX2 version that computes the
// same bits; tests/output_merge_test.cpp holds them to agree on every class of input.
#pragma once

#include <cstdint>

#include "raster/format/conversions.h"
#include "raster/framebuffer/texture.h"
#include "raster/simd/glsl.h"

namespace raster::output_merge {

// Depth codes of clamped window z per lane (z already clamped to [0, 1], NaN -> 0).
template <class F>
void depthCodes(F z, TexelFormat format, uint32_t* codes) {
  alignas(32) float lanes[F::kCount];
  z.store(lanes);
  for (int i = 0; i < F::kCount; ++i)
    codes[i] = format == TexelFormat::Depth24 ? format::depth24FromFloat(lanes[i]) : format::depth16FromFloat(lanes[i]);
}

// RGBA8 texels (r in the low byte, as stored in memory) per lane.
template <class F>
void packRgba8(const glsl::vec4<F>& color, uint32_t* texels) {
  alignas(32) float c[4][F::kCount];
  color.x.store(c[0]);
  color.y.store(c[1]);
  color.z.store(c[2]);
  color.w.store(c[3]);
  for (int i = 0; i < F::kCount; ++i) {
    texels[i] = 0;
    for (int ch = 0; ch < 4; ++ch) texels[i] |= uint32_t(format::unorm8FromFloat(c[ch][i])) << (8 * ch);
  }
}

#if RASTER_AVX2
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

template <>
inline void packRgba8<simd::Float8>(const glsl::vec4<simd::Float8>& color, uint32_t* texels) {
  // min(1, x) keeps NaN (minps returns its second operand), * 255, cvtps2dq (NaN -> INT_MIN),
  // clamp to [0, 255]: the same as unorm8FromFloat per channel.
  auto channel = [](__m256 x) {
    const __m256 clamped = _mm256_min_ps(_mm256_set1_ps(1.0f), x);
    const __m256i scaled = _mm256_cvtps_epi32(_mm256_mul_ps(clamped, _mm256_set1_ps(255.0f)));
    return _mm256_min_epi32(_mm256_max_epi32(scaled, _mm256_setzero_si256()), _mm256_set1_epi32(255));
  };
  const __m256i r = channel(color.x.v), g = channel(color.y.v), b = channel(color.z.v), a = channel(color.w.v);
  const __m256i rgba = _mm256_or_si256(_mm256_or_si256(r, _mm256_slli_epi32(g, 8)),
                                       _mm256_or_si256(_mm256_slli_epi32(b, 16), _mm256_slli_epi32(a, 24)));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(texels), rgba);
}
#endif

}  // namespace raster::output_merge
