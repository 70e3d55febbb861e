// Fuzz target: the OBJ loader (io/obj_validate.h, then tinyobjloader and the mesh
// build). Any input must load or be refused with a SceneError; nothing else may happen.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_common.h"
#include "io/assets.h"
#include "scenes/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzzSetUpOnce();
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    scenes::parseCatMesh("fuzz.obj", text);
  } catch (const scenes::SceneError&) {
  }
  return 0;
}
