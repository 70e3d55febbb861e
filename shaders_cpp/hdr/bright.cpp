// The registry row of BrightPass (hdr/bright.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/hdr/bright.h"

#include "scenes/program_registry.h"

namespace shaders::hdr {

scenes::ProgramEntry brightProgram() { return scenes::programEntry<BrightPass>(); }

}  // namespace shaders::hdr
