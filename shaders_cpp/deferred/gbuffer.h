// C++ port of gbuffer.vert / gbuffer.frag (10 - Deferred Shading, geometry pass), line by
// line. The material branch is on a uniform, so it is a plain `if`.
#pragma once

#include "raster/shader/program.h"
#include "scenes/program_entry.h"

namespace shaders::deferred {

using namespace raster::glsl;

struct GBufferPass {
  static constexpr const char* kName = "deferred/gbuffer";
  static constexpr int kColorOutputs = 3;
  struct Uniforms {
    glm::mat4 u_model{1.0f};
    glm::mat4 u_view{1.0f};
    glm::mat4 u_proj{1.0f};
    float u_material = 0.0f;   // 0 = cat, 1 = floor
    raster::Sampler2D cat_albedo, cat_normal, cat_arm;
    raster::Sampler2D floor_albedo, floor_normal, floor_ao, floor_roughness;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("u_model", &Uniforms::u_model),
      raster::uniform("u_view", &Uniforms::u_view),
      raster::uniform("u_proj", &Uniforms::u_proj),
      raster::uniform("u_material", &Uniforms::u_material),
      raster::uniform("cat_albedo", &Uniforms::cat_albedo),
      raster::uniform("cat_normal", &Uniforms::cat_normal),
      raster::uniform("cat_arm", &Uniforms::cat_arm),
      raster::uniform("floor_albedo", &Uniforms::floor_albedo),
      raster::uniform("floor_normal", &Uniforms::floor_normal),
      raster::uniform("floor_ao", &Uniforms::floor_ao),
      raster::uniform("floor_roughness", &Uniforms::floor_roughness),
  };

  template <class F>
  struct Varyings {
    vec3<F> gv_world_pos;
    vec3<F> gv_world_normal;
    vec2<F> gv_uv;
  };

  template <class F>
  static void vertex(const Uniforms& u, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    const vec3<F> a_pos = in.attribute[0].xyz();
    const vec3<F> a_normal = in.attribute[1].xyz();
    const vec2<F> a_uv = in.attribute[2].xy();
    const vec4<F> world = u.u_model * vec4<F>(a_pos, F(1.0f));
    out.gv_world_pos = world.xyz();
    out.gv_world_normal = normalize((u.u_model * vec4<F>(a_normal, F(0.0f))).xyz());
    out.gv_uv = a_uv;
    gl_Position = u.u_proj * (u.u_view * world);
  }

  // Derivative-based TBN (Schueler 2010): a tangent frame from screen-space derivatives of
  // world position + uv, no per-vertex tangent buffer.
  template <class F>
  static vec3<F> perturb_normal(vec3<F> nrm, vec3<F> p, vec2<F> uv, vec3<F> tn) {
    const vec3<F> dp1 = raster::dFdx(p);
    const vec3<F> dp2 = raster::dFdy(p);
    const vec2<F> duv1 = raster::dFdx(uv);
    const vec2<F> duv2 = raster::dFdy(uv);
    const vec3<F> dp2perp = cross(dp2, nrm);
    const vec3<F> dp1perp = cross(nrm, dp1);
    const vec3<F> T = dp2perp * duv1.x + dp1perp * duv2.x;
    const vec3<F> B = dp2perp * duv1.y + dp1perp * duv2.y;
    const F invmax = F(1.0f) / sqrt(max(dot(T, T), dot(B, B)));
    return normalize(T * (tn.x * invmax) + B * (tn.y * invmax) + nrm * tn.z);
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const vec3<F> n = normalize(in.gv_world_normal);
    vec3<F> albedo = vec3<F>(F(0.0f), F(0.0f), F(0.0f));
    F spec_i = F(0.0f);
    F shininess = F(32.0f);
    vec3<F> perturbed = n;
    // sRGB albedo textures -> linear so the deferred lighting is done in linear space.
    const vec3<F> sRGB = vec3<F>(F(2.2f), F(2.2f), F(2.2f));
    if (u.u_material > 0.5f) {
      const vec2<F> uv = vec2<F>(in.gv_world_pos.x, in.gv_world_pos.z) * F(0.35f);
      // Not in the GLSL: the other three maps' texels start loading now, while the first
      // lookup waits on its own (sampler.h, texturePrefetch), and then all four maps' texels
      // of the block usually shaded next (nextBlockCoords, program.h). No value changes.
      raster::texturePrefetch(u.floor_albedo, uv);
      raster::texturePrefetch(u.floor_roughness, uv);
      raster::texturePrefetch(u.floor_normal, uv);
      const vec2<F> next = raster::nextBlockCoords(uv);
      raster::texturePrefetch(u.floor_ao, next);
      raster::texturePrefetch(u.floor_albedo, next);
      raster::texturePrefetch(u.floor_roughness, next);
      raster::texturePrefetch(u.floor_normal, next);
      const F fb_ao = raster::texture(u.floor_ao, uv).x;
      albedo = pow(raster::texture(u.floor_albedo, uv).xyz(), sRGB) * (F(0.5f) + F(0.5f) * fb_ao);
      spec_i = (F(1.0f) - raster::texture(u.floor_roughness, uv).x) * F(0.4f);
      shininess = F(24.0f);
      // boost the tangent xy so the mortar reads, then renormalize
      const vec3<F> tn_raw = raster::texture(u.floor_normal, uv).xyz() * F(2.0f) - vec3<F>(F(1.0f), F(1.0f), F(1.0f));
      const vec3<F> tn = normalize(vec3<F>(tn_raw.x * F(3.0f), tn_raw.y * F(3.0f), tn_raw.z));
      perturbed = perturb_normal(n, in.gv_world_pos, uv, tn);
    } else {
      raster::texturePrefetch(u.cat_arm, in.gv_uv);   // as the floor's, above
      raster::texturePrefetch(u.cat_normal, in.gv_uv);
      const vec2<F> next = raster::nextBlockCoords(in.gv_uv);
      raster::texturePrefetch(u.cat_albedo, next);
      raster::texturePrefetch(u.cat_arm, next);
      raster::texturePrefetch(u.cat_normal, next);
      const vec3<F> alb = pow(raster::texture(u.cat_albedo, in.gv_uv).xyz(), sRGB);
      const vec3<F> arm = raster::texture(u.cat_arm, in.gv_uv).xyz();
      albedo = alb * (F(0.55f) + F(0.45f) * arm.x);
      spec_i = (F(1.0f) - arm.y) * F(0.6f);
      shininess = F(48.0f);
      const vec3<F> tn = normalize(raster::texture(u.cat_normal, in.gv_uv).xyz() * F(2.0f) - vec3<F>(F(1.0f), F(1.0f), F(1.0f)));
      perturbed = perturb_normal(n, in.gv_world_pos, in.gv_uv, tn);
    }
    out.color[0] = vec4<F>(albedo, spec_i);
    out.color[1] = vec4<F>(perturbed, shininess);
    out.color[2] = vec4<F>(in.gv_world_pos, F(u.u_material));
  }
};

// This port's row in the program registry. gbuffer.cpp defines it: the pipeline is
// instantiated over GBufferPass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry gbufferProgram();

}  // namespace shaders::deferred
