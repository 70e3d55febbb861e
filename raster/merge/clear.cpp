// Tile-rectangle clears (see clear.h).
#include "raster/merge/clear.h"

#include <algorithm>
#include <cstring>

#include "raster/texture/format.h"

namespace raster::merge {
namespace {

// Every row of the rectangle stored from 32 bytes of repeated texels: a texel is 4, 8 or
// 16 bytes, so the pattern lines up at any texel. (Copying a first row into the others cost
// a library call per 256-byte row and read as much as it wrote.)
template <class T>
void fillRows(T* data, size_t width, const TileBounds& rect, const T* texel, size_t perTexel) {
  const size_t texelBytes = perTexel * sizeof(T);
  unsigned char pattern[32];
  for (size_t i = 0; i < sizeof pattern; i += texelBytes) std::memcpy(pattern + i, texel, texelBytes);
  const size_t rowBytes = size_t(rect.x1 + 1 - rect.x0) * texelBytes;
  for (int y = rect.y0; y <= rect.y1; ++y) {
    unsigned char* row = reinterpret_cast<unsigned char*>(data + (size_t(y) * width + size_t(rect.x0)) * perTexel);
    size_t i = 0;
    for (; i + sizeof pattern <= rowBytes; i += sizeof pattern) std::memcpy(row + i, pattern, sizeof pattern);
    std::memcpy(row + i, pattern, rowBytes - i);
  }
}

}  // namespace

void clearRect(const Framebuffer& framebuffer, const ClearValues& values, const TileBounds& rect, bool colorToo) {
  if (rect.x1 < rect.x0 || rect.y1 < rect.y0) return;
  const size_t width = size_t(framebuffer.width);
  if (values.color && colorToo) {
    for (Texture* target : framebuffer.colors) {
      if (target->format == TexelFormat::RGBA8) {
        uint8_t texel[4];
        for (int c = 0; c < 4; ++c) texel[c] = format::unorm8FromFloat(std::clamp(values.colorValue[c], 0.0f, 1.0f));
        fillRows(target->rgba8.data(), width, rect, texel, 4);
      } else if (target->format == TexelFormat::RGBA32F) {
        fillRows(target->f32.data(), width, rect, values.colorValue, 4);
      } else if (target->format == TexelFormat::RGBA16F) {
        uint16_t texel[4];
        for (int c = 0; c < 4; ++c) texel[c] = format::halfFromFloat(values.colorValue[c], methods::active().half);
        fillRows(target->half.data(), width, rect, texel, 4);
      }
    }
  }
  if (values.depth && framebuffer.depth) {
    const uint32_t code = format::depthClearCode(values.depthValue, framebuffer.depth->depthBits());
    fillRows(framebuffer.depth->depth.data(), width, rect, &code, 1);
  }
}

}  // namespace raster::merge
