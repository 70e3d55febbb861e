// The registry row of LightingPass (deferred/lighting.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/deferred/lighting.h"

#include "scenes/program_registry.h"

namespace shaders::deferred {

scenes::ProgramEntry lightingProgram() { return scenes::programEntry<LightingPass>(); }

}  // namespace shaders::deferred
