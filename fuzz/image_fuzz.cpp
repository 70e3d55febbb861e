// Fuzz target: the JPEG / PNG loader (structure walk, header size checks, memory reservation
// from the header, stb_image). Any input must decode or be refused with a SceneError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_common.h"
#include "io/assets.h"
#include "scenes/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzzSetUpOnce();
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const scenes::ImageRgba8 image = scenes::decodeImageRgba8("fuzz.img", bytes);
    if (image.pixels.size() != size_t(image.width) * size_t(image.height) * 4) __builtin_trap();
  } catch (const scenes::SceneError&) {
  }
  return 0;
}
