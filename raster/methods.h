// Methods: the numerics of each pipeline step where GL implementations differ, or where
// speed can be bought with accuracy, named and switchable.
//
// Every step has the llvmpipe-exact method as its default, so a default MethodSet renders
// the bytes llvmpipe renders. `raster methods` lists every step and method with what it
// trades (methodCatalog() below, made from methods.cpp's one row per method); the presets are
//   gl       every step llvmpipe-exact (the default);
//   precise  the most accurate method of every step;
//   fast     the fastest set that keeps every scene at >= 40 dB against llvmpipe;
//   draft    fast with 2x2 coarse shading in offscreen post passes: >= 30 dB on every
//            scene at 320x240 and 640x480; hdr at 1920x1080 falls below (TRADEOFF.md).
//
// Adding a method: its enumerator below (the values run 0, 1, ... in declaration order;
// none sets its own), its row in methods.cpp, and its answer in the step's picker below.
// The compiler asks for each: -Werror=switch (CMakeLists.txt) rejects a switch over the
// enum that leaves an enumerator out, and every read of the set goes through one.
//
// Where each step is decided:
//   math    simd/gl_math.h        the GLSL transcendentals the shader ports call (the
//                                 vertex stage's view of the set: Renderer::shadeVertices)
//   filter  texture/sample_color  bilinear weights of RGBA8 colour lookups
//   lookup  texture/lookup_filter.h   a LINEAR colour lookup's 2x2 footprint, or its one
//                                 texel of largest weight
//   half    merge/color_write.h   float -> half rounding on writes to RGBA16F targets
//   div     simd/div_approx.h     normalize / inversesqrt (simd/glsl.h), and the 1/w of
//                                 perspective-correct interpolation
//   interp  geometry/setup.cpp, tile/interpolate.h   perspective or screen-linear varyings
//   compare texture/sample_compare  how a shadow lookup (sampler2DShadow, LINEAR) filters
//                                 its texel compares
//   shading renderer.cpp (which passes), tile/coarse_tile.h   one fragment-shader
//                                 invocation per pixel, or per coarse pixel of 2x1 .. 4x4
//
// Why one process-wide set: the shader ports call GLSL functions that take no context
// (sin(x), normalize(v), texture(s, uv)), exactly as GLSL does, so the method cannot travel
// as an argument without every port saying so. The set is a property of a frame: the
// renderer's owner installs it (ScopedMethods) before drawing and no frame of another set
// runs at the same time (bench and tradeoff interleave whole frames, one after another).
// Worker threads read it after the task hand-off, which orders the write before the reads.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raster {

enum class MathMethod : uint8_t {
  Llvmpipe,   // llvmpipe's polynomials, bit for bit (gl_math.h)
  Libm,       // the C library in double, rounded once to float: the precise reference
  Fast,       // low-degree polynomials with a documented error bound (fast_math.h)
  FastFragment,   // Fast in fragment shaders, Llvmpipe in vertex shaders (vertexStageSet)
};
enum class FilterMethod : uint8_t {
  Unorm8,     // llvmpipe's 8-bit fixed-point weights and lerps (AoS path)
  Float,      // float32 weights and lerps, as softpipe and llvmpipe's float formats
};
enum class HalfMethod : uint8_t {
  TowardZero,   // llvmpipe: vcvtps2ph with truncation
  NearestEven,  // IEEE 754 round to nearest, ties to even
};
enum class DivMethod : uint8_t {
  Exact,      // true division and square root, correctly rounded
  Approx,     // a bit-pattern seed refined by Newton steps (same bits on every CPU)
};
enum class InterpMethod : uint8_t {
  Perspective,  // GL: varyings / w interpolated, then divided by the interpolated 1 / w
  Affine,       // screen-linear across each triangle: no divide, wrong at grazing angles
};

// How many texels a sampler2D lookup of a LINEAR texture reads.
enum class LookupMethod : uint8_t {
  Linear,     // GL: the 2x2 footprint, blended bilinearly (the `filter` step's weights)
  Nearest,    // the footprint's texel of largest weight alone, as NEAREST filtering reads it
};

enum class CompareMethod : uint8_t {
  Bilinear,   // llvmpipe: the 2x2 footprint's compares weighted bilinearly
  Nearest,    // the compare of the one texel the coordinate lands in (GL allows either)
};

// Coarse fragments as Vulkan's VK_KHR_fragment_shading_rate defines them: one invocation
// per coarse pixel (its centre interpolated, derivatives over coarse quads), its outputs
// written to every pixel of it that is covered and passes the depth test.
enum class ShadingMethod : uint8_t {
  Rate1x1,      // GL: one invocation per pixel
  Rate2x1,      // coarse pixels 2 wide, 1 high, in post passes (renderer.cpp says which)
  Rate1x2,      // 1 wide, 2 high, in post passes
  Rate2x2,      // 2x2, in post passes
  Rate4x4,      // 4x4, in post passes
  Rate2x2All,   // 2x2 in every pass that writes colour, geometry passes too
  Rate2x2Local,       // 2x2 in post passes that sample only at or next to their pixel
  Rate2x2Offscreen,   // 2x2 in those of Rate2x2Local's passes that draw offscreen targets
  Rate4x4Offscreen,   // 4x4 in the same passes
  Rate2x2Smooth,      // 2x2 in those of Rate2x2Offscreen's passes that minify no texture and
                      // read only finite texels (blurs, upsamples)
};

