// The registry row of SsaoPass (pbr/ssao.h): the pipeline's code for this port, SIMD and scalar
// lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/pbr/ssao.h"

#include "scenes/program_registry.h"

namespace shaders::pbr {

scenes::ProgramEntry ssaoProgram() { return scenes::programEntry<SsaoPass>(); }

}  // namespace shaders::pbr
