// The registry row of MainPass (shadow/main.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/shadow/main.h"

#include "scenes/program_registry.h"

namespace shaders::shadow {

scenes::ProgramEntry mainProgram() { return scenes::programEntry<MainPass>(); }

}  // namespace shaders::shadow
