// C++ port of post.vert / ssao.frag (10 - Deferred Shading, SSAO pass), line by line; the
// sample loop is split in three, with the same operations per sample (see shade()), what a
// sample makes of the two G-buffer texels it reads is one function, storedViewZ, which the
// pipeline evaluates once a texel (texelPlanes), and each sample's projection leaves out
// u_proj's zero entries where that gives the same bits (projectSample). Per-lane branches
// run under masks: both sides are computed and select() keeps the one GLSL would take,
// which gives the same values lane by lane.
#pragma once

#include <cmath>
#include <limits>

#include "raster/shader/program.h"
#include "raster/shader/texel_planes.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/deferred/post.h"

namespace shaders::deferred {

using namespace raster::glsl;

struct SsaoPass : PostProgram {
  static constexpr const char* kName = "deferred/post+ssao";
  static constexpr int kColorOutputs = 1;
  // Its 16 samples a pixel land up to SSAO_RADIUS away in the world, tens to hundreds of
  // pixels on the screen: the pipeline shades its tiles in an order that keeps neighbours
  // together (raster::samplesAroundPixel).
  static constexpr bool kSamplesAroundPixel = true;
  struct Uniforms {
    glm::mat4 u_view{1.0f};
    glm::mat4 u_proj{1.0f};
    raster::Sampler2D ssao_g_normal, ssao_g_worldpos;
    // Not a GLSL uniform: storedViewZ at every G-buffer texel, made once a draw (texelPlanes).
    raster::TexelPlane stored_vz;
    // Not a GLSL uniform: whether the matrices have the zero entries projectSample leaves
    // out, found once a draw (deriveUniforms).
    bool projectsSparsely = false;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("u_view", &Uniforms::u_view),
      raster::uniform("u_proj", &Uniforms::u_proj),
      raster::uniform("ssao_g_normal", &Uniforms::ssao_g_normal),
      raster::uniform("ssao_g_worldpos", &Uniforms::ssao_g_worldpos),
  };

  static constexpr int SSAO_K = 16;
  static constexpr float SSAO_RADIUS = 0.6f;
  static constexpr float SSAO_BIAS = 0.03f;
  static constexpr float SSAO_STRENGTH = 1.7f;

  template <class F>
  static F smoothstep3(F a, F b, F x) {
    const F t = clamp((x - a) / (b - a), F(0.0f), F(1.0f));
    return t * t * (F(3.0f) - F(2.0f) * t);
  }

  // range_check = smoothstep3(0.0, 1.0, SSAO_RADIUS / range). Where range <= SSAO_RADIUS the
  // exact quotient is at least 1, so the rounded one is too, and the clamp makes t and the
  // smoothstep exactly 1; only lanes in `counts` are added. A group whose every counted lane
  // is so skips the division (the sample's third, with the projection's two): the same sum.
  template <class F, class M>
  static F rangeCheck(F range, M counts) {
    if (all((!counts) | (range <= F(SSAO_RADIUS)))) return F(1.0f);
    return smoothstep3(F(0.0f), F(1.0f), F(SSAO_RADIUS) / range);
  }

  // What a sample makes of the G-buffer texels it reads at uv: the GLSL's
  //   stored_p = texture(ssao_g_worldpos, suv).xyz, stored_n = texture(ssao_g_normal, suv).xyz,
  //   stored_vz = (u_view * vec4(stored_p, 1.0)).z,
  // and its test dot(stored_n, stored_n) > 0.01 folded in: stored_vz where the texel holds a
  // surface, NaN where it does not. A NaN fails the test `stored_vz >= sample_vz +
  // SSAO_BIAS` that every counted sample passes too, so the two tests count the same samples.
  template <class F>
  static F storedViewZ(const Uniforms& u, vec2<F> uv) {
    const vec3<F> stored_p = raster::texture(u.ssao_g_worldpos, uv).xyz();
    const vec3<F> stored_n = raster::texture(u.ssao_g_normal, uv).xyz();
    const F stored_vz = (u.u_view * vec4<F>(stored_p, F(1.0f))).z;
    return select(dot(stored_n, stored_n) > F(0.01f), stored_vz, F(std::numeric_limits<float>::quiet_NaN()));
  }

