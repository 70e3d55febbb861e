// C++ port of post.vert / lighting.frag (seed 004, lighting pass), line by line. Branches on
// per-pixel values (the sky, the cascade) run under masks: each side some lane takes is
// computed and select() keeps the one GLSL takes.
#pragma once

#include <array>

#include "raster/shader/program.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/pbr/post.h"

namespace shaders::pbr {

using namespace raster::glsl;

struct LightingPass : PostProgram {
  static constexpr const char* kName = "pbr/post+lighting";
  static constexpr int kColorOutputs = 1;
  static constexpr int NUM_CASCADES = 3;
  static constexpr int NUM_POINT_LIGHTS = 3;
  static constexpr float PI = 3.14159265359f;
  struct Uniforms {
    raster::Sampler2D gAlbedo, gNormal, gMRA, gEmissive, gDepth, uSSAO;
    raster::Sampler2DShadow uShadowMap0, uShadowMap1, uShadowMap2;
    std::array<glm::mat4, NUM_CASCADES> uLightVP{};
    std::array<float, NUM_CASCADES - 1> cascadeSplits{};
    glm::mat4 uInvViewProj{1.0f};
    glm::mat4 uView{1.0f};
    glm::vec3 uCamPos{0.0f};
    glm::vec3 uSunDir{0.0f, 1.0f, 0.0f};
    glm::vec3 uSunColor{1.0f};
    std::array<glm::vec3, NUM_POINT_LIGHTS> uPointPos{};
    std::array<glm::vec3, NUM_POINT_LIGHTS> uPointColor{};
    float uRoughnessFloor = 0.0f;
    float uExposure = 1.0f;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("gAlbedo", &Uniforms::gAlbedo),
      raster::uniform("gNormal", &Uniforms::gNormal),
      raster::uniform("gMRA", &Uniforms::gMRA),
      raster::uniform("gEmissive", &Uniforms::gEmissive),
      raster::uniform("gDepth", &Uniforms::gDepth),
      raster::uniform("uSSAO", &Uniforms::uSSAO),
      raster::uniform("uShadowMap0", &Uniforms::uShadowMap0),
      raster::uniform("uShadowMap1", &Uniforms::uShadowMap1),
      raster::uniform("uShadowMap2", &Uniforms::uShadowMap2),
      raster::uniform("uLightVP", &Uniforms::uLightVP),
      raster::uniform("cascadeSplits", &Uniforms::cascadeSplits),
      raster::uniform("uInvViewProj", &Uniforms::uInvViewProj),
      raster::uniform("uView", &Uniforms::uView),
      raster::uniform("uCamPos", &Uniforms::uCamPos),
      raster::uniform("uSunDir", &Uniforms::uSunDir),
      raster::uniform("uSunColor", &Uniforms::uSunColor),
      raster::uniform("uPointPos", &Uniforms::uPointPos),
      raster::uniform("uPointColor", &Uniforms::uPointColor),
      raster::uniform("uRoughnessFloor", &Uniforms::uRoughnessFloor),
      raster::uniform("uExposure", &Uniforms::uExposure),
  };

  template <class F>
  static vec3<F> ReconstructPosition(F depth, vec2<F> uv, const glm::mat4& invVP) {
    const vec4<F> clip = vec4<F>(uv.x * F(2.0f) - F(1.0f), uv.y * F(2.0f) - F(1.0f), depth * F(2.0f) - F(1.0f), F(1.0f));
    const vec4<F> world = invVP * clip;
    return world.xyz() / world.w;
  }

  // 1.0 / vec2(textureSize(shadowMap, 0)): one per map, the same division.
  static float texelSizeOf(const raster::Sampler2DShadow& map) { return 1.0f / float(map.texture->width); }

