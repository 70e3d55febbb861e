// C++ port of post.vert / blur.frag (seed 004, the SSAO's separable Gaussian blur), line by
// line: the loop of four is unrolled by Mesa, and each WEIGHTS[i] folds to its float.
#pragma once

#include "raster/shader/program.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/pbr/post.h"

namespace shaders::pbr {

using namespace raster::glsl;

struct BlurPass : PostProgram {
  static constexpr const char* kName = "pbr/post+blur";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    raster::Sampler2D uInput;
    glm::vec2 uDirection{0.0f};
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("uInput", &Uniforms::uInput),
      raster::uniform("uDirection", &Uniforms::uDirection),
  };

  static constexpr float WEIGHTS[5] = {0.227027f, 0.1945946f, 0.1216216f, 0.054054f, 0.016216f};

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    // The nine texture() calls, made at once so that a block's taps share their texel loads:
    // taps[4 + i] is texture(uInput, fragUV + uDirection * float(i)), and taps[4 - i] the one
    // at fragUV - uDirection * float(i), bit for bit.
    vec4<F> taps[9];
    raster::textureLine<4>(u.uInput, in.fragUV, u.uDirection, taps);
    F result = taps[4].x * F(WEIGHTS[0]);
    for (int i = 1; i < 5; ++i) {
      result = result + taps[4 + i].x * F(WEIGHTS[i]);
      result = result + taps[4 - i].x * F(WEIGHTS[i]);
    }
    out.color[0] = vec4<F>(result, result, result, F(1.0f));
  }
};

// This port's row in the program registry, defined in blur.cpp.
scenes::ProgramEntry blurProgram();

}  // namespace shaders::pbr
