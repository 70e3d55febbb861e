// Colour texture sampling (sampler2D, no mipmaps), as llvmpipe does it.
//
// RGBA8 textures take llvmpipe's AoS path (lp_bld_sample_aos.c), 8-bit fixed point:
//   linear:  s_fix = iround(s * float(W * 256)) - 128; x0 = s_fix >> 8; w = s_fix & 255;
//            lerp8(w, a, b) = a + floor((w * (b - a) + 128) / 256)   (pmulhrsw), rows then
//            columns, each lerp rounded to 8 bits; result u8 * float(1/255).
//   nearest: x = ifloor(s * float(W)), then wrap.
//   wrap (integer): CLAMP_TO_EDGE clamps x0 and takes x1 = x0 + 1 only when 0 <= x0 < W-1;
//            REPEAT on a power-of-two size masks with W-1 (x1 wraps to 0); other sizes
//            start from fract(s) (lp_build_coord_repeat_npot_linear_int).
// Float textures (RGBA16F, RGB16F stored as RGBA with alpha 1) take the SoA path
// (lp_bld_sample_soa.c), in float32; so do RGBA8 textures under the `filter=float` method
// (methods.h), their texels read as unorm8 * float(1/255) first:
//   linear:  CLAMP_TO_EDGE c = max(min(s * W, W) - 0.5, 0); REPEAT (POT) c = s * W - 0.5;
//            x0 = floor(c), w = c - floor(c); texels lerped with fma(w, b - a, a), rows
//            then columns.
//   nearest: CLAMP_TO_EDGE x = clamp(trunc(s * W), 0, W-1); REPEAT (POT) floor & (W-1).
#include <algorithm>
#include <cmath>

#include "raster/texture/footprint_strips.h"
#include "raster/texture/format.h"
#include "raster/texture/lookup_filter.h"
#include "raster/texture/sample_trace.h"
#include "raster/texture/sampler.h"

