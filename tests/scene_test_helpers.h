// Rendering a whole scene with a backend, for the scene, determinism and benchmark tests.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scenes/backends.h"
#include "scenes/scene.h"

namespace testing_support {

// Renders one frame of `scene` at time t and size w x h, and reads every target back.
inline std::vector<scenes::Target> renderScene(scenes::Backend& backend, const std::string& scene, float t, int w,
                                               int h) {
  scenes::SceneOptions options;
  options.time = t;
  options.width = w;
  options.height = h;
  std::unique_ptr<scenes::Scene> s = scenes::makeScene(scene, options);
  backend.resizeDefaultFramebuffer(w, h);
  s->setup(backend);
  s->renderFrame(backend, t);
  return s->readTargets(backend);
}

inline std::vector<scenes::Target> renderWithLlvmpipe(const std::string& scene, float t, int w, int h) {
  std::unique_ptr<scenes::Backend> gl = scenes::makeGlBackend();
  return renderScene(*gl, scene, t, w, h);
}

}  // namespace testing_support
