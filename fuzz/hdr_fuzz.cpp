// Fuzz target: the Radiance HDR loader (header and every run-length scanline checked before
// stb_image, which loops forever on some truncated data). Decodes or refuses; never hangs.
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
    const scenes::ImageRgbFloat image = scenes::decodeHdrRgb("fuzz.hdr", bytes);
    if (image.pixels.size() != size_t(image.width) * size_t(image.height) * 3) __builtin_trap();
  } catch (const scenes::SceneError&) {
  }
  return 0;
}
