// The contract between shader ports and the pipeline.
//
// A shader port (shaders_cpp/<scene>/*.h) is a struct with:
//   static constexpr const char* kName;          // "shadow/main": shaders_cpp/shadow/main.{vert,frag}
//   static constexpr int kColorOutputs;          // fragment outputs written (layout(location = i))
//   struct Uniforms { ... };                     // GLSL uniforms, samplers as Sampler2D(Shadow)
//   static constexpr auto kUniformTable;         // name -> member, see uniform() below
//   template <class F> struct Varyings { ... };  // vertex -> fragment, only vecN<F> / F members
//   template <class F> static void vertex(const Uniforms&, const VertexInput<F>&,
//                                         glsl::vec4<F>& gl_Position, Varyings<F>& out);
//   template <class F> static void fragment(const Uniforms&, const FragmentInput<F>&,
//                                           const Varyings<F>& in, FragmentOutput<F>& out);
// Optional: static void deriveUniforms(Uniforms&) (values of the uniforms alone, once a
// draw: program_instance.h), static void texelPlanes(TexelPlaneMaker<Uniforms>&) (values
// of single texels, once a texel and a draw: shader/texel_planes.h), and the hints
// kLanesIndependent and kSamplesAroundPixel (below).
// F is a lane type (simd/lanes.h). Varyings<F> must be exactly N consecutive F values: the
// pipeline interpolates it as an array of N floats, every one perspective-correct.
// Shaders never see depth, blending or the framebuffer.
//
// A port computes what Mesa's compiler makes of the GLSL, not the GLSL read naively:
// docs/porting.md lists the rewrites (one row each, with the Mesa pass that makes it), how
// to find the next one, and the checklist for a new port. The ports in shaders_cpp/ say in
// their headers which rows they follow.
#pragma once

#include <cstring>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "raster/contract.h"
#include "raster/simd/glsl.h"
#include "raster/texture/sampler.h"

namespace raster {

// Derivatives: GLSL dFdx / dFdy over the lanes of each 2x2 quad (fine, as llvmpipe).
template <class F> F dFdx(F a) { return simd::quadDdx(a); }
template <class F> F dFdy(F a) { return simd::quadDdy(a); }
template <class F> glsl::vec2<F> dFdx(glsl::vec2<F> a) { return {dFdx(a.x), dFdx(a.y)}; }
template <class F> glsl::vec2<F> dFdy(glsl::vec2<F> a) { return {dFdy(a.x), dFdy(a.y)}; }
template <class F> glsl::vec3<F> dFdx(glsl::vec3<F> a) { return {dFdx(a.x), dFdx(a.y), dFdx(a.z)}; }
template <class F> glsl::vec3<F> dFdy(glsl::vec3<F> a) { return {dFdy(a.x), dFdy(a.y), dFdy(a.z)}; }

// Not GLSL: the coordinates one 4x4 block to the right, uv + 4 * dFdx(uv), each quad's own
// derivative carried on: where the block usually shaded next reads, for texturePrefetch.
// The tile stage shades a tile's blocks along each row, left to right (covered_tile_avx2.h,
// visible_first.h), so inside a surface that block is next, and a port that prefetches its
// texels here finds them loaded there. A guess only: nothing but a prefetch reads it.
template <class F> glsl::vec2<F> nextBlockCoords(glsl::vec2<F> uv) { return uv + dFdx(uv) * F(float(limits::kBlockSize)); }

// Number of interpolated floats of a program.
template <class Program>
constexpr int varyingFloatCount() {
  using V = typename Program::template Varyings<float>;
  constexpr size_t bytes = std::is_empty_v<V> ? 0 : sizeof(V);
  static_assert(bytes % sizeof(float) == 0 && bytes / sizeof(float) <= limits::kMaxVaryingFloats);
  return int(bytes / sizeof(float));
}

// Copies between a Varyings<F> struct and the pipeline's flat array of N lane values.
template <class Program, class F>
typename Program::template Varyings<F> varyingsFromArray(const F* values) {
  using V = typename Program::template Varyings<F>;
  V v{};
  if constexpr (!std::is_empty_v<V>) {
    static_assert(sizeof(V) == sizeof(F) * varyingFloatCount<Program>(), "Varyings must hold only F values");
    // Value by value, unrolled, not memcpy: the compiler turns a block copy of the whole
    // struct into rep movs, which stalls the shader's first loads; single lane values fold
    // into those loads.
    F* fields = reinterpret_cast<F*>(static_cast<void*>(&v));
    [&]<size_t... I>(std::index_sequence<I...>) {
      ((fields[I] = values[I]), ...);
    }(std::make_index_sequence<size_t(varyingFloatCount<Program>())>{});
  }
  return v;
}
template <class Program, class F>
void varyingsToArray(const typename Program::template Varyings<F>& v, F* values) {
  if constexpr (!std::is_empty_v<typename Program::template Varyings<F>>) std::memcpy(static_cast<void*>(values), &v, sizeof(v));
}

// One entry of a port's uniform table: the GLSL name and the Uniforms member it sets.
template <class Uniforms, class T>
struct UniformEntry {
  std::string_view name;
  T Uniforms::*member;
};
template <class Uniforms, class T>
constexpr UniformEntry<Uniforms, T> uniform(std::string_view name, T Uniforms::*member) {
  return {name, member};
}

// Whether a program has a sampler uniform, i.e. its fragment shader reads textures.
template <class Entry> struct IsSamplerEntry : std::false_type {};
template <class Uniforms> struct IsSamplerEntry<UniformEntry<Uniforms, Sampler2D>> : std::true_type {};
template <class Uniforms> struct IsSamplerEntry<UniformEntry<Uniforms, Sampler2DShadow>> : std::true_type {};
template <class Program>
constexpr bool samplesTextures() {
  return std::apply([](auto... entry) { return (... || IsSamplerEntry<decltype(entry)>::value); }, Program::kUniformTable);
}

// Whether a program's lanes are independent: its fragment shader reads nothing of another
// lane (no dFdx / dFdy, no texture() whose level of detail they set), so a lane's outputs
// are its own inputs' alone. A port says so with `static constexpr bool kLanesIndependent
// = true;`; the visibility-first walk then shades the triangles one lane group shows in one
// call (tile/visible_first.h). Without it, false: the safe answer.
template <class Program>
constexpr bool lanesIndependent() {
  if constexpr (requires { Program::kLanesIndependent; }) return Program::kLanesIndependent;
  else return false;
}

// Whether a program's fragment shader samples textures at points spread around its pixel,
// many texels away (SSAO's hemisphere of samples), rather than at or next to it. A port says
// so with `static constexpr bool kSamplesAroundPixel = true;`; a pass drawing it then has
// its tiles shaded in Hilbert order (Renderer::flush), where a tile's neighbours on the
// screen are mostly its neighbours in time too, so the texels it reads are still cached from
// theirs. A hint about speed alone: the order of tiles never changes a byte.
template <class Program>
constexpr bool samplesAroundPixel() {
  if constexpr (requires { Program::kSamplesAroundPixel; }) return Program::kSamplesAroundPixel;
  else return false;
}

}  // namespace raster
