// C++ port of post.vert / lighting.frag (10 - Deferred Shading, lighting pass), line by line.
// The if / else-if chain is per lane: every side some lane takes is computed, and select()
// applied in reverse order keeps the first true branch, as GLSL does. Constant expressions
// of the unrolled loops (cos(fi * 2.5), ...) are folded by the GLSL compiler with the C
// library in float, so they are computed that way here.
#pragma once

#include <cmath>

#include "raster/shader/program.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/deferred/post.h"

namespace shaders::deferred {

using namespace raster::glsl;

struct LightingPass : PostProgram {
  static constexpr const char* kName = "deferred/post+lighting";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    glm::mat4 u_light_vp{1.0f};
    glm::vec3 u_cam_pos{0.0f};
    glm::vec3 u_light_dir{0.0f};
    float u_time = 0.0f;
    raster::Sampler2D lit_albedo, lit_normal, lit_worldpos, lit_ssao;
    raster::Sampler2DShadow shadow_map;
    raster::Sampler2D env_map;
    // Not GLSL uniforms: the three orbiting lights' positions, which depend on u_time alone,
    // computed once a draw by deriveUniforms().
    glm::vec3 light_pos[3]{};
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("u_light_vp", &Uniforms::u_light_vp),
      raster::uniform("u_cam_pos", &Uniforms::u_cam_pos),
      raster::uniform("u_light_dir", &Uniforms::u_light_dir),
      raster::uniform("u_time", &Uniforms::u_time),
      raster::uniform("lit_albedo", &Uniforms::lit_albedo),
      raster::uniform("lit_normal", &Uniforms::lit_normal),
      raster::uniform("lit_worldpos", &Uniforms::lit_worldpos),
      raster::uniform("lit_ssao", &Uniforms::lit_ssao),
      raster::uniform("shadow_map", &Uniforms::shadow_map),
      raster::uniform("env_map", &Uniforms::env_map),
  };

  static constexpr float SHADOW_DIM_F = 1024.0f;

  // lp = vec3(cos(ang) * 3.2, 1.6 + 0.6 * sin(u_time + fi), sin(ang) * 3.2) with ang =
  // u_time * 0.7 + fi * 2.0944: every lane computes the same values from the same operands,
  // so they are computed once a draw, in float, by the same operations (gl_math.h's sin and
  // cos give a float what they give each lane), where the GLSL's three sines and cosines a
  // light cost each lane group hundreds of operations.
  static void deriveUniforms(Uniforms& u) {
    for (int i = 0; i < 3; i++) {
      const float fi = float(i);
      const float ang = u.u_time * 0.7f + fi * 2.0944f;
      u.light_pos[i] = glm::vec3(raster::glsl::cos(ang) * 3.2f, 1.6f + 0.6f * raster::glsl::sin(u.u_time + fi),
                                 raster::glsl::sin(ang) * 3.2f);
    }
  }

  template <class F>
  static vec3<F> reflect3(vec3<F> i, vec3<F> nn) {
    return i - nn * (F(2.0f) * dot(nn, i));
  }

  template <class F>
  static vec2<F> equirect_uv(vec3<F> d) {
    const F u = atan(d.z, d.x) * F(0.15915494f) + F(0.5f);
    const F v = acos(clamp(d.y, F(-1.0f), F(1.0f))) * F(0.31830989f);
    return vec2<F>(u, v);
  }

  // GLSL's uv is ndc.xy * 0.5 + 0.5; it comes here as half_ndc = ndc.xy * 0.5, because
  // Mesa compiles each tap's uv + off as (0.5 + off) + half_ndc (textureCompareGrid).
  template <class F>
  static F pcf_shadow(const Uniforms& u, vec2<F> half_ndc, F ref) {
    const float texel = 1.0f / SHADOW_DIM_F;
    // The 25 texture() calls of the loop below, made at once so the sampler can share the
    // texels that neighbouring taps read: taps[j + 2][i + 2] is
    // texture(shadow_map, vec3(uv + vec2(i, j) * texel, ref)), bit for bit.
    F taps[5][5];
    raster::textureCompareGrid<2>(u.shadow_map, half_ndc, 0.5f, texel, ref, taps);
    F sum = F(0.0f);
    for (int j = -2; j < 3; j++) {
      for (int i = -2; i < 3; i++) {
        sum = sum + taps[j + 2][i + 2];
      }
    }
    return sum * F(1.0f / 25.0f);
  }

