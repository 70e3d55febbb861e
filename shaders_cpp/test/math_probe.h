// C++ port of math_probe.vert / math_probe.frag, line by line: one GLSL built-in picked by
// u_func (a uniform branch, so a plain `if`), on arguments x and y, written as
// (f(x, y), x, y, 0). GLSL literal exponents are pow<Y>() here (Mesa folds pow(x, 2.0)
// to x * x, see raster/simd/gl_math.h); a varying exponent is the run-time pow.
#pragma once

#include "raster/shader/program.h"

namespace shaders::test {

using namespace raster::glsl;

struct MathProbe {
  static constexpr const char* kName = "test/math_probe";
  static constexpr int kColorOutputs = 1;
  struct Uniforms {
    int u_func = 0;
  };
  static constexpr auto kUniformTable = std::tuple{
      raster::uniform("u_func", &Uniforms::u_func),
  };

  // Function ids (u_func), in the order of math_probe.frag.
  enum Function {
    kExp2, kLog2, kPow, kPow48, kPow2_2, kPow0_4545, kPow2, kPow4, kSin, kCos, kAtan2, kAcos, kAsin, kAtan,
    kPowVec3Const, kPowVec3, kFunctionCount
  };

  template <class F>
  struct Varyings {
    vec4<F> v_x;
    vec4<F> v_y;
  };

  template <class F>
  static void vertex(const Uniforms&, const raster::VertexInput<F>& in, vec4<F>& gl_Position, Varyings<F>& out) {
    out.v_x = in.attribute[1];
    out.v_y = in.attribute[2];
    gl_Position = in.attribute[0];
  }

  template <class F>
  static void fragment(const Uniforms& u, const raster::FragmentInput<F>&, const Varyings<F>& in,
                       raster::FragmentOutput<F>& out) {
    const F x = (in.v_x.x * in.v_x.y) * in.v_x.z;
    const F y = (in.v_y.x * in.v_y.y) * in.v_y.z;
    F r = F(0.0f);
    switch (u.u_func) {
      case kExp2: r = exp2(x); break;
      case kLog2: r = log2(x); break;
      case kPow: r = pow(x, y); break;
      case kPow48: r = pow<48.0f>(x); break;
      case kPow2_2: r = pow<2.2f>(x); break;
      case kPow0_4545: r = pow<0.4545f>(x); break;
      case kPow2: r = pow<2.0f>(x); break;
      case kPow4: r = pow<4.0f>(x); break;
      case kSin: r = sin(x); break;
      case kCos: r = cos(x); break;
      case kAtan2: r = atan(x, y); break;
      case kAcos: r = acos(x); break;
      case kAsin: r = asin(x); break;
      case kAtan: r = atan(x); break;
      case kPowVec3Const: r = pow<2.2f>(vec3<F>(x, y, x)).y; break;
      case kPowVec3: r = pow(vec3<F>(x, x, x), vec3<F>(y, F(0.4545f), F(2.0f))).x; break;
      default: break;
    }
    out.color[0] = vec4<F>(r, x, y, F(0.0f));
  }
};

}  // namespace shaders::test
