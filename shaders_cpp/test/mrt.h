// C++ port of mrt.vert / mrt.frag: one draw, three colour outputs (MRT).
#pragma once

#include "raster/shader/program.h"

namespace shaders::test {

using namespace raster::glsl;

struct Mrt {
  static constexpr const char* kName = "test/mrt";
  static constexpr int kColorOutputs = 3;
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
    out.color[1] = in.v_color * F(2.0f) - vec4<F>(F(1.0f), F(1.0f), F(1.0f), F(1.0f));
    out.color[2] = in.v_color * F(300.0f);
  }
};

}  // namespace shaders::test
