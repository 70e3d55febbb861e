// C++ port of post.vert, the fullscreen triangle's vertex shader the SSAO, blur and lighting
// passes share.
#pragma once

#include "raster/shader/program.h"

namespace shaders::pbr {

using namespace raster::glsl;

template <class F>
struct PostVaryings {
  vec2<F> fragUV;
};

// The part every fullscreen program shares: post.vert's varyings and vertex shader.
struct PostProgram {
  template <class F>
  using Varyings = PostVaryings<F>;

  template <class Uniforms, class F>
  static void vertex(const Uniforms&, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    const vec2<F> aPos = in.attribute[0].xy();
    gl_Position = vec4<F>(aPos.x, aPos.y, F(0.0f), F(1.0f));
    out.fragUV = aPos * F(0.5f) + vec2<F>(F(0.5f));
  }
};

}  // namespace shaders::pbr
