// C++ port of post.vert / bright.frag (11 - HDR + Bloom, pass 2: the bright pass), line by
// line. 1.0 / (1.0 + luma) is GLSL IR's rcp, which llvmpipe computes as a true division.
#pragma once

#include "raster/shader/program.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/hdr/post.h"

namespace shaders::hdr {

using namespace raster::glsl;

struct BrightPass : PostProgram {
  static constexpr const char* kName = "hdr/post+bright";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    raster::Sampler2D src0;           // the HDR scene (texture unit 0)
    float u_threshold = 0.0f;         // pixels below this luma are killed
    float u_soft_knee = 0.0f;         // soft-knee width around the threshold
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("src0", &Uniforms::src0),
      raster::uniform("u_threshold", &Uniforms::u_threshold),
      raster::uniform("u_soft_knee", &Uniforms::u_soft_knee),
  };

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const vec3<F> hdr = raster::texture(u.src0, in.v_uv).xyz();
    const F luma = dot(hdr, vec3<F>(F(0.2126f), F(0.7152f), F(0.0722f)));   // BT.709 luminance
    const F knee = F(max(u.u_soft_knee, 0.0001f));
    const F tt = clamp((luma - F(u.u_threshold) + knee) / (F(2.0f) * knee), F(0.0f), F(1.0f));
    const F curve = tt * tt * (F(3.0f) - F(2.0f) * tt);
    const F karis_weight = F(1.0f) / (F(1.0f) + luma);
    out.color[0] = vec4<F>(hdr * karis_weight * curve, F(1.0f));
  }
};

// This port's row in the program registry. bright.cpp defines it: the pipeline is
// instantiated over BrightPass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry brightProgram();

}  // namespace shaders::hdr
