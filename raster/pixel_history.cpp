// Reading one pixel of a framebuffer for pixel history (pixel_history.h).
#include "raster/pixel_history.h"

#include "raster/texture/format.h"

namespace raster {

PixelValue readPixel(const Framebuffer& framebuffer, int x, int y) {
  PixelValue value;
  const size_t texel = size_t(y) * size_t(framebuffer.width) + size_t(x);
  for (const Texture* color : framebuffer.colors) {
    std::array<float, 4> rgba{};
    for (int c = 0; c < 4; ++c) {
      const size_t i = texel * 4 + size_t(c);
      if (color->format == TexelFormat::RGBA8) rgba[size_t(c)] = float(color->rgba8[i]) * float(1.0 / 255.0);
      else if (color->format == TexelFormat::RGBA32F) rgba[size_t(c)] = color->f32[i];
      else rgba[size_t(c)] = format::floatFromHalf(color->half[i]);
    }
    value.colors.push_back(rgba);
  }
  if (framebuffer.depth) {
    value.hasDepth = true;
    value.depthCode = framebuffer.depth->depth[texel];
  }
  return value;
}

}  // namespace raster
