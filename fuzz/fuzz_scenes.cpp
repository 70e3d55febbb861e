// The registry's built-in rows for the cli fuzz target, which cannot compile the shader
// ports (fuzz/CMakeLists.txt): one scene, `fuzz`, with the parameters the scenes share and
// no factory, so every check of a command line runs as it does for a real scene.
#include "scenes/registry.h"

namespace scenes {

std::vector<SceneEntry> builtinScenes() {
  SceneEntry row;
  row.name = "fuzz";
  row.params = {param::time(), param::size(), param::lightElevation("45"), param::offsetScale(), param::nearPlane(),
                param::worldOffset()};
  return {row};
}

std::vector<ProgramEntry> builtinPrograms() { return {}; }

}  // namespace scenes