// Which passes a shading rate applies to (passShadingRate in shading_rate.h decides from the
// pass's draws and framebuffer).
enum class CoarsePasses : uint8_t {
  Post,        // every post pass: no colour draw of the pass tests depth
  All,         // every pass that writes colour
  Local,       // post passes none of whose draws samples around its pixel (SSAO: its
               // per-pixel rotation, drawn again at each coarse centre, is all it shows)
  Offscreen,   // Local's passes that draw offscreen targets, not the window's: the final
               // image's own pass keeps its edges per pixel
  Smooth,      // Offscreen's passes that read no texture larger than their target and no
               // non-finite texel: a pass that minifies (a bright pass, a downsample) reads
               // detail finer than its pixels, which one sample per coarse pixel aliases, and
               // a coarse centre alone would decide which pixels a NaN or infinity reaches
};

struct MethodSet {
  MathMethod math = MathMethod::Llvmpipe;
  FilterMethod filter = FilterMethod::Unorm8;
  HalfMethod half = HalfMethod::TowardZero;
  DivMethod div = DivMethod::Exact;
  InterpMethod interp = InterpMethod::Perspective;
  CompareMethod compare = CompareMethod::Bilinear;
  ShadingMethod shading = ShadingMethod::Rate1x1;
  LookupMethod lookup = LookupMethod::Linear;
  bool operator==(const MethodSet&) const = default;
};

// An unknown preset, step or method: the message is one line listing the valid names.
struct MethodError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// ---- the catalog -----------------------------------------------------------------------------

struct MethodInfo {
  std::string name;     // as typed: `fast`, `8bit`, `rne`
  std::string trade;    // one line: what it gives and what it costs
};
struct StepInfo {
  std::string name;     // as typed: `math`, `filter`
  std::string what;     // which operations the step covers
  std::vector<MethodInfo> methods;   // the first is llvmpipe's (the default)
};
const std::vector<StepInfo>& methodCatalog();
const std::vector<std::string>& presetNames();   // gl, precise, fast, draft

// The set a preset names; MethodError for an unknown name.
MethodSet presetMethods(std::string_view preset);
// What a preset promises against llvmpipe and where that holds, as measured (TRADEOFF.md,
// STABILITY.md): one line for `raster methods`; MethodError for an unknown name.
std::string_view presetPromise(std::string_view preset);
// Applies "STEP=NAME[,STEP=NAME...]" to `set`; MethodError for an unknown step or method.
void applyMethodOverrides(MethodSet& set, std::string_view overrides);
// step -> method name, every step, in catalog order.
std::vector<std::pair<std::string, std::string>> methodNames(const MethodSet& set);
// The method a set uses for one step, by name (`math` -> `llvmpipe`).
std::string methodName(const MethodSet& set, std::string_view step);
// Sets one step by names; MethodError for an unknown step or method.
void setMethod(MethodSet& set, std::string_view step, std::string_view method);
// The set the vertex stage runs under: `set` with math=fast-fragment read as llvmpipe's
// math, so every vertex position and varying (and so which pixels a triangle covers) is
// GL's; every other step as in `set`.
MethodSet vertexStageSet(const MethodSet& set);
// A short label: the preset's name when the set equals a preset, else "STEP=NAME,..." of
// the steps that differ from gl.
std::string methodLabel(const MethodSet& set);

// ---- the active set ------------------------------------------------------------------------

namespace methods {
// Read by the hot code of each step; written only by ScopedMethods.
inline MethodSet activeSet;
inline const MethodSet& active() { return activeSet; }
}  // namespace methods

