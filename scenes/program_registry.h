// Shader ports by program name, for the raster backend.
//
// A BoundProgram is a port plus its current uniform values, set by GLSL name as
// glUniform* would; each draw takes a snapshot (ShaderInstance) with samplers resolved to
// the textures bound to their units at that moment. A ProgramEntry names a port and makes
// its BoundPrograms; each scene's row lists its programs (scenes/registry.h), and
// programEntry<Port>() makes one from a port's kName and kUniformTable.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "backends/backend.h"
#include "raster/program_instance.h"
#include "scenes/program_entry.h"

namespace scenes {

constexpr int kTextureUnits = 16;
using TextureUnits = std::array<const raster::Texture*, kTextureUnits>;

class BoundProgram {
 public:
  virtual ~BoundProgram() = default;
  // Unknown names are ignored, as GL ignores a name that is not an active uniform; a value
  // of the wrong type throws. (The GL backend checks, as it links a program, that its port
  // has every active uniform and nothing its GLSL does not declare.)
  virtual void setUniform(const std::string& name, const UniformValue& value) = 0;
  // Throws when a sampler's unit has no texture bound.
  virtual std::unique_ptr<raster::ShaderInstance> instantiate(const TextureUnits& units) const = 0;
};

// Throws std::runtime_error for a name with no C++ port in the registry.
std::unique_ptr<BoundProgram> makeBoundProgram(const std::string& name);

namespace program_detail {

// Uniform assignment by type: a value of another type throws, a sampler takes a unit.
void assign(glm::mat4& member, const UniformValue& value, const std::string& name);
void assign(glm::vec4& member, const UniformValue& value, const std::string& name);
void assign(glm::vec3& member, const UniformValue& value, const std::string& name);
void assign(glm::vec2& member, const UniformValue& value, const std::string& name);
void assign(float& member, const UniformValue& value, const std::string& name);
void assign(int& member, const UniformValue& value, const std::string& name);
void assign(raster::Sampler2D& member, const UniformValue& value, const std::string& name);
void assign(raster::Sampler2DShadow& member, const UniformValue& value, const std::string& name);

// "u_samples[12]" as its array's name and the index 12; a name without brackets has the index
// kNotAnElement (an array's element 0, a plain uniform itself); a malformed index, a
// name that is no uniform (SIZE_MAX - 1).
constexpr size_t kNotAnElement = ~size_t(0);
struct ElementName {
  std::string base;
  size_t index = kNotAnElement;
};
ElementName splitElementName(const std::string& name);

// A sampler's unit resolved to the texture bound there (throws when none is); other
// uniforms are left as they are.
template <class T>
void resolve(T&, const TextureUnits&) {}
void resolve(raster::Sampler2D& sampler, const TextureUnits& units);
void resolve(raster::Sampler2DShadow& sampler, const TextureUnits& units);

// A uniform array (GLSL `uniform vec3 u_samples[64];`, a std::array member): GL sets one
// element by the name "u_samples[i]", and the plain name is element 0. An index past the
// end is ignored, as GL ignores a name that has no location.
template <class T, size_t N>
void assign(std::array<T, N>& member, size_t index, const UniformValue& value, const std::string& name) {
  if (index == kNotAnElement) index = 0;
  if (index < N) assign(member[index], value, name);
}
// A uniform that is not an array has no element names: "u_time[0]" is ignored, as in GL.
template <class T>
void assign(T& member, size_t index, const UniformValue& value, const std::string& name) {
  if (index == kNotAnElement) assign(member, value, name);
}

template <class Program>
class BoundProgramOf final : public BoundProgram {
 public:
  void setUniform(const std::string& name, const UniformValue& value) override {
    const ElementName element = splitElementName(name);
    std::apply([&](const auto&... entry) {
      ((entry.name == element.base ? assign(uniforms_.*entry.member, element.index, value, name) : void()), ...);
    }, Program::kUniformTable);
  }
  std::unique_ptr<raster::ShaderInstance> instantiate(const TextureUnits& units) const override {
    typename Program::Uniforms snapshot = uniforms_;
    std::apply([&](const auto&... entry) { (resolve(snapshot.*entry.member, units), ...); }, Program::kUniformTable);
    return std::make_unique<raster::ProgramInstance<Program>>(snapshot);
  }

 private:
  typename Program::Uniforms uniforms_;
};

}  // namespace program_detail

// The registry entry of a port (a struct with kName, Uniforms and kUniformTable).
template <class Program>
ProgramEntry programEntry() {
  std::vector<std::string> uniforms;
  std::apply([&](const auto&... entry) { (uniforms.emplace_back(entry.name), ...); }, Program::kUniformTable);
  return {Program::kName, std::move(uniforms), [] { return std::make_unique<program_detail::BoundProgramOf<Program>>(); }};
}

}  // namespace scenes
