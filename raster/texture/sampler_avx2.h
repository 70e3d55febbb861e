// The lookups for Float8 and Float8x2 lanes (AVX2 gathers and F16C; AVX-512 where built):
// overloads of sampler.h's sampling::lookup*() names, each bit-identical to the reference
// lane for lane. The 8-lane samplers live in sample_color_avx2.cpp (with
// sample_rgba8_avx2.h) and sample_compare_avx2.cpp, the 16-lane PCF grids in
// sample_compare_avx512.cpp; Float8x2 lookups issue both groups' texel loads before either
// blends, so their cache misses overlap.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_AVX2
#include "raster/texture/sample_half_avx512.h"
#include "raster/texture/sample_half_grid_avx512.h"
#include "raster/texture/sample_half_separable_avx512.h"
#include "raster/texture/sample_nearest_avx512.h"
#include "raster/texture/sample_rgba8_avx512.h"
#include "raster/texture/sampler.h"

namespace raster::sampling {

// ---- the 8-lane samplers (sample_*_avx2.cpp) -----------------------------------------------

// The same lookup for 8 lanes at once (AVX2 gathers), bit-identical to the scalar one.
simd::Float8 compareLinearClamp8(const Texture& depth, simd::Float8 s, simd::Float8 t, simd::Float8 ref);
// compareNearestClamp for 8 lanes (one gather), and compareClamp: the active method's.
simd::Float8 compareNearestClamp8(const Texture& depth, simd::Float8 s, simd::Float8 t, simd::Float8 ref);
simd::Float8 compareClamp8(const Texture& depth, simd::Float8 s, simd::Float8 t, simd::Float8 ref);

// The (2R + 1)^2 lookups at ((origin + i * step) + s, (origin + j * step) + t), i and j in
// -R..R, each bit-identical to compareClamp8 there; taps[(j + R) * (2R + 1) + (i + R)].
// Overlapping taps share their texels. Defined for R = 1 and 2 (sample_compare.cpp).
template <int R>
void compareGrid8(const Texture& depth, simd::Float8 s, simd::Float8 t, float origin, float step, simd::Float8 ref,
                  simd::Float8* taps);
// Two such grids (Float8x2 shading), each bit-identical to compareGrid8: both groups'
// texel rows are loaded before either blends, so their cache misses overlap.
template <int R>
void compareGrid8x2(const Texture& depth, const simd::Float8 s[2], const simd::Float8 t[2], float origin, float step,
                    const simd::Float8 ref[2], simd::Float8* lo, simd::Float8* hi);
#if RASTER_ZMM_PAIRS
// Both grids in 512-bit registers (sample_compare_avx512.cpp) where every lane's footprints
// lie in one window of 2R + 2 texels a side (one texel apart, or piled together at a map
// edge): taps[(j + R) * (2R + 1) + (i + R)], each bit-identical to compareGrid8x2's.
// False, with nothing written, otherwise.
template <int R>
bool compareGrid16(const Texture& depth, simd::Float8x2 s, simd::Float8x2 t, float origin, float step, simd::Float8x2 ref,
                   simd::Float8x2* taps);
#endif

// The same lookups for 8 lanes at once, bit-identical to sampleColor lane by lane.
void sampleColor8(const Texture& texture, simd::Float8 s, simd::Float8 t, simd::Float8 out[4]);

// Two independent 8-lane lookups at once (Float8x2 shading), each bit-identical to
// sampleColor8: every texel load of both is issued before either blends, so their cache
// misses overlap.
void sampleColor8x2(const Texture& texture, const simd::Float8 s[2], const simd::Float8 t[2], simd::Float8 out[2][4]);

#if RASTER_ZMM_PAIRS
// The same for Float8x2 in one 512-bit register, with the result in that form too.
void sampleColor8x2(const Texture& texture, simd::Float8x2 s, simd::Float8x2 t, simd::Float8x2 out[4]);
#endif

// A texel plane's values at 8 lanes' NEAREST texels (one gather), bit-identical to
// sampler.h's lookupPlane lane by lane.
simd::Float8 samplePlane8(const TexelPlane& plane, simd::Float8 s, simd::Float8 t);

// Starts loading the texels sampleColor8 would read at these coordinates (RGBA8 and
// RGBA16F LINEAR: each lane's two footprint rows), and returns; nothing for other formats
// and filters.
void prefetchColor8(const Texture& texture, simd::Float8 s, simd::Float8 t);

// The 3x3 lookups at (s + i * stepS, t + j * stepT), i and j in -1..1, each bit-identical to
// sampleColor8 there: taps[(j + 1) * 3 + (i + 1)][channel]. For RGBA16F with LINEAR and
// CLAMP_TO_EDGE, neighbouring taps share their texel loads where they can.
void sampleColorGrid8(const Texture& texture, simd::Float8 s, simd::Float8 t, float stepS, float stepT,
                      simd::Float8 (*taps)[4]);

// Float8x2 lookups are two 8-lane lookups, one per half.
// Two halves' channel planes (r, g, b, a each), as one colour.
inline glsl::vec4<simd::Float8x2> joinHalves(const simd::Float8 (&lo)[4], const simd::Float8 (&hi)[4]) {
  return {{lo[0], hi[0]}, {lo[1], hi[1]}, {lo[2], hi[2]}, {lo[3], hi[3]}};
}
// The same for a sampleColor8x2 lookup's planes.
inline glsl::vec4<simd::Float8x2> joinHalves(const simd::Float8 (&rgba)[2][4]) { return joinHalves(rgba[0], rgba[1]); }

// ---- the lookups of sampler.h, for Float8 and Float8x2 -------------------------------------

inline void prefetchColor(const Texture& texture, glsl::vec2<simd::Float8> uv) { prefetchColor8(texture, uv.x, uv.y); }
inline void prefetchColor(const Texture& texture, glsl::vec2<simd::Float8x2> uv) {
#if RASTER_RGBA8_ZMM
  if (texture.hasStripCopy() && isRgba8Bilinear(texture)) return prefetchRgba8Strips(texture, uv.x, uv.y);
#endif
  prefetchColor8(texture, uv.x.low(), uv.y.low());
  prefetchColor8(texture, uv.x.high(), uv.y.high());
}

[[gnu::always_inline]] inline glsl::vec4<simd::Float8> lookupColor(const Texture& texture, glsl::vec2<simd::Float8> uv) {
  simd::Float8 rgba[4];
  sampleColor8(texture, uv.x, uv.y, rgba);
  return {rgba[0], rgba[1], rgba[2], rgba[3]};
}

[[gnu::always_inline]] inline glsl::vec4<simd::Float8x2> lookupColor(const Texture& texture,
                                                                     glsl::vec2<simd::Float8x2> uv) {
#if RASTER_ZMM_PAIRS
  simd::Float8x2 rgba[4];
  if (isHalfNearest(texture)) sampleHalfNearestPair(texture, uv.x, uv.y, rgba);   // inline (sample_half_avx512.h)
  else if (isNearest32(texture)) sampleNearest32Pair(texture, uv.x, uv.y, rgba);   // inline (sample_nearest_avx512.h)
#if RASTER_RGBA8_ZMM
  else if (isRgba8Bilinear(texture)) sampleRgba8Pair(texture, uv.x, uv.y, rgba);   // inline (sample_rgba8_avx512.h)
#endif
  else if (!isHalfBilinearClamp(texture) || !sampleHalfBilinearPair(texture, uv.x, uv.y, rgba))   // inline too
    sampleColor8x2(texture, uv.x, uv.y, rgba);   // every other lookup, and RGBA16F at its right edge
  return {rgba[0], rgba[1], rgba[2], rgba[3]};
#else
  const simd::Float8 s[2] = {uv.x.low(), uv.x.high()}, t[2] = {uv.y.low(), uv.y.high()};
  simd::Float8 rgba[2][4];
  sampleColor8x2(texture, s, t, rgba);
  return joinHalves(rgba);
#endif
}

[[gnu::always_inline]] inline simd::Float8 lookupPlane(const TexelPlane& plane, glsl::vec2<simd::Float8> uv) {
  return samplePlane8(plane, uv.x, uv.y);
}

[[gnu::always_inline]] inline simd::Float8x2 lookupPlane(const TexelPlane& plane, glsl::vec2<simd::Float8x2> uv) {
#if RASTER_ZMM_PAIRS
  return samplePlanePair(plane, uv.x, uv.y);   // inline (sample_nearest_avx512.h)
#else
  return {samplePlane8(plane, uv.x.low(), uv.y.low()), samplePlane8(plane, uv.x.high(), uv.y.high())};
#endif
}

[[gnu::always_inline]] inline simd::Float8 lookupCompare(const Texture& depth, glsl::vec2<simd::Float8> uv,
                                                         simd::Float8 ref) {
  return compareClamp8(depth, uv.x, uv.y, ref);
}

[[gnu::always_inline]] inline simd::Float8x2 lookupCompare(const Texture& depth, glsl::vec2<simd::Float8x2> uv,
                                                           simd::Float8x2 ref) {
  return {compareClamp8(depth, uv.x.low(), uv.y.low(), ref.low()), compareClamp8(depth, uv.x.high(), uv.y.high(), ref.high())};
}

[[gnu::always_inline]] inline void lookupColorGrid3x3(const Texture& texture, glsl::vec2<simd::Float8> uv,
                                                      glm::vec2 step, glsl::vec4<simd::Float8> (&taps)[3][3]) {
  simd::Float8 planes[9][4];
  sampleColorGrid8(texture, uv.x, uv.y, step.x, step.y, planes);
  for (int k = 0; k < 9; ++k) taps[k / 3][k % 3] = {planes[k][0], planes[k][1], planes[k][2], planes[k][3]};
}

[[gnu::always_inline]] inline void lookupColorGrid3x3(const Texture& texture, glsl::vec2<simd::Float8x2> uv,
                                                      glm::vec2 step, glsl::vec4<simd::Float8x2> (&taps)[3][3]) {
#if RASTER_ZMM_PAIRS
  if (isHalfBilinearClamp(texture)) {
    if (mayBeSeparable16(texture, uv.x.v, uv.y.v)) {
      // Planes of its own: handed the ones below, the call had cost the downsample 8%
      // though it never takes this path (most likely as their address then escapes, and the
      // compiler could no longer drop from blendHalfGrid16's code the taps and channels the
      // shader never reads: the downsample reads 5 taps of 9, 3 channels of 4).
      simd::Float8x2 lined[9][4];
      if (blendHalfGridSeparable16(texture, uv.x.v, uv.y.v, step.x, step.y, lined)) {
        for (int k = 0; k < 9; ++k) taps[k / 3][k % 3] = {lined[k][0], lined[k][1], lined[k][2], lined[k][3]};
        return;
      }
    }
    // The downsample's blocks away from a mip's edges line up two texels a column; the
    // others (edges, a step that is not one texel) take the lane-by-lane grid.
    simd::Float8x2 planes[9][4];
    auto laneByLane = [&]() __attribute__((always_inline)) {
      LinearTaps16 x[3], y[3];
      bloomGridTaps16(texture, uv.x.v, uv.y.v, step.x, step.y, x, y);
      return blendHalfGrid16(texture, x, y, planes);
    };
    if (blendHalfGridStrided16(texture, uv.x.v, uv.y.v, step.x, step.y, planes) || laneByLane()) {
      for (int k = 0; k < 9; ++k) taps[k / 3][k % 3] = {planes[k][0], planes[k][1], planes[k][2], planes[k][3]};
      return;
    }
  }
#endif
  simd::Float8 lo[9][4], hi[9][4];
  sampleColorGrid8(texture, uv.x.low(), uv.y.low(), step.x, step.y, lo);
  sampleColorGrid8(texture, uv.x.high(), uv.y.high(), step.x, step.y, hi);
  for (int k = 0; k < 9; ++k) taps[k / 3][k % 3] = joinHalves(lo[k], hi[k]);
}

// textureLine's taps (sampler.h) on 16 lanes: a block's line along x or y of a NEAREST RGBA8 or
// depth texture shares its texel loads (sampleNearest32Line); every other line, and every
// other texture, is the lone lookups one tap at a time.
template <int N>
[[gnu::always_inline]] inline void lookupColorLine(const Texture& texture, glsl::vec2<simd::Float8x2> uv,
                                                   glm::vec2 step, glsl::vec4<simd::Float8x2> (&taps)[N]) {
  using simd::Float8x2;
  constexpr int R = N / 2;
  const auto at = [&](int i) -> glsl::vec2<Float8x2> {
    if (i == 0) return uv;
    const glsl::vec2<Float8x2> offset(Float8x2(step.x * float(i < 0 ? -i : i)), Float8x2(step.y * float(i < 0 ? -i : i)));
    return i > 0 ? uv + offset : uv - offset;
  };
#if RASTER_ZMM_PAIRS
  if (isNearest32(texture)) {
    // Straight into the caller's taps: through an array of planes first, each tap had been
    // stored, loaded and stored again (9% of the pbr blur's samples).
    if (sampleNearest32Line(texture, uv.x, uv.y, step, taps)) return;
    for (int i = -R; i <= R; ++i) {
      const glsl::vec2<Float8x2> tap = at(i);
      sampleNearest32Pair(texture, tap.x, tap.y, taps[i + R]);
    }
    return;
  }
#endif
  for (int i = -R; i <= R; ++i) taps[i + R] = lookupColor(texture, at(i));
}

template <int N>
void lookupCompareGrid(const Texture& depth, glsl::vec2<simd::Float8> base, float origin, float step, simd::Float8 ref,
                       simd::Float8 (&taps)[N][N]) {
  compareGrid8<N / 2>(depth, base.x, base.y, origin, step, ref, &taps[0][0]);
}

template <int N>
void lookupCompareGrid(const Texture& depth, glsl::vec2<simd::Float8x2> base, float origin, float step, simd::Float8x2 ref,
                       simd::Float8x2 (&taps)[N][N]) {
  constexpr int R = N / 2, kTaps = N * N;
#if RASTER_ZMM_PAIRS
  if (compareGrid16<R>(depth, base.x, base.y, origin, step, ref, &taps[0][0])) return;
#endif
  simd::Float8 lo[kTaps], hi[kTaps];
  const simd::Float8 s[2] = {base.x.low(), base.x.high()}, t[2] = {base.y.low(), base.y.high()},
                     refs[2] = {ref.low(), ref.high()};
  compareGrid8x2<R>(depth, s, t, origin, step, refs, lo, hi);
  for (int k = 0; k < kTaps; ++k) taps[k / N][k % N] = {lo[k], hi[k]};
}

}  // namespace raster::sampling
#endif
