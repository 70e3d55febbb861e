// C++ port of post.vert / composite.frag (11 - HDR + Bloom, pass 5: ACES tonemap and gamma
// to the default framebuffer), line by line. g = 1.0 / 2.2 is folded by the compiler in
// float32, so pow(mapped, vec3(g)) has a constant exponent: pow<g> (gl_math.h).
#pragma once

#include "raster/shader/program.h"
#include "scenes/program_entry.h"
#include "shaders_cpp/hdr/post.h"

namespace shaders::hdr {

using namespace raster::glsl;

// GLSL clamp(vec3, vec3, vec3), component-wise min(max(x, lo), hi).
using raster::glsl::clamp;
template <class F>
vec3<F> clamp(vec3<F> x, vec3<F> lo, vec3<F> hi) {
  return {clamp(x.x, lo.x, hi.x), clamp(x.y, lo.y, hi.y), clamp(x.z, lo.z, hi.z)};
}

struct CompositePass : PostProgram {
  static constexpr const char* kName = "hdr/post+composite";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    raster::Sampler2D src0;           // the HDR scene (texture unit 0)
    raster::Sampler2D src_bloom;      // bloom mip 0 (texture unit 1)
    float u_bloom_intensity = 0.0f;   // how loud bloom is over the scene
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("src0", &Uniforms::src0),
      raster::uniform("src_bloom", &Uniforms::src_bloom),
      raster::uniform("u_bloom_intensity", &Uniforms::u_bloom_intensity),
  };

  // ACES filmic fit (Narkowicz 2015): one rational polynomial that mimics the ACES
  // shoulder/toe, mapping the unbounded HDR range into [0, 1].
  template <class F>
  static vec3<F> aces_fit(vec3<F> x) {
    const vec3<F> a = vec3<F>(F(2.51f), F(2.51f), F(2.51f));
    const vec3<F> b = vec3<F>(F(0.03f), F(0.03f), F(0.03f));
    const vec3<F> c = vec3<F>(F(2.43f), F(2.43f), F(2.43f));
    const vec3<F> d = vec3<F>(F(0.59f), F(0.59f), F(0.59f));
    const vec3<F> e = vec3<F>(F(0.14f), F(0.14f), F(0.14f));
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), vec3<F>(F(0.0f), F(0.0f), F(0.0f)),
                 vec3<F>(F(1.0f), F(1.0f), F(1.0f)));
  }

  static constexpr float g = 1.0f / 2.2f;

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const vec3<F> hdr = raster::texture(u.src0, in.v_uv).xyz();
    const vec3<F> bloom = raster::texture(u.src_bloom, in.v_uv).xyz();
    const vec3<F> merged = hdr + bloom * F(u.u_bloom_intensity);
    const vec3<F> mapped = aces_fit(merged);
    // WebGL2's default framebuffer does no sRGB encode, so gamma-encode here.
    const vec3<F> encoded = pow<g>(mapped);
    out.color[0] = vec4<F>(encoded, F(1.0f));
  }
};

// This port's row in the program registry. composite.cpp defines it: the pipeline is
// instantiated over CompositePass (SIMD and scalar lanes) there, once, in a file of its own.
scenes::ProgramEntry compositeProgram();

}  // namespace shaders::hdr
