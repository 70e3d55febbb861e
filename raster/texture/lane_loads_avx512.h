// Per-lane scalar loads for the 16-lane lookups (sample_half_avx512.h, sample_rgba8_avx512.h):
// each lane's index stored once, then one 8-byte load a lane, two lanes to a 16-byte
// register. On the AMD EPYC Zen 4 host these beat 8-element 64-bit gathers
// (docs/notes/2026-11-21-what-made-it-faster.md); the values are the gathers' exactly.
#pragma once

#include "raster/simd/isa.h"
#if RASTER_ZMM_PAIRS
#include "raster/simd/intrinsics.h"

namespace raster::sampling {

// Sixteen lane indices (texel or window starts) stored for the caller to read back one
// scalar load at a time, as four 16-byte stores. Left to itself the compiler pulls each out
// of a vector register, three instructions per texel load (composite -2%); and a 4-byte load
// from the middle of one 64-byte store waited for it on the Intel Xeon host, where from a
// 16-byte store it is forwarded (docs/notes/2026-11-29-window-starts-in-quarters.md).
[[gnu::always_inline]] inline void storeLaneIndices16(__m512i index, int (&out)[16]) {
  _mm_store_si128(reinterpret_cast<__m128i*>(out), _mm512_castsi512_si128(index));
  _mm_store_si128(reinterpret_cast<__m128i*>(out + 4), _mm512_extracti32x4_epi32(index, 1));
  _mm_store_si128(reinterpret_cast<__m128i*>(out + 8), _mm512_extracti32x4_epi32(index, 2));
  _mm_store_si128(reinterpret_cast<__m128i*>(out + 12), _mm512_extracti32x4_epi32(index, 3));
  asm volatile("" : "+m"(out));   // read back from memory, not from the register
}

// The 8-byte values at base + index[lane] * scale bytes for lanes first..first + 7, in lane
// order: what _mm512_i32gather_epi64 of those indices returns.
[[gnu::always_inline]] inline __m512i loadEightLanes64(const void* base, const int (&index)[16], int first, int scale) {
  const char* bytes = static_cast<const char*>(base);
  auto two = [&](int lane) __attribute__((always_inline)) {   // lanes lane and lane + 1
    const __m128d low =
        _mm_castsi128_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bytes + ptrdiff_t(index[lane]) * scale)));
    return _mm_castpd_si128(_mm_loadh_pd(low, reinterpret_cast<const double*>(bytes + ptrdiff_t(index[lane + 1]) * scale)));
  };
  const __m256i low = _mm256_inserti128_si256(_mm256_castsi128_si256(two(first)), two(first + 2), 1);
  const __m256i high = _mm256_inserti128_si256(_mm256_castsi128_si256(two(first + 4)), two(first + 6), 1);
  return _mm512_inserti64x4(_mm512_castsi256_si512(low), high, 1);
}

// The 4-byte values at base[index[lane]] for all sixteen lanes, in lane order: what
// _mm512_i32gather_epi32 of those indices returns.
[[gnu::always_inline]] inline __m512i loadSixteenLanes32(const uint32_t* base, const int (&index)[16]) {
  auto four = [&](int lane) __attribute__((always_inline)) {   // lanes lane..lane + 3
    __m128i v = _mm_cvtsi32_si128(int(base[index[lane]]));
    v = _mm_insert_epi32(v, int(base[index[lane + 1]]), 1);
    v = _mm_insert_epi32(v, int(base[index[lane + 2]]), 2);
    return _mm_insert_epi32(v, int(base[index[lane + 3]]), 3);
  };
  const __m256i low = _mm256_inserti128_si256(_mm256_castsi128_si256(four(0)), four(4), 1);
  const __m256i high = _mm256_inserti128_si256(_mm256_castsi128_si256(four(8)), four(12), 1);
  return _mm512_inserti64x4(_mm512_castsi256_si512(low), high, 1);
}

}  // namespace raster::sampling
#endif
