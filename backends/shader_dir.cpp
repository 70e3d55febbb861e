// Where the GLSL sources (and their C++ ports) live: shaders_cpp/ under the source root.
//
// $RASTER_SOURCE_DIR (when set and not empty) overrides the source root at run time (tests point it at a temporary
// folder); otherwise the RASTER_SOURCE_DIR compile definition set by CMakeLists.txt is used.
#include <cstdlib>
#include <string>

#include "backends/backend.h"

#ifndef RASTER_SOURCE_DIR
#define RASTER_SOURCE_DIR "."
#endif

namespace scenes {

std::string shaderSourceDir() {
  const char* root = std::getenv("RASTER_SOURCE_DIR");
  return std::string(root != nullptr && *root != '\0' ? root : RASTER_SOURCE_DIR) + "/shaders_cpp";
}

ProgramFiles programFiles(const std::string& program) {
  // The '+' is looked for in the program's name only: a source folder may hold one.
  const std::string dir = shaderSourceDir() + "/";
  const size_t plus = program.find('+');
  if (plus == std::string::npos) return {dir + program + ".vert", dir + program + ".frag"};
  const size_t slash = program.rfind('/', plus);
  const std::string folder = slash == std::string::npos ? std::string() : program.substr(0, slash + 1);
  return {dir + program.substr(0, plus) + ".vert", dir + folder + program.substr(plus + 1) + ".frag"};
}

}  // namespace scenes