  template <class F>
  static F ShadowPCF(const raster::Sampler2DShadow& shadowMap, vec4<F> lightSpacePos, F bias) {
    vec3<F> projCoords = lightSpacePos.xyz() / lightSpacePos.w;
    projCoords = projCoords * F(0.5f) + vec3<F>(F(0.5f));
    F shadow = F(0.0f);
    const float texelSize = texelSizeOf(shadowMap);   // the maps are square
    // The 25 texture() calls of the loop, made at once so neighbouring taps share texels:
    // taps[y + 2][x + 2] is texture(shadowMap, vec3(projCoords.xy + vec2(x, y) * texelSize,
    // projCoords.z - bias)), bit for bit (origin 0: the offset is not a constant, so nothing
    // is folded into it).
    F taps[5][5];
    raster::textureCompareGrid<2>(shadowMap, projCoords.xy(), 0.0f, texelSize, projCoords.z - bias, taps);
    for (int x = -2; x <= 2; ++x) {
      for (int y = -2; y <= 2; ++y) {
        shadow = shadow + taps[y + 2][x + 2];
      }
    }
    return shadow / F(25.0f);
  }

  // GGX Normal Distribution Function
  template <class F>
  static F D_GGX(F NdotH, F roughness) {
    const F a = roughness * roughness;
    const F a2 = a * a;
    // NdotH * NdotH * (a2 - 1.0) + 1.0, distributed by Mesa's NIR into (1 - n2) + a2 * n2
    // (docs/porting.md, row lerp-detect; read in Mesa's dump, section 3).
    const F NdotH2 = NdotH * NdotH;
    const F d = (F(1.0f) - NdotH2) + a2 * NdotH2;
    return a2 / (F(PI) * d * d);
  }

  // Smith Geometry function (combined masking + shadowing)
  template <class F>
  static F G_Smith(F NdotV, F NdotL, F roughness) {
    const F r = roughness + F(1.0f);
    const F k = (r * r) / F(8.0f);   // direct lighting remapping
    const F gv = NdotV / (NdotV * (F(1.0f) - k) + k);
    const F gl = NdotL / (NdotL * (F(1.0f) - k) + k);
    return gv * gl;
  }

  // Fresnel-Schlick
  template <class F>
  static vec3<F> F_Schlick(F cosTheta, vec3<F> F0) {
    const F p = pow<5.0f>(clamp(F(1.0f) - cosTheta, F(0.0f), F(1.0f)));
    return F0 + (vec3<F>(F(1.0f)) - F0) * p;
  }

  // Full Cook-Torrance specular term
  template <class F>
  static vec3<F> CookTorranceSpecular(vec3<F> N, vec3<F> V, vec3<F> L, vec3<F> F0, F roughness) {
    const vec3<F> H = normalize(V + L);
    const F NdotH = max(dot(N, H), F(0.0f));
    const F NdotV = max(dot(N, V), F(0.0f));
    const F NdotL = max(dot(N, L), F(0.0f));
    const F D = D_GGX(NdotH, roughness);
    const F G = G_Smith(NdotV, NdotL, roughness);
    const vec3<F> Fr = F_Schlick(max(dot(H, V), F(0.0f)), F0);
    return (D * G * Fr) / (F(4.0f) * NdotV * NdotL + F(0.0001f));
  }

  // ACES filmic tone map approximation (Narkowicz 2015)
  template <class F>
  static vec3<F> ACESFilmic(vec3<F> x) {
    const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    auto one = [&](F v) {
      return clamp((v * (F(a) * v + F(b))) / (v * (F(c) * v + F(d)) + F(e)), F(0.0f), F(1.0f));
    };
    return vec3<F>(one(x.x), one(x.y), one(x.z));
  }

