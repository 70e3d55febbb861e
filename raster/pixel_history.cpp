// Reading one pixel of a framebuffer for pixel history (pixel_history.h).
#include "raster/pixel_history.h"

namespace raster {

PixelValue readPixel(const Framebuffer& framebuffer, int x, int y) {
  PixelValue value;
  const size_t texel = size_t(y) * size_t(framebuffer.width) + size_t(x);
  for (const Texture* color : framebuffer.colors) {
    std::array<float, 4> rgba{};
    sampling::colorTexelValue(*color, x, y, rgba.data());
    value.colors.push_back(rgba);
  }
  if (framebuffer.depth) {
    value.hasDepth = true;
    value.depthCode = framebuffer.depth->depth[texel];
  }
  return value;
}

}  // namespace raster
