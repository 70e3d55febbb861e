// A shader program as the registry lists it: its name and uniform names, and how to make a
// BoundProgram of its C++ port (scenes/program_registry.h: programEntry<Port>() fills one).
// Apart from program_registry.h so that the registry's table needs none of the pipeline.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace scenes {

class BoundProgram;   // scenes/program_registry.h

struct ProgramEntry {
  std::string name;                    // shaders_cpp/ path: "shadow/main", "hdr/post+bright"
  std::vector<std::string> uniforms;   // the port's uniform names, as its GLSL spells them
  std::function<std::unique_ptr<BoundProgram>()> make;
};

}  // namespace scenes
