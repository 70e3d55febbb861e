// Texture storage: the one image type for render targets and sampled textures alike.
//
// A Texture holds texels in memory rows: row 0 is GL's t = 0 (the first row glTexImage2D
// uploads, the bottom of a rendered FBO image). The default framebuffer is the exception,
// stored with row 0 at the top, as llvmpipe stores window-system buffers (see Framebuffer).
//
// This is the vocabulary of formats, filters, wraps and compare modes that scenes, both
// backends and the pipeline share.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "raster/texture/cleared_tiles.h"
#include "raster/util/huge_pages.h"

namespace raster {

// The texture formats of the scenes, as GL internal formats:
//   RGBA8     4 bytes a texel (GL_RGBA8)
//   RGBA16F   4 half-floats (GL_RGBA16F)
//   RGB16F    a sampled texture uploaded from 3 floats a texel (GL_RGB16F: the HDR
//             environment); a Texture stores it as RGBA16F with alpha 1, as llvmpipe's RGBX
//   RGBA32F   4 floats (GL_RGBA32F), a render target for tests that need exact values
//   Depth16, Depth24   uint32 codes holding a 16- or 24-bit unsigned-normalized depth
enum class TexelFormat { RGBA8, RGBA16F, RGB16F, RGBA32F, Depth16, Depth24 };

enum class Filter { Nearest, Linear };               // GL_NEAREST, GL_LINEAR (min and mag)
enum class Wrap { Repeat, ClampToEdge };             // GL_REPEAT, GL_CLAMP_TO_EDGE

// GL sampler state of a texture object (the scenes use no separate sampler objects).
struct SamplerState {
  Filter filter = Filter::Linear;   // min and mag alike; no mipmaps
  Wrap wrapS = Wrap::ClampToEdge;
  Wrap wrapT = Wrap::ClampToEdge;
  bool compareLequal = false;       // GL_COMPARE_REF_TO_TEXTURE, GL_LEQUAL
};

// Bytes a Texture of this size and format holds (RGB16F is stored as RGBA16F; depth codes
// take 32 bits each).
inline uint64_t textureStorageBytes(int width, int height, TexelFormat format) {
  const uint64_t texels = uint64_t(width > 0 ? width : 0) * uint64_t(height > 0 ? height : 0);
  switch (format) {
    case TexelFormat::RGBA8: return texels * 4;
    case TexelFormat::RGBA16F:
    case TexelFormat::RGB16F: return texels * 8;
    case TexelFormat::RGBA32F: return texels * 16;
    case TexelFormat::Depth16:
    case TexelFormat::Depth24: return texels * 4;
  }
  return texels * 16;
}

struct Texture {
  int width = 0;
  int height = 0;
  TexelFormat format = TexelFormat::RGBA8;
  SamplerState sampler;
  std::vector<uint8_t, HugePageAllocator<uint8_t>> rgba8;       // RGBA8 rows (empty where strips8 holds the texels)
  std::vector<uint16_t, HugePageAllocator<uint16_t>> half;       // RGBA16F, 4 per texel
  std::vector<float> f32;           // RGBA32F, 4 per texel
  std::vector<uint32_t, HugePageAllocator<uint32_t>> depth;      // Depth16 / Depth24 codes
  // A second layout of a grey RGBA8 texture, for the samplers: see makeGreyCopy().
  std::vector<uint8_t, HugePageAllocator<uint8_t>> grey8;
  // An RGBA8 texture sampled bilinearly, in overlapping row strips for the 16-lane sampler:
  // an upload keeps these instead of rows (footprint_strips.h, releaseRows).
  std::vector<uint8_t, HugePageAllocator<uint8_t>> strips8;
  ClearedTiles clearedTiles;   // the tiles that hold only the last clear (cleared_tiles.h)
  std::string label;   // what the scene calls it ("shadow_map"), as glObjectLabel: pixel history names it

  Texture() = default;
  Texture(int w, int h, TexelFormat f) : width(w), height(h), format(f == TexelFormat::RGB16F ? TexelFormat::RGBA16F : f) {
    const size_t texels = size_t(w) * size_t(h);
    switch (f) {
      case TexelFormat::RGBA8: zeroedTexels(rgba8, texels * 4); break;
      case TexelFormat::RGBA16F:
      case TexelFormat::RGB16F: zeroedTexels(half, texels * 4); break;
      case TexelFormat::RGBA32F: f32.assign(texels * 4, 0.0f); break;
      case TexelFormat::Depth16:
      case TexelFormat::Depth24: zeroedTexels(depth, texels); break;
    }
  }
  // `count` zero elements, written by one memset (HugePageAllocator says why).
  template <class T>
  static void zeroedTexels(std::vector<T, HugePageAllocator<T>>& texels, size_t count) {
    texels.resize(count);
    if (count) std::memset(texels.data(), 0, count * sizeof(T));
  }
  bool hasGreyCopy() const { return !grey8.empty(); }
  bool hasStripCopy() const { return !strips8.empty(); }
  bool isDepth() const { return format == TexelFormat::Depth16 || format == TexelFormat::Depth24; }
  int depthBits() const { return format == TexelFormat::Depth24 ? 24 : (format == TexelFormat::Depth16 ? 16 : 0); }
};

// Zero bytes after a grey copy's last texel, so that a 4-byte load at any texel stays
// inside the array.
inline constexpr size_t kGreyCopyPadding = 3;

// An RGBA8 texture whose every texel is grey and opaque (r = g = b, a = 255: a
// one-channel JPEG, such as an ambient-occlusion or roughness map, uploaded as RGBA) also
// keeps its r bytes in grey8, one byte a texel. A bilinear footprint there spans two bytes
// a row instead of eight, so it touches a quarter of the cache lines, and one 32-bit gather
// element fetches a row's two texels. rgba8 stays whole and is what every writer, every
// other reader and the reference sampler use; grey8 is a read-only copy, made at upload
// when the texels allow it (returns whether they did) and dropped when the texture becomes
// a render target (dropGreyCopy, from the backend's createFramebuffer), so it never goes
// stale. The values sampled from it are the same bits: the vector samplers
// (sample_rgba8_avx2.h, sample_rgba8_avx512.h) filter the one channel as they would each
// of r, g and b, and alpha is 255.
inline bool makeGreyCopy(Texture& t) {
  t.grey8 = {};
  if (t.format != TexelFormat::RGBA8 || t.rgba8.empty()) return false;
  const size_t texels = t.rgba8.size() / 4;
  for (size_t i = 0; i < texels; ++i) {
    const uint8_t* p = &t.rgba8[i * 4];
    if (p[0] != p[1] || p[0] != p[2] || p[3] != 255) return false;
  }
  t.grey8.resize(texels + kGreyCopyPadding, 0);
  for (size_t i = 0; i < texels; ++i) t.grey8[i] = t.rgba8[i * 4];
  return true;
}

inline void dropGreyCopy(Texture& t) { t.grey8 = {}; }

}  // namespace raster
