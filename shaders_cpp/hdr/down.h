// C++ port of post.vert / down.frag (11 - HDR + Bloom, pass 3: the 5-tap downsample), line
// by line, its five lookups made as one 3x3 grid (see fragment()). The offsets -o.x, -o.y
// negate a uniform: exact, wherever it is computed.
// lt + rt + lb + rb: Mesa's compiler rebalances the chain ((lt + rt) + lb) + rb into
// (lt + rt) + (lb + rb) (most likely GLSL IR's opt_rebalance_tree), so the port adds in that
// order. Measured: a + b + c + d of four varyings is (a + b) + (c + d) in 4096 of 4096 cases.
#pragma once

#include "raster/shader/program.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/hdr/post.h"

namespace shaders::hdr {

using namespace raster::glsl;

struct DownPass : PostProgram {
  static constexpr const char* kName = "hdr/post+down";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    raster::Sampler2D src0;           // the larger mip (texture unit 0)
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
    // The five texture() calls are the centre and corners of the 3x3 grid of lookups one
    // offset apart, made at once so the sampler can share their texels (as the upsample
    // does): grid[j + 1][i + 1] is texture(src0, v_uv + vec2(i * o.x, j * o.y)), bit for bit.
    vec4<F> grid[3][3];
    raster::textureGrid3x3(u.src0, in.v_uv, o, grid);
    const vec3<F> c = grid[1][1].xyz();    // texture(src0, v_uv)
    const vec3<F> lt = grid[0][0].xyz();   // texture(src0, v_uv + vec2(-o.x, -o.y))
    const vec3<F> rt = grid[0][2].xyz();   // texture(src0, v_uv + vec2(o.x, -o.y))
    const vec3<F> lb = grid[2][0].xyz();   // texture(src0, v_uv + vec2(-o.x, o.y))
    const vec3<F> rb = grid[2][2].xyz();   // texture(src0, v_uv + vec2(o.x, o.y))
    const vec3<F> sum = c * F(0.5f) + ((lt + rt) + (lb + rb)) * F(0.125f);
    out.color[0] = vec4<F>(sum, F(1.0f));
  }
};

// This port's row in the program registry. down.cpp defines it: the pipeline is
// instantiated over DownPass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry downProgram();

}  // namespace shaders::hdr
