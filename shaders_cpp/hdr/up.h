// C++ port of post.vert / up.frag (11 - HDR + Bloom, pass 4: the 9-tap tent upsample), line
// by line. The weights 1.0 / 16.0, 2.0 / 16.0, 4.0 / 16.0 are folded constants (exact).
// Each four-tap sum a + b + c + d is rebalanced by Mesa's compiler into (a + b) + (c + d)
// (see down.h), so the port adds in that order.
#pragma once

#include "raster/shader/program.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/hdr/post.h"

namespace shaders::hdr {

using namespace raster::glsl;

struct UpPass : PostProgram {
  static constexpr const char* kName = "hdr/post+up";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    raster::Sampler2D src0;           // the smaller mip (texture unit 0)
    glm::vec2 u_src_rcp{0.0f};        // 1 / source-mip size, the sample offset
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("src0", &Uniforms::src0),
      raster::uniform("u_src_rcp", &Uniforms::u_src_rcp),
  };

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const glm::vec2 o = u.u_src_rcp;
    // The nine texture() calls, made at once so the sampler can share the texels that
    // neighbouring taps read: grid[j + 1][i + 1] is texture(src0, v_uv + vec2(i * o.x, j * o.y)),
    // bit for bit (i or j = 0 adds 0.0, which samples the same texels with the same weights).
    vec4<F> grid[3][3];
    raster::textureGrid3x3(u.src0, in.v_uv, o, grid);
    const vec3<F> s00 = grid[0][0].xyz();   // texture(src0, v_uv + vec2(-o.x, -o.y))
    const vec3<F> s10 = grid[0][1].xyz();   // texture(src0, v_uv + vec2(0.0, -o.y))
    const vec3<F> s20 = grid[0][2].xyz();   // texture(src0, v_uv + vec2(o.x, -o.y))
    const vec3<F> s01 = grid[1][0].xyz();   // texture(src0, v_uv + vec2(-o.x, 0.0))
    const vec3<F> s11 = grid[1][1].xyz();   // texture(src0, v_uv)
    const vec3<F> s21 = grid[1][2].xyz();   // texture(src0, v_uv + vec2(o.x, 0.0))
    const vec3<F> s02 = grid[2][0].xyz();   // texture(src0, v_uv + vec2(-o.x, o.y))
    const vec3<F> s12 = grid[2][1].xyz();   // texture(src0, v_uv + vec2(0.0, o.y))
    const vec3<F> s22 = grid[2][2].xyz();   // texture(src0, v_uv + vec2(o.x, o.y))
    const vec3<F> tent = (((s00 + s20) + (s02 + s22)) * F(1.0f / 16.0f) +
                          ((s10 + s01) + (s21 + s12)) * F(2.0f / 16.0f) +
                          s11 * F(4.0f / 16.0f));
    out.color[0] = vec4<F>(tent, F(1.0f));
  }
};

// This port's row in the program registry. up.cpp defines it: the pipeline is
// instantiated over UpPass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry upProgram();

}  // namespace shaders::hdr
