// The registry row of UpPass (hdr/up.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/hdr/up.h"

#include "scenes/program_registry.h"

namespace shaders::hdr {

scenes::ProgramEntry upProgram() { return scenes::programEntry<UpPass>(); }

}  // namespace shaders::hdr
