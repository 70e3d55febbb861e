// Samplers as shader ports see them: GLSL's sampler2D / sampler2DShadow and the lookups
// texture(), textureCompare() and the grids of lookups the scenes' filters make.
//
// Each lookup is one line over sampling::lookup*(), which is written here lane by lane over
// the scalar lookups of sample_color.cpp and sample_compare.cpp: the reference. The vector
// forms for Float8 and Float8x2 (AVX2 gathers; AVX-512 where built) are overloads of the
// same names in sampler_avx2.h, bit-identical lane for lane (tests/texture hold them equal).
#pragma once

#include <glm/vec2.hpp>

#include "raster/simd/glsl.h"
#include "raster/texture/sample_trace.h"
#include "raster/texture/texture.h"

namespace raster {

struct Sampler2D {
  int unit = 0;                       // the uniform's value (texture unit)
  const Texture* texture = nullptr;   // resolved at draw time
};

struct Sampler2DShadow {
  int unit = 0;
  const Texture* texture = nullptr;
};

// Not GLSL: a texel plane, one float a texel. It holds what a fragment shader computes from
// the texels that NEAREST lookups of its textures return at one texel, made once a draw
// (shader/texel_planes.h), so that a lookup reads that one float (textureFromPlane, below)
// instead of its texels and the arithmetic on them. Rows are the sources' memory rows.
struct TexelPlane {
  std::vector<float, HugePageAllocator<float>> values;   // empty: not made this draw
  int width = 0, height = 0;
  Wrap wrapS = Wrap::ClampToEdge, wrapT = Wrap::ClampToEdge;
  bool made() const { return !values.empty(); }
};

namespace sampling {

// What a depth map's codes are multiplied by to read as floats in [0, 1] (format.h's
// depth24ToFloat and depth16ToFloat), for the vector compares of both ISA files.
inline float depthCodeScale(const Texture& depth) {
  return depth.format == TexelFormat::Depth24 ? float(1.0 / 16777215.0) : float(1.0 / 65535.0);
}

// One colour lookup (sampler2D): RGBA8 through llvmpipe's 8-bit fixed-point path, float
// formats in float32 (see sample_color.cpp). Writes r, g, b, a.
void sampleColor(const Texture& texture, float s, float t, float out[4]);

// One shadow lookup, llvmpipe's arithmetic (lp_bld_sample_soa.c, linear filtering with
// compare, CLAMP_TO_EDGE): the four bilinear texels are each compared with the reference
// (ref <= texel, LEQUAL, ordered), and the 0/1 results weighted bilinearly:
//   per row:  (m1 ? w : 0) + (m0 ? 1 - w : 0)        (lp_build_masklerp)
//   rows:     fma(wy, row1 - row0, row0)              (lp_build_lerp, fmuladd)
// The reference is clamped to [0, 1] (NaN -> 0) but not quantized to the depth format.
float compareLinearClamp(const Texture& depth, float s, float t, float ref);

// compare=nearest (methods.h): the compare of the one texel the coordinate lands in,
// floor(clamp(coord * size, 0, size - 1)) on each axis (NaN -> 0), as 0 or 1. GL leaves the
// filtering of a LINEAR shadow lookup's compares to the implementation ("a value in the
// range [0, 1] which is proportional to the number of comparison passes", GL 3.3, Texture
// Comparison Modes). That texel is the footprint texel of compareLinearClamp with the
// largest weight (at least 1/4), so the two agree wherever the bilinear result is 0 or 1,
// and differ by at most 0.75.
float compareNearestClamp(const Texture& depth, float s, float t, float ref);

// The shadow lookup of the active compare method: one of the two above.
float compareClamp(const Texture& depth, float s, float t, float ref);

// ---- the lookups over a lane type, lane by lane --------------------------------------------

inline glsl::vec4<float> lookupColor(const Texture& texture, glsl::vec2<float> uv) {
  float rgba[4];
  sampleColor(texture, uv.x, uv.y, rgba);
  return {rgba[0], rgba[1], rgba[2], rgba[3]};
}

template <class F>
glsl::vec4<F> lookupColor(const Texture& texture, glsl::vec2<F> uv) {
  alignas(64) float s[F::kCount], t[F::kCount], out[4][F::kCount];
  uv.x.store(s);
  uv.y.store(t);
  for (int i = 0; i < F::kCount; ++i) {
    float rgba[4];
    sampleColor(texture, s[i], t[i], rgba);
    for (int c = 0; c < 4; ++c) out[c][i] = rgba[c];
  }
  const float* const lanes[4] = {out[0], out[1], out[2], out[3]};
  recordColorLookup(texture, s, t, lanes);   // pixel history only (sample_trace.h)
  return {F::load(out[0]), F::load(out[1]), F::load(out[2]), F::load(out[3])};
}

inline float lookupCompare(const Texture& depth, glsl::vec2<float> uv, float ref) {
  return compareClamp(depth, uv.x, uv.y, ref);
}

template <class F>
F lookupCompare(const Texture& depth, glsl::vec2<F> uv, F ref) {
  alignas(64) float s[F::kCount], t[F::kCount], r[F::kCount], out[F::kCount];
  uv.x.store(s);
  uv.y.store(t);
  ref.store(r);
  for (int i = 0; i < F::kCount; ++i) out[i] = compareClamp(depth, s[i], t[i], r[i]);
  recordCompareLookup(depth, s, t, r, out);   // pixel history only (sample_trace.h)
  return F::load(out);
}

// NEAREST's texel index along one axis, as every NEAREST lookup of the float path computes
// it (sample_color.cpp; RGBA8's fixed-point path differs only before a clamp that makes the
// two the same): CLAMP_TO_EDGE truncates, then clamps; REPEAT wraps.
int nearestIndex(float coord, int size, Wrap wrap);

// The plane's value at the texel a NEAREST lookup at uv reads.
inline float lookupPlane(const TexelPlane& plane, glsl::vec2<float> uv) {
  const int x = nearestIndex(uv.x, plane.width, plane.wrapS), y = nearestIndex(uv.y, plane.height, plane.wrapT);
  return plane.values[size_t(y) * size_t(plane.width) + size_t(x)];
}
template <class F>
F lookupPlane(const TexelPlane& plane, glsl::vec2<F> uv) {
  alignas(64) float s[F::kCount], t[F::kCount], out[F::kCount];
  uv.x.store(s);
  uv.y.store(t);
  for (int i = 0; i < F::kCount; ++i) out[i] = lookupPlane(plane, glsl::vec2<float>(s[i], t[i]));
  return F::load(out);
}

// A prefetch changes nothing the reference computes.
template <class F>
void prefetchColor(const Texture&, glsl::vec2<F>) {}

// taps[j + 1][i + 1] = the lookup at uv + (i * step.x, j * step.y), i and j in -1..1.
template <class F>
void lookupColorGrid3x3(const Texture& texture, glsl::vec2<F> uv, glm::vec2 step, glsl::vec4<F> (&taps)[3][3]) {
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      taps[j + 1][i + 1] = lookupColor(texture, uv + glsl::vec2<F>(F(float(i) * step.x), F(float(j) * step.y)));
}

// taps[i + R] = the lookup at uv + float(i) * step, i in -R..R (N = 2R + 1); taps[R] at uv
// itself.
template <int N, class F>
void lookupColorLine(const Texture& texture, glsl::vec2<F> uv, glm::vec2 step, glsl::vec4<F> (&taps)[N]) {
  constexpr int R = N / 2;
  taps[R] = lookupColor(texture, uv);
  for (int i = 1; i <= R; ++i) {
    const glsl::vec2<F> offset(F(step.x * float(i)), F(step.y * float(i)));
    taps[R + i] = lookupColor(texture, uv + offset);
    taps[R - i] = lookupColor(texture, uv - offset);
  }
}

// taps[j + R][i + R] = the compare lookup at (origin + (i, j) * step) + base, i and j in -R..R
// (N = 2R + 1), each constant offset folded in float first.
template <int N, class F>
void lookupCompareGrid(const Texture& depth, glsl::vec2<F> base, float origin, float step, F ref, F (&taps)[N][N]) {
  constexpr int R = N / 2;
  for (int j = -R; j <= R; ++j)
    for (int i = -R; i <= R; ++i)
      taps[j + R][i + R] = lookupCompare(
          depth, glsl::vec2<F>(F(origin + float(i) * step) + base.x, F(origin + float(j) * step) + base.y), ref);
}

}  // namespace sampling
}  // namespace raster

