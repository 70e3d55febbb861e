// The registry row of BlurPass (pbr/blur.h): the pipeline's code for this port, SIMD and scalar
// lanes, is instantiated here, so each port compiles on its own and once.
#include "shaders_cpp/pbr/blur.h"

#include "scenes/program_registry.h"

namespace shaders::pbr {

scenes::ProgramEntry blurProgram() { return scenes::programEntry<BlurPass>(); }

}  // namespace shaders::pbr
