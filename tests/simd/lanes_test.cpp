// The lane types (raster/simd/lanes.h): simd::Float8 (AVX2) must equal simd::Lanes<8> (the
// plain-loop reference) bit for bit, lane by lane, on inputs that include NaN, +-0, +-Inf
// and denormals; and the GLSL helpers (raster/simd/glsl.h) over lanes must equal the same
// helpers instantiated with F = float, lane by lane.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "raster/simd/glsl.h"
#include "raster/simd/lanes.h"
#include "tests/float_bits.h"

namespace {

using raster::simd::Lanes;
using L8 = Lanes<8>;

using testing_support::bitsOf;
using testing_support::floatOf;

std::string hex(uint32_t b) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", b);
  return text;
}

// Random floats with the special classes well represented.
float specialFloat(std::mt19937& rng) {
  static const float specials[] = {
      0.0f, -0.0f, INFINITY, -INFINITY, std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN(),
      floatOf(0x7FC12345u), floatOf(0xFFA00001u), floatOf(0x7F800001u) /* signalling */, std::numeric_limits<float>::denorm_min(),
      -std::numeric_limits<float>::denorm_min(), floatOf(0x007FFFFFu), std::numeric_limits<float>::min(),
      std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), 1.0f, -1.0f, 0.5f, 1.5f, -2.5f, 3.5f};
  switch (rng() % 4) {
    case 0: return specials[rng() % (sizeof specials / sizeof specials[0])];
    case 1: return floatOf(uint32_t(rng()));                                      // any bit pattern
    case 2: return floatOf(uint32_t(rng()) & 0x807FFFFFu);                        // denormals
    default: return std::uniform_real_distribution<float>(-100.0f, 100.0f)(rng);  // ordinary values
  }
}

#if RASTER_AVX2
using raster::simd::Float8;
using raster::simd::Mask8;

struct Pair {
  L8 ref;
  Float8 fast;
};

Pair randomPair(std::mt19937& rng) {
  alignas(32) float v[8];
  for (float& x : v) x = specialFloat(rng);
  return {L8::load(v), Float8::load(v)};
}

// Lanes whose bit patterns differ. When both lanes are NaN only the payload can differ:
// with two or more NaN operands x86 propagates the first source's NaN, and the compiler may
// swap the operands of a commutative operation (in either lane type), so such lanes are
// counted apart in `nanPayload`; every other difference counts in the return value.
int differingLanes(const L8& ref, const Float8& fast, std::string& first, const char* what, int& nanPayload) {
  alignas(32) float f[8];
  fast.store(f);
  int n = 0;
  for (int i = 0; i < 8; ++i) {
    if (bitsOf(ref.lane[i]) == bitsOf(f[i])) continue;
    if (std::isnan(ref.lane[i]) && std::isnan(f[i])) {
      ++nanPayload;
      continue;
    }
    if (n++ == 0 && first.empty())
      first = std::string(what) + " lane " + std::to_string(i) + ": Lanes<8> " + hex(bitsOf(ref.lane[i])) + " vs Float8 " + hex(bitsOf(f[i]));
  }
  return n;
}
#endif

}  // namespace

