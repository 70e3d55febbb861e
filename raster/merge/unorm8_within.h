// Where a colour's RGBA8 byte is known without its last bits: the lanes where every value
// within `error` of `value` converts to one unorm8 byte, as the RGBA8 write converts it
// (format::unorm8FromFloat: min(x, 1), * 255 in float, rounded to the nearest integer, ties
// to even, saturated). A port whose output goes only to RGBA8 targets
// (FragmentOutput::unorm8Outputs) may compute that output with a cheaper form of known
// error, and take the exact one where some lane is not within (docs/porting.md, section 5,
// "Bytes, not floats").
//
// Why it holds: take the exact y and the lane's v, |y - v| <= error. The write's byte is
// the saturated round(fl(x * 255)) (the clamp to 1 first changes no byte), which moves only
// where the product, monotonic in x, crosses some k + 0.5 with k from 0 to 254. Near those
// the products lie below 256, so fl(y * 255) and fl(v * 255) differ by at most 255 * error
// plus a rounding of each, 2^-17 at most; where fl(v * 255) lies farther than that from every
// k + 0.5, y and v give one byte. The test below asks it of every half-integer, with room to
// spare (2^-12). A tie is never within, nor is NaN (its comparison is false).
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
