// GLSL-like vector math over a lane type F, so shader ports read like their GLSL.
//
// vec2/vec3/vec4<F> hold one value per lane per component (structure of arrays).
// Functions carry GLSL names and the operation order llvmpipe's compiler produces from the
// GLSL; the comment above each names its row of docs/porting.md (section 1: the rewrite, the
// Mesa pass that makes it). Uniform matrices are glm::mat4 (host math); they multiply lane
// vectors.
//
// Mesa's compiler also rewrites whole expressions, which no function here can follow (rows
// graft, rebalance, add-chain, factor, const-up-mul, const-add-chain, const-reassoc-ir,
// mix-const-t, const-fold): a port writes those in the rewritten order itself.
// docs/porting.md section 2 says how the next one is found (`raster compare --float-final`,
// `raster trace`, the extra-use bisection).
#pragma once

#include <glm/glm.hpp>

#include "raster/methods.h"
#include "raster/simd/gl_math.h"
#include "raster/simd/isa.h"

namespace raster::glsl {

using simd::abs;
using simd::floor;
using simd::fma;
using simd::max;
using simd::min;
using simd::select;
using simd::sqrt;

// Scalar overloads, so ports can be instantiated with F = float where no quad is needed.
inline float select(bool m, float a, float b) { return m ? a : b; }
inline float min(float a, float b) { return a < b ? a : b; }
inline float max(float a, float b) { return a > b ? a : b; }
inline float floor(float a) { return std::floor(a); }
inline float sqrt(float a) { return std::sqrt(a); }

template <class F>
struct vec2 {
  F x, y;
  vec2() = default;
  vec2(F x_, F y_) : x(x_), y(y_) {}
  explicit vec2(F s) : x(s), y(s) {}
  explicit vec2(glm::vec2 v) : x(v.x), y(v.y) {}
};

template <class F>
struct vec3 {
  F x, y, z;
  vec3() = default;
  vec3(F x_, F y_, F z_) : x(x_), y(y_), z(z_) {}
  explicit vec3(F s) : x(s), y(s), z(s) {}
  explicit vec3(glm::vec3 v) : x(v.x), y(v.y), z(v.z) {}
  vec2<F> xy() const { return {x, y}; }
};

template <class F>
struct vec4 {
  F x, y, z, w;
  vec4() = default;
  vec4(F x_, F y_, F z_, F w_) : x(x_), y(y_), z(z_), w(w_) {}
  vec4(vec3<F> v, F w_) : x(v.x), y(v.y), z(v.z), w(w_) {}
  explicit vec4(glm::vec4 v) : x(v.x), y(v.y), z(v.z), w(v.w) {}
  vec3<F> xyz() const { return {x, y, z}; }
  vec2<F> xy() const { return {x, y}; }
};

// Component-wise arithmetic, vector op vector and vector op scalar, as GLSL.
#define RASTER_GLSL_OPS(op)                                                                            \
  template <class F> vec2<F> operator op(vec2<F> a, vec2<F> b) { return {a.x op b.x, a.y op b.y}; }     \
  template <class F> vec3<F> operator op(vec3<F> a, vec3<F> b) { return {a.x op b.x, a.y op b.y, a.z op b.z}; } \
  template <class F> vec4<F> operator op(vec4<F> a, vec4<F> b) { return {a.x op b.x, a.y op b.y, a.z op b.z, a.w op b.w}; } \
  template <class F> vec2<F> operator op(vec2<F> a, F s) { return {a.x op s, a.y op s}; }                \
  template <class F> vec3<F> operator op(vec3<F> a, F s) { return {a.x op s, a.y op s, a.z op s}; }      \
  template <class F> vec4<F> operator op(vec4<F> a, F s) { return {a.x op s, a.y op s, a.z op s, a.w op s}; } \
  template <class F> vec2<F> operator op(F s, vec2<F> a) { return {s op a.x, s op a.y}; }                \
  template <class F> vec3<F> operator op(F s, vec3<F> a) { return {s op a.x, s op a.y, s op a.z}; }
RASTER_GLSL_OPS(+)
RASTER_GLSL_OPS(-)
RASTER_GLSL_OPS(*)
RASTER_GLSL_OPS(/)
#undef RASTER_GLSL_OPS

// Uniform (host) vectors mixed with lane vectors.
template <class F> vec3<F> operator+(vec3<F> a, glm::vec3 b) { return a + vec3<F>(b); }
template <class F> vec3<F> operator+(glm::vec3 a, vec3<F> b) { return vec3<F>(a) + b; }
template <class F> vec3<F> operator-(glm::vec3 a, vec3<F> b) { return vec3<F>(a) - b; }
template <class F> vec3<F> operator*(vec3<F> a, glm::vec3 b) { return a * vec3<F>(b); }
template <class F> vec3<F> operator*(glm::vec3 a, vec3<F> b) { return vec3<F>(a) * b; }
template <class F> vec2<F> operator+(vec2<F> a, glm::vec2 b) { return a + vec2<F>(b); }
template <class F> vec2<F> operator*(vec2<F> a, glm::vec2 b) { return a * vec2<F>(b); }

// dot adds from the last component: a.x*b.x + (a.y*b.y + a.z*b.z) (row dot).
template <class F> F dot(vec2<F> a, vec2<F> b) { return a.x * b.x + a.y * b.y; }
template <class F> F dot(vec3<F> a, vec3<F> b) { return a.x * b.x + (a.y * b.y + a.z * b.z); }
template <class F> F dot(vec4<F> a, vec4<F> b) { return a.x * b.x + (a.y * b.y + (a.z * b.z + a.w * b.w)); }
template <class F> F length(vec3<F> v) { return sqrt(dot(v, v)); }
// inversesqrt and normalize take the `div` step of the method set (methods.h): exact is
// llvmpipe's 1 / sqrt(x) (GLSL IR's rsq), approx is inversesqrtApprox (div_approx.h).
// normalize(v) is v * inversesqrt(dot(v, v)) (row normalize).
template <class F> F inversesqrt(F x) {
  if (methods::approximateDivide(methods::active().div)) return inversesqrtApprox(x);
  return F(1.0f) / sqrt(x);
}
template <class F> vec3<F> normalize(vec3<F> v) { return v * inversesqrt(dot(v, v)); }
// normalize of a uniform: every lane would compute the same value from the same operands,
// so it is computed once, in float, by the same operations, and broadcast. The same bits as
// the lanes' own normalize (div_methods_test), without a vector square root and division
// per lane group.
template <class F> vec3<F> normalizeUniform(glm::vec3 v) {
  const vec3<float> n = normalize(vec3<float>(v));
  return {F(n.x), F(n.y), F(n.z)};
}

// mix(a, b, t) = a + t * (b - a), nir_lower_flrp's form for a t that is not constant (row
// mix); with a constant t the port writes a * (1 - t) + b * t itself (row mix-const-t).
template <class F> F mix(F a, F b, F t) { return a + t * (b - a); }
template <class F> vec3<F> mix(vec3<F> a, vec3<F> b, vec3<F> t) { return {mix(a.x, b.x, t.x), mix(a.y, b.y, t.y), mix(a.z, b.z, t.z)}; }
template <class F> F clamp(F x, F lo, F hi) { return min(max(x, lo), hi); }
template <class F> vec3<F> max(vec3<F> a, F b) { return {max(a.x, b), max(a.y, b), max(a.z, b)}; }

// Not GLSL: the guard of a port's exact rewrite that holds only for finite operands (the
// SSAO passes' sparse projections). guard + v * 0 stays the guard while v is finite and is
// NaN from the first v that is not, so all(guard == 0) after a loop says every v was.
template <class F> [[gnu::always_inline]] inline F addFiniteGuard(F guard, F v) { return guard + v * F(0.0f); }

// Transcendentals (pow, exp2, log2, sin, cos, asin, acos, atan) are in gl_math.h: bit-exact
// ports of llvmpipe's approximations. Component-wise vec3 forms of pow:
//   pow(v, e)      run-time exponents (a uniform or computed vec3);
//   pow<Y>(v)      GLSL pow(v, vec3(Y)) with a literal Y, folded as Mesa folds it (gl_math.h).
template <class F> vec3<F> pow(vec3<F> v, vec3<F> e) { return {pow(v.x, e.x), pow(v.y, e.y), pow(v.z, e.z)}; }
// Always inlined: GCC outlined it, and the three chains then ran apart from the rest of the
// shader (the composite, whose gamma it is, 5% slower).
template <float Y, class F>
[[gnu::always_inline]] inline vec3<F> pow(vec3<F> v) {
  return {pow<Y>(v.x), pow<Y>(v.y), pow<Y>(v.z)};
}

template <class F> vec3<F> operator-(vec3<F> a) { return {-a.x, -a.y, -a.z}; }
// GLSL cross as Mesa's builtin: a.yzx * b.zxy - a.zxy * b.yzx.
template <class F> vec3<F> cross(vec3<F> a, vec3<F> b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// Per-lane choice between two vectors (divergent branches and ternaries run under masks).
template <class M, class F> vec2<F> select(M m, vec2<F> a, vec2<F> b) { return {select(m, a.x, b.x), select(m, a.y, b.y)}; }
template <class M, class F> vec3<F> select(M m, vec3<F> a, vec3<F> b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
template <class M, class F> vec4<F> select(M m, vec4<F> a, vec4<F> b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z), select(m, a.w, b.w)};
}

// The four components of a lane vector as planes of plain floats (lane i of component c
// at planes[c][i]), for code that leaves SIMD: per-lane writes, scalar fallbacks.
template <class F>
void storePlanes(const vec4<F>& v, float (*planes)[F::kCount]) {
  v.x.store(planes[0]);
  v.y.store(planes[1]);
  v.z.store(planes[2]);
  v.w.store(planes[3]);
}

// mat4 * vec4, column by column in GLSL order: ((c0*v.x + c1*v.y) + c2*v.z) + c3*v.w (row
// mat-vec); GLSL's M * N * v is written M * (N * v) (row mat-mat-vec). Always inlined:
// shaders often keep one component ((m * v).z) or repeat a product, and only inlined code
// lets the compiler drop the unused rows and share the repeats, as Mesa's optimizer does.
template <class F>
[[gnu::always_inline]] inline vec4<F> operator*(const glm::mat4& m, const vec4<F>& v) {
  auto column = [&](int row) { return ((F(m[0][row]) * v.x + F(m[1][row]) * v.y) + F(m[2][row]) * v.z) + F(m[3][row]) * v.w; };
  return {column(0), column(1), column(2), column(3)};
}

}  // namespace raster::glsl
