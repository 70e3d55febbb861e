// C++ port of uniform_array.vert / uniform_array.frag, line by line: uniform arrays as
// std::array members, set element by element through the program registry.
#pragma once

#include <array>

#include "raster/shader/program.h"

namespace shaders::test {

using namespace raster::glsl;

struct UniformArray {
  static constexpr const char* kName = "test/uniform_array";
  static constexpr int kColorOutputs = 2;
  struct Uniforms {
    std::array<glm::vec3, 3> uVectors{};
    std::array<float, 2> uScalars{};
    std::array<glm::mat4, 2> uMatrices{};
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("uVectors", &Uniforms::uVectors),
      raster::uniform("uScalars", &Uniforms::uScalars),
      raster::uniform("uMatrices", &Uniforms::uMatrices),
  };

  template <class F>
  struct Varyings {
    vec4<F> v_color;
  };

  template <class F>
  static void vertex(const Uniforms&, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    out.v_color = in.attribute[1];
    gl_Position = in.attribute[0];
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    out.color[0] = vec4<F>(F(u.uVectors[0].x), F(u.uVectors[1].y), F(u.uVectors[2].z), in.v_color.w);
    out.color[1] = vec4<F>(F(u.uScalars[0]), F(u.uScalars[1]), F(u.uMatrices[0][1].y), F(u.uMatrices[1][3].x));
  }
};

}  // namespace shaders::test
