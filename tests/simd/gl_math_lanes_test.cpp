// The instantiations of raster/simd/gl_math.h against each other, without GL: Float8 and
// Float8x2 (AVX2), Lanes<8> and float give the same bits on millions of random arguments,
// denormals flushed and kept, and pow's shortcut for plain groups gives its full path's
// bits. gl_math_test.cpp checks them against llvmpipe through real GL.
#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "raster/simd/glsl.h"
#include "tests/sanitizer_build.h"
#include "tests/simd/gl_math_args.h"

using namespace gl_math_test;

TEST_SUITE("gl_math") {
  TEST_CASE("Float8, Float8x2, Lanes<8> and float give the same bits on millions of arguments, denormals flushed and kept") {
    using raster::simd::Lanes;
    namespace glsl = raster::glsl;
    using L8 = Lanes<8>;
#if RASTER_AVX2
    using raster::simd::Float8;
    using raster::simd::Float8x2;
#endif
    struct Fn {
      const char* name;
      L8 (*lanes)(L8, L8);
#if RASTER_AVX2
      Float8 (*fast)(Float8, Float8);
      Float8x2 (*paired)(Float8x2, Float8x2);
#endif
      float (*scalar)(float, float);
    };
#if RASTER_AVX2
#define RASTER_GL_MATH_FN(name, expr)                                                            \
  Fn {                                                                                           \
    name, [](L8 x, L8 y) -> L8 { (void)y; return expr; }, [](Float8 x, Float8 y) -> Float8 { (void)y; return expr; }, \
        [](Float8x2 x, Float8x2 y) -> Float8x2 { (void)y; return expr; },                      \
        [](float x, float y) -> float { (void)y; return expr; }                                  \
  }
#else
#define RASTER_GL_MATH_FN(name, expr)                                                            \
  Fn { name, [](L8 x, L8 y) -> L8 { (void)y; return expr; }, [](float x, float y) -> float { (void)y; return expr; } }
#endif
    const Fn functions[] = {
        RASTER_GL_MATH_FN("exp2", glsl::exp2(x)),       RASTER_GL_MATH_FN("log2", glsl::log2(x)),
        RASTER_GL_MATH_FN("pow", glsl::pow(x, y)),      RASTER_GL_MATH_FN("pow<48>", glsl::pow<48.0f>(x)),
        RASTER_GL_MATH_FN("pow<2.2>", glsl::pow<2.2f>(x)), RASTER_GL_MATH_FN("pow<0.4545>", glsl::pow<1.0f / 2.2f>(x)),
        RASTER_GL_MATH_FN("pow<2>", glsl::pow<2.0f>(x)),
        RASTER_GL_MATH_FN("pow<4>", glsl::pow<4.0f>(x)), RASTER_GL_MATH_FN("sin", glsl::sin(x)),
        RASTER_GL_MATH_FN("cos", glsl::cos(x)),         RASTER_GL_MATH_FN("atan2", glsl::atan(x, y)),
        RASTER_GL_MATH_FN("atan", glsl::atan(x)),       RASTER_GL_MATH_FN("acos", glsl::acos(x)),
        RASTER_GL_MATH_FN("asin", glsl::asin(x)),
    };
#undef RASTER_GL_MATH_FN
    // Per function, while flushing. Under a sanitizer an eighth: what it looks for there
    // (undefined shifts and conversions, out-of-bounds accesses) needs every kind of
    // argument, not millions, and each of the 256 exponents is still drawn hundreds of
    // times; the other builds compare the bits at full count (2^21 took 15 of the
    // ASan + UBSan suites' 345 seconds).
    constexpr size_t kArguments = size_t(1) << (testing_support::kUnderSanitizer ? 18 : 21);
    // Both of llvmpipe's denormal modes: flushed, and kept (a fragment shader after a draw
    // into a half-float target), where AVX-512's log2 instructions would read a denormal
    // unlike the bit operations; a quarter of the kept mode's x are denormals.
    for (const bool flush : {true, false})
    for (const Fn& fn : functions) {
      const raster::glsl::ScopedDenormalMode mode(flush);
      CAPTURE(flush);
      CAPTURE(fn.name);
      std::mt19937 rng(99);
      size_t differing = 0, scalarDiffering = 0;
      std::string first;
      for (size_t i = 0; i < (flush ? kArguments : kArguments / 4); i += 8) {
        alignas(32) float xs[8], ys[8], lanesOut[8];
        for (int l = 0; l < 8; ++l) {
          // Half arbitrary bit patterns (every class), half the usual shader ranges.
          const bool raw = rng() & 1u;
          xs[l] = raw ? anyBits(rng) : magnitude(rng, -12, 20);
          ys[l] = raw ? anyBits(rng) : uniformIn(rng, -64.0f, 64.0f);
          if (!flush && rng() % 4u == 0) xs[l] = std::bit_cast<float>(uint32_t(rng()) & 0x807fffffu);
        }
        fn.lanes(L8::load(xs), L8::load(ys)).store(lanesOut);
#if RASTER_AVX2
        alignas(32) float fastOut[8], swappedOut[8], pairedOut[16];
        fn.fast(Float8::load(xs), Float8::load(ys)).store(fastOut);
        fn.fast(Float8::load(ys), Float8::load(xs)).store(swappedOut);
        // Float8x2: (x, y) in the low half, (y, x) in the high half.
        fn.paired({Float8::load(xs), Float8::load(ys)}, {Float8::load(ys), Float8::load(xs)}).store(pairedOut);
#endif
        for (int l = 0; l < 8; ++l) {
#if RASTER_AVX2
          if (bitsOf(fastOut[l]) != bitsOf(lanesOut[l]) && differing++ == 0)
            first = "x = " + std::to_string(xs[l]) + ", y = " + std::to_string(ys[l]) + ": Float8 " +
                    std::to_string(fastOut[l]) + ", Lanes<8> " + std::to_string(lanesOut[l]);
          if ((bitsOf(pairedOut[l]) != bitsOf(fastOut[l]) || bitsOf(pairedOut[l + 8]) != bitsOf(swappedOut[l])) && differing++ == 0)
            first = "x = " + std::to_string(xs[l]) + ", y = " + std::to_string(ys[l]) + ": Float8x2 differs from Float8";
#endif
          scalarDiffering += bitsOf(fn.scalar(xs[l], ys[l])) != bitsOf(lanesOut[l]);
        }
      }
      CAPTURE(first);
      CHECK(differing == 0);
      CHECK(scalarDiffering == 0);
    }
  }

#if RASTER_AVX2
  // pow takes a shortcut when every lane's base is 0 or a positive normal float (and the
  // exponent is 0 or not tiny): no daz, no edge cases. One negative lane sends the whole
  // group down the full path, so each group is computed both ways and compared lane by lane.
  TEST_CASE("pow's shortcut for plain groups gives the full path's bits") {
    using raster::simd::Float8;
    using raster::simd::Float8x2;
    std::mt19937 rng(7);
    auto plainBase = [&]() -> float {
      switch (rng() % 6u) {
        case 0: return 0.0f;
        case 1: return floatOf(bitsOf(1.0f) + (rng() % 64u) - 32u);   // log2 near 0
        case 2: return std::fabs(magnitude(rng, -126, 127));
        case 3: return std::numeric_limits<float>::min();
        case 4: return std::numeric_limits<float>::max();
        default: return uniformIn(rng, 0.0f, 1.0f);
      }
    };
    auto plainExponent = [&]() -> float {
      switch (rng() % 5u) {
        case 0: return 0.0f;
        case 1: return magnitude(rng, -55, -40);   // the smallest exponents the shortcut takes
        case 2: return magnitude(rng, 100, 127);   // products far outside exp2's range
        default: return uniformIn(rng, -64.0f, 64.0f);
      }
    };
    size_t differing = 0, groups = 0;
    std::string first;
    auto compare = [&](const char* name, auto fn) {
      for (int round = 0; round < 20000; ++round) {
        alignas(32) float xs[8], ys[8], plain[8], full[8];
        for (int l = 0; l < 8; ++l) xs[l] = plainBase(), ys[l] = plainExponent();
        const float y = ys[0];
        for (int l = 0; l < 8; ++l) ys[l] = (round & 1) ? y : ys[l];   // uniform exponents too
        fn(Float8::load(xs), Float8::load(ys)).store(plain);
        // Float8x2 (its own instructions where AVX-512 is built): both halves as Float8.
        alignas(64) float paired[16];
        fn(Float8x2{Float8::load(xs), Float8::load(xs)}, Float8x2{Float8::load(ys), Float8::load(ys)}).store(paired);
        for (int l = 0; l < 16; ++l)
          if (bitsOf(paired[l]) != bitsOf(plain[l % 8]) && differing++ == 0)
            first = std::string(name) + "(" + std::to_string(xs[l % 8]) + ", " + std::to_string(ys[l % 8]) + ") as Float8x2";
        alignas(32) float xsBroken[8];
        std::memcpy(xsBroken, xs, sizeof xs);
        xsBroken[round % 8] = -1.0f;   // not plain: the full path for every lane
        fn(Float8::load(xsBroken), Float8::load(ys)).store(full);
        ++groups;
        for (int l = 0; l < 8; ++l)
          if (l != round % 8 && bitsOf(plain[l]) != bitsOf(full[l]) && differing++ == 0)
            first = std::string(name) + "(" + std::to_string(xs[l]) + ", " + std::to_string(ys[l]) + ")";
      }
    };
    namespace glsl = raster::glsl;
    compare("pow", [](auto x, auto y) { return glsl::pow(x, y); });
    compare("pow<2.2>", [](auto x, auto) { return glsl::pow<2.2f>(x); });
    compare("pow<0.4545>", [](auto x, auto) { return glsl::pow<1.0f / 2.2f>(x); });
    compare("pow<2.5>", [](auto x, auto) { return glsl::pow<2.5f>(x); });
    compare("pow<48>", [](auto x, auto) { return glsl::pow<48.0f>(x); });
    CAPTURE(first);
    CHECK(groups == 100000);
    CHECK(differing == 0);
  }
#endif
}
