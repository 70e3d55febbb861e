// The uniform plumbing generic over a port's kUniformTable, and the lookup of a program
// by name in the registry (scenes/registry.h).
#include "scenes/program_registry.h"

#include <stdexcept>

#include "scenes/registry.h"

namespace scenes {
namespace program_detail {
namespace {

template <class T>
void assignUniform(T& member, const UniformValue& value, const std::string& name) {
  if (const T* v = std::get_if<T>(&value)) {
    member = *v;
    return;
  }
  throw std::runtime_error("uniform " + name + " set with a value of the wrong type");
}

template <class Sampler>
void assignSampler(Sampler& sampler, const UniformValue& value, const std::string& name) {
  const int* unit = std::get_if<int>(&value);
  if (!unit || *unit < 0 || *unit >= kTextureUnits) throw std::runtime_error("sampler " + name + " needs a texture unit");
  sampler.unit = *unit;
}

template <class Sampler>
void resolveSampler(Sampler& sampler, const TextureUnits& units) {
  sampler.texture = units[size_t(sampler.unit)];
  if (!sampler.texture) throw std::runtime_error("no texture bound to unit " + std::to_string(sampler.unit));
}

}  // namespace

void assign(glm::mat4& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(glm::vec4& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(glm::vec3& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(glm::vec2& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(float& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(int& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(raster::Sampler2D& m, const UniformValue& v, const std::string& n) { assignSampler(m, v, n); }
void assign(raster::Sampler2DShadow& m, const UniformValue& v, const std::string& n) { assignSampler(m, v, n); }
ElementName splitElementName(const std::string& name) {
  const size_t open = name.find('[');
  if (open == std::string::npos) return {name, kNotAnElement};
  ElementName element{name.substr(0, open), kNotAnElement - 1};
  const std::string digits = name.substr(open + 1);
  if (digits.size() < 2 || digits.back() != ']' || digits.size() > 10) return element;
  size_t index = 0;
  for (size_t i = 0; i + 1 < digits.size(); ++i) {
    if (digits[i] < '0' || digits[i] > '9') return element;
    index = index * 10 + size_t(digits[i] - '0');
  }
  element.index = index;
  return element;
}

void resolve(raster::Sampler2D& s, const TextureUnits& units) { resolveSampler(s, units); }
void resolve(raster::Sampler2DShadow& s, const TextureUnits& units) { resolveSampler(s, units); }

}  // namespace program_detail

std::unique_ptr<BoundProgram> makeBoundProgram(const std::string& name) {
  if (const ProgramEntry* entry = findProgram(name)) return entry->make();
  throw std::runtime_error("no C++ port of shader program " + name);
}

}  // namespace scenes
