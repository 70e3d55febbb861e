// The registry row of CompositePass (hdr/composite.h): the pipeline's code for this port,
// SIMD and scalar lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/hdr/composite.h"

#include "scenes/program_registry.h"

namespace shaders::hdr {

scenes::ProgramEntry compositeProgram() { return scenes::programEntry<CompositePass>(); }

}  // namespace shaders::hdr
