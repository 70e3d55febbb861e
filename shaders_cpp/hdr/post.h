// C++ port of post.vert (11 - HDR + Bloom, post_vs), the fullscreen-triangle vertex shader
// the bright, down, up and composite passes share.

#pragma once

#include "raster/shader/program.h"

namespace shaders::hdr {

using namespace raster::glsl;

template <class F>
struct PostVaryings {
  vec2<F> v_uv;
};

template <class F>
void post_vs(const raster::VertexInput<F>& in, vec4<F>& gl_Position, PostVaryings<F>& out) {
  const vec2<F> q_pos = in.attribute[0].xy();
  gl_Position = vec4<F>(q_pos.x, q_pos.y, F(0.0f), F(1.0f));
  out.v_uv = q_pos * F(0.5f) + vec2<F>(F(0.5f), F(0.5f));
}

// The part every fullscreen post program shares: post.vert's varyings and vertex shader.
// A port derives from it and adds its fragment shader and uniforms.
struct PostProgram {
  template <class F>
  using Varyings = PostVaryings<F>;

  template <class Uniforms, class F>
  static void vertex(const Uniforms&, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    post_vs(in, gl_Position, out);
  }
};

}  // namespace shaders::hdr
