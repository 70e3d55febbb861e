// C++ port of post.vert / ssao.frag (seed 004, SSAO pass), line by line; the sample loop runs
// in chunks of eight, each split in three, with the same operations per sample (see
// shade()), and its two matrix products leave out the projections' zero entries where that
// gives the same bits (projectSample, ReconstructViewZ).
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "raster/shader/program.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/pbr/post.h"

namespace shaders::pbr {

using namespace raster::glsl;

struct SsaoPass : PostProgram {
  static constexpr const char* kName = "pbr/post+ssao";
  static constexpr int kColorOutputs = 1;
  // Its 64 samples a pixel land up to uRadius away in view space, many pixels on the screen:
  // the pipeline shades its tiles in an order that keeps neighbours together.
  static constexpr bool kSamplesAroundPixel = true;
  static constexpr int KERNEL_SIZE = 64;
  static constexpr int kChunk = 8;   // samples whose depth lookups are issued together
  static_assert(KERNEL_SIZE % kChunk == 0);
  struct Uniforms {
    std::array<glm::vec3, KERNEL_SIZE> uSamples{};
    raster::Sampler2D uDepth, uNormal, uNoise;
    glm::mat4 uProjection{1.0f};
    glm::mat4 uInvProjection{1.0f};
    glm::mat4 uView{1.0f};
    glm::vec2 noiseScale{1.0f};
    float uRadius = 0.5f;
    float uBias = 0.025f;
    // Not a GLSL uniform: whether the two projections have the zero entries the sparse
    // forms below leave out, found once a draw (deriveUniforms).
    bool projectsSparsely = false;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("uSamples", &Uniforms::uSamples),
      raster::uniform("uDepth", &Uniforms::uDepth),
      raster::uniform("uNormal", &Uniforms::uNormal),
      raster::uniform("uNoise", &Uniforms::uNoise),
      raster::uniform("uProjection", &Uniforms::uProjection),
      raster::uniform("uInvProjection", &Uniforms::uInvProjection),
      raster::uniform("uView", &Uniforms::uView),
      raster::uniform("noiseScale", &Uniforms::noiseScale),
      raster::uniform("uRadius", &Uniforms::uRadius),
      raster::uniform("uBias", &Uniforms::uBias),
  };

  // ReconstructViewPos(uv).z, the only component the shader reads of it (Mesa drops the
  // rest): row z of uInvProjection * clip over its w, clip = (uv * 2 - 1, depth * 2 - 1, 1);
  // the column of w = 1 is added as it is (c3 * 1.0 folded).
  template <class F>
  static vec2<F> clipXY(vec2<F> uv) {
    return uv * F(2.0f) - vec2<F>(F(1.0f));
  }
  // Not in the GLSL: the sample's two matrix products leave out the entries that are zero,
  // as deferred/ssao.h's projectSample does (its comment proves the rule): dropping a term
  // +-0 * v changes no bit of a row's sum where v is finite, except the sign of a zero sum.
  // uProjection (glm::perspective) has one non-zero entry in rows x, y and w, so
  // ox = P00 x, oy = P11 y, ow = P23 z; uInvProjection (its inverse) has none in the first
  // three columns of row z and two in row w, so viewZ = M32 and viewW = M23 z + M33, which
  // M32, M33 != 0 keep exact even for a zero M23 z. The guards, as `check` (below): every
  // dropped operand finite (the sample point, the lookup's clip xy and z), and no zero ow,
  // the one row whose zero's sign a reader sees (ox / ow): a zero ow makes ox / ow, and so
  // the lookup's clip xy, non-finite. A zero ox or oy gives ox / ow * 0.5 + 0.5 = 0.5 either
  // way. `check` takes the sums of those values (addFiniteGuard): 0 while each is finite, NaN
  // after any that is not (or overflows: shaded in full too).
  static bool hasSparseProjections(const glm::mat4& p, const glm::mat4& m) {
    const bool projection = p[1][0] == 0.0f && p[2][0] == 0.0f && p[3][0] == 0.0f && p[0][1] == 0.0f &&
                            p[2][1] == 0.0f && p[3][1] == 0.0f && p[0][3] == 0.0f && p[1][3] == 0.0f && p[3][3] == 0.0f;
    const bool inverse = m[0][2] == 0.0f && m[1][2] == 0.0f && m[2][2] == 0.0f && m[0][3] == 0.0f && m[1][3] == 0.0f &&
                         m[3][2] != 0.0f && m[3][3] != 0.0f && std::isfinite(m[3][2]) && std::isfinite(m[3][3]);
    return projection && inverse;
  }
  static void deriveUniforms(Uniforms& u) { u.projectsSparsely = hasSparseProjections(u.uProjection, u.uInvProjection); }

