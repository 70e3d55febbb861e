// C++ port of shadow_lookup.vert / shadow_lookup.frag, line by line: one sampler2DShadow
// lookup per fragment at an interpolated (u, v, ref).
#pragma once

#include "raster/shader/program.h"

namespace shaders::test {

using namespace raster::glsl;

struct ShadowLookup {
  static constexpr const char* kName = "test/shadow_lookup";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    raster::Sampler2DShadow shadow_map;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("shadow_map", &Uniforms::shadow_map),
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
    out.color[0] = vec4<F>(raster::textureCompare(u.shadow_map, in.v_lookup.xy(), in.v_lookup.z), F(0.0f), F(0.0f), F(1.0f));
  }
};

}  // namespace shaders::test