namespace raster::sampling {
namespace {

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

// float -> int as cvttps2dq / cvtps2dq do: out-of-range and NaN give INT32_MIN.
int32_t truncToInt(float x) { return (x > -2147483648.0f && x < 2147483648.0f) ? int32_t(x) : INT32_MIN; }
int32_t floorToInt(float x) { return truncToInt(std::floor(x)); }
float fract(float x) { return x - std::floor(x); }
// 32-bit two's-complement subtraction, as the vector code does (cvtps2dq gives INT32_MIN on NaN).
int32_t wrappingSub(int32_t a, int32_t b) { return int32_t(uint32_t(a) - uint32_t(b)); }
// lp_build_fract_safe: fract kept below 1 (x - floor(x) rounds to 1 for tiny negatives); NaN -> the bound.
float fractSafe(float x) {
  const float f = fract(x);
  return f < 0.99999994f ? f : 0.99999994f;
}

// ---- RGBA8: 8-bit fixed point (AoS) --------------------------------------------------------

struct FixedTaps {
  int x0, x1;
  int weight;   // 0..255, meaning weight / 256 of x1
};

FixedTaps wrapLinearFixed(float coord, int size, Wrap wrap) {
  FixedTaps taps;
  int32_t fixed;
  if (wrap == Wrap::Repeat && !isPowerOfTwo(size)) {
    const float scaled = fract(coord) * float(size) * 256.0f;
    fixed = wrappingSub(format::roundToNearestEven(scaled), 128);
    taps.weight = fixed & 255;
    taps.x0 = fixed >> 8;
    if (taps.x0 < 0) taps.x0 = size - 1;
    taps.x0 = std::min(taps.x0, size - 1);
    taps.x1 = taps.x0 != size - 1 ? taps.x0 + 1 : 0;
    return taps;
  }
  fixed = wrappingSub(format::roundToNearestEven(coord * float(size << 8)), 128);
  taps.weight = fixed & 255;
  const int x0 = fixed >> 8;
  if (wrap == Wrap::Repeat) {
    taps.x0 = x0 & (size - 1);
    taps.x1 = taps.x0 != size - 1 ? taps.x0 + 1 : 0;
  } else {
    const bool low = x0 >= 0, high = x0 < size - 1;
    taps.x0 = high ? (low ? x0 : 0) : size - 1;
    taps.x1 = taps.x0 + (low && high ? 1 : 0);
  }
  return taps;
}

int wrapNearestFixed(float coord, int size, Wrap wrap) {
  if (wrap == Wrap::Repeat) {
    if (isPowerOfTwo(size)) return floorToInt(coord * float(size)) & (size - 1);
    return std::clamp(truncToInt(fractSafe(coord) * float(size)), 0, size - 1);
  }
  return std::clamp(floorToInt(coord * float(size)), 0, size - 1);
}

// lerp8 with pmulhrsw: a + floor((w * (b - a) * 128 + 16384) / 32768).
int lerp8(int weight, int a, int b) { return (a + ((weight * (b - a) * 128 + 16384) >> 15)) & 0xFF; }

void sampleRgba8(const Texture& t, float s, float tc, float out[4]) {
  auto texel = [&](int x, int y) { return rgba8Texel(t, x, y); };
  constexpr float kUnorm8 = float(1.0 / 255.0);
  if (lookupFilter(t) == Filter::Nearest) {
    const uint8_t* p = texel(wrapNearestFixed(s, t.width, t.sampler.wrapS), wrapNearestFixed(tc, t.height, t.sampler.wrapT));
    for (int c = 0; c < 4; ++c) out[c] = float(p[c]) * kUnorm8;
    return;
  }
  const FixedTaps x = wrapLinearFixed(s, t.width, t.sampler.wrapS);
  const FixedTaps y = wrapLinearFixed(tc, t.height, t.sampler.wrapT);
  const uint8_t *p00 = texel(x.x0, y.x0), *p01 = texel(x.x1, y.x0), *p10 = texel(x.x0, y.x1), *p11 = texel(x.x1, y.x1);
  for (int c = 0; c < 4; ++c) {
    const int row0 = lerp8(x.weight, p00[c], p01[c]);
    const int row1 = lerp8(x.weight, p10[c], p11[c]);
    out[c] = float(lerp8(y.weight, row0, row1)) * kUnorm8;
  }
}

// ---- float textures (SoA) ---------------------------------------------------------------------

// A depth texture read through a sampler2D (no compare mode): llvmpipe's SoA fetch unpacks
// the unorm code as lp_build_unsigned_norm_to_float does for a width up to 24 bits, a
// conversion to float times float(1 / (2^bits - 1)), the same as the compare path reads it
// (depthCodeScale); the texel is (d, 0, 0, 1), a core profile's depth swizzle.
float depthTexelChannel(const Texture& t, int x, int y, int c) {
  if (c != 0) return c == 3 ? 1.0f : 0.0f;
  return float(t.depth[size_t(y) * size_t(t.width) + size_t(x)]) * depthCodeScale(t);
}

struct FloatTaps {
  int x0, x1;
  float weight;
};

FloatTaps wrapLinearFloat(float coord, int size, Wrap wrap) {
  const float sizeF = float(size);
  FloatTaps taps;
  float c;
  if (wrap == Wrap::Repeat && isPowerOfTwo(size)) {
    c = coord * sizeF - 0.5f;
    const float floorC = std::floor(c);
    taps.x0 = truncToInt(floorC) & (size - 1);
    taps.x1 = (truncToInt(floorC) + 1) & (size - 1);
    taps.weight = c - floorC;
    return taps;
  }
  if (wrap == Wrap::Repeat) {   // lp_build_coord_repeat_npot_linear
    c = fract(coord) * sizeF - 0.5f;
    const float floorC = std::floor(c);
    // A NaN coordinate gives texel 0 rather than an out-of-range index.
    taps.x0 = c < 0.0f ? size - 1 : std::clamp(truncToInt(floorC), 0, size - 1);
    taps.weight = c - floorC;
    taps.x1 = taps.x0 != size - 1 ? taps.x0 + 1 : 0;
    return taps;
  }
  c = coord * sizeF;
  c = (c < sizeF) ? c : sizeF;          // min, NaN -> size
  c = c - 0.5f;
  c = (c > 0.0f) ? c : 0.0f;
  const float floorC = std::floor(c);
  taps.x0 = truncToInt(floorC);
  taps.weight = c - floorC;
  taps.x1 = std::min(taps.x0 + 1, size - 1);
  return taps;
}

int wrapNearestFloat(float coord, int size, Wrap wrap) {
  if (wrap == Wrap::Repeat) {
    if (isPowerOfTwo(size)) return floorToInt(coord * float(size)) & (size - 1);
    return std::clamp(truncToInt(fractSafe(coord) * float(size)), 0, size - 1);
  }
  return std::clamp(truncToInt(coord * float(size)), 0, size - 1);
}

void sampleFloat(const Texture& t, float s, float tc, float out[4]) {
  auto texel = [&](int x, int y, int c) {
    if (t.format == TexelFormat::RGBA8) return float(rgba8Texel(t, x, y)[c]) * float(1.0 / 255.0);
    if (t.isDepth()) return depthTexelChannel(t, x, y, c);
    const size_t i = (size_t(y) * size_t(t.width) + size_t(x)) * 4 + size_t(c);
    return t.format == TexelFormat::RGBA32F ? t.f32[i] : format::floatFromHalf(t.half[i]);
  };
  if (lookupFilter(t) == Filter::Nearest) {
    const int x = wrapNearestFloat(s, t.width, t.sampler.wrapS), y = wrapNearestFloat(tc, t.height, t.sampler.wrapT);
    for (int c = 0; c < 4; ++c) out[c] = texel(x, y, c);
    return;
  }
  const FloatTaps x = wrapLinearFloat(s, t.width, t.sampler.wrapS);
  const FloatTaps y = wrapLinearFloat(tc, t.height, t.sampler.wrapT);
  for (int c = 0; c < 4; ++c) {
    const float row0 = std::fma(x.weight, texel(x.x1, y.x0, c) - texel(x.x0, y.x0, c), texel(x.x0, y.x0, c));
    const float row1 = std::fma(x.weight, texel(x.x1, y.x1, c) - texel(x.x0, y.x1, c), texel(x.x0, y.x1, c));
    out[c] = std::fma(y.weight, row1 - row0, row0);
  }
}

// The texels a lookup reads and each one's share, for pixel history (sample_trace.h).
void setFootprint(const Texture& t, SampleRecord& r, int x0, int x1, int y0, int y1, float ws, float wt) {
  r.weightS = ws;
  r.weightT = wt;
  r.texelCount = 4;
  const int xs[4] = {x0, x1, x0, x1}, ys[4] = {y0, y0, y1, y1};
  const float weights[4] = {(1 - ws) * (1 - wt), ws * (1 - wt), (1 - ws) * wt, ws * wt};
  for (int k = 0; k < 4; ++k) {
    r.texels[k].x = xs[k];
    r.texels[k].y = ys[k];
    r.texels[k].weight = weights[k];
    colorTexelValue(t, xs[k], ys[k], r.texels[k].value);
  }
}

}  // namespace

int nearestIndex(float coord, int size, Wrap wrap) { return wrapNearestFloat(coord, size, wrap); }

void colorTexelValue(const Texture& t, int x, int y, float out[4]) {
  const size_t i = (size_t(y) * size_t(t.width) + size_t(x)) * 4;
  for (int c = 0; c < 4; ++c) {
    if (t.isDepth()) out[c] = depthTexelChannel(t, x, y, c);
    else if (t.format == TexelFormat::RGBA8) out[c] = float(rgba8Texel(t, x, y)[c]) * float(1.0 / 255.0);
    else if (t.format == TexelFormat::RGBA32F) out[c] = t.f32[i + size_t(c)];
    else out[c] = format::floatFromHalf(t.half[i + size_t(c)]);
  }
}

void explainColor(const Texture& texture, SampleRecord& record) {
  const bool fixedPoint = texture.format == TexelFormat::RGBA8 && methods::fixedPointFilter(methods::active().filter);
  const float s = record.s, t = record.t;
  if (lookupFilter(texture) == Filter::Nearest) {
    record.filter = "nearest";
    record.texelCount = 1;
    FootprintTexel& texel = record.texels[0];
    texel.x = fixedPoint ? wrapNearestFixed(s, texture.width, texture.sampler.wrapS)
                         : wrapNearestFloat(s, texture.width, texture.sampler.wrapS);
    texel.y = fixedPoint ? wrapNearestFixed(t, texture.height, texture.sampler.wrapT)
                         : wrapNearestFloat(t, texture.height, texture.sampler.wrapT);
    texel.weight = 1.0f;
    colorTexelValue(texture, texel.x, texel.y, texel.value);
  } else if (fixedPoint) {
    record.filter = "unorm8 fixed point (weights in 1/256, each lerp rounded to 8 bits)";
    const FixedTaps x = wrapLinearFixed(s, texture.width, texture.sampler.wrapS);
    const FixedTaps y = wrapLinearFixed(t, texture.height, texture.sampler.wrapT);
    setFootprint(texture, record, x.x0, x.x1, y.x0, y.x1, float(x.weight) / 256.0f, float(y.weight) / 256.0f);
  } else {
    record.filter = "float";
    const FloatTaps x = wrapLinearFloat(s, texture.width, texture.sampler.wrapS);
    const FloatTaps y = wrapLinearFloat(t, texture.height, texture.sampler.wrapT);
    setFootprint(texture, record, x.x0, x.x1, y.x0, y.x1, x.weight, y.weight);
  }
  sampleColor(texture, s, t, record.explained);
}

void sampleColor(const Texture& texture, float s, float t, float out[4]) {
  if (texture.format == TexelFormat::RGBA8 && methods::fixedPointFilter(methods::active().filter)) sampleRgba8(texture, s, t, out);
  else sampleFloat(texture, s, t, out);
}

}  // namespace raster::sampling
