// Shader ports by program name, for the raster backend.
//
// A BoundProgram is a port plus its current uniform values, set by GLSL name as
// glUniform* would; each draw takes a snapshot (ShaderInstance) with samplers resolved to
// the textures bound to their units at that moment. A ProgramEntry names a port and makes
// its BoundPrograms; each scene's row lists its programs (scenes/registry.h), and
// programEntry<Port>() makes one from a port's kName and kUniformTable.
#pragma once

#include <array>
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

// A sampler's unit resolved to the texture bound there (throws when none is); other
// uniforms are left as they are.
template <class T>
void resolve(T&, const TextureUnits&) {}
void resolve(raster::Sampler2D& sampler, const TextureUnits& units);
void resolve(raster::Sampler2DShadow& sampler, const TextureUnits& units);

template <class Program>
class BoundProgramOf final : public BoundProgram {
 public:
  void setUniform(const std::string& name, const UniformValue& value) override {
    std::apply([&](const auto&... entry) { ((entry.name == name ? assign(uniforms_.*entry.member, value, name) : void()), ...); },
               Program::kUniformTable);
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
