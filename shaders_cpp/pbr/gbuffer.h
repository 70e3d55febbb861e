// C++ port of gbuffer.vert / gbuffer.frag (seed 004, geometry pass), line by line. The
// material branch is on a uniform, so it is a plain `if`.
#pragma once

#include "raster/shader/program.h"
#include "scenes/program_entry.h"

namespace shaders::pbr {

using namespace raster::glsl;

struct GBufferPass {
  static constexpr const char* kName = "pbr/gbuffer";
  static constexpr int kColorOutputs = 4;
  struct Uniforms {
    glm::mat4 u_model{1.0f};
    glm::mat4 u_view{1.0f};
    glm::mat4 u_proj{1.0f};
    float uMaterial = 0.0f;   // 0 = cat, 1 = floor
    raster::Sampler2D uAlbedoMap, uNormalMap, uMRAMap;
    raster::Sampler2D uFloorAlbedoMap, uFloorNormalMap, uFloorRoughnessMap, uFloorAOMap;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("u_model", &Uniforms::u_model),
      raster::uniform("u_view", &Uniforms::u_view),
      raster::uniform("u_proj", &Uniforms::u_proj),
      raster::uniform("uMaterial", &Uniforms::uMaterial),
      raster::uniform("uAlbedoMap", &Uniforms::uAlbedoMap),
      raster::uniform("uNormalMap", &Uniforms::uNormalMap),
      raster::uniform("uMRAMap", &Uniforms::uMRAMap),
      raster::uniform("uFloorAlbedoMap", &Uniforms::uFloorAlbedoMap),
      raster::uniform("uFloorNormalMap", &Uniforms::uFloorNormalMap),
      raster::uniform("uFloorRoughnessMap", &Uniforms::uFloorRoughnessMap),
      raster::uniform("uFloorAOMap", &Uniforms::uFloorAOMap),
  };

  template <class F>
  struct Varyings {
    vec3<F> fragPos;
    vec3<F> fragNormal;
    vec2<F> fragUV;
  };

  template <class F>
  static void vertex(const Uniforms& u, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    const vec3<F> a_pos = in.attribute[0].xyz();
    const vec3<F> a_normal = in.attribute[1].xyz();
    const vec2<F> a_uv = in.attribute[2].xy();
    const vec4<F> world = u.u_model * vec4<F>(a_pos, F(1.0f));
    out.fragPos = world.xyz();
    out.fragNormal = normalize((u.u_model * vec4<F>(a_normal, F(0.0f))).xyz());
    out.fragUV = a_uv;
    gl_Position = u.u_proj * (u.u_view * world);   // u_proj * u_view * world (docs/porting.md, row mat-mat-vec)
  }

  // Derivative-based TBN (Schueler 2010): a tangent frame from screen-space derivatives of
  // world position + uv.
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
    vec3<F> normal = normalize(in.fragNormal);
    vec3<F> albedo, mra, tn;
    vec2<F> uv;
    if (u.uMaterial > 0.5f) {
      uv = vec2<F>(in.fragPos.x, in.fragPos.z) * F(0.35f);
      // Not in the GLSL: the other maps' texels start loading while the first lookup waits
      // on its own (sampler.h, texturePrefetch), and then all four maps' texels of the block
      // usually shaded next (nextBlockCoords, program.h); no value changes.
      raster::texturePrefetch(u.uFloorRoughnessMap, uv);
      raster::texturePrefetch(u.uFloorAOMap, uv);
      raster::texturePrefetch(u.uFloorNormalMap, uv);
      const vec2<F> next = raster::nextBlockCoords(uv);
      raster::texturePrefetch(u.uFloorAlbedoMap, next);
      raster::texturePrefetch(u.uFloorRoughnessMap, next);
      raster::texturePrefetch(u.uFloorAOMap, next);
      raster::texturePrefetch(u.uFloorNormalMap, next);
      albedo = raster::texture(u.uFloorAlbedoMap, uv).xyz();
      mra = vec3<F>(F(0.0f), raster::texture(u.uFloorRoughnessMap, uv).x, raster::texture(u.uFloorAOMap, uv).x);
      tn = raster::texture(u.uFloorNormalMap, uv).xyz() * F(2.0f) - vec3<F>(F(1.0f));
    } else {
      uv = in.fragUV;
      raster::texturePrefetch(u.uMRAMap, uv);   // as the floor's, above
      raster::texturePrefetch(u.uNormalMap, uv);
      const vec2<F> next = raster::nextBlockCoords(uv);
      raster::texturePrefetch(u.uAlbedoMap, next);
      raster::texturePrefetch(u.uMRAMap, next);
      raster::texturePrefetch(u.uNormalMap, next);
      albedo = raster::texture(u.uAlbedoMap, uv).xyz();
      const vec3<F> arm = raster::texture(u.uMRAMap, uv).xyz();
      mra = vec3<F>(arm.z, arm.y, arm.x);
      tn = raster::texture(u.uNormalMap, uv).xyz() * F(2.0f) - vec3<F>(F(1.0f));
    }
    normal = perturb_normal(normal, in.fragPos, uv, normalize(tn));
    // Encode normal to [0,1] range for storage
    out.color[1] = vec4<F>(normal * F(0.5f) + vec3<F>(F(0.5f)), F(1.0f));
    out.color[0] = vec4<F>(albedo, F(1.0f));
    out.color[2] = vec4<F>(mra, F(1.0f));
    out.color[3] = vec4<F>(F(0.0f), F(0.0f), F(0.0f), F(1.0f));
  }
};

// This port's row in the program registry, defined in gbuffer.cpp (the pipeline is
// instantiated over GBufferPass there, once).
scenes::ProgramEntry gbufferProgram();

}  // namespace shaders::pbr
