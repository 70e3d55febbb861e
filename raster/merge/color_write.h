// The output merge: a shaded lane group's colour outputs converted to each attachment's
// format, blended, and written to the lanes' texels. The shader never sees the framebuffer;
// this is the only code that writes colour.
//
// As llvmpipe does it (lp_bld_conv.c, lp_bld_blend.c):
//   RGBA8     each channel to unorm8 (format.h: clamp, * 255, round to nearest even);
//             ONE/ONE blending is a saturating 8-bit add of the converted values;
//   RGBA16F   the exact float32 value (with ONE/ONE: the stored half as float32 plus the
//             source, in float32), converted once, toward zero;
//   RGBA32F   stored as is (plus the stored value when blending), for tests.
//
// This file is the reference, lane by lane. color_write_avx2.h converts a whole Float8
// group at once and writes it a memory row at a time; the bits are the same.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "raster/contract.h"
#include "raster/texture/format.h"

namespace raster::merge {

// RGBA8 texels per lane, r in the low byte: r g b a in memory on little-endian x86.
template <class F>
void packRgba8(const glsl::vec4<F>& color, uint32_t* texels) {
  alignas(64) float c[4][F::kCount];
  glsl::storePlanes(color, c);
  for (int i = 0; i < F::kCount; ++i) {
    texels[i] = 0;
    for (int ch = 0; ch < 4; ++ch) texels[i] |= uint32_t(format::unorm8FromFloat(c[ch][i])) << (8 * ch);
  }
}

// Writes the covered lanes' colours to RGBA16F texels (4 halves each, at texel[i] * 4).
template <class F>
void writeHalfTexels(const glsl::vec4<F>& color, uint16_t* texels, const size_t* texel, unsigned laneMask, bool blend) {
  alignas(64) float c[4][F::kCount];
  glsl::storePlanes(color, c);
  const HalfMethod rounding = methods::active().half;   // the `half` step (methods.h)
  for (int i = 0; i < F::kCount; ++i) {
    if (!(laneMask >> i & 1u)) continue;
    uint16_t* dst = texels + texel[i] * 4;
    for (int ch = 0; ch < 4; ++ch) {
      const float value = blend ? format::floatFromHalf(dst[ch]) + c[ch][i] : c[ch][i];
      dst[ch] = format::halfFromFloat(value, rounding);
    }
  }
}

// Writes the lanes `laneMask` of one colour output to an attachment, lane i at texel[i].
template <class F>
void writeColorOutput(Texture& target, const glsl::vec4<F>& color, const size_t* texel, unsigned laneMask,
                      bool blendAdditive) {
  if (target.format == TexelFormat::RGBA8) {
    uint32_t packed[F::kCount];
    packRgba8(color, packed);
    for (int i = 0; i < F::kCount; ++i) {
      if (!(laneMask >> i & 1u)) continue;
      uint8_t* dst = &target.rgba8[texel[i] * 4];
      if (!blendAdditive) {
        std::memcpy(dst, &packed[i], 4);   // bytes r g b a, as packed
        continue;
      }
      for (int c = 0; c < 4; ++c) dst[c] = uint8_t(std::min(255, int(dst[c]) + int(uint8_t(packed[i] >> (8 * c)))));
    }
  } else if (target.format == TexelFormat::RGBA16F) {
    writeHalfTexels(color, target.half.data(), texel, laneMask, blendAdditive);
  } else {   // RGBA32F
    alignas(64) float rgba[4][F::kCount];
    glsl::storePlanes(color, rgba);
    for (int i = 0; i < F::kCount; ++i) {
      if (!(laneMask >> i & 1u)) continue;
      float* dst = &target.f32[texel[i] * 4];
      for (int c = 0; c < 4; ++c) dst[c] = blendAdditive ? dst[c] + rgba[c][i] : rgba[c][i];
    }
  }
}

}  // namespace raster::merge

// The Float8 forms, declared before the functions below that call them: a qualified or
// template call binds to the overloads visible where it is written.
#include "raster/merge/color_write_avx2.h"

namespace raster::merge {

// Writes every colour output of a shaded group that both its shader and the framebuffer have.
template <class F>
void writeGroup(const Framebuffer& framebuffer, const FragmentGroup<F>& group, const FragmentOutput<F>& out) {
  for (int k = 0; k < group.outputs; ++k)
    writeColorOutput(*framebuffer.colors[k], out.color[k], group.texel, group.laneMask, group.draw->state.blendAdditive);
}

// Writes one colour output of a coarse-shaded group (tile/coarse_tile.h): lane i's colour to
// the pixels of its coarse pixel, pixel s of them at texel[i] + offset[s], where bit i of
// laneMask[s] is set (covered, and passed the depth test). Each lane's colour is converted
// once and stored to each of its pixels: the bytes of writeColorOutput, lane by lane (the
// row-at-a-time Float8 form assumes a group's texels lie side by side, which a coarse
// group's do not).
template <class F>
void writeCoarseColorOutput(Texture& target, const glsl::vec4<F>& color, const size_t* texel, const size_t* offset,
                            const unsigned* laneMask, int pixels, bool blendAdditive) {
  if (target.format == TexelFormat::RGBA8 && !blendAdditive) {
    uint32_t packed[F::kCount];
    packRgba8(color, packed);
    for (int s = 0; s < pixels; ++s)
      for (int i = 0; i < F::kCount; ++i)
        if (laneMask[s] >> i & 1u) std::memcpy(&target.rgba8[(texel[i] + offset[s]) * 4], &packed[i], 4);
    return;
  }
  for (int s = 0; s < pixels; ++s) {
    if (!laneMask[s]) continue;
    size_t at[F::kCount];
    for (int i = 0; i < F::kCount; ++i) at[i] = texel[i] + offset[s];
    writeColorOutput<F>(target, color, at, laneMask[s], blendAdditive);   // the lane-by-lane form
  }
}

}  // namespace raster::merge