// The Float8 and Float8x2 forms, declared before the GLSL functions below that call them.
#include "raster/texture/sampler_avx2.h"

namespace raster {

// GLSL: texture(sampler2D, uv).
template <class F>
[[gnu::always_inline]] inline glsl::vec4<F> texture(const Sampler2D& sampler, glsl::vec2<F> uv) {
  return sampling::lookupColor(*sampler.texture, uv);
}

// Not GLSL: a hint that texture(sampler, uv) will follow. It starts loading the texels that
// lookup reads and returns at once, changing no value. A shader that makes several lookups
// at one uv, each with arithmetic between (the G-buffer's material maps), otherwise waits
// on their cache misses one lookup after another: the out-of-order window holds about one
// lookup. Kept where it measured faster (docs/notes/2026-11-26-texel-traffic-gbuffer.md).
// The lines go to level 2, not level 1 (simd::prefetchLineToL2 says why); a port may also
// prefetch the block it will shade next (nextBlockCoords, shader/program.h).
template <class F>
[[gnu::always_inline]] inline void texturePrefetch(const Sampler2D& sampler, glsl::vec2<F> uv) {
  sampling::prefetchColor(*sampler.texture, uv);
}

// Not GLSL: value(uv), where `plane` holds value's result at every texel of the textures
// value reads (shader/texel_planes.h says when it may): read from the plane where it was
// made, computed by value(uv) itself where it was not, and for the lane pixel history
// traces, whose texture lookups the trace then shows. The same bits either way.
template <class F, class Value>
[[gnu::always_inline]] inline F textureFromPlane(const TexelPlane& plane, glsl::vec2<F> uv, Value value) {
  if (!plane.made() || sampling::tActiveSampleTrace) return value(uv);
  return sampling::lookupPlane(plane, uv);
}

// GLSL: texture(sampler2DShadow, vec3(uv, ref)), as the seed's textureCompare.
template <class F>
[[gnu::always_inline]] inline F textureCompare(const Sampler2DShadow& sampler, glsl::vec2<F> uv, F ref) {
  return sampling::lookupCompare(*sampler.texture, uv, ref);
}

// A 3x3 grid of colour lookups one step apart, as a tent filter makes them:
//   taps[j + 1][i + 1] = texture(sampler, uv + vec2(i * step.x, j * step.y)),  i, j in -1..1,
// each bit-identical to that lone lookup; the vector forms only share the texels that
// neighbouring taps have in common (4x4 texels instead of 9 footprints of 2x2). Always
// inlined: outlined, the Float8x2 form passed its 36 joined taps through memory, which made
// the bloom upsample 20% slower with Float8x2 in one AVX-512 register.
template <class F>
[[gnu::always_inline]] inline void textureGrid3x3(const Sampler2D& sampler, glsl::vec2<F> uv, glm::vec2 step,
                                                  glsl::vec4<F> (&taps)[3][3]) {
  sampling::lookupColorGrid3x3(*sampler.texture, uv, step, taps);
}

// The 2R + 1 colour lookups of a separable filter's loop, one step apart along a line:
//   taps[R] = texture(sampler, uv),
//   taps[R + i] = texture(sampler, uv + step * float(i)),
//   taps[R - i] = texture(sampler, uv - step * float(i)),  i in 1..R,
// each bit-identical to that lone lookup. Made at once, the taps can share their texel loads:
// the 16-lane form reads a block's line along x or y of a NEAREST RGBA8 or depth texture
// from one window of texels (sampleNearest32Line).
template <int R, class F>
[[gnu::always_inline]] inline void textureLine(const Sampler2D& sampler, glsl::vec2<F> uv, glm::vec2 step,
                                               glsl::vec4<F> (&taps)[2 * R + 1]) {
  sampling::lookupColorLine(*sampler.texture, uv, step, taps);
}

// The PCF loops of the seeds' shaders, their lookups made at once:
//   taps[j + R][i + R] = texture(shadow, vec3((origin + vec2(i, j) * step) + base, ref)),
// i, j in -R..R. That is GLSL's uv + vec2(i, j) * step where uv = base + origin and origin
// is a constant (the seeds' ndc * 0.5 + 0.5): Mesa's compiler folds each tap's constant
// offset into origin first (nir_opt_algebraic, "Reassociate constants in add chains"), and
// adds base last. Every tap equals that lone lookup bit for bit; the vector forms only share
// the texel loads and compares that neighbouring taps have in common (a 3x3 grid of 2x2
// footprints covers 4x4 texels, not 36). The shader still sums the taps itself, in its own
// order.
template <int R, class F>
void textureCompareGrid(const Sampler2DShadow& sampler, glsl::vec2<F> base, float origin, float step, F ref,
                        F (&taps)[2 * R + 1][2 * R + 1]) {
  static_assert(R == 1 || R == 2, "3x3 and 5x5 grids");
  sampling::lookupCompareGrid(*sampler.texture, base, origin, step, ref, taps);
}

}  // namespace raster