  template <class F>
  static vec3<F> point_light(vec3<F> lp, vec3<F> lcol, vec3<F> p, vec3<F> nrm, vec3<F> vdir, F shininess, F spec_i,
                             F rng) {
    const vec3<F> lvec = lp - p;
    const F d = max(length(lvec), F(0.0001f));
    const vec3<F> ldir = lvec / vec3<F>(d, d, d);
    const F ndotl = max(dot(nrm, ldir), F(0.0f));
    const F atten = pow<2.0f>(max(F(1.0f) - d / rng, F(0.0f)));
    const vec3<F> hv = normalize(ldir + vdir);
    const F spec = pow(max(dot(nrm, hv), F(0.0f)), shininess) * spec_i;
    return lcol * (ndotl + spec) * atten;
  }

  // The `else` branch: the shaded surface.
  template <class F>
  static vec3<F> shade_surface(const Uniforms& u, vec3<F> albedo, F spec_i, F shininess, vec3<F> p, vec3<F> n,
                               F ssao_factor) {
    const vec3<F> view_dir = normalize(u.u_cam_pos - p);
    // Not in the GLSL's order: both environment lookups' coordinates are computed here, and
    // their texels start loading (texturePrefetch), while the shadow and the point lights
    // are computed; the lookups themselves stay where the GLSL makes them. The same values:
    // each coordinate is computed once, from the same operands.
    const vec3<F> inc = vec3<F>(-view_dir.x, -view_dir.y, -view_dir.z);
    const vec3<F> rdir = reflect3(inc, n);
    const vec2<F> env_uv_n = equirect_uv(n), env_uv_r = equirect_uv(rdir);
    raster::texturePrefetch(u.env_map, env_uv_n);
    raster::texturePrefetch(u.env_map, env_uv_r);

    // shadowed sun: light-space NDC -> shadow uv + depth ref (GL z in [-1,1] -> [0,1])
    const vec3<F> sun_dir = normalizeUniform<F>(u.u_light_dir);   // normalize(u_light_dir), once a group
    const F ndotl_sun = max(dot(n, sun_dir), F(0.0f));
    const vec4<F> lc = u.u_light_vp * vec4<F>(p, F(1.0f));
    const F lw = max(lc.w, F(0.0001f));
    const vec3<F> ndc = vec3<F>(lc.x / lw, lc.y / lw, lc.z / lw);
    // shadow_uv = vec2(ndc.x * 0.5 + 0.5, ndc.y * 0.5 + 0.5), handed to pcf_shadow without
    // its + 0.5.
    const vec2<F> shadow_half_ndc = vec2<F>(ndc.x * F(0.5f), ndc.y * F(0.5f));
    const F ref_depth = clamp(ndc.z * F(0.5f) + F(0.5f), F(0.0f), F(1.0f));
    const F bias = max(F(0.0025f) * (F(1.0f) - ndotl_sun), F(0.0009f));
    F shadow = pcf_shadow(u, shadow_half_ndc, ref_depth - bias);
    shadow = select(ndotl_sun < F(0.05f), F(0.0f), shadow);
    const vec3<F> hv_sun = normalize(sun_dir + view_dir);
    const F spec_sun = pow(max(dot(n, hv_sun), F(0.0f)), shininess) * spec_i;
    const vec3<F> sun = vec3<F>(glm::vec3(1.25f, 1.10f, 0.80f)) * (ndotl_sun + spec_sun) * shadow;

    // three orbiting coloured point lights, from u_time
    vec3<F> pts = vec3<F>(F(0.0f), F(0.0f), F(0.0f));
    for (int i = 0; i < 3; i++) {
      const float fi = float(i);
      const vec3<F> lp = vec3<F>(u.light_pos[i]);   // deriveUniforms()
      const glm::vec3 lcol(0.5f + 0.5f * std::cos(fi * 2.5f), 0.5f + 0.5f * std::cos(fi * 2.5f + 2.0f),
                           0.5f + 0.5f * std::cos(fi * 2.5f + 4.0f));
      pts = pts + point_light(lp, vec3<F>(lcol * 1.4f), p, n, view_dir, shininess, spec_i, F(5.5f));
    }

    const F ao = clamp(ssao_factor, F(0.0f), F(1.0f));
    const F amb_t = n.y * F(0.5f) + F(0.5f);
    const vec3<F> hemi = mix(vec3<F>(glm::vec3(0.08f, 0.06f, 0.05f)), vec3<F>(glm::vec3(0.22f, 0.24f, 0.36f)),
                             vec3<F>(amb_t, amb_t, amb_t));
    const vec3<F> env_amb = raster::texture(u.env_map, env_uv_n).xyz();
    // mix with a constant t: nir_lower_flrp takes the strict form x * (1 - t) + y * t there
    // (nir_lower_flrp.c, "If t is constant"), with 1 - t folded in float.
    const vec3<F> ambient = hemi * F(1.0f - 0.4f) + env_amb * F(0.4f);

    const vec3<F> env_refl = raster::texture(u.env_map, env_uv_r).xyz();
    // fres = pow(x, 4.0) is (x * x) * (x * x) (gl_math.h), used once, in 0.7 * fres:
    // nir_opt_algebraic moves the constant into the product, (x2 * 0.7) * x2.
    const F fres_base = F(1.0f) - max(dot(n, view_dir), F(0.0f));
    const F fres_squared = pow<2.0f>(fres_base);
    const vec3<F> env_spec = env_refl * (spec_i * (F(0.10f) + (fres_squared * F(0.7f)) * fres_squared));

    const vec3<F> lighting = (ambient * ao) + (sun + pts) * (F(0.55f) + F(0.45f) * ao) + env_spec * ao;
    // linear -> sRGB for the display (the default GL framebuffer does no sRGB encode)
    const vec3<F> g = vec3<F>(F(0.4545f), F(0.4545f), F(0.4545f));
    return pow(albedo * lighting, g);
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const vec2<F> l_uv = in.l_uv;
    // ----- bottom filmstrip: raw G-buffer (albedo / normal / world-pos) + SSAO -----
    const float TH = 0.18f;
    const float GAP = 0.012f;
    const float Y0 = 0.02f;
    const auto in_strip = (l_uv.y >= F(Y0)) & (l_uv.y <= F(Y0 + TH));
    const F tv = (l_uv.y - F(Y0)) / F(TH);
    const float x0 = GAP;
    const float x1 = GAP * 2.0f + TH;
    const float x2 = GAP * 3.0f + TH * 2.0f;
    const float x3 = GAP * 4.0f + TH * 3.0f;

    const vec4<F> albedo_spec = raster::texture(u.lit_albedo, l_uv);
    const vec4<F> normal_sh = raster::texture(u.lit_normal, l_uv);
    const vec4<F> worldpos = raster::texture(u.lit_worldpos, l_uv);
    const F ssao_factor = raster::texture(u.lit_ssao, l_uv).x;
    const vec3<F> albedo = albedo_spec.xyz();
    const F spec_i = albedo_spec.w;
    const F shininess = normal_sh.w;
    const vec3<F> p = worldpos.xyz();
    const vec3<F> n_raw = normal_sh.xyz();
    const auto is_bg = dot(n_raw, n_raw) < F(0.01f);
    const vec3<F> n = select(is_bg, vec3<F>(F(0.0f), F(1.0f), F(0.0f)), normalize(n_raw));

    auto strip = [&](float x) { return in_strip & (l_uv.x >= F(x)) & (l_uv.x <= F(x + TH)); };
    const auto in0 = strip(x0), in1 = strip(x1), in2 = strip(x2), in3 = strip(x3);
    const auto surface = !(in0 | in1 | in2 | in3 | is_bg);

    vec3<F> out_col = vec3<F>(F(0.0f), F(0.0f), F(0.0f));
    if (any(surface)) out_col = shade_surface(u, albedo, spec_i, shininess, p, n, ssao_factor);
    if (any(is_bg)) {
      const F t = clamp(l_uv.y, F(0.0f), F(1.0f));
      out_col = select(is_bg, mix(vec3<F>(glm::vec3(0.10f, 0.10f, 0.16f)), vec3<F>(glm::vec3(0.34f, 0.24f, 0.26f)), vec3<F>(t, t, t)),
                       out_col);
    }
    if (any(in3)) {
      const F ao = raster::texture(u.lit_ssao, vec2<F>((l_uv.x - F(x3)) / F(TH), tv)).x;
      out_col = select(in3, vec3<F>(ao, ao, ao), out_col);
    }
    if (any(in2)) {
      const vec3<F> pp = raster::texture(u.lit_worldpos, vec2<F>((l_uv.x - F(x2)) / F(TH), tv)).xyz();
      out_col = select(in2, pp * F(0.12f) + vec3<F>(F(0.5f), F(0.5f), F(0.5f)), out_col);
    }
    if (any(in1)) {
      const vec3<F> nn = raster::texture(u.lit_normal, vec2<F>((l_uv.x - F(x1)) / F(TH), tv)).xyz();
      out_col = select(in1, nn * F(0.5f) + vec3<F>(F(0.5f), F(0.5f), F(0.5f)), out_col);
    }
    if (any(in0)) {
      out_col = select(in0, raster::texture(u.lit_albedo, vec2<F>((l_uv.x - F(x0)) / F(TH), tv)).xyz(), out_col);
    }
    out.color[0] = vec4<F>(out_col, F(1.0f));
  }
};

// This port's row in the program registry. lighting.cpp defines it: the pipeline is
// instantiated over LightingPass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry lightingProgram();

}  // namespace shaders::deferred
