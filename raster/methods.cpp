// The catalog of steps and methods, the presets, and the parsing of their names.
#include "raster/methods.h"

#include <array>
#include <type_traits>

namespace raster {
namespace {

// One step's names, in the order of its enum (the first is llvmpipe's), and where the
// step's value lives in a MethodSet.
struct StepBinding {
  const char* step;
  std::array<const char*, 4> names;   // unused slots are nullptr
  uint8_t (*get)(const MethodSet&);   // the enum's value, an index into names
  void (*set)(MethodSet&, uint8_t);
};

template <auto Field>
uint8_t getField(const MethodSet& set) { return uint8_t(set.*Field); }
template <auto Field>
void setField(MethodSet& set, uint8_t index) { set.*Field = std::remove_reference_t<decltype(set.*Field)>(index); }
#define RASTER_STEP_FIELD(field) &getField<&MethodSet::field>, &setField<&MethodSet::field>

const std::array<StepBinding, 6>& bindings() {
  static const std::array<StepBinding, 6> table{{
      {"math", {"llvmpipe", "libm", "fast", "fast-fragment"}, RASTER_STEP_FIELD(math)},
      {"filter", {"8bit", "float", nullptr}, RASTER_STEP_FIELD(filter)},
      {"half", {"rtz", "rne", nullptr}, RASTER_STEP_FIELD(half)},
      {"div", {"exact", "approx", nullptr}, RASTER_STEP_FIELD(div)},
      {"interp", {"perspective", "affine", nullptr}, RASTER_STEP_FIELD(interp)},
      {"compare", {"bilinear", "nearest", nullptr}, RASTER_STEP_FIELD(compare)},
  }};
  return table;
}
#undef RASTER_STEP_FIELD

std::string listOf(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out.append(out.empty() ? "" : ", ").append(n);
  return out;
}

const StepBinding& bindingOf(std::string_view step) {
  for (const StepBinding& b : bindings())
    if (step == b.step) return b;
  std::vector<std::string> steps;
  for (const StepBinding& b : bindings()) steps.emplace_back(b.step);
  throw MethodError(std::string("unknown step '").append(step).append("' (steps: ").append(listOf(steps)).append(")"));
}

}  // namespace

const std::vector<StepInfo>& methodCatalog() {
  static const std::vector<StepInfo> catalog{
      {"math",
       "GLSL transcendentals in the shader ports: sin cos exp2 log2 pow atan atan2 asin acos",
       {{"llvmpipe", "llvmpipe's polynomials, bit for bit (relative error up to ~1e-4 in pow; 2-3 ulp in sin)"},
        {"libm", "the C library in double, rounded once: correctly rounded float; 5-20x slower per call"},
        {"fast", "low-degree polynomials, documented bounds in fast_math.h; fewer operations than llvmpipe's"},
        {"fast-fragment", "fast in fragment shaders, llvmpipe's in vertex shaders: the same speed, and every vertex (so coverage) is GL's"}}},
      {"filter",
       "bilinear weights of RGBA8 colour lookups (shadow compares are float in every method)",
       {{"8bit", "llvmpipe's AoS path: 8-bit weights, every lerp rounded to 8 bits"},
        {"float", "float32 weights and lerps, as softpipe: off by up to ~1 of 255 from 8bit"}}},
      {"half",
       "float -> half rounding on writes and clears of RGBA16F targets",
       {{"rtz", "llvmpipe's truncation toward zero: up to 1 half ulp low, biased"},
        {"rne", "IEEE round to nearest even: half an ulp, unbiased; the same cost with F16C"}}},
      {"div",
       "normalize and inversesqrt in the shaders, and the 1/w of perspective-correct interpolation",
       {{"exact", "correctly rounded division and square root"},
        {"approx", "bit-pattern seed and Newton steps: 1/x within 7e-8, 1/sqrt within 5e-6; no divider or sqrt unit"}}},
      {"interp",
       "how varyings are interpolated across a triangle",
       {{"perspective", "GL: perspective-correct, one reciprocal per pixel"},
        {"affine", "screen-linear: no reciprocal, textures swim and bend on triangles at grazing angles"}}},
      {"compare",
       "how a shadow lookup (sampler2DShadow, LINEAR) filters its texel compares; GL leaves it to the implementation",
       {{"bilinear", "llvmpipe: the 2x2 footprint's four compares weighted bilinearly: smooth penumbrae"},
        {"nearest", "one compare, of the texel the coordinate lands in: a 0 or 1 per tap, within 0.75 of bilinear; fewer texels and no blend"}}},
  };
  return catalog;
}

const std::vector<std::string>& presetNames() {
  static const std::vector<std::string> names{"gl", "precise", "fast"};
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
  throw MethodError(std::string("unknown preset '").append(preset).append("' (presets: ").append(listOf(presetNames())).append(")"));
}

void setMethod(MethodSet& set, std::string_view step, std::string_view method) {
  const StepBinding& b = bindingOf(step);
  std::vector<std::string> valid;
  for (size_t i = 0; i < b.names.size() && b.names[i]; ++i) {
    if (method == b.names[i]) {
      b.set(set, uint8_t(i));
      return;
    }
    valid.emplace_back(b.names[i]);
  }
  throw MethodError(std::string("unknown method '").append(method).append("' for step ").append(step)
                        .append(" (methods: ").append(listOf(valid)).append(")"));
}

void applyMethodOverrides(MethodSet& set, std::string_view overrides) {
  while (!overrides.empty()) {
    const size_t comma = overrides.find(',');
    const std::string_view item = overrides.substr(0, comma);
    const size_t eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0)
      throw MethodError(std::string("'").append(item).append("' is not STEP=METHOD (for example math=fast)"));
    setMethod(set, item.substr(0, eq), item.substr(eq + 1));
    if (comma == std::string_view::npos) break;
    overrides.remove_prefix(comma + 1);
    if (overrides.empty()) throw MethodError("a trailing comma in --method");
  }
}

std::string methodName(const MethodSet& set, std::string_view step) {
  const StepBinding& b = bindingOf(step);
  return b.names[b.get(set)];
}

std::vector<std::pair<std::string, std::string>> methodNames(const MethodSet& set) {
  std::vector<std::pair<std::string, std::string>> names;
  for (const StepBinding& b : bindings()) names.emplace_back(b.step, b.names[b.get(set)]);
  return names;
}

MethodSet vertexStageSet(const MethodSet& set) {
  MethodSet vertex = set;
  if (vertex.math == MathMethod::FastFragment) vertex.math = MathMethod::Llvmpipe;
  return vertex;
}

std::string methodLabel(const MethodSet& set) {
  for (const std::string& preset : presetNames())
    if (presetMethods(preset) == set) return preset;
  const MethodSet gl;
  std::string label;
  for (const StepBinding& b : bindings()) {
    if (b.get(set) == b.get(gl)) continue;
    label.append(label.empty() ? "" : ",").append(b.step).append("=").append(b.names[b.get(set)]);
  }
  return label;
}

}  // namespace raster
