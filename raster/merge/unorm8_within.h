// Where a colour's RGBA8 byte is known without its last bits: the lanes where every value
// within `error` of `value` converts to one unorm8 byte, as the RGBA8 write converts it
// (format::unorm8FromFloat: min(x, 1), * 255 in float, rounded to the nearest integer, ties
// to even, saturated). A port whose output goes only to RGBA8 targets
// (FragmentOutput::unorm8Outputs) may compute that output with a cheaper form of known
// error, and take the exact one where some lane is not within (docs/porting.md, section 5,
// "Bytes, not floats").
//
// Why it holds (for an error below 1): take the exact y and the lane's v, |y - v| <= error.
// The write's byte is a monotonic function of round(fl(y * 255)) (the clamp to 1 and the
// saturation only merge bytes), so y and v give one byte where fl(y * 255) and fl(v * 255)
// round to one integer: where fl(v * 255) lies farther from every k + 0.5 than 255 * error
// plus both products' roundings. Below 8 (products below 2040) each rounding is at most
// 2^-14; at 8 and above, and at -8 and below, y and v both give 255, or both 0, whatever the
// test says. A tie is never within, nor is NaN (its comparison is false).
#pragma once

#include "raster/simd/glsl.h"

namespace raster::merge {

template <class F>
[[gnu::always_inline]] inline auto unorm8Within(F value, F error) {
  const F scaled = value * F(255.0f);
  const F fromHalf = glsl::abs(scaled - glsl::floor(scaled) - F(0.5f));   // to the nearest k + 0.5
  // 255 * error, rounded up by more than its own rounding, and both products' roundings.
  return fromHalf > error * F(255.0f * (1.0f + 0x1p-20f)) + F(0x1p-12f);
}

}  // namespace raster::merge