  // Not in the GLSL: storedViewZ depends on uv only through its NEAREST lookups, so the
  // pipeline makes it once a texel before the pass, and each of the sixteen samples a pixel
  // reads one float (shader/texel_planes.h) where the GLSL reads two texels and does the
  // arithmetic: a texel is read by about sixteen samples.
  static void texelPlanes(raster::TexelPlaneMaker<Uniforms>& make) {
    make(&Uniforms::stored_vz, {&Uniforms::ssao_g_worldpos, &Uniforms::ssao_g_normal},
         [](const Uniforms& u, auto uv) { return storedViewZ(u, uv); });
  }

  // Not in the GLSL: u_proj * view_sp leaves out the entries of u_proj that are zero.
  // llvmpipe cannot know a uniform's values, so its clip.x is ((P00 vx + P10 vy) + P20 vz) +
  // P30 vw in full; a perspective projection (glm::perspective, as the scene makes it) has
  // P10 = P20 = P30 = 0, and so for clip.y and clip.w: 12 multiplies and 9 adds a sample
  // become 3 multiplies. The same bits, where:
  //  - every dropped operand is finite (else 0 * v is NaN, which the full sum would keep):
  //    vx, vy and vz are checked (their sum is finite only if each is; `guard` turns NaN in
  //    the lanes where it is not: addFiniteGuard); vw is ((0 sp.x + 0 sp.y) + 0 sp.z) + V33 for u_view's
  //    zero w row and a finite V33 (deriveUniforms checks both), so finite where sp is, and
  //    a non-finite coordinate of sp makes each of vx, vy and vz non-finite;
  //  - adding the dropped terms, each +-0, changes nothing: x + (+-0) is x for any non-zero
  //    x (NaN and infinities too); a zero sum stays a zero, whose sign may differ, and the
  //    next non-zero term gives the same value either way. So only a zero result's sign can
  //    differ, and no reader of clip sees it: clip.x / wv * 0.5 + 0.5 is 0.5 for either
  //    zero (wv >= 0.0001), and clip.w > 0.0 and max(clip.w, 0.0001) are alike for both.
  // clip.z is never read (the GLSL reads x, y and w).
  static bool hasSparseProjection(const glm::mat4& p, const glm::mat4& v) {
    return p[1][0] == 0.0f && p[2][0] == 0.0f && p[3][0] == 0.0f && p[0][1] == 0.0f && p[2][1] == 0.0f &&
           p[3][1] == 0.0f && p[0][3] == 0.0f && p[1][3] == 0.0f && p[3][3] == 0.0f && v[0][3] == 0.0f &&
           v[1][3] == 0.0f && v[2][3] == 0.0f && std::isfinite(v[3][3]);
  }
  static void deriveUniforms(Uniforms& u) { u.projectsSparsely = hasSparseProjection(u.u_proj, u.u_view); }

  // clip = u_proj * view_sp as the sample reads it (x, y and w): in full, or (kSparse, for
  // matrices hasSparseProjection accepts) with the zero entries left out, `guard` turning NaN
  // in the lanes where that could differ.
  template <bool kSparse, class F>
  [[gnu::always_inline]] static vec4<F> projectSample(const glm::mat4& p, const vec4<F>& view_sp, F& guard) {
    if constexpr (!kSparse) {
      return p * view_sp;
    } else {
      guard = addFiniteGuard(guard, view_sp.x + view_sp.y + view_sp.z);
      return vec4<F>(F(p[0][0]) * view_sp.x, F(p[1][1]) * view_sp.y, F(0.0f), F(p[2][3]) * view_sp.z);
    }
  }

  template <class F>
  static F hash21(vec2<F> p) {
    const F v = sin(dot(p, vec2<F>(F(127.1f), F(311.7f)))) * F(43758.5453f);
    return v - floor(v);
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    if (u.projectsSparsely && shade<true>(u, in, out)) return;
    shade<false>(u, in, out);
  }

