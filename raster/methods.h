// Methods: the numerics of each pipeline step where GL implementations differ, or where
// speed can be bought with accuracy, named and switchable.
//
// Every step has the llvmpipe-exact method as its default, so a default MethodSet renders
// the bytes llvmpipe renders. `raster methods` lists every step and method with what it
// trades (methodCatalog() below); the presets are
//   gl       every step llvmpipe-exact (the default);
//   precise  the most accurate method of every step;
//   fast     the fastest set that keeps every scene at >= 40 dB against llvmpipe.
//
// Where each step is decided:
//   math    simd/gl_math.h        the GLSL transcendentals the shader ports call (the
//                                 vertex stage's view of the set: Renderer::shadeVertices)
//   filter  texture/sample_color  bilinear weights of RGBA8 colour lookups
//   half    merge/color_write.h   float -> half rounding on writes to RGBA16F targets
//   div     simd/div_approx.h     normalize / inversesqrt (simd/glsl.h), and the 1/w of
//                                 perspective-correct interpolation
//   interp  geometry/setup.cpp, tile/interpolate.h   perspective or screen-linear varyings
//   compare texture/sample_compare  how a shadow lookup (sampler2DShadow, LINEAR) filters
//                                 its texel compares
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

enum class CompareMethod : uint8_t {
  Bilinear,   // llvmpipe: the 2x2 footprint's compares weighted bilinearly
  Nearest,    // the compare of the one texel the coordinate lands in (GL allows either)
};

struct MethodSet {
  MathMethod math = MathMethod::Llvmpipe;
  FilterMethod filter = FilterMethod::Unorm8;
  HalfMethod half = HalfMethod::TowardZero;
  DivMethod div = DivMethod::Exact;
  InterpMethod interp = InterpMethod::Perspective;
  CompareMethod compare = CompareMethod::Bilinear;
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
const std::vector<std::string>& presetNames();   // gl, precise, fast

// The set a preset names; MethodError for an unknown name.
MethodSet presetMethods(std::string_view preset);
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