  // The sample point's projection (uProjection * vec4(samplePos, 1.0)).xyw, in full or
  // (kSparse) with uProjection's zero entries left out.
  template <bool kSparse, class F>
  [[gnu::always_inline]] static vec3<F> projectSample(const glm::mat4& p, const vec3<F>& samplePos, F& check) {
    if constexpr (kSparse) {
      check = addFiniteGuard(check, samplePos.x + samplePos.y + samplePos.z);
      return vec3<F>(F(p[0][0]) * samplePos.x, F(p[1][1]) * samplePos.y, F(p[2][3]) * samplePos.z);
    }
    return vec3<F>(((F(p[0][0]) * samplePos.x + F(p[1][0]) * samplePos.y) + F(p[2][0]) * samplePos.z) + F(p[3][0]),
                   ((F(p[0][1]) * samplePos.x + F(p[1][1]) * samplePos.y) + F(p[2][1]) * samplePos.z) + F(p[3][1]),
                   ((F(p[0][3]) * samplePos.x + F(p[1][3]) * samplePos.y) + F(p[2][3]) * samplePos.z) + F(p[3][3]));
  }

  // ReconstructViewZ's arithmetic: (m * vec4(xy, z, 1.0)).z over its w, in full or (kSparse)
  // with uInvProjection's zero entries left out.
  template <bool kSparse, class F>
  [[gnu::always_inline]] static F viewZFromClip(const glm::mat4& m, vec2<F> xy, F z, F& check) {
    if constexpr (kSparse) {
      check = addFiniteGuard(check, xy.x + xy.y + z);
      return F(m[3][2]) / (F(m[2][3]) * z + F(m[3][3]));
    }
    const F viewZ = ((F(m[0][2]) * xy.x + F(m[1][2]) * xy.y) + F(m[2][2]) * z) + F(m[3][2]);
    const F viewW = ((F(m[0][3]) * xy.x + F(m[1][3]) * xy.y) + F(m[2][3]) * z) + F(m[3][3]);
    return viewZ / viewW;
  }
  // Inline (GCC called it): a call spills every live vector register, the chunk's lanes.
  template <bool kSparse, class F>
  [[gnu::always_inline]] static F ReconstructViewZ(const Uniforms& u, vec2<F> uv, F& check) {
    const F depth = raster::texture(u.uDepth, uv).x;
    const vec2<F> xy = clipXY(uv);
    const F z = depth * F(2.0f) - F(1.0f);
    return viewZFromClip<kSparse>(u.uInvProjection, xy, z, check);
  }

  // GLSL smoothstep(0.0, 1.0, x): (x - 0) / (1 - 0) folds to x, then Mesa's built-in
  // (glsl/builtin_functions.cpp, _smoothstep) multiplies nested to the right,
  // t * (t * (3 - 2 * t)), not left to right as the specification writes it: a rounding
  // apart, which turned one SSAO byte at t = 1.922, 201x438 (docs/porting.md, row smoothstep).
  template <class F>
  static F smoothstep01(F x) {
    const F t = clamp(x, F(0.0f), F(1.0f));
    return t * (t * (F(3.0f) - F(2.0f) * t));
  }

  // rangeCheck = smoothstep(0.0, 1.0, uRadius / range). Where range <= uRadius, for a
  // positive finite uRadius (0 / 0 and inf / inf are NaN, which the clamp makes 0), the exact
  // quotient is at least 1 or infinite, so the rounded one is too, and the clamp makes t and
  // the smoothstep exactly 1; only lanes in `counts` are added. A group whose every counted
  // lane is so skips the division, one of the sample's four: the same sum.
  template <class F, class M>
  static F rangeCheck(const Uniforms& u, F range, M counts) {
    const bool radiusFinite = u.uRadius > 0.0f && u.uRadius <= std::numeric_limits<float>::max();
    if (radiusFinite && all((!counts) | (range <= F(u.uRadius)))) return F(1.0f);
    return smoothstep01(F(u.uRadius) / range);
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    if (u.projectsSparsely && shade<true>(u, in, out)) return;
    shade<false>(u, in, out);
  }

