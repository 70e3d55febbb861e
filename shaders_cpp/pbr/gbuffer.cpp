// The registry row of GBufferPass (pbr/gbuffer.h): the pipeline's code for this port, SIMD and scalar
// lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/pbr/gbuffer.h"

#include "scenes/program_registry.h"

namespace shaders::pbr {

scenes::ProgramEntry gbufferProgram() { return scenes::programEntry<GBufferPass>(); }

}  // namespace shaders::pbr
