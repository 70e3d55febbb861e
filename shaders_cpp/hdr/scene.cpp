// The registry row of ScenePass (hdr/scene.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/hdr/scene.h"

#include "scenes/program_registry.h"

namespace shaders::hdr {

scenes::ProgramEntry sceneProgram() { return scenes::programEntry<ScenePass>(); }

}  // namespace shaders::hdr
