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
    F result = raster::texture(u.uInput, in.fragUV).x * F(WEIGHTS[0]);
    for (int i = 1; i < 5; ++i) {
      // uDirection * float(i): a uniform times a constant, the same float product per lane.
      const vec2<F> step = vec2<F>(F(u.uDirection.x * float(i)), F(u.uDirection.y * float(i)));
      result = result + raster::texture(u.uInput, in.fragUV + step).x * F(WEIGHTS[i]);
      result = result + raster::texture(u.uInput, in.fragUV - step).x * F(WEIGHTS[i]);
    }
    out.color[0] = vec4<F>(result, result, result, F(1.0f));
  }
};

// This port's row in the program registry, defined in blur.cpp.
scenes::ProgramEntry blurProgram();

}  // namespace shaders::pbr
