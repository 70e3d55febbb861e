// Shader ports by program name, for the raster backend.
//
// A BoundProgram is a port plus its current uniform values, set by GLSL name as
// glUniform* would; each draw takes a snapshot (ShaderInstance) with samplers resolved to
// the textures bound to their units at that moment.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "raster/program_instance.h"
#include "scenes/backend.h"

namespace scenes {

constexpr int kTextureUnits = 16;
using TextureUnits = std::array<const raster::Texture*, kTextureUnits>;

class BoundProgram {
 public:
  virtual ~BoundProgram() = default;
  // Unknown names are ignored (GL drops unused uniforms); a value of the wrong type throws.
  virtual void setUniform(const std::string& name, const UniformValue& value) = 0;
  // Throws when a sampler's unit has no texture bound.
  virtual std::unique_ptr<raster::ShaderInstance> instantiate(const TextureUnits& units) const = 0;
};

// Throws std::runtime_error for a name with no C++ port.
std::unique_ptr<BoundProgram> makeBoundProgram(const std::string& name);

}  // namespace scenes