  // The GLSL's main, its projections as projectSample<kSparse> and ReconstructViewZ<kSparse>
  // make them. Returns false, having written nothing, where a lane failed the sparse forms'
  // guards: the group is then shaded in full.
  template <bool kSparse, class F>
  static bool shade(const Uniforms& u, const Varyings<F>& in, raster::FragmentOutput<F>& out) {
    const vec2<F> uv = in.fragUV;
    const vec3<F> worldNormal = raster::texture(u.uNormal, uv).xyz() * F(2.0f) - vec3<F>(F(1.0f));
    // (uView * vec4(worldNormal, 0.0)).xyz: the w column's c3 * 0.0 and its + 0.0 fold away.
    const glm::mat4& v = u.uView;
    auto row = [&](int r) { return (F(v[0][r]) * worldNormal.x + F(v[1][r]) * worldNormal.y) + F(v[2][r]) * worldNormal.z; };
    const vec3<F> normal = normalize(vec3<F>(row(0), row(1), row(2)));
    const vec3<F> randVec = normalize(raster::texture(u.uNoise, uv * u.noiseScale).xyz());
    // Gram-Schmidt: build TBN from noise + normal
    const vec3<F> tangent = normalize(randVec - normal * dot(randVec, normal));
    const vec3<F> bitangent = cross(normal, tangent);
    // mat3 TBN = mat3(tangent, bitangent, normal): its columns.
    F occlusion = F(0.0f);
    // fragPos = ReconstructViewPos(uv): x and y are only read through samplePos, z also in
    // the range check.
    const F depth = raster::texture(u.uDepth, uv).x;
    const vec4<F> fragClip = vec4<F>(clipXY(uv).x, clipXY(uv).y, depth * F(2.0f) - F(1.0f), F(1.0f));
    const vec4<F> fragView = u.uInvProjection * fragClip;
    const vec3<F> fragPos = fragView.xyz() / fragView.w;
    F check = F(0.0f);   // the sparse forms' guards (hasSparseProjections)
    // The GLSL loop in chunks of kChunk samples, each split in three with the same
    // operations per sample, in the same order of the sum: the chunk's sample points, then
    // their depth lookups, then the tests. A GLSL compiler unrolls this constant loop and is
    // free to order it so; here it lets a chunk's lookups be in flight together instead of
    // each waiting behind the previous sample's tests.
    for (int first = 0; first < KERNEL_SIZE; first += kChunk) {
      vec2<F> offsets[kChunk];
      F sampleZ[kChunk], sampleDepth[kChunk];   // samplePos.z and the stored point's view z
      for (int k = 0; k < kChunk; ++k) {
        const glm::vec3 s = u.uSamples[size_t(first + k)];
        // TBN * uSamples[i]: column by column (docs/porting.md, row mat-vec), then * uRadius.
        const vec3<F> rotated = (tangent * F(s.x) + bitangent * F(s.y)) + normal * F(s.z);
        const vec3<F> samplePos = fragPos + rotated * F(u.uRadius);
        const vec3<F> projected = projectSample<kSparse>(u.uProjection, samplePos, check);
        F ox = projected.x, oy = projected.y;
        const F ow = projected.z;
        ox = ox / ow;
        oy = oy / ow;
        offsets[k] = vec2<F>(ox * F(0.5f) + F(0.5f), oy * F(0.5f) + F(0.5f));
        sampleZ[k] = samplePos.z;
      }
      for (int k = 0; k < kChunk; ++k) sampleDepth[k] = ReconstructViewZ<kSparse>(u, offsets[k], check);
      for (int k = 0; k < kChunk; ++k) {
        const auto occludes = sampleDepth[k] >= sampleZ[k] + F(u.uBias);
        occlusion = occlusion + select(occludes, rangeCheck(u, abs(fragPos.z - sampleDepth[k]), occludes), F(0.0f));
      }
    }
    if (kSparse && !all(check == F(0.0f))) return false;
    const F ao = F(1.0f) - occlusion / F(float(KERNEL_SIZE));
    out.color[0] = vec4<F>(ao, ao, ao, F(1.0f));
    return true;
  }
};

// This port's row in the program registry, defined in ssao.cpp.
scenes::ProgramEntry ssaoProgram();

}  // namespace shaders::pbr
