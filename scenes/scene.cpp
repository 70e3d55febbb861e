// The scene registry and the asset folder lookup.
#include "scenes/scene.h"

#include <cstdlib>

#include "scenes/deferred/deferred_scene.h"
#include "scenes/hdr/hdr_scene.h"
#include "scenes/shadow/shadow_scene.h"

namespace scenes {

std::vector<std::string> sceneNames() { return {"shadow", "deferred", "hdr"}; }

std::unique_ptr<Scene> makeScene(const std::string& name, const SceneOptions& options) {
  if (name == "shadow") return makeShadowScene(options);
  if (name == "deferred") return makeDeferredScene(options);
  if (name == "hdr") return makeHdrScene(options);
  std::string known;
  for (const std::string& n : sceneNames()) known += (known.empty() ? "" : ", ") + n;
  throw SceneError("unknown scene '" + name + "' (known: " + known + ")");
}

std::string assetDirectory(const SceneOptions& options) {
  if (!options.assetDir.empty()) return options.assetDir;
  if (const char* env = std::getenv("RASTER_ASSETS"); env && *env) return env;
#ifdef RASTER_DEFAULT_ASSETS
  return RASTER_DEFAULT_ASSETS;
#else
  return "../shared/assets";
#endif
}

}  // namespace scenes
