// C++ port of derivatives.vert / derivatives.frag, line by line: dFdx / dFdy of functions
// of a varying, computed per 2x2 quad (fine derivatives, as llvmpipe).
// q is factored in the GLSL too: Mesa's compiler turns a*b + a*c into a*(b + c)
// (nir_opt_algebraic, an inexact float rewrite), so the unfactored form would not be
// bit-exact against a literal port.
#pragma once

#include "raster/shader/program.h"

namespace shaders::test {

using namespace raster::glsl;

struct Derivatives {
  static constexpr const char* kName = "test/derivatives";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {};
  static constexpr auto kUniformTable = std::tuple{};

  template <class F>
  struct Varyings {
    vec4<F> v_value;
  };

  template <class F>
  static void vertex(const Uniforms&, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    out.v_value = in.attribute[1];
    gl_Position = in.attribute[0];
  }

  template <class F>
  static void fragment(const Uniforms&, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const F q = in.v_value.y * (in.v_value.x * in.v_value.x + F(0.25f));
    const F p = in.v_value.x * in.v_value.y;
    out.color[0] = vec4<F>(raster::dFdx(q), raster::dFdy(q), raster::dFdx(p), raster::dFdy(p * in.v_value.z));
  }
};

}  // namespace shaders::test