// ---- the pickers -----------------------------------------------------------------------------
// What the hot code of a step asks of its method, one function per question, each a switch
// over every enumerator of the step with no default: a new method does not compile until
// each question has its answer for it (and a method that needs a path of its own turns
// the question into a switch at the sites that ask it: grep the picker's name). The hot
// code reads the active set where it always did (once per call, outside its loops) and
// asks. The value after each switch is never returned (a MethodSet holds enumerators only:
// setMethod sets rows' values); it is the one that folds the picker into the compare the
// hot code had before (`m == Approx`: with __builtin_unreachable there GCC tests the whole
// byte instead, and stopped unswitching a loop for it). The math step's sites switch
// themselves (simd/gl_math.h).
namespace methods {
// filter: llvmpipe's 8-bit fixed-point weights and lerps for RGBA8 lookups (else float).
constexpr bool fixedPointFilter(FilterMethod m) {
  switch (m) {
    case FilterMethod::Unorm8: return true;
    case FilterMethod::Float: return false;
  }
  return false;
}
// half: float -> half rounds to nearest even (else toward zero).
constexpr bool halfNearestEven(HalfMethod m) {
  switch (m) {
    case HalfMethod::TowardZero: return false;
    case HalfMethod::NearestEven: return true;
  }
  return false;
}
// div: the approximate reciprocal and inverse square root (else true division and sqrt).
constexpr bool approximateDivide(DivMethod m) {
  switch (m) {
    case DivMethod::Exact: return false;
    case DivMethod::Approx: return true;
  }
  return false;
}
// interp: varyings perspective-correct (else screen-linear).
constexpr bool perspectiveVaryings(InterpMethod m) {
  switch (m) {
    case InterpMethod::Perspective: return true;
    case InterpMethod::Affine: return false;
  }
  return true;
}
// lookup: a LINEAR sampler2D lookup reads the one texel of largest bilinear weight, as a
// NEAREST texture does (else its 2x2 footprint, blended). Asked through
// sampling::lookupFilter (texture/lookup_filter.h), the one place colour lookups read their
// texture's filter.
constexpr bool nearestLookup(LookupMethod m) {
  switch (m) {
    case LookupMethod::Linear: return false;
    case LookupMethod::Nearest: return true;
  }
  return false;
}
// compare: one compare, of the texel a shadow coordinate lands in (else the 2x2 footprint's
// compares weighted bilinearly).
constexpr bool nearestCompare(CompareMethod m) {
  switch (m) {
    case CompareMethod::Bilinear: return false;
    case CompareMethod::Nearest: return true;
  }
  return false;
}
// shading: the coarse pixel's width and height in pixels (1 and 1: GL's one invocation per
// pixel).
constexpr int coarsePixelWidth(ShadingMethod m) {
  switch (m) {
    case ShadingMethod::Rate1x1:
    case ShadingMethod::Rate1x2: return 1;
    case ShadingMethod::Rate2x1:
    case ShadingMethod::Rate2x2:
    case ShadingMethod::Rate2x2All:
    case ShadingMethod::Rate2x2Local:
    case ShadingMethod::Rate2x2Offscreen:
    case ShadingMethod::Rate2x2Smooth: return 2;
    case ShadingMethod::Rate4x4:
    case ShadingMethod::Rate4x4Offscreen: return 4;
  }
  return 1;
}
constexpr int coarsePixelHeight(ShadingMethod m) {
  switch (m) {
    case ShadingMethod::Rate1x1:
    case ShadingMethod::Rate2x1: return 1;
    case ShadingMethod::Rate1x2:
    case ShadingMethod::Rate2x2:
    case ShadingMethod::Rate2x2All:
    case ShadingMethod::Rate2x2Local:
    case ShadingMethod::Rate2x2Offscreen:
    case ShadingMethod::Rate2x2Smooth: return 2;
    case ShadingMethod::Rate4x4:
    case ShadingMethod::Rate4x4Offscreen: return 4;
  }
  return 1;
}
// shading: which passes the rate applies to (passShadingRate, shading_rate.h).
constexpr CoarsePasses coarsePasses(ShadingMethod m) {
  switch (m) {
    case ShadingMethod::Rate1x1:
    case ShadingMethod::Rate2x1:
    case ShadingMethod::Rate1x2:
    case ShadingMethod::Rate2x2:
    case ShadingMethod::Rate4x4: return CoarsePasses::Post;
    case ShadingMethod::Rate2x2All: return CoarsePasses::All;
    case ShadingMethod::Rate2x2Local: return CoarsePasses::Local;
    case ShadingMethod::Rate2x2Offscreen:
    case ShadingMethod::Rate4x4Offscreen: return CoarsePasses::Offscreen;
    case ShadingMethod::Rate2x2Smooth: return CoarsePasses::Smooth;
  }
  return CoarsePasses::Post;
}
// math: the method the vertex stage runs (vertexStageSet).
constexpr MathMethod vertexMath(MathMethod m) {
  switch (m) {
    case MathMethod::Llvmpipe:
    case MathMethod::Libm:
    case MathMethod::Fast: return m;
    case MathMethod::FastFragment: return MathMethod::Llvmpipe;
  }
  return m;
}
}  // namespace methods

// Installs a set for its lifetime and restores the previous one after.
class ScopedMethods {
 public:
  explicit ScopedMethods(const MethodSet& set) : previous_(methods::activeSet) { methods::activeSet = set; }
  ~ScopedMethods() { methods::activeSet = previous_; }
  ScopedMethods(const ScopedMethods&) = delete;
  ScopedMethods& operator=(const ScopedMethods&) = delete;

 private:
  MethodSet previous_;
};

}  // namespace raster
