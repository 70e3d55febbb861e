// The registry row of ShadowPass (shadow/shadow.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/shadow/shadow.h"

#include "scenes/program_registry.h"

namespace shaders::shadow {

scenes::ProgramEntry shadowProgram() { return scenes::programEntry<ShadowPass>(); }

}  // namespace shaders::shadow
