// C++ port of main.vert / main.frag (08 - The Shadow Map, main pass), line by line.
// Differences forced by C++: uniform branches are plain `if`s on uniforms; per-lane
// branches and ternaries are select().
// Differences forced by Mesa's compiler (docs/porting.md, the rows named):
//   - GLSL's u_proj * u_view * world is (u_proj * u_view) * world; GLSL IR rewrites a
//     matrix product times a vector as u_proj * (u_view * world), and vertex() computes
//     that (mat-mat-vec);
//   - each PCF tap's uv + off is (0.5 + off) + ndc.xy * 0.5 (const-add-chain, pcf_shadow);
//   - albedo * diffuse is (albedo * sun) * (ndotl * lit) (graft + rebalance, fragment());
//   - pow(x, 48.0) has a literal exponent: pow<48.0f> (pow-literal); where the target is
//     RGBA8, powWithin<48.0f> (x^32 * x^16) serves the groups whose bytes its bound cannot
//     move (docs/porting.md, section 5, "Bytes, not floats").
#pragma once

#include "raster/merge/unorm8_within.h"
#include "raster/shader/program.h"
#include "scenes/program_entry.h"

namespace shaders::shadow {

using namespace raster::glsl;

struct MainPass {
  static constexpr const char* kName = "shadow/main";
  static constexpr int kColorOutputs = 1;

  struct Uniforms {
    glm::mat4 u_light_vp{1.0f};
    glm::mat4 u_model{1.0f};
    glm::mat4 u_view{1.0f};
    glm::mat4 u_proj{1.0f};
    glm::vec3 u_light_dir{0.0f};
    glm::vec3 u_cam_pos{0.0f};
    float u_is_floor = 0.0f;
    raster::Sampler2DShadow shadow_map;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("u_light_vp", &Uniforms::u_light_vp), raster::uniform("u_model", &Uniforms::u_model),
      raster::uniform("u_view", &Uniforms::u_view),         raster::uniform("u_proj", &Uniforms::u_proj),
      raster::uniform("u_light_dir", &Uniforms::u_light_dir), raster::uniform("u_cam_pos", &Uniforms::u_cam_pos),
      raster::uniform("u_is_floor", &Uniforms::u_is_floor), raster::uniform("shadow_map", &Uniforms::shadow_map),
  };

  template <class F>
  struct Varyings {
    vec3<F> v_world_pos;
    vec3<F> v_world_normal;
    vec4<F> v_light_space;
  };

  template <class F>
  static void vertex(const Uniforms& u, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    const vec3<F> a_pos = in.attribute[0].xyz();
    const vec3<F> a_normal = in.attribute[1].xyz();
    const vec4<F> world = u.u_model * vec4<F>(a_pos, F(1.0f));
    out.v_world_pos = world.xyz();
    // model is rotation + uniform scale only, so a (normal, 0) multiply is correct
    out.v_world_normal = (u.u_model * vec4<F>(a_normal, F(0.0f))).xyz();
    out.v_light_space = u.u_light_vp * world;
    gl_Position = u.u_proj * (u.u_view * world);
  }

  static constexpr float SHADOW_DIM_F = 1024.0f;

