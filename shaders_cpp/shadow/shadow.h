// C++ port of shadow.vert / shadow.frag (08 - The Shadow Map, shadow pass), line by line.
#pragma once

#include "raster/shader/program.h"
#include "scenes/program_entry.h"

namespace shaders::shadow {

using namespace raster::glsl;

struct ShadowPass {
  static constexpr const char* kName = "shadow/shadow";
  static constexpr int kColorOutputs = 1;

  struct Uniforms {
    glm::mat4 u_light_vp{1.0f};
    glm::mat4 u_model{1.0f};
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("u_light_vp", &Uniforms::u_light_vp),
      raster::uniform("u_model", &Uniforms::u_model),
  };

  template <class F>
  struct Varyings {};

  template <class F>
  static void vertex(const Uniforms& u, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>&) {
    const vec3<F> a_pos = in.attribute[0].xyz();
    // GLSL (u_light_vp * u_model) * v: Mesa's optimizer evaluates u_light_vp * (u_model * v).
    gl_Position = u.u_light_vp * (u.u_model * vec4<F>(a_pos, F(1.0f)));
  }

  template <class F>
  static void fragment(const Uniforms&, const raster::FragmentInput<F>&, const Varyings<F>&,
                       raster::FragmentOutput<F>& out) {
    // depth-only framebuffer: this colour is discarded (draw buffer is GL_NONE)
    out.color[0] = vec4<F>(F(1.0f), F(1.0f), F(1.0f), F(1.0f));
  }
};

// This port's row in the program registry. shadow.cpp defines it: the pipeline is
// instantiated over ShadowPass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry shadowProgram();

}  // namespace shaders::shadow
