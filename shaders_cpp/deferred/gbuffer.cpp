// The registry row of GBufferPass (deferred/gbuffer.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/deferred/gbuffer.h"

#include "scenes/program_registry.h"

namespace shaders::deferred {

scenes::ProgramEntry gbufferProgram() { return scenes::programEntry<GBufferPass>(); }

}  // namespace shaders::deferred
