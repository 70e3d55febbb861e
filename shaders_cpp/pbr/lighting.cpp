// The registry row of LightingPass (pbr/lighting.h): the pipeline's code for this port, SIMD and scalar
// lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/pbr/lighting.h"

#include "scenes/program_registry.h"

namespace shaders::pbr {

scenes::ProgramEntry lightingProgram() { return scenes::programEntry<LightingPass>(); }

}  // namespace shaders::pbr
