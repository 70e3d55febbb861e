// Tile-rectangle clears (see clear.h).
#include "raster/merge/clear.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "raster/limits.h"
#include "raster/merge/clear_avx2.h"
#include "raster/simd/prefetch.h"
#include "raster/texture/format.h"

namespace raster::merge {
namespace {

// Every row of the rectangle stored from 32 bytes of repeated texels: a texel is 4, 8 or
// 16 bytes, so the pattern lines up at any texel. (Copying a first row into the others cost
// a library call per 256-byte row and read as much as it wrote.)
template <class T>
void fillRows(T* data, size_t width, const TileBounds& rect, const T* texel, size_t perTexel, bool streaming) {
  const size_t texelBytes = perTexel * sizeof(T);
  unsigned char pattern[32];
  for (size_t i = 0; i < sizeof pattern; i += texelBytes) std::memcpy(pattern + i, texel, texelBytes);
  const size_t rowBytes = size_t(rect.x1 + 1 - rect.x0) * texelBytes;
  for (int y = rect.y0; y <= rect.y1; ++y) {
    const int ahead = y + simd::kPrefetchRowsAhead;
    if (!streaming && ahead <= rect.y1)
      simd::prefetchLines(data + (size_t(ahead) * width + size_t(rect.x0)) * perTexel, rowBytes);
    storeRow(reinterpret_cast<unsigned char*>(data + (size_t(y) * width + size_t(rect.x0)) * perTexel), pattern, rowBytes,
             streaming);
  }
}

}  // namespace

void clearRect(const Framebuffer& framebuffer, const ClearValues& values, const TileBounds& rect, bool colorToo, bool untouched) {
  if (rect.x1 < rect.x0 || rect.y1 < rect.y0) return;
  const size_t width = size_t(framebuffer.width);
  if (values.color && colorToo) {
    for (Texture* target : framebuffer.colors) {
      if (target->format == TexelFormat::RGBA8) {
        uint8_t texel[4];
        for (int c = 0; c < 4; ++c) texel[c] = format::unorm8FromFloat(std::clamp(values.colorValue[c], 0.0f, 1.0f));
        fillRows(target->rgba8.data(), width, rect, texel, 4, untouched);
      } else if (target->format == TexelFormat::RGBA32F) {
        fillRows(target->f32.data(), width, rect, values.colorValue, 4, untouched);
      } else if (target->format == TexelFormat::RGBA16F) {
        uint16_t texel[4];
        for (int c = 0; c < 4; ++c) texel[c] = format::halfFromFloat(values.colorValue[c], methods::active().half);
        fillRows(target->half.data(), width, rect, texel, 4, untouched);
      }
    }
  }
  if (values.depth && framebuffer.depth) {
    const uint32_t code = format::depthClearCode(values.depthValue, framebuffer.depth->depthBits());
    fillRows(framebuffer.depth->depth.data(), width, rect, &code, 1, untouched);
  }
  if (untouched) endStreaming();
}

void recordClearedTiles(const Framebuffer& framebuffer, bool clearedColor, int tilesX, std::span<const uint8_t> touched) {
  const size_t count = touched.size();
  for (Texture* target : framebuffer.colors) {
    ClearedTiles& tiles = target->clearedTiles;
    if (target->format != TexelFormat::RGBA16F || target->width != framebuffer.width ||
        target->height != framebuffer.height || framebuffer.flipY) {
      tiles.forget();
      continue;
    }
    if (!clearedColor) {   // untouched tiles hold what they held; touched ones something else
      if (tiles.any())
        for (size_t tile = 0; tile < count; ++tile) tiles.cleared[tile] &= uint8_t(!touched[tile]);
      continue;
    }
    tiles.forget();
    const auto untouched = std::find(touched.begin(), touched.end(), uint8_t(0));
    if (untouched == touched.end()) continue;
    // The clear's texel as stored: the first texel of a tile nothing drew to.
    const int tile = int(untouched - touched.begin());
    const size_t texel = size_t(tile / tilesX) * size_t(limits::kTileSize) * size_t(target->width) +
                         size_t(tile % tilesX) * size_t(limits::kTileSize);
    bool plain = true;
    for (int c = 0; c < 4; ++c) {
      const float v = format::floatFromHalf(target->half[texel * 4 + size_t(c)]);
      plain &= std::isfinite(v) && !(v == 0.0f && std::signbit(v));
      tiles.value[c] = v;
    }
    if (!plain) continue;
    tiles.tilesX = tilesX;
    tiles.cleared.resize(count);
    for (size_t i = 0; i < count; ++i) tiles.cleared[i] = uint8_t(!touched[i]);
  }
}

}  // namespace raster::merge
