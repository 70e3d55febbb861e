// Samplers as shader ports see them: GLSL's sampler2D / sampler2DShadow, bound to a
// texture unit by a uniform, resolved to a Texture when a draw is recorded.
#pragma once

#include <type_traits>

#include "raster/texture/texture.h"
#include "raster/simd/glsl.h"

namespace raster {

struct Sampler2D {
  int unit = 0;                       // the uniform's value (texture unit)
  const Texture* texture = nullptr;   // resolved at draw time
};

struct Sampler2DShadow {
  int unit = 0;
  const Texture* texture = nullptr;
};

namespace sampling {

// One shadow lookup, llvmpipe's arithmetic (lp_bld_sample_soa.c, linear filtering with
// compare, CLAMP_TO_EDGE): the four bilinear texels are each compared with the reference
// (ref <= texel, LEQUAL, ordered), and the 0/1 results weighted bilinearly:
//   per row:  (m1 ? w : 0) + (m0 ? 1 - w : 0)        (lp_build_masklerp)
//   rows:     fma(wy, row1 - row0, row0)              (lp_build_lerp, fmuladd)
// The reference is clamped to [0, 1] (NaN -> 0) but not quantized to the depth format.
float compareLinearClamp(const Texture& depth, float s, float t, float ref);

#if RASTER_AVX2
// The same lookup for 8 lanes at once (AVX2 gathers), bit-identical to the scalar one.
simd::Float8 compareLinearClamp8(const Texture& depth, simd::Float8 s, simd::Float8 t, simd::Float8 ref);

// The (2R + 1)^2 lookups at (s + i * step, t + j * step), i and j in -R..R, each
// bit-identical to compareLinearClamp8 there; taps[(j + R) * (2R + 1) + (i + R)].
// Overlapping taps share their texels. Defined for R = 1 and 2 (sample_compare.cpp).
template <int R>
void compareGrid8(const Texture& depth, simd::Float8 s, simd::Float8 t, float step, simd::Float8 ref,
                  simd::Float8* taps);
// Two such grids (Float8x2 shading), each bit-identical to compareGrid8: both groups'
// texel rows are loaded before either blends, so their cache misses overlap.
template <int R>
void compareGrid8x2(const Texture& depth, const simd::Float8 s[2], const simd::Float8 t[2], float step,
                    const simd::Float8 ref[2], simd::Float8* lo, simd::Float8* hi);
#endif

// One colour lookup (sampler2D): RGBA8 through llvmpipe's 8-bit fixed-point path, float
// formats in float32 (see sample_color.cpp). Writes r, g, b, a.
void sampleColor(const Texture& texture, float s, float t, float out[4]);

#if RASTER_AVX2
// The same lookups for 8 lanes at once, bit-identical to sampleColor lane by lane.
void sampleColor8(const Texture& texture, simd::Float8 s, simd::Float8 t, simd::Float8 out[4]);

// The same lookups where only the lanes in `live` are needed: the others' results are
// unspecified (zero where their loads are skipped).
void sampleColor8(const Texture& texture, simd::Float8 s, simd::Float8 t, simd::Mask8 live, simd::Float8 out[4]);

// Two independent 8-lane lookups at once (Float8x2 shading), each bit-identical to
// sampleColor8: every texel load of both is issued before either blends, so their cache
// misses overlap. The second form takes `live` masks as the masked sampleColor8.
void sampleColor8x2(const Texture& texture, const simd::Float8 s[2], const simd::Float8 t[2], simd::Float8 out[2][4]);
void sampleColor8x2(const Texture& texture, const simd::Float8 s[2], const simd::Float8 t[2], const simd::Mask8 live[2],
                    simd::Float8 out[2][4]);

#if RASTER_ZMM_PAIRS
// The same for Float8x2 in one 512-bit register, with the result in that form too; the
// second form takes `live` lanes as the masked sampleColor8.
void sampleColor8x2(const Texture& texture, simd::Float8x2 s, simd::Float8x2 t, simd::Float8x2 out[4]);
void sampleColor8x2(const Texture& texture, simd::Float8x2 s, simd::Float8x2 t, simd::Mask8x2 live, simd::Float8x2 out[4]);
#endif

// The 3x3 lookups at (s + i * stepS, t + j * stepT), i and j in -1..1, each bit-identical to
// sampleColor8 there: taps[(j + 1) * 3 + (i + 1)][channel]. For RGBA16F with LINEAR and
// CLAMP_TO_EDGE, neighbouring taps share their texel loads where they can.
void sampleColorGrid8(const Texture& texture, simd::Float8 s, simd::Float8 t, float stepS, float stepT,
                      simd::Float8 (*taps)[4]);
#endif

#if RASTER_AVX2
// Float8x2 lookups are two 8-lane lookups, one per half.
// Two halves' channel planes (r, g, b, a each), as one colour.
inline glsl::vec4<simd::Float8x2> joinHalves(const simd::Float8 (&lo)[4], const simd::Float8 (&hi)[4]) {
  return {{lo[0], hi[0]}, {lo[1], hi[1]}, {lo[2], hi[2]}, {lo[3], hi[3]}};
}
// The same for a sampleColor8x2 lookup's planes.
inline glsl::vec4<simd::Float8x2> joinHalves(const simd::Float8 (&rgba)[2][4]) { return joinHalves(rgba[0], rgba[1]); }
#endif

}  // namespace sampling

// GLSL: texture(sampler2D, uv).
template <class F>
glsl::vec4<F> texture(const Sampler2D& sampler, glsl::vec2<F> uv) {
  if constexpr (std::is_same_v<F, float>) {
    float rgba[4];
    sampling::sampleColor(*sampler.texture, uv.x, uv.y, rgba);
    return {rgba[0], rgba[1], rgba[2], rgba[3]};
#if RASTER_AVX2
  } else if constexpr (std::is_same_v<F, simd::Float8>) {
    simd::Float8 rgba[4];
    sampling::sampleColor8(*sampler.texture, uv.x, uv.y, rgba);
    return {rgba[0], rgba[1], rgba[2], rgba[3]};
  } else if constexpr (std::is_same_v<F, simd::Float8x2>) {
#if RASTER_ZMM_PAIRS
    simd::Float8x2 rgba[4];
    sampling::sampleColor8x2(*sampler.texture, uv.x, uv.y, rgba);
    return {rgba[0], rgba[1], rgba[2], rgba[3]};
#else
    const simd::Float8 s[2] = {uv.x.low(), uv.x.high()}, t[2] = {uv.y.low(), uv.y.high()};
    simd::Float8 rgba[2][4];
    sampling::sampleColor8x2(*sampler.texture, s, t, rgba);
    return sampling::joinHalves(rgba);
#endif
#endif
  } else {
    alignas(32) float s[F::kCount], t[F::kCount], out[4][F::kCount];
    uv.x.store(s);
    uv.y.store(t);
    for (int i = 0; i < F::kCount; ++i) {
      float rgba[4];
      sampling::sampleColor(*sampler.texture, s[i], t[i], rgba);
      for (int c = 0; c < 4; ++c) out[c][i] = rgba[c];
    }
    return {F::load(out[0]), F::load(out[1]), F::load(out[2]), F::load(out[3])};
  }
}

// GLSL: texture(sampler2D, uv) in a port that knows some lanes will never use the result:
// only the lanes in `needed` get their texel, the others an unspecified value. A shader
// compiler that worked lane by lane would skip those reads; SSAO uses this to skip the
// memory traffic of lookups whose lanes have already failed a test.
template <class F, class M>
glsl::vec4<F> textureWhere(M needed, const Sampler2D& sampler, glsl::vec2<F> uv) {
#if RASTER_AVX2
  if constexpr (std::is_same_v<F, simd::Float8>) {
    simd::Float8 rgba[4];
    sampling::sampleColor8(*sampler.texture, uv.x, uv.y, needed, rgba);
    return {rgba[0], rgba[1], rgba[2], rgba[3]};
  } else if constexpr (std::is_same_v<F, simd::Float8x2>) {
#if RASTER_ZMM_PAIRS
    simd::Float8x2 rgba[4];
    sampling::sampleColor8x2(*sampler.texture, uv.x, uv.y, needed, rgba);
    return {rgba[0], rgba[1], rgba[2], rgba[3]};
#else
    const simd::Float8 s[2] = {uv.x.low(), uv.x.high()}, t[2] = {uv.y.low(), uv.y.high()};
    const simd::Mask8 live[2] = {needed.low(), needed.high()};
    simd::Float8 rgba[2][4];
    sampling::sampleColor8x2(*sampler.texture, s, t, live, rgba);
    return sampling::joinHalves(rgba);
#endif
  }
#endif
  (void)needed;
  return texture(sampler, uv);   // scalar and portable lanes: every lane, as GLSL reads them
}

// GLSL: texture(sampler2DShadow, vec3(uv, ref)), as the seed's textureCompare.
template <class F>
F textureCompare(const Sampler2DShadow& sampler, glsl::vec2<F> uv, F ref) {
  if constexpr (std::is_same_v<F, float>) {
    return sampling::compareLinearClamp(*sampler.texture, uv.x, uv.y, ref);
#if RASTER_AVX2
  } else if constexpr (std::is_same_v<F, simd::Float8>) {
    return sampling::compareLinearClamp8(*sampler.texture, uv.x, uv.y, ref);
  } else if constexpr (std::is_same_v<F, simd::Float8x2>) {
    return {sampling::compareLinearClamp8(*sampler.texture, uv.x.low(), uv.y.low(), ref.low()),
            sampling::compareLinearClamp8(*sampler.texture, uv.x.high(), uv.y.high(), ref.high())};
#endif
  } else {
    alignas(32) float s[F::kCount], t[F::kCount], r[F::kCount], out[F::kCount];
    uv.x.store(s);
    uv.y.store(t);
    ref.store(r);
    for (int i = 0; i < F::kCount; ++i) out[i] = sampling::compareLinearClamp(*sampler.texture, s[i], t[i], r[i]);
    return F::load(out);
  }
}

// A 3x3 grid of colour lookups one step apart, as a tent filter makes them:
//   taps[j + 1][i + 1] = texture(sampler, uv + vec2(i * step.x, j * step.y)),  i, j in -1..1,
// each bit-identical to that lone lookup; the sampler only shares the texels that
// neighbouring taps have in common (4x4 texels instead of 9 footprints of 2x2). Always
// inlined: outlined, the Float8x2 form passed its 36 joined taps through memory, which made
// the bloom upsample 20% slower with Float8x2 in one AVX-512 register.
template <class F>
[[gnu::always_inline]] inline void textureGrid3x3(const Sampler2D& sampler, glsl::vec2<F> uv, glm::vec2 step,
                                                  glsl::vec4<F> (&taps)[3][3]) {
#if RASTER_AVX2
  if constexpr (std::is_same_v<F, simd::Float8>) {
    simd::Float8 planes[9][4];
    sampling::sampleColorGrid8(*sampler.texture, uv.x, uv.y, step.x, step.y, planes);
    for (int k = 0; k < 9; ++k) taps[k / 3][k % 3] = {planes[k][0], planes[k][1], planes[k][2], planes[k][3]};
    return;
  } else if constexpr (std::is_same_v<F, simd::Float8x2>) {
    simd::Float8 lo[9][4], hi[9][4];
    sampling::sampleColorGrid8(*sampler.texture, uv.x.low(), uv.y.low(), step.x, step.y, lo);
    sampling::sampleColorGrid8(*sampler.texture, uv.x.high(), uv.y.high(), step.x, step.y, hi);
    for (int k = 0; k < 9; ++k) taps[k / 3][k % 3] = sampling::joinHalves(lo[k], hi[k]);
    return;
  }
#endif
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      taps[j + 1][i + 1] = texture(sampler, uv + glsl::vec2<F>(F(float(i) * step.x), F(float(j) * step.y)));
}

// The PCF loops of the seeds' shaders, their lookups made at once:
//   taps[j + R][i + R] = texture(shadow, vec3(uv + vec2(i, j) * step, ref)),  i, j in -R..R.
// Every tap equals that lone lookup bit for bit; the sampler only shares the texel loads
// and compares that neighbouring taps have in common (a 3x3 grid of 2x2 footprints covers
// 4x4 texels, not 36). The shader still sums the taps itself, in its own order.
template <int R, class F>
void textureCompareGrid(const Sampler2DShadow& sampler, glsl::vec2<F> uv, float step, F ref, F (&taps)[2 * R + 1][2 * R + 1]) {
  static_assert(R == 1 || R == 2, "3x3 and 5x5 grids");
#if RASTER_AVX2
  if constexpr (std::is_same_v<F, simd::Float8>) {
    sampling::compareGrid8<R>(*sampler.texture, uv.x, uv.y, step, ref, &taps[0][0]);
    return;
  } else if constexpr (std::is_same_v<F, simd::Float8x2>) {
    constexpr int kTaps = (2 * R + 1) * (2 * R + 1);
    simd::Float8 lo[kTaps], hi[kTaps];
    const simd::Float8 s[2] = {uv.x.low(), uv.x.high()}, t[2] = {uv.y.low(), uv.y.high()}, refs[2] = {ref.low(), ref.high()};
    sampling::compareGrid8x2<R>(*sampler.texture, s, t, step, refs, lo, hi);
    for (int k = 0; k < kTaps; ++k) taps[k / (2 * R + 1)][k % (2 * R + 1)] = {lo[k], hi[k]};
    return;
  }
#endif
  for (int j = -R; j <= R; ++j)
    for (int i = -R; i <= R; ++i)
      taps[j + R][i + R] = textureCompare(sampler, uv + glsl::vec2<F>(F(float(i) * step), F(float(j) * step)), ref);
}

}  // namespace raster
