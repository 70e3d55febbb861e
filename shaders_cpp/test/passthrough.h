// C++ port of passthrough.vert / passthrough.frag: clip-space positions, one colour.
// Used by the GL-comparison tests of coverage, depth and interpolation.
#pragma once

#include "raster/shader/program.h"

namespace shaders::test {

using namespace raster::glsl;

struct Passthrough {
  static constexpr const char* kName = "test/passthrough";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {};
  static constexpr auto kUniformTable = std::tuple{};

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
  static void fragment(const Uniforms&, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    out.color[0] = in.v_color;
  }
};

}  // namespace shaders::test
