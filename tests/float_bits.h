// A float's bit pattern and back, and the special values, for the tests that compare floats
// bit for bit (the math, lane and GL-comparison tests).
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

namespace testing_support {

inline uint32_t bitsOf(float f) { return std::bit_cast<uint32_t>(f); }
inline float floatOf(uint32_t bits) { return std::bit_cast<float>(bits); }

inline constexpr float kInf = std::numeric_limits<float>::infinity();
inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

}  // namespace testing_support