TEST_SUITE("simd") {
#if RASTER_AVX2
  TEST_CASE("Float8 equals Lanes<8> bit for bit: arithmetic, fma, min/max, floor, sqrt, abs, select, compares, quad derivatives") {
    std::mt19937 rng(10010);
    std::string first;
    int diffs = 0, maskDiffs = 0, nanPayload = 0;
    constexpr int kRounds = 20000;
    for (int round = 0; round < kRounds; ++round) {
      const Pair a = randomPair(rng), b = randomPair(rng), c = randomPair(rng);
      diffs += differingLanes(a.ref + b.ref, a.fast + b.fast, first, "+", nanPayload);
      diffs += differingLanes(a.ref - b.ref, a.fast - b.fast, first, "-", nanPayload);
      diffs += differingLanes(a.ref * b.ref, a.fast * b.fast, first, "*", nanPayload);
      diffs += differingLanes(a.ref / b.ref, a.fast / b.fast, first, "/", nanPayload);
      diffs += differingLanes(-a.ref, -a.fast, first, "negate", nanPayload);
      L8 r = a.ref;
      Float8 f = a.fast;
      r += b.ref, f += b.fast, r *= c.ref, f *= c.fast, r -= a.ref, f -= a.fast, r /= b.ref, f /= b.fast;
      diffs += differingLanes(r, f, first, "compound assignment", nanPayload);
      diffs += differingLanes(raster::simd::fma(a.ref, b.ref, c.ref), raster::simd::fma(a.fast, b.fast, c.fast), first, "fma", nanPayload);
      diffs += differingLanes(raster::simd::min(a.ref, b.ref), raster::simd::min(a.fast, b.fast), first, "min", nanPayload);
      diffs += differingLanes(raster::simd::max(a.ref, b.ref), raster::simd::max(a.fast, b.fast), first, "max", nanPayload);
      diffs += differingLanes(raster::simd::floor(a.ref), raster::simd::floor(a.fast), first, "floor", nanPayload);
      diffs += differingLanes(raster::simd::sqrt(a.ref), raster::simd::sqrt(a.fast), first, "sqrt", nanPayload);
      diffs += differingLanes(raster::simd::abs(a.ref), raster::simd::abs(a.fast), first, "abs", nanPayload);
      diffs += differingLanes(raster::simd::quadDdx(a.ref), raster::simd::quadDdx(a.fast), first, "quadDdx", nanPayload);
      diffs += differingLanes(raster::simd::quadDdy(a.ref), raster::simd::quadDdy(a.fast), first, "quadDdy", nanPayload);

      const raster::simd::Mask<8> refMasks[] = {a.ref < b.ref, a.ref <= b.ref, a.ref > b.ref, a.ref >= b.ref, a.ref == b.ref};
      const Mask8 fastMasks[] = {a.fast < b.fast, a.fast <= b.fast, a.fast > b.fast, a.fast >= b.fast, a.fast == b.fast};
      for (int m = 0; m < 5; ++m) {
        maskDiffs += refMasks[m].bits() != fastMasks[m].bits();
        diffs += differingLanes(raster::simd::select(refMasks[m], a.ref, b.ref), raster::simd::select(fastMasks[m], a.fast, b.fast),
                                first, "select", nanPayload);
      }
      const auto refMask = (refMasks[0] | refMasks[4]) & !refMasks[3];
      const auto fastMask = (fastMasks[0] | fastMasks[4]) & !fastMasks[3];
      maskDiffs += refMask.bits() != fastMask.bits();
      maskDiffs += raster::simd::any(refMask) != raster::simd::any(fastMask);
      maskDiffs += raster::simd::all(refMask) != raster::simd::all(fastMask);
      const unsigned random = unsigned(rng()) & 0xFFu;
      maskDiffs += raster::simd::Mask<8>::fromBits(random).bits() != random || Mask8::fromBits(random).bits() != random;
    }
    MESSAGE("Float8 vs Lanes<8>: " << kRounds << " rounds, " << diffs << " differing lanes, " << maskDiffs
                                   << " differing masks; " << nanPayload
                                   << " NaN lanes whose payload differs (two or more NaN operands)");
    CAPTURE(first);
    CHECK(diffs == 0);
    CHECK(maskDiffs == 0);
  }

  TEST_CASE("Float8 and Lanes<8> propagate a single NaN operand's payload exactly, in either operand position") {
    // With one NaN operand the result is that NaN, quieted, whatever the operand order.
    std::mt19937 rng(10011);
    std::string first;
    int diffs = 0, nanPayload = 0;
    for (int round = 0; round < 5000; ++round) {
      alignas(32) float nan[8], num[8], num2[8];
      for (int i = 0; i < 8; ++i) {
        nan[i] = floatOf((uint32_t(rng()) & 0x807FFFFFu) | 0x7F800001u);   // any sign, payload, quiet or not
        do num[i] = specialFloat(rng); while (std::isnan(num[i]));
        do num2[i] = specialFloat(rng); while (std::isnan(num2[i]));
      }
      const L8 rn = L8::load(nan), rx = L8::load(num), ry = L8::load(num2);
      const Float8 fn = Float8::load(nan), fx = Float8::load(num), fy = Float8::load(num2);
      diffs += differingLanes(rn + rx, fn + fx, first, "NaN + x", nanPayload);
      diffs += differingLanes(rx + rn, fx + fn, first, "x + NaN", nanPayload);
      diffs += differingLanes(rn - rx, fn - fx, first, "NaN - x", nanPayload);
      diffs += differingLanes(rx - rn, fx - fn, first, "x - NaN", nanPayload);
      diffs += differingLanes(rn * rx, fn * fx, first, "NaN * x", nanPayload);
      diffs += differingLanes(rx * rn, fx * fn, first, "x * NaN", nanPayload);
      diffs += differingLanes(rn / rx, fn / fx, first, "NaN / x", nanPayload);
      diffs += differingLanes(rx / rn, fx / fn, first, "x / NaN", nanPayload);
      diffs += differingLanes(raster::simd::fma(rn, rx, ry), raster::simd::fma(fn, fx, fy), first, "fma(NaN, x, y)", nanPayload);
      diffs += differingLanes(raster::simd::fma(rx, rn, ry), raster::simd::fma(fx, fn, fy), first, "fma(x, NaN, y)", nanPayload);
      diffs += differingLanes(raster::simd::fma(rx, ry, rn), raster::simd::fma(fx, fy, fn), first, "fma(x, y, NaN)", nanPayload);
      diffs += differingLanes(raster::simd::sqrt(rn), raster::simd::sqrt(fn), first, "sqrt(NaN)", nanPayload);
      diffs += differingLanes(raster::simd::floor(rn), raster::simd::floor(fn), first, "floor(NaN)", nanPayload);
      diffs += differingLanes(raster::simd::quadDdx(rn), raster::simd::quadDdx(fn), first, "quadDdx(NaN)", nanPayload);
    }
    MESSAGE("single-NaN propagation: " << diffs << " differing lanes, " << nanPayload << " NaN payload differences");
    CAPTURE(first);
    CHECK(diffs == 0);
    CHECK(nanPayload == 0);
  }

  TEST_CASE("Float8's transposed store writes each lane's eight values where the reference does") {
    // The vertex stage's records: every stride it meets (8 + varyings), every lane count,
    // and nothing written past a lane's eight floats (the next record's start stays put).
    for (int stride = 8; stride <= 24; ++stride) {
      for (int count = 1; count <= 8; ++count) {
        raster::simd::Float8 rows[8];
        for (int r = 0; r < 8; ++r) {
          float lanes[8];
          for (int i = 0; i < 8; ++i) lanes[i] = float(r * 8 + i) + 0.5f;
          rows[r] = raster::simd::Float8::load(lanes);
        }
        std::vector<float> got(size_t(stride) * 9, -1.0f), want(size_t(stride) * 9, -1.0f);
        raster::simd::storeLanesTransposed(rows, got.data(), size_t(stride), count);
        for (int i = 0; i < count; ++i)
          for (int r = 0; r < 8; ++r) want[size_t(i) * size_t(stride) + size_t(r)] = float(r * 8 + i) + 0.5f;
        CAPTURE(stride);
        CAPTURE(count);
        CHECK(got == want);
      }
    }
  }

  TEST_CASE("quad derivatives follow llvmpipe's lane layout (fine: per row and per column)") {
    alignas(32) const float v[8] = {1.0f, 3.0f, 10.0f, 30.0f, 100.0f, 300.0f, 1000.0f, 3000.0f};
    alignas(32) float dx[8], dy[8];
    raster::simd::quadDdx(Float8::load(v)).store(dx);
    raster::simd::quadDdy(Float8::load(v)).store(dy);
    // Lanes TL, TR, BL, BR per quad: dFdx = TR - TL on the top row, BR - BL on the bottom.
    const float expectDx[8] = {2, 2, 20, 20, 200, 200, 2000, 2000};
    const float expectDy[8] = {9, 27, 9, 27, 900, 2700, 900, 2700};
    for (int i = 0; i < 8; ++i) {
      CAPTURE(i);
      CHECK(dx[i] == expectDx[i]);
      CHECK(dy[i] == expectDy[i]);
    }
  }
#endif

  TEST_CASE("glsl::dot/normalize/mix/pow over lanes equal the F = float versions lane by lane") {
    using namespace raster::glsl;
    using F = raster::simd::FastLanes;
    constexpr int kLanes = F::kCount;
    std::mt19937 rng(11011);
    auto component = [&](int round) {
      // Mostly ordinary values (normalize of tiny/huge vectors included), some special ones.
      if (round % 5 == 0) return specialFloat(rng);
      return std::ldexp(std::uniform_real_distribution<float>(-1.0f, 1.0f)(rng), int(rng() % 40) - 20);
    };
    int diffs = 0, nanPayload = 0;
    std::string first;
    auto compare = [&](const F& lanes, const float* scalar, const char* what) {
      alignas(32) float out[kLanes];
      lanes.store(out);
      for (int i = 0; i < kLanes; ++i) {
        if (bitsOf(out[i]) == bitsOf(scalar[i])) continue;
        if (std::isnan(out[i]) && std::isnan(scalar[i])) {   // payload choice among several NaNs
          ++nanPayload;
          continue;
        }
        if (diffs++ == 0)
          first = std::string(what) + " lane " + std::to_string(i) + ": " + hex(bitsOf(out[i])) + " vs " + hex(bitsOf(scalar[i]));
      }
    };
    for (int round = 0; round < 20000; ++round) {
      alignas(32) float in[10][kLanes];
      for (auto& row : in)
        for (float& x : row) x = component(round);
      for (int i = 0; i < kLanes; ++i) in[9][i] = std::fabs(in[9][i]);   // pow's base mostly positive
      auto lanesOf = [&](int k) { return F::load(in[k]); };
      const vec3<F> a(lanesOf(0), lanesOf(1), lanesOf(2)), b(lanesOf(3), lanesOf(4), lanesOf(5));
      const vec4<F> a4(lanesOf(0), lanesOf(1), lanesOf(2), lanesOf(6)), b4(lanesOf(3), lanesOf(4), lanesOf(5), lanesOf(7));

      alignas(32) float dot3[kLanes], dot4[kLanes], dot2[kLanes], nx[kLanes], ny[kLanes], nz[kLanes], mixed[kLanes], powed[kLanes];
      for (int i = 0; i < kLanes; ++i) {
        const vec3<float> sa(in[0][i], in[1][i], in[2][i]), sb(in[3][i], in[4][i], in[5][i]);
        dot3[i] = dot(sa, sb);
        dot4[i] = dot(vec4<float>(sa, in[6][i]), vec4<float>(sb, in[7][i]));
        dot2[i] = dot(sa.xy(), sb.xy());
        const vec3<float> n = normalize(sa);
        nx[i] = n.x, ny[i] = n.y, nz[i] = n.z;
        mixed[i] = mix(in[0][i], in[3][i], in[8][i]);
        powed[i] = pow(in[9][i], in[1][i]);
      }
      compare(dot(a, b), dot3, "dot(vec3)");
      compare(dot(a4, b4), dot4, "dot(vec4)");
      compare(dot(a.xy(), b.xy()), dot2, "dot(vec2)");
      const vec3<F> n = normalize(a);
      compare(n.x, nx, "normalize.x");
      compare(n.y, ny, "normalize.y");
      compare(n.z, nz, "normalize.z");
      compare(mix(lanesOf(0), lanesOf(3), lanesOf(8)), mixed, "mix");
      compare(pow(lanesOf(9), lanesOf(1)), powed, "pow");
    }
    MESSAGE("glsl helpers over lanes vs float: " << diffs << " differing lanes; " << nanPayload
                                                  << " NaN lanes whose payload differs (two or more NaN operands)");
    CAPTURE(first);
    CHECK(diffs == 0);
  }
}
