// The table of shader ports, and the uniform plumbing generic over a port's kUniformTable.
#include "scenes/program_registry.h"

#include <functional>
#include <map>
#include <stdexcept>
#include <tuple>

#include "shaders_cpp/deferred/gbuffer.h"
#include "shaders_cpp/deferred/lighting.h"
#include "shaders_cpp/deferred/ssao.h"
#include "shaders_cpp/hdr/bright.h"
#include "shaders_cpp/hdr/composite.h"
#include "shaders_cpp/hdr/down.h"
#include "shaders_cpp/hdr/scene.h"
#include "shaders_cpp/hdr/up.h"
#include "shaders_cpp/shadow/main.h"
#include "shaders_cpp/shadow/shadow.h"
#include "shaders_cpp/test/derivatives.h"
#include "shaders_cpp/test/instanced.h"
#include "shaders_cpp/test/color_lookup.h"
#include "shaders_cpp/test/math_probe.h"
#include "shaders_cpp/test/mrt.h"
#include "shaders_cpp/test/passthrough.h"
#include "shaders_cpp/test/shadow_lookup.h"

namespace scenes {
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

void assign(glm::mat4& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
[[maybe_unused]] void assign(glm::vec4& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(glm::vec3& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(glm::vec2& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(float& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(int& m, const UniformValue& v, const std::string& n) { assignUniform(m, v, n); }
void assign(raster::Sampler2D& m, const UniformValue& v, const std::string& n) { assignSampler(m, v, n); }
void assign(raster::Sampler2DShadow& m, const UniformValue& v, const std::string& n) { assignSampler(m, v, n); }

template <class T>
void resolve(T&, const TextureUnits&) {}
template <class Sampler>
void resolveSampler(Sampler& sampler, const TextureUnits& units) {
  sampler.texture = units[size_t(sampler.unit)];
  if (!sampler.texture) throw std::runtime_error("no texture bound to unit " + std::to_string(sampler.unit));
}
void resolve(raster::Sampler2D& s, const TextureUnits& units) { resolveSampler(s, units); }
void resolve(raster::Sampler2DShadow& s, const TextureUnits& units) { resolveSampler(s, units); }

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

template <class Program>
std::pair<std::string, std::function<std::unique_ptr<BoundProgram>()>> entry() {
  return {Program::kName, [] { return std::make_unique<BoundProgramOf<Program>>(); }};
}

}  // namespace

std::unique_ptr<BoundProgram> makeBoundProgram(const std::string& name) {
  static const std::map<std::string, std::function<std::unique_ptr<BoundProgram>()>> registry = {
      entry<shaders::shadow::ShadowPass>(),
      entry<shaders::shadow::MainPass>(),
      entry<shaders::deferred::GBufferPass>(),
      entry<shaders::deferred::SsaoPass>(),
      entry<shaders::deferred::LightingPass>(),
      entry<shaders::hdr::ScenePass>(),
      entry<shaders::hdr::BrightPass>(),
      entry<shaders::hdr::DownPass>(),
      entry<shaders::hdr::UpPass>(),
      entry<shaders::hdr::CompositePass>(),
      entry<shaders::test::Passthrough>(),
      entry<shaders::test::ColorLookup>(),
      entry<shaders::test::Derivatives>(),
      entry<shaders::test::Instanced>(),
      entry<shaders::test::ShadowLookup>(),
      entry<shaders::test::MathProbe>(),
      entry<shaders::test::Mrt>(),
  };
  const auto it = registry.find(name);
  if (it == registry.end()) throw std::runtime_error("no C++ port of shader program " + name);
  return it->second();
}

}  // namespace scenes
