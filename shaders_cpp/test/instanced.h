// C++ port of instanced.vert / instanced.frag: per-vertex and per-instance attributes and
// gl_InstanceID. Used by the instancing test (tests/pipeline/hdr_features_test.cpp).
#pragma once

#include "raster/shader/program.h"

namespace shaders::test {

using namespace raster::glsl;

struct Instanced {
  static constexpr const char* kName = "test/instanced";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {};
  static constexpr auto kUniformTable = std::tuple{};

  template <class F>
  struct Varyings {
    vec4<F> v_color;
  };

  template <class F>
  static void vertex(const Uniforms&, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    const vec4<F> a_pos = in.attribute[0];
    const vec4<F> a_color = in.attribute[1];
    const vec3<F> i_offset = in.attribute[2].xyz();
    const vec4<F> i_color = in.attribute[3];
    out.v_color = vec4<F>(a_color.xyz() * i_color.xyz(), in.gl_InstanceID);
    gl_Position = vec4<F>(a_pos.xyz() + i_offset, a_pos.w);
  }

  template <class F>
  static void fragment(const Uniforms&, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    out.color[0] = in.v_color;
  }
};

}  // namespace shaders::test