  // 3x3 PCF: average 9 taps over a one-texel radius; each tap is a hardware 2x2 compare.
  // GLSL's uv is ndc.xy * 0.5 + 0.5; it comes here as half_ndc = ndc.xy * 0.5, because
  // Mesa compiles each tap's uv + off as (0.5 + off) + half_ndc (textureCompareGrid).
  template <class F>
  static F pcf_shadow(const Uniforms& u, vec2<F> half_ndc, F ref) {
    const float texel = 1.0f / SHADOW_DIM_F;
    // The 9 texture() calls of the loop below, made at once so the sampler can share the
    // texels that neighbouring taps read: taps[j + 1][i + 1] is
    // texture(shadow_map, vec3(uv + vec2(i, j) * texel, ref)), bit for bit.
    F taps[3][3];
    raster::textureCompareGrid<1>(u.shadow_map, half_ndc, 0.5f, texel, ref, taps);
    F sum = F(0.0f);
    for (int j = -1; j < 2; j++) {
      for (int i = -1; i < 2; i++) {
        sum += taps[j + 1][i + 1];
      }
    }
    return sum * F(1.0f / 9.0f);
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const vec3<F> n = normalize(in.v_world_normal);
    const vec3<F> l = normalizeUniform<F>(u.u_light_dir);   // normalize(u_light_dir), once a group
    const F ndotl = max(dot(n, l), F(0.0f));
    const vec3<F> v = normalize(u.u_cam_pos - in.v_world_pos);
    // Light-space NDC -> [0, 1] uv and depth reference.
    const F w = max(in.v_light_space.w, F(0.0001f));
    const vec3<F> ndc = in.v_light_space.xyz() / vec3<F>(w, w, w);
    // shadow_uv = ndc.xy * 0.5 + vec2(0.5, 0.5), handed to pcf_shadow without its + 0.5.
    const vec2<F> shadow_half_ndc = ndc.xy() * F(0.5f);
    const F ref_depth = ndc.z * F(0.5f) + F(0.5f);
    // N.L-scaled bias on top of the pipeline's polygon offset.
    const F bias = max(F(0.0025f) * (F(1.0f) - ndotl), F(0.0008f));
    // Faces turned away from the light are in shadow regardless of the depth test. Their
    // lookup's result is thrown away, so a group whose every lane is turned away does not
    // make it: texture() has no side effect, and the bytes are the same either way.
    const auto turned_away = ndotl < F(0.05f);
    F lit = F(0.0f);
    if (!all(turned_away)) lit = pcf_shadow(u, shadow_half_ndc, ref_depth - bias);
    lit = select(turned_away, F(0.0f), lit);
    // Hemisphere ambient: warm-ish sky overhead blended to a dim ground bounce, by n.y.
    const F amb_t = n.y * F(0.5f) + F(0.5f);
    const vec3<F> ambient = mix(vec3<F>(glm::vec3(0.10f, 0.09f, 0.08f)), vec3<F>(glm::vec3(0.30f, 0.34f, 0.42f)),
                                vec3<F>(amb_t, amb_t, amb_t));
    const vec3<F> sun = vec3<F>(glm::vec3(1.30f, 1.15f, 0.90f));
    // Albedo: a checkerboard on the floor, a warm solid on the cube.
    vec3<F> albedo;
    F spec_strength = F(0.5f);
    if (u.u_is_floor > 0.5f) {
      const F gx = floor(in.v_world_pos.x * F(0.5f) + F(100.0f));
      const F gz = floor(in.v_world_pos.z * F(0.5f) + F(100.0f));
      const F cell = gx + gz;
      const F parity = cell - floor(cell * F(0.5f)) * F(2.0f);
      const F checker = select(parity < F(0.5f), F(0.85f), F(0.30f));
      albedo = vec3<F>(checker, checker, checker) * glm::vec3(0.80f, 0.82f, 0.88f);
      spec_strength = F(0.15f);
    } else {
      albedo = vec3<F>(glm::vec3(0.85f, 0.45f, 0.30f));
    }
    // Blinn-Phong specular, killed in shadow along with the diffuse.
    const vec3<F> hvec = normalize(l + v);
    const F n_dot_h = max(dot(n, hvec), F(0.0f));
    // diffuse = sun * ndotl * lit is used once, so GLSL IR grafts it into albedo * diffuse:
    // albedo * ((sun * ndotl) * lit), a tree of products alone, which Mesa's
    // do_rebalance_tree (opt_rebalance_tree.cpp) balances as (albedo * sun) * (ndotl * lit).
    const vec3<F> albedo_diffuse = (albedo * sun) * (ndotl * lit);
    // col = ambient * albedo + albedo_diffuse + vec3(spec), with spec = pow(n_dot_h, 48.0) *
    // lit * spec_strength, for the pow given.
    const auto colorWith = [&](F pow48) {
      const F spec = pow48 * lit * spec_strength;
      return ambient * albedo + albedo_diffuse + vec3<F>(spec, spec, spec);
    };
    // An RGBA8 target keeps only col's bytes. There pow(x, 48.0) by products, within a
    // measured bound of llvmpipe's pow, serves every group whose bytes that bound cannot move
    // (docs/porting.md, section 5); other groups take llvmpipe's pow.
    if (out.keepsUnorm8Only(0)) {
      const auto pow48 = powWithin<48.0f>(n_dot_h);
      const vec3<F> col = colorWith(pow48.value);
      // The bound carried through spec's two products and col's last sum (their roundings:
      // under 2^-20 for col below 8; above that the byte is 255 either way).
      const F error = pow48.error * lit * spec_strength * F(1.0f + 0x1p-20f) + F(0x1p-20f);
      if (all(raster::merge::unorm8Within(col.x, error) & raster::merge::unorm8Within(col.y, error) &
              raster::merge::unorm8Within(col.z, error))) {
        out.color[0] = vec4<F>(col, F(1.0f));
        return;
      }
    }
    out.color[0] = vec4<F>(colorWith(pow<48.0f>(n_dot_h)), F(1.0f));
  }
};

// This port's row in the program registry. main.cpp defines it: the pipeline is
// instantiated over MainPass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry mainProgram();

}  // namespace shaders::shadow