  template <class F>
  static vec3<F> DirectLight(vec3<F> N, vec3<F> V, vec3<F> L, vec3<F> radiance, vec3<F> albedo, F metallic, F roughness,
                             vec3<F> F0) {
    const vec3<F> kD = (vec3<F>(F(1.0f)) - F_Schlick(max(dot(normalize(V + L), V), F(0.0f)), F0)) * (F(1.0f) - metallic);
    const vec3<F> specular = CookTorranceSpecular(N, V, L, F0, roughness);
    const F NdotL = max(dot(N, L), F(0.0f));
    const vec3<F> brdf = kD * albedo / F(PI) + specular;
    const vec3<F> lit = radiance * NdotL;
    return brdf * lit;
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const vec2<F> uv = in.fragUV;
    vec3<F> color = mix(vec3<F>(glm::vec3(0.30f, 0.36f, 0.46f)), vec3<F>(glm::vec3(0.62f, 0.70f, 0.82f)),
                        vec3<F>(uv.y));   // the sky
    const vec4<F> emissiveFlag = raster::texture(u.gEmissive, uv);
    const auto geometry = emissiveFlag.w > F(0.5f);
    if (any(geometry)) {
      const F depth = raster::texture(u.gDepth, uv).x;
      const vec3<F> P = ReconstructPosition(depth, uv, u.uInvViewProj);
      const vec3<F> N = normalize(raster::texture(u.gNormal, uv).xyz() * F(2.0f) - vec3<F>(F(1.0f)));
      const vec3<F> albedo = pow<2.2f>(raster::texture(u.gAlbedo, uv).xyz());   // sRGB texels -> linear
      const vec3<F> mra = raster::texture(u.gMRA, uv).xyz();
      const F metallic = mra.x;
      const F roughness = max(mra.y, F(u.uRoughnessFloor));
      const F ao = mra.z * raster::texture(u.uSSAO, uv).x;
      const vec3<F> emissive = emissiveFlag.xyz();
      const vec3<F> V = normalize(u.uCamPos - P);
      // mix(vec3(0.04), albedo, metallic): the three components share (x, t), so
      // nir_lower_flrp takes the strict form x * (1 - t) + y * t (docs/porting.md, row mix).
      const F F0_base = F(0.04f) * (F(1.0f) - metallic);
      const vec3<F> F0 = vec3<F>(F0_base) + albedo * metallic;

      const F viewDepth = -(u.uView * vec4<F>(P, F(1.0f))).z;
      // GetCascadeIndex(viewDepth), its loop unrolled: the first split above viewDepth.
      const auto in0 = viewDepth < F(u.cascadeSplits[0]);
      const auto in1 = (!in0) & (viewDepth < F(u.cascadeSplits[1]));
      const auto in2 = !(in0 | in1);
      const F NdotSun = max(dot(N, vec3<F>(u.uSunDir)), F(0.0f));
      const F bias = max(F(0.0015f) * (F(1.0f) - NdotSun), F(0.0004f));
      // CascadeShadow(cascade, P, bias): each cascade's PCF for the lanes that take it.
      F shadow = F(0.0f);
      const raster::Sampler2DShadow* maps[NUM_CASCADES] = {&u.uShadowMap0, &u.uShadowMap1, &u.uShadowMap2};
      const decltype(in0) takes[NUM_CASCADES] = {in0 & geometry, in1 & geometry, in2 & geometry};
      for (int c = 0; c < NUM_CASCADES; ++c)
        if (any(takes[c])) shadow = select(takes[c], ShadowPCF(*maps[c], u.uLightVP[size_t(c)] * vec4<F>(P, F(1.0f)), bias), shadow);

      vec3<F> Lo = DirectLight(N, V, vec3<F>(u.uSunDir), u.uSunColor * vec3<F>(shadow), albedo, metallic, roughness, F0);
      for (int i = 0; i < NUM_POINT_LIGHTS; ++i) {
        const vec3<F> toLight = u.uPointPos[size_t(i)] - P;
        const F dist2 = dot(toLight, toLight);
        const F dist = sqrt(dist2);   // length(toLight)
        const vec3<F> L = toLight / dist;
        // dist * dist is sqrt(x) * sqrt(x), which Mesa's NIR folds back to x, the dot itself
        // (docs/porting.md, row sqrt-square).
        Lo = Lo + DirectLight(N, V, L, vec3<F>(u.uPointColor[size_t(i)]) / dist2, albedo, metallic, roughness, F0);
      }
      const vec3<F> ambient = vec3<F>(F(0.03f)) * albedo * ao;
      color = select(geometry, ambient + Lo + emissive, color);
    }
    vec3<F> hdrColor = color;
    // Exposure adjustment before tone mapping
    hdrColor = hdrColor * F(u.uExposure);
    vec3<F> ldr = ACESFilmic(hdrColor);
    // Gamma correction (linear -> sRGB): 1.0 / 2.2 folded in float
    ldr = pow<1.0f / 2.2f>(ldr);
    out.color[0] = vec4<F>(ldr, F(1.0f));
  }
};

// This port's row in the program registry, defined in lighting.cpp.
scenes::ProgramEntry lightingProgram();

}  // namespace shaders::pbr
