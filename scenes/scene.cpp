// The scene names and the asset folder lookup (the factory is scene_factory.cpp).
#include "scenes/scene.h"

#include <cstdlib>


namespace scenes {

std::vector<std::string> sceneNames() { return {"shadow", "deferred", "hdr"}; }

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