  // The GLSL's main, its projection of each sample as projectSample<kSparse> makes it.
  // Returns false, having written nothing, where a lane that shows a surface cannot take the
  // sparse projection (a non-finite sample point): the group is then shaded in full.
  template <bool kSparse, class F>
  static bool shade(const Uniforms& u, const Varyings<F>& in, raster::FragmentOutput<F>& out) {
    const vec2<F> l_uv = in.l_uv;
    const vec3<F> n_raw = raster::texture(u.ssao_g_normal, l_uv).xyz();
    F ao = F(1.0f);
    const auto has_surface = dot(n_raw, n_raw) >= F(0.01f);
    if (any(has_surface)) {
      const vec3<F> n = normalize(n_raw);
      const vec3<F> p = raster::texture(u.ssao_g_worldpos, l_uv).xyz();
      const F cur_vz = (u.u_view * vec4<F>(p, F(1.0f))).z;

      vec3<F> up = vec3<F>(F(0.0f), F(1.0f), F(0.0f));
      up = select(abs(n.y) > F(0.95f), vec3<F>(F(1.0f), F(0.0f), F(0.0f)), up);
      const vec3<F> tangent = normalize(cross(up, n));
      const vec3<F> bitangent = cross(n, tangent);
      const F ang0 = hash21(l_uv * F(1024.0f)) * F(6.2831853f);

      // The GLSL loop, split in three with the same operations per sample: its sample
      // points, then what each makes of its stored texels, then the tests. A GLSL compiler
      // unrolls this constant loop and is free to order it so; here it lets the 16 reads be
      // in flight together instead of each waiting behind the previous sample's tests.
      vec2<F> suv[SSAO_K];
      F clip_w[SSAO_K], sample_vz[SSAO_K];   // what the tests read of clip and of the view-space point
      F guard = F(0.0f);   // NaN in the lanes projectSample<true> cannot vouch for
      for (int i = 0; i < SSAO_K; i++) {
        // Constant per unrolled iteration: folded by the GLSL compiler in float.
        const float fi = (float(i) + 0.5f) / float(SSAO_K);
        const F ang = ang0 + F(float(i) * 2.3998277f);
        const float rr = SSAO_RADIUS * std::sqrt(fi);
        // off = (cos(ang) * tangent + sin(ang) * bitangent) * rr + n * (rr * 0.5), used only
        // in p + off: Mesa's NIR rewrites a sum of two products used once, plus a
        // non-product, as (product + p) + product ("Reassociate add chains",
        // nir_opt_algebraic.py), so sp adds p to the first product before the second.
        const vec3<F> along = (cos(ang) * tangent + sin(ang) * bitangent) * F(rr);
        const vec3<F> sp = (along + p) + n * F(rr * 0.5f);
        // u_view * vec4(sp, 1.0) is also sample_vz's (below): computed once, as the GLSL
        // compiler's common-subexpression pass leaves it.
        const vec4<F> view_sp = u.u_view * vec4<F>(sp, F(1.0f));
        sample_vz[i] = view_sp.z;
        const vec4<F> clip = projectSample<kSparse>(u.u_proj, view_sp, guard);
        clip_w[i] = clip.w;
        const F wv = max(clip.w, F(0.0001f));
        suv[i] = vec2<F>(clip.x / wv * F(0.5f) + F(0.5f), clip.y / wv * F(0.5f) + F(0.5f));
      }
      // Lanes without a surface keep ao = 1.0 whatever their samples make.
      if (kSparse && !all((guard == F(0.0f)) | !has_surface)) return false;
      F stored_vz[SSAO_K];
      for (int i = 0; i < SSAO_K; i++)
        stored_vz[i] = raster::textureFromPlane(u.stored_vz, suv[i], [&](vec2<F> uv) { return storedViewZ(u, uv); });

      F occ = F(0.0f);
      for (int i = 0; i < SSAO_K; i++) {
        // view looks down -Z: a stored surface closer to the camera (greater z) occludes;
        // the GLSL's `dot(stored_n, stored_n) > 0.01` is inside stored_vz (storedViewZ)
        const auto occludes = (clip_w[i] > F(0.0f)) & (suv[i].x >= F(0.0f)) & (suv[i].x <= F(1.0f)) &
                              (suv[i].y >= F(0.0f)) & (suv[i].y <= F(1.0f)) &
                              (stored_vz[i] >= sample_vz[i] + F(SSAO_BIAS));
        const F range = max(abs(cur_vz - stored_vz[i]), F(0.0001f));
        occ = select(occludes, occ + rangeCheck(range, occludes), occ);
      }
      ao = select(has_surface, clamp(F(1.0f) - F(SSAO_STRENGTH) * occ / F(float(SSAO_K)), F(0.0f), F(1.0f)), ao);
    }
    out.color[0] = vec4<F>(ao, ao, ao, F(1.0f));
    return true;
  }
};

// This port's row in the program registry. ssao.cpp defines it: the pipeline is
// instantiated over SsaoPass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry ssaoProgram();

}  // namespace shaders::deferred
