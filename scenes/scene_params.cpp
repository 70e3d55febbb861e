// The scene parameter catalog (scene_params.h).
#include "scenes/scene_params.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "scenes/registry.h"

namespace scenes {
namespace param {

ParamSpec time() {
  return {"time", 0, 1e30, false, "s", "1",
          "time of the frame; large values lose float precision in every angle the scene derives from it"};
}
ParamSpec size() {
  return {"size", 1, 16384, true, "px", "640x480",
          "final image WxH, or a width at 4:3; 1x1 to 16384 (GL_MAX_TEXTURE_SIZE of llvmpipe)"};
}
ParamSpec nearPlane() {
  return {"near", 1e-7, 10, false, "", "0.1",
          "camera near plane; toward 0 the depth buffer's precision collapses (z-fighting)"};
}
ParamSpec worldOffset() {
  return {"world_offset", -1e20, 1e20, false, "", "0",
          "scene and camera moved by (d, d, d): float precision far from the origin"};
}
ParamSpec lightElevation(const char* byDefault) {
  return {"light_elevation", 0.01, 89.9, false, "deg", byDefault,
          "sun angle above the ground; toward 0 the light grazes the floor (shadow acne, peter-panning)"};
}
ParamSpec offsetScale() {
  return {"offset_scale", 0, 1000, false, "", "1",
          "multiplier on the shadow pass's polygon offset (factor 2, units 4); 0 = none (acne)"};
}

}  // namespace param

std::vector<ParamSpec> sceneParams(const std::string& scene) { return sceneEntry(scene).params; }

ParamSpec findParam(const std::string& scene, const std::string& name) {
  const std::vector<ParamSpec> specs = sceneParams(scene);
  for (const ParamSpec& spec : specs)
    if (spec.name == name) return spec;
  std::string known;
  for (const ParamSpec& spec : specs) known += (known.empty() ? "" : ", ") + spec.name;
  throw ParamError("unknown parameter '" + name + "' of scene " + scene + " (its parameters: " + known + ")");
}

bool parseSizeValue(const std::string& text, int& width, int& height) {
  auto whole = [](const std::string& s, int& out) {
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && error == std::errc() && end == s.data() + s.size() && out >= 1 && out <= 16384;
  };
  const size_t x = text.find('x');
  if (x == std::string::npos) {
    if (!whole(text, width)) return false;
    height = std::max(1, int(std::lround(double(width) * 3.0 / 4.0)));
    return true;
  }
  return whole(text.substr(0, x), width) && whole(text.substr(x + 1), height);
}

std::optional<double> parseDecimal(const std::string& text) {
  // from_chars, unlike strtod, takes no leading spaces, no '+' and no "0x" hex.
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

double parseParamValue(const std::string& scene, const std::string& name, const std::string& value) {
  const ParamSpec spec = findParam(scene, name);
  const std::optional<double> parsed = parseDecimal(value);
  if (!parsed) throw ParamError(name + ": '" + value + "' is not a finite number");
  const double v = *parsed;
  if (spec.integer && v != std::floor(v)) throw ParamError(name + ": '" + value + "' is not a whole number");
  // A scene takes its parameters as floats: the range holds for the float it gets, so the
  // text a child process is handed back ("%.9g" of that float: 1e30 is 1.00000002e+30) passes.
  const bool outside = spec.integer ? (v < spec.min || v > spec.max) : (float(v) < float(spec.min) || float(v) > float(spec.max));
  if (outside) {
    char range[96];
    std::snprintf(range, sizeof range, "%g..%g", spec.min, spec.max);
    throw ParamError(name + ": " + value + " is out of range (" + range + ")");
  }
  return v;
}

glm::vec3 lightAtElevation(float yaw, float elevationDegrees) {
  const float e = elevationDegrees * float(M_PI / 180.0);
  return {std::cos(yaw) * std::cos(e), std::sin(e), std::sin(yaw) * std::cos(e)};
}

bool isFrameOption(std::string_view name) {
  return name == "time" || name == "size" || name == "instances";
}

void applyParam(SceneParams& params, const std::string& name, double value) {
  if (isFrameOption(name))
    throw ParamError("parameter '" + name + "' is an option of the frame, not a scene setting");
  params.set(name, float(value));
}

}  // namespace scenes
