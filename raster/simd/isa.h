// The one place that selects instruction-set variants.
//
// The pipeline is written once over a lane type F (lanes.h). Which wider lane types exist
// is decided here, from the build's options (CMakeLists.txt):
//   RASTER_AVX2 (CMake option, default on)   Float8 and Float8x2 (lanes_avx2.h), and the
//                                             *_avx2 siblings of the files that use them
//   AVX-512F/DQ/VL in the compiler's target   Float8x2 in one 512-bit register
//     (RASTER_AVX512, AUTO by default)        (lanes_avx512.h: RASTER_ZMM_PAIRS)
// Everything else follows from the lane type: a function with a faster form for Float8 or
// Float8x2 has it as an overload in an *_avx2 / *_avx512 sibling file, and the generic
// form in the plain file is the readable reference, the whole algorithm. With RASTER_AVX2
// off, FastLanes is Lanes<8> and no sibling is compiled; `raster --scalar` picks
// ScalarLanes at run time for the same effect in a SIMD build. The bytes are the same in
// every configuration.
#pragma once

#include "raster/simd/lanes.h"

#if RASTER_AVX2
#if defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512VL__)
#define RASTER_ZMM_PAIRS 1
#endif
#include "raster/simd/lanes_avx2.h"
#if RASTER_ZMM_PAIRS
#include "raster/simd/lanes_avx512.h"
#endif
#endif

namespace raster::simd {

#if RASTER_AVX2
using FastLanes = Float8;   // what tiles shade with by default
#else
using FastLanes = Lanes<8>;
#endif

}  // namespace raster::simd

namespace raster {

// The lane type the reference path shades with (`--scalar`): one 2x2 quad in plain loops.
using ScalarLanes = simd::Lanes<4>;
using simd::FastLanes;
#if RASTER_AVX2
// Two FastLanes groups shaded in one call (tile/group_shader_avx2.h pairs them).
using PairedLanes = simd::Float8x2;
#endif

}  // namespace raster
