// The registry row of DownPass (hdr/down.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/hdr/down.h"

#include "scenes/program_registry.h"

namespace shaders::hdr {

scenes::ProgramEntry downProgram() { return scenes::programEntry<DownPass>(); }

}  // namespace shaders::hdr
