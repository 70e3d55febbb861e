// Texture storage: the one image type for render targets and sampled textures alike.
//
// A Texture holds texels in memory rows: row 0 is GL's t = 0 (the first row glTexImage2D
// uploads, the bottom of a rendered FBO image). The default framebuffer is the exception,
// stored with row 0 at the top, as llvmpipe stores window-system buffers (see Framebuffer).
//
// This is the vocabulary of formats, filters, wraps and compare modes that scenes, both
// backends and the pipeline share.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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
  std::vector<uint8_t, HugePageAllocator<uint8_t>> rgba8;       // RGBA8
  std::vector<uint16_t, HugePageAllocator<uint16_t>> half;       // RGBA16F, 4 per texel
  std::vector<float> f32;           // RGBA32F, 4 per texel
  std::vector<uint32_t, HugePageAllocator<uint32_t>> depth;      // Depth16 / Depth24 codes
  std::string label;   // what the scene calls it ("shadow_map"), as glObjectLabel: pixel history names it

  Texture() = default;
  Texture(int w, int h, TexelFormat f) : width(w), height(h), format(f == TexelFormat::RGB16F ? TexelFormat::RGBA16F : f) {
    const size_t texels = size_t(w) * size_t(h);
    switch (f) {
      case TexelFormat::RGBA8: rgba8.assign(texels * 4, 0); break;
      case TexelFormat::RGBA16F:
      case TexelFormat::RGB16F: half.assign(texels * 4, 0); break;
      case TexelFormat::RGBA32F: f32.assign(texels * 4, 0.0f); break;
      case TexelFormat::Depth16:
      case TexelFormat::Depth24: depth.assign(texels, 0); break;
    }
  }
  bool isDepth() const { return format == TexelFormat::Depth16 || format == TexelFormat::Depth24; }
  int depthBits() const { return format == TexelFormat::Depth24 ? 24 : (format == TexelFormat::Depth16 ? 16 : 0); }
};

}  // namespace raster
