// Float <-> storage conversions, exactly as llvmpipe performs them on this CPU
// (../shared/reference/llvmpipe-numerics.md sections 3 and 7; lp_bld_conv.c).
//
//   unorm8FromFloat   render-target write: min(x, 1), * 255 in float, round to nearest even
//                     (cvtps2dq), saturate; negatives and NaN give 0 (AVX path).
//   depth24FromFloat  z * 16777215.0f, round to nearest even (cvtps2dq).
//   depth16FromFloat  the "magic number" trick: z * (65535/65536)f + 128.0f, low 16 bits.
//   depth24ToFloat    texel read for sampling: code * (float)(1/16777215).
//   halfFromFloatTowardZero  RGBA16F render-target write (vcvtps2ph imm 3): truncation,
//                     so finite overflow gives 65504 (0x7BFF); Inf and NaN are kept.
//                     Measured: glTexImage2D uploads (GL_FLOAT -> RGBA16F / RGB16F) and
//                     glClear of half targets truncate the same way on Mesa 22.3.
//   halfFromFloatNearestEven IEEE round-to-nearest-even: the `half=rne` method (methods.h).
//   halfFromFloat     the rounding the active method set asks for (rtz: llvmpipe's).
//   floatFromHalf     exact.
//   depthClearCode    glClear's conversion: round(z * (2^bits - 1)) in double
//                     (measured against the GL backend: truncation differs).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "raster/methods.h"

namespace raster::format {

constexpr uint32_t kDepth24Max = (1u << 24) - 1;
constexpr uint32_t kDepth16Max = (1u << 16) - 1;

// Round half to even, as cvtps2dq does under the default MXCSR; out-of-range and NaN give
// INT32_MIN like the instruction.
inline int32_t roundToNearestEven(float x) {
  if (!(x > -2147483648.0f && x < 2147483648.0f)) return INT32_MIN;
  return int32_t(std::nearbyint(x));
}

inline uint8_t unorm8FromFloat(float x) {
  const float clamped = (x >= 1.0f) ? 1.0f : x;         // min(x, 1.0), NaN passes through
  const int32_t scaled = roundToNearestEven(clamped * 255.0f);
  return uint8_t(scaled < 0 ? 0 : (scaled > 255 ? 255 : scaled));
}

inline uint32_t depth24FromFloat(float z) {
  const int32_t code = roundToNearestEven(z * 16777215.0f);
  return uint32_t(code < 0 ? 0 : code);
}

inline uint32_t depth16FromFloat(float z) {
  const float t = z * (65535.0f / 65536.0f) + 128.0f;
  uint32_t bits;
  std::memcpy(&bits, &t, sizeof bits);
  return bits & 0xFFFFu;
}

inline float depth24ToFloat(uint32_t code) { return float(code) * float(1.0 / 16777215.0); }
inline float depth16ToFloat(uint32_t code) { return float(code) * float(1.0 / 65535.0); }

inline uint32_t floatBits(float f) { uint32_t b; std::memcpy(&b, &f, sizeof b); return b; }
inline float floatFromBits(uint32_t b) { float f; std::memcpy(&f, &b, sizeof f); return f; }

inline uint16_t halfFromFloatTowardZero(float f) {
  const uint32_t x = floatBits(f);
  const uint16_t sign = uint16_t((x >> 16) & 0x8000u);
  const uint32_t magnitude = x & 0x7FFFFFFFu;
  if (magnitude > 0x7F800000u) return uint16_t(sign | 0x7E00u | ((magnitude >> 13) & 0x3FFu));  // NaN, quiet
  if (magnitude == 0x7F800000u) return uint16_t(sign | 0x7C00u);                                // Inf
  if (magnitude >= 0x47800000u) return uint16_t(sign | 0x7BFFu);          // >= 65536: largest finite
  if (magnitude < 0x38800000u) {                                          // below 2^-14: denormal
    return uint16_t(sign | uint16_t(floatFromBits(magnitude) * 16777216.0f));  // exact scale, truncate
  }
  return uint16_t(sign | ((magnitude - 0x38000000u) >> 13));              // rebias, drop low bits
}

inline uint16_t halfFromFloatNearestEven(float f) {
  const uint32_t x = floatBits(f);
  const uint16_t sign = uint16_t((x >> 16) & 0x8000u);
  const uint32_t magnitude = x & 0x7FFFFFFFu;
  if (magnitude > 0x7F800000u) return uint16_t(sign | 0x7E00u | ((magnitude >> 13) & 0x3FFu));
  if (magnitude >= 0x477FF000u) return uint16_t(sign | 0x7C00u);          // rounds to Inf
  if (magnitude < 0x38800000u) {                                          // denormal: round the scaled value
    return uint16_t(sign | uint16_t(std::nearbyint(floatFromBits(magnitude) * 16777216.0f)));
  }
  const uint32_t rebased = magnitude - 0x38000000u;
  const uint32_t rounded = rebased + 0xFFFu + ((rebased >> 13) & 1u);     // ties to even
  return uint16_t(sign | (rounded >> 13));
}

// Render-target writes and clears of half targets: the `half` step of the method set.
inline uint16_t halfFromFloat(float f, HalfMethod method) {
  return methods::halfNearestEven(method) ? halfFromFloatNearestEven(f) : halfFromFloatTowardZero(f);
}

inline float floatFromHalf(uint16_t h) {
  const uint32_t sign = uint32_t(h & 0x8000u) << 16;
  const uint32_t exponent = (h >> 10) & 0x1Fu;
  const uint32_t mantissa = h & 0x3FFu;
  if (exponent == 0) {                                                    // zero or denormal: exact
    const float value = float(mantissa) * (1.0f / 16777216.0f);
    return sign ? -value : value;
  }
  if (exponent == 31) return floatFromBits(sign | 0x7F800000u | (mantissa << 13));
  return floatFromBits(sign | ((exponent + 112u) << 23) | (mantissa << 13));
}

inline uint32_t depthClearCode(float depth, int bits) {
  const double clamped = depth < 0.0f ? 0.0 : (depth > 1.0f ? 1.0 : double(depth));
  return uint32_t(std::lround(clamped * double((1u << bits) - 1)));
}

}  // namespace raster::format
