// C++ port of scene.vert / scene.frag (11 - HDR + Bloom, pass 1: the instanced swarm into
// the RGBA16F target), line by line.
// Differences forced by C++ or by what Mesa's compiler does to the GLSL:
//   - u_proj * u_view * v is evaluated as u_proj * (u_view * v), as Mesa's GLSL optimizer does;
//   - normalize(vec3(0.5, 1.0, 0.3)) is a constant GLSL IR folds in float32, where its dot
//     loop adds (x + y) + z (ir_constant_expression.cpp): folded_l() (for this vector either
//     order gives the same bits);
//   - rotated + a_offset is reassociated by the compiler (see the vertex shader);
//   - EMISSIVE_BOOST - 1.0 is folded to 7.0;
//   - vec3(0.25, 0.35, 0.55) * rim * 0.4: GLSL IR's opt_algebraic reassociates the two
//     constants (reassociate_constant), so the shader computes (vec3(...) * 0.4) * rim,
//     with the constant product folded in float32 (measured: written left to right instead,
//     7932 pixels of an RGBA32F scene target at t = 1 differ from GL; this way, none);
//   - pow(x, 2.5) has a literal exponent: pow<2.5f> (gl_math.h).
#pragma once

#include <cmath>

#include "raster/shader/program.h"
#include "scenes/program_entry.h"

namespace shaders::hdr {

using namespace raster::glsl;

struct ScenePass {
  static constexpr const char* kName = "hdr/scene";
  static constexpr int kColorOutputs = 1;
  // No dFdx / dFdy and no texture(): each lane's colour is its own inputs' alone
  // (raster::lanesIndependent), so a lane group may gather the lanes of several triangles.
  static constexpr bool kLanesIndependent = true;

  struct Uniforms {
    glm::mat4 u_view{1.0f};
    glm::mat4 u_proj{1.0f};
    float u_time = 0.0f;
    glm::vec3 u_cam_pos{0.0f};
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("u_view", &Uniforms::u_view),
      raster::uniform("u_proj", &Uniforms::u_proj),
      raster::uniform("u_time", &Uniforms::u_time),
      raster::uniform("u_cam_pos", &Uniforms::u_cam_pos),
  };

  template <class F>
  struct Varyings {
    vec3<F> w_pos;
    vec3<F> w_normal;
    vec3<F> w_color;
    F w_emissive;
  };

  template <class F>
  static void vertex(const Uniforms& u, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    // per-vertex (binding 0): pos + normal
    const vec3<F> a_pos = in.attribute[0].xyz();
    const vec3<F> a_normal = in.attribute[1].xyz();
    // per-instance (binding 1): offset + colour + phase + emissive flag (1 = glows)
    const vec3<F> a_offset = in.attribute[2].xyz();
    const vec3<F> a_color = in.attribute[3].xyz();
    const F a_phase = in.attribute[4].x;
    const F a_emissive = in.attribute[5].x;

    const F t = F(u.u_time);
    // per-instance breathing + gentle spin about Y, desynchronised by the phase
    const F breathe = F(0.7f) + F(0.2f) * sin(t * F(1.5f) + a_phase * F(6.2832f));
    const vec3<F> local = a_pos * breathe;
    const F ang = t * F(0.25f) + a_phase * F(6.2832f);
    const F c = cos(ang);
    const F s = sin(ang);
    // rotated + a_offset: Mesa's compiler reassociates each (p + q) + offset, q a product,
    // into (p + offset) + q. Measured on 4096 random vertices: this order matches GL's
    // world position and gl_Position bit for bit; the order as written misses ~27%.
    const vec3<F> world = vec3<F>((c * local.x + a_offset.x) - s * local.z, local.y + a_offset.y,
                                  (s * local.x + a_offset.z) + c * local.z);
    gl_Position = u.u_proj * (u.u_view * vec4<F>(world, F(1.0f)));
    out.w_pos = world;
    out.w_normal = vec3<F>(c * a_normal.x - s * a_normal.z, a_normal.y, s * a_normal.x + c * a_normal.z);
    out.w_color = a_color;
    out.w_emissive = a_emissive;
  }

  // GLSL IR's folding of normalize(vec3(0.5, 1.0, 0.3)): v * rsq(dot(v, v)) in float, the dot
  // accumulated left to right, rsq = 1 / sqrt.
  static glm::vec3 folded_l() {
    const glm::vec3 c(0.5f, 1.0f, 0.3f);
    const float d = (c.x * c.x + c.y * c.y) + c.z * c.z;
    return c * (1.0f / std::sqrt(d));
  }

  static constexpr float EMISSIVE_BOOST = 8.0f;   // glowing cubes hit ~8x -- well above the bright-pass knee
  static constexpr float LIT_AMBIENT = 0.25f;
  static constexpr float LIT_KEY = 0.7f;

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const vec3<F> n = normalize(in.w_normal);
    const vec3<F> v = normalize(u.u_cam_pos - in.w_pos);
    static const glm::vec3 l_folded = folded_l();
    const vec3<F> l = vec3<F>(l_folded);   // normalize(vec3(0.5, 1.0, 0.3)), folded
    const F key = max(dot(n, l), F(0.0f)) * F(LIT_KEY) + F(LIT_AMBIENT);
    const F rim = pow<2.5f>(F(1.0f) - max(dot(n, v), F(0.0f)));
    // lit_lo stays in [0, 1]; emissive cubes multiply by EMISSIVE_BOOST, so the float
    // target carries values up to ~8 that the bright pass will threshold.
    const vec3<F> lit_lo = in.w_color * key + vec3<F>(glm::vec3(0.25f, 0.35f, 0.55f) * 0.4f) * rim;
    const vec3<F> lit = lit_lo * (F(1.0f) + in.w_emissive * F(EMISSIVE_BOOST - 1.0f));
    out.color[0] = vec4<F>(lit, F(1.0f));
  }
};

// This port's row in the program registry. scene.cpp defines it: the pipeline is
// instantiated over ScenePass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry sceneProgram();

}  // namespace shaders::hdr
