// The scenes this project ships: one line per scene, each row written in the scene's own
// folder (scenes/NAME/). Adding a scene adds its line here (CONTRIBUTING.md).
#include "scenes/deferred/deferred_scene.h"
#include "scenes/hdr/hdr_scene.h"
#include "scenes/pbr/pbr_scene.h"
#include "scenes/registry.h"
#include "scenes/shadow/shadow_scene.h"
#include "scenes/soup/soup_check.h"

namespace scenes {

std::vector<SceneEntry> builtinScenes() {
  return {
      shadowScene(),     // scenes/shadow/
      deferredScene(),   // scenes/deferred/
      hdrScene(),        // scenes/hdr/
      pbrScene(),        // scenes/pbr/
  };
}

std::vector<ProgramEntry> builtinPrograms() { return soup::programs(); }   // `raster soup`

}  // namespace scenes
