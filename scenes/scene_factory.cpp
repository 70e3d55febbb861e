// The scene factory: a name to its scene.
#include "scenes/deferred/deferred_scene.h"
#include "scenes/hdr/hdr_scene.h"
#include "scenes/scene.h"
#include "scenes/shadow/shadow_scene.h"

namespace scenes {

std::unique_ptr<Scene> makeScene(const std::string& name, const SceneOptions& options) {
  if (name == "shadow") return makeShadowScene(options);
  if (name == "deferred") return makeDeferredScene(options);
  if (name == "hdr") return makeHdrScene(options);
  std::string known;
  for (const std::string& n : sceneNames()) known += (known.empty() ? "" : ", ") + n;
  throw SceneError("unknown scene '" + name + "' (known: " + known + ")");
}

}  // namespace scenes
