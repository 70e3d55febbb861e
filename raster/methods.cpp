// The catalog of steps and methods, the presets, and the parsing of their names.
#include "raster/methods.h"

#include <algorithm>
#include <array>
#include <type_traits>

namespace raster {
namespace {

// ---- the table: one row per method -------------------------------------------------------------
// Each step's rows are a switch over its enum with no default, so under -Werror=switch
// (CMakeLists.txt) an enumerator without its row does not compile. A step's methods are
// its enum's values 0, 1, ... up to the first without a row, in enum order (the first is
// llvmpipe's, the default); stepRow below checks at compile time that no value past that
// has a row (the enumerators run without gaps) and that the names are distinct, and
// stepsAreTheMembers that kSteps names every member of MethodSet once.

struct MethodRow {
  std::string_view name;    // as typed: `fast`, `8bit`, `rne`; empty: not an enumerator
  std::string_view trade;   // one line: what it gives and what it costs
};

constexpr MethodRow rowOf(MathMethod m) {
  switch (m) {
    case MathMethod::Llvmpipe: return {"llvmpipe", "llvmpipe's polynomials, bit for bit (relative error up to ~1e-4 in pow; 2-3 ulp in sin)"};
    case MathMethod::Libm: return {"libm", "the C library in double, rounded once: correctly rounded float; 5-20x slower per call"};
    case MathMethod::Fast: return {"fast", "low-degree polynomials, documented bounds in fast_math.h; fewer operations than llvmpipe's"};
    case MathMethod::FastFragment:
      return {"fast-fragment", "fast in fragment shaders, llvmpipe's in vertex shaders: the same speed, and every vertex (so coverage) is GL's"};
  }
  return {};
}
constexpr MethodRow rowOf(FilterMethod m) {
  switch (m) {
    case FilterMethod::Unorm8: return {"8bit", "llvmpipe's AoS path: 8-bit weights, every lerp rounded to 8 bits"};
    case FilterMethod::Float: return {"float", "float32 weights and lerps, as softpipe: off by up to ~1 of 255 from 8bit"};
  }
  return {};
}
constexpr MethodRow rowOf(HalfMethod m) {
  switch (m) {
    case HalfMethod::TowardZero: return {"rtz", "llvmpipe's truncation toward zero: up to 1 half ulp low, biased"};
    case HalfMethod::NearestEven: return {"rne", "IEEE round to nearest even: half an ulp, unbiased; the same cost with F16C"};
  }
  return {};
}
constexpr MethodRow rowOf(DivMethod m) {
  switch (m) {
    case DivMethod::Exact: return {"exact", "correctly rounded division and square root"};
    case DivMethod::Approx:
      return {"approx", "bit-pattern seed and Newton steps: 1/x within 7e-8, 1/sqrt within 5e-6; no divider or sqrt unit"};
  }
  return {};
}
constexpr MethodRow rowOf(InterpMethod m) {
  switch (m) {
    case InterpMethod::Perspective: return {"perspective", "GL: perspective-correct, one reciprocal per pixel"};
    case InterpMethod::Affine: return {"affine", "screen-linear: no reciprocal, textures swim and bend on triangles at grazing angles"};
  }
  return {};
}
constexpr MethodRow rowOf(LookupMethod m) {
  switch (m) {
    case LookupMethod::Linear: return {"linear", "GL: a LINEAR texture's lookup blends its 2x2 footprint of texels"};
    case LookupMethod::Nearest:
      return {"nearest",
              "the footprint's texel of largest weight alone (NEAREST): a quarter of the texel reads and no blend; "
              "texel edges show where a texture is magnified"};
  }
  return {};
}
constexpr MethodRow rowOf(CompareMethod m) {
  switch (m) {
    case CompareMethod::Bilinear:
      return {"bilinear", "llvmpipe: the 2x2 footprint's four compares weighted bilinearly: smooth penumbrae"};
    case CompareMethod::Nearest:
      return {"nearest",
              "one compare, of the texel the coordinate lands in: a 0 or 1 per tap, within 0.75 of bilinear; fewer texels and no blend"};
  }
  return {};
}

constexpr MethodRow rowOf(ShadingMethod m) {
  switch (m) {
    case ShadingMethod::Rate1x1: return {"1x1", "GL: one fragment-shader invocation per pixel"};
    case ShadingMethod::Rate2x1:
      return {"2x1", "one invocation per 2x1 pixels in post passes: about half their shading; detail across x halved"};
    case ShadingMethod::Rate1x2:
      return {"1x2", "one invocation per 1x2 pixels in post passes: about half their shading; detail along y halved"};
    case ShadingMethod::Rate2x2:
      return {"2x2", "one invocation per 2x2 pixels in post passes: about a quarter of their shading; blocky at sharp detail"};
    case ShadingMethod::Rate4x4:
      return {"4x4", "one invocation per 4x4 pixels in post passes: a sixteenth of their shading; visibly blocky"};
    case ShadingMethod::Rate2x2All:
      return {"2x2-all", "2x2 in every pass that writes colour, geometry passes too: texture detail and G-buffer normals blocky"};
    case ShadingMethod::Rate2x2Local:
      return {"2x2-local",
              "2x2 in post passes that sample only at or next to their pixel: SSAO's spread of samples, rotated per "
              "pixel, stays 1x1"};
    case ShadingMethod::Rate2x2Offscreen:
      return {"2x2-offscreen",
              "2x2 in 2x2-local's passes that draw offscreen targets (blurs, bloom): the pass into the window, the "
              "final image's edges, stays 1x1"};
    case ShadingMethod::Rate4x4Offscreen:
      return {"4x4-offscreen", "4x4 in 2x2-offscreen's passes: a sixteenth of their shading, where a blur follows"};
    case ShadingMethod::Rate2x2Smooth:
      return {"2x2-smooth",
              "2x2 in 2x2-offscreen's passes that read no texture larger than their target and no non-finite texel "
              "(blurs, upsamples): no pass that minifies (a bright pass, a downsample) aliases, and NaNs spread "
              "as at 1x1"};
  }
  return {};
}

// The number of methods of the step whose enum is E.
template <class E>
constexpr size_t methodCount() {
  size_t n = 0;
  while (n < 256 && !rowOf(E(n)).name.empty()) ++n;
  return n;
}

// E's rows are its values 0 .. methodCount - 1 (none after), named, each with its trade,
// no two with one name.
template <class E>
constexpr bool rowsAreWhole() {
  static_assert(std::is_same_v<std::underlying_type_t<E>, uint8_t>, "a MethodSet member is one byte");
  const size_t n = methodCount<E>();
  if (n < 2) return false;   // a step is a choice
  for (size_t v = n; v < 256; ++v)
    if (!rowOf(E(v)).name.empty()) return false;
  for (size_t i = 0; i < n; ++i) {
    if (rowOf(E(i)).trade.empty()) return false;
    for (size_t j = 0; j < i; ++j)
      if (rowOf(E(i)).name == rowOf(E(j)).name) return false;
  }
  return true;
}

// One step: its name, what it covers, its methods' rows, and where it lives in a MethodSet.
struct StepRow {
  std::string_view name;   // as typed: `math`, `filter`
  std::string_view what;   // which operations the step covers
  size_t count;            // methods: the values 0 .. count - 1 of the step's enum
  MethodRow (*row)(size_t index);
  size_t (*get)(const MethodSet&);   // the method's value, an index into the rows
  void (*set)(MethodSet&, size_t index);
};

template <auto Field>
constexpr StepRow stepRow(std::string_view name, std::string_view what) {
  using E = std::remove_cvref_t<decltype(MethodSet{}.*Field)>;
  static_assert(rowsAreWhole<E>(), "every enumerator of the step has its row (rowOf), in enum order, with no gaps");
  return {name, what, methodCount<E>(), [](size_t index) { return rowOf(E(index)); },
          [](const MethodSet& set) { return size_t(set.*Field); },
          [](MethodSet& set, size_t index) { set.*Field = E(index); }};
}

constexpr std::array kSteps{
    stepRow<&MethodSet::math>("math", "GLSL transcendentals in the shader ports: sin cos exp2 log2 pow atan atan2 asin acos"),
    stepRow<&MethodSet::filter>("filter", "bilinear weights of RGBA8 colour lookups (shadow compares are float in every method)"),
    stepRow<&MethodSet::half>("half", "float -> half rounding on writes and clears of RGBA16F targets"),
    stepRow<&MethodSet::div>("div", "normalize and inversesqrt in the shaders, and the 1/w of perspective-correct interpolation"),
    stepRow<&MethodSet::interp>("interp", "how varyings are interpolated across a triangle"),
    stepRow<&MethodSet::lookup>(
        "lookup", "how many texels a sampler2D lookup of a LINEAR texture reads (colour, G-buffer and post-pass lookups)"),
    stepRow<&MethodSet::compare>(
        "compare", "how a shadow lookup (sampler2DShadow, LINEAR) filters its texel compares; GL leaves it to the implementation"),
    stepRow<&MethodSet::shading>(
        "shading",
        "fragment-shader invocations per pixel (Vulkan's coarse fragments: the coarse pixel's centre interpolated, "
        "derivatives over coarse quads, coverage and depth per pixel); a rate applies to post passes (no colour draw "
        "of the pass tests depth), geometry passes stay 1x1 unless the method says all; -local leaves out passes "
        "that sample around their pixel (SSAO), -offscreen those and the pass into the window, -smooth those and "
        "passes that minify a texture or read a non-finite texel"),
};

// Every member of MethodSet is one step, each its own: setting a step changes no other.
constexpr bool stepsAreTheMembers() {
  if (sizeof(MethodSet) != kSteps.size()) return false;
  for (size_t i = 0; i < kSteps.size(); ++i) {
    MethodSet set;
    kSteps[i].set(set, kSteps[i].count - 1);
    for (size_t j = 0; j < kSteps.size(); ++j)
      if ((kSteps[j].get(set) != 0) != (i == j)) return false;
  }
  return true;
}
static_assert(stepsAreTheMembers(), "kSteps has one row per member of MethodSet");

std::string listOf(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out.append(out.empty() ? "" : ", ").append(n);
  return out;
}

const StepRow& stepOf(std::string_view step) {
  for (const StepRow& s : kSteps)
    if (step == s.name) return s;
  std::vector<std::string> steps;
  for (const StepRow& s : kSteps) steps.emplace_back(s.name);
  throw MethodError(std::string("unknown step '").append(step).append("' (steps: ").append(listOf(steps)).append(")"));
}

std::string_view nameIn(const StepRow& step, const MethodSet& set) { return step.row(step.get(set)).name; }

}  // namespace

const std::vector<StepInfo>& methodCatalog() {
  static const std::vector<StepInfo> catalog = [] {
    std::vector<StepInfo> steps;
    for (const StepRow& s : kSteps) {
      StepInfo& step = steps.emplace_back(StepInfo{std::string(s.name), std::string(s.what), {}});
      for (size_t i = 0; i < s.count; ++i)
        step.methods.push_back(MethodInfo{std::string(s.row(i).name), std::string(s.row(i).trade)});
    }
    return steps;
  }();
  return catalog;
}

const std::vector<std::string>& presetNames() {
  static const std::vector<std::string> names{"gl", "precise", "fast", "draft"};
  return names;
}

MethodSet presetMethods(std::string_view preset) {
  MethodSet set;
  if (preset == "gl") return set;
  if (preset == "precise") {
    set.math = MathMethod::Libm;
    set.filter = FilterMethod::Float;
    set.half = HalfMethod::NearestEven;
    return set;
  }
  // Not div=approx, nor math=fast's vertex stage: neither buys a measurable share of a frame,
  // and either moves hdr's one pixel where llvmpipe's rim pow takes a negative base at
  // 1920x1080, which llvmpipe's bloom turns into a black block (TRADEOFF.md).
  if (preset == "fast") {
    set.math = MathMethod::FastFragment;
    set.compare = CompareMethod::Nearest;
    return set;
  }
  // fast, with a quarter of the invocations in the offscreen post passes that filter what
  // is already at their scale (blurs, upsamples). Not 2x2-offscreen: its coarse bright pass
  // aliases hdr's bloom source, 30.5 dB at 320x240 and under 30 at small sizes and loud
  // bloom (STABILITY.md, "Coarse bloom"). Not lookup=nearest: it takes hdr's bloom to 23 dB
  // and deferred's magnified material maps to 29.7 dB at 320x240 (TRADEOFF.md).
  if (preset == "draft") {
    set = presetMethods("fast");
    set.shading = ShadingMethod::Rate2x2Smooth;
    return set;
  }
  throw MethodError(std::string("unknown preset '").append(preset).append("' (presets: ").append(listOf(presetNames())).append(")"));
}

std::string_view presetPromise(std::string_view preset) {
  if (preset == "gl") return "llvmpipe's bytes in every target: every scene, size, time and parameter swept";
  if (preset == "precise")
    return "each step's most accurate method: off llvmpipe's bytes wherever llvmpipe's own numerics are off "
           "(STABILITY.md names where it parts from llvmpipe)";
  if (preset == "fast")
    return ">= 40 dB at every scene's defaults, 320x240 to 1920x1080; lower only at sweep extremes (deferred "
           "31.8 dB at t = 1e10, 37.6 at a world offset of 316, 39.9 at 20x15) and where llvmpipe's frame is "
           "not finite";
  if (preset == "draft")
    return ">= 30 dB wherever fast is: the stability sweeps find it failing only where fast does (llvmpipe's "
           "own non-finite pixels), hdr's coarse upsamples at 37-50 dB, the other scenes within 0.4 dB of fast";
  throw MethodError(std::string("unknown preset '").append(preset).append("' (presets: ").append(listOf(presetNames())).append(")"));
}

void setMethod(MethodSet& set, std::string_view step, std::string_view method) {
  const StepRow& s = stepOf(step);
  std::vector<std::string> valid;
  for (size_t i = 0; i < s.count; ++i) {
    if (method == s.row(i).name) {
      s.set(set, i);
      return;
    }
    valid.emplace_back(s.row(i).name);
  }
  throw MethodError(std::string("unknown method '").append(method).append("' for step ").append(step)
                        .append(" (methods: ").append(listOf(valid)).append(")"));
}

void applyMethodOverrides(MethodSet& set, std::string_view overrides) {
  std::vector<std::string_view> stepsGiven;   // a step twice is ambiguous, not "the last wins"
  while (!overrides.empty()) {
    const size_t comma = overrides.find(',');
    const std::string_view item = overrides.substr(0, comma);
    const size_t eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0)
      throw MethodError(std::string("'").append(item).append("' is not STEP=METHOD (for example math=fast)"));
    const std::string_view step = item.substr(0, eq);
    if (std::find(stepsGiven.begin(), stepsGiven.end(), step) != stepsGiven.end())
      throw MethodError(std::string("step ").append(step).append(" is given twice"));
    stepsGiven.push_back(step);
    setMethod(set, step, item.substr(eq + 1));
    if (comma == std::string_view::npos) break;
    overrides.remove_prefix(comma + 1);
    if (overrides.empty()) throw MethodError("a trailing comma in --method");
  }
}

std::string methodName(const MethodSet& set, std::string_view step) { return std::string(nameIn(stepOf(step), set)); }

std::vector<std::pair<std::string, std::string>> methodNames(const MethodSet& set) {
  std::vector<std::pair<std::string, std::string>> names;
  for (const StepRow& s : kSteps) names.emplace_back(s.name, nameIn(s, set));
  return names;
}

MethodSet vertexStageSet(const MethodSet& set) {
  MethodSet vertex = set;
  vertex.math = methods::vertexMath(set.math);
  return vertex;
}

std::string methodLabel(const MethodSet& set) {
  for (const std::string& preset : presetNames())
    if (presetMethods(preset) == set) return preset;
  const MethodSet gl;
  std::string label;
  for (const StepRow& s : kSteps) {
    if (s.get(set) == s.get(gl)) continue;
    label.append(label.empty() ? "" : ",").append(s.name).append("=").append(nameIn(s, set));
  }
  return label;
}

}  // namespace raster
