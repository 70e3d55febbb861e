// What every scene shares: the --float-final target, and the asset folder lookup.
#include "scenes/scene.h"

#include <algorithm>
#include <cstdlib>

namespace scenes {

void Scene::createFinalTarget(Backend& backend, const SceneOptions& options, bool depth) {
  if (!options.floatFinal) return;
  const SamplerState nearest{Filter::Nearest, Wrap::ClampToEdge, Wrap::ClampToEdge, false};
  const int w = std::max(options.width, 1), h = std::max(options.height, 1);
  const Handle color = backend.createTexture({w, h, TexelFormat::RGBA32F, nearest});
  backend.labelTexture(color, "final");
  const Handle depthBuffer = depth ? backend.createTexture({w, h, TexelFormat::Depth24, nearest}) : 0;
  final_ = backend.createFramebuffer({{color}, depthBuffer});
}

std::string assetDirectory(const SceneOptions& options) {
  if (!options.assetDir.empty()) return options.assetDir;
  if (const char* env = std::getenv("RASTER_ASSETS"); env && *env) return env;
#ifdef RASTER_DEFAULT_ASSETS
  return RASTER_DEFAULT_ASSETS;
#else
  return "assets";   // the repository's asset folder, from the repository root
#endif
}

}  // namespace scenes
