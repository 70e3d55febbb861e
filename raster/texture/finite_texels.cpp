#include "raster/texture/finite_texels.h"

#include <bit>
#include <cstdint>

namespace raster {

bool holdsNonFiniteTexels(const Texture& texture) {
  // Or-reductions of "exponent bits all set", branch-free loops the compiler vectorizes.
  switch (texture.format) {
    case TexelFormat::RGBA16F:
    case TexelFormat::RGB16F: {
      uint16_t found = 0;
      for (const uint16_t half : texture.half) found |= uint16_t((half & 0x7C00u) == 0x7C00u);
      return found != 0;
    }
    case TexelFormat::RGBA32F: {
      uint32_t found = 0;
      for (const float value : texture.f32) found |= uint32_t((std::bit_cast<uint32_t>(value) & 0x7F800000u) == 0x7F800000u);
      return found != 0;
    }
    case TexelFormat::RGBA8:
    case TexelFormat::Depth16:
    case TexelFormat::Depth24: return false;
  }
  return false;
}

}  // namespace raster
