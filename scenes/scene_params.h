// The scalar parameters a scene declares for its failure modes, settable on every command
// with `--set NAME=VALUE` (so one point of a sweep can be rendered again with `render` or
// `compare`), and listed by `raster params SCENE`.
//
// Each parameter moves one thing toward where some method breaks: float precision of time,
// depth precision of the near plane, shadow acne at grazing light, half-float overflow,
// coordinates far from the origin, huge and tiny images. A scene declares only the ones its
// failure modes need. Unset parameters leave the scene exactly as its seed renders it (the
// same bytes as before parameters existed).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace scenes {

// What --set changes inside a scene: the value of each parameter set, by name. A scene
// reads its own parameters with get(); one never set keeps the scene's own value.
class SceneParams {
 public:
  std::optional<float> get(std::string_view name) const {
    const auto it = values_.find(name);
    return it == values_.end() ? std::nullopt : std::optional<float>(it->second);
  }
  void set(const std::string& name, float value) { values_[name] = value; }

 private:
  std::map<std::string, float, std::less<>> values_;
};

struct ParamSpec {
  std::string name;      // as typed after --set
  double min, max;       // the accepted range, inclusive
  bool integer;          // whole numbers only
  std::string unit;      // "s", "deg", "px", "" ...
  std::string byDefault; // the scene's own value, as text
  std::string meaning;   // one line: what it moves and toward which failure
};

// A --set that names no parameter of the scene, or a value out of its range (exit 2).
struct ParamError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// The parameters of a scene (its registry row, scenes/registry.h), in the order `raster
// params` lists them. `time`, `size` and `instances` are the frame's own options; the
// others land in SceneParams.
std::vector<ParamSpec> sceneParams(const std::string& scene);
ParamSpec findParam(const std::string& scene, const std::string& name);   // ParamError

// A finite decimal number that is the whole text: no spaces, no hex, no inf or nan (the
// form every number of the command line takes, so that --time and --set time= agree).
std::optional<double> parseDecimal(const std::string& text);
// Parses and range-checks VALUE for parameter `name` of `scene` (ParamError naming both).
// `size` is not a number: see parseSizeValue.
double parseParamValue(const std::string& scene, const std::string& name, const std::string& value);
// `size` as WxH, or a width (the height then keeps the scene's 4:3 aspect, at least 1).
bool parseSizeValue(const std::string& text, int& width, int& height);

// The parameters several scenes share, for their registry rows; a scene's own are written
// in its folder.
namespace param {
ParamSpec time();
ParamSpec size();
ParamSpec nearPlane();     // "near"
ParamSpec worldOffset();   // "world_offset"
ParamSpec lightElevation(const char* byDefault);   // "light_elevation", the scene's own angle
ParamSpec offsetScale();   // "offset_scale"
}  // namespace param

// The unit direction toward a sun at `yaw` radians around the y axis and `elevationDegrees`
// above the ground: the form light_elevation gives the scenes' orbiting suns.
glm::vec3 lightAtElevation(float yaw, float elevationDegrees);

// Whether `name` is one of the frame's own options (time, size, instances): a scene
// parameter a command line may give as --set NAME= or as --NAME, which the frame holds
// rather than SceneParams. The one list: applyParam, cli::childFrameOptions and the check
// that refuses one given both ways read it (cli::validateFrame's --set gives each its field).
bool isFrameOption(std::string_view name);

// Sets a parameter in SceneParams (not one of the frame's own options: isFrameOption).
void applyParam(SceneParams& params, const std::string& name, double value);

}  // namespace scenes
