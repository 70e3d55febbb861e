// C++ port of color_lookup.vert / color_lookup.frag, line by line: one sampler2D lookup per
// fragment at an interpolated (u, v).
#pragma once

#include "raster/shader/program.h"

namespace shaders::test {

using namespace raster::glsl;

struct ColorLookup {
  static constexpr const char* kName = "test/color_lookup";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    raster::Sampler2D tex;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("tex", &Uniforms::tex),
  };

  template <class F>
  struct Varyings {
    vec4<F> v_lookup;
  };

  template <class F>
  static void vertex(const Uniforms&, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    out.v_lookup = in.attribute[1];
    gl_Position = in.attribute[0];
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    out.color[0] = raster::texture(u.tex, in.v_lookup.xy());
  }
};

}  // namespace shaders::test
