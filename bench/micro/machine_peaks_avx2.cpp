// The machine's own peaks, the yardsticks docs/notes/2026-11-25-microbenchmarks.md holds
// each lookup against:
//   peak/gather_dword/KIB   _mm256_i32gather_ps: 8 random 4-byte elements a gather
//   peak/gather_qword/KIB   _mm256_i32gather_epi64: 4 random 8-byte elements a gather, the
//                           samplers' texel-pair and half-float fetch
//   peak/fma/chains:N       _mm256_fmadd_ps in N independent accumulator chains: N = 1 is
//                           the FMA's latency, N = 12 its throughput
//   peak/fma512/chains:12   the same in 512-bit registers, where the build has AVX-512
// Gathers read a working set of KIB KiB (16 KiB .. 256 MiB in steps of 2, so every texture
// size has its point; 2 MiB pages, as textures get them: util/huge_pages.h) at random
// indices from a vector xorshift, four independent streams, so the rate is the memory
// system's with as many misses in flight as the core allows: what a lookup's fetch sees
// when its addresses do not depend on earlier loads.
// Items are elements gathered (gather) or FMA instructions (fma); flops counts 2 per lane.
#include "raster/simd/isa.h"
#if RASTER_AVX2
#include <benchmark/benchmark.h>
#include <immintrin.h>

#include <vector>

#include "bench/micro/micro_common.h"
#include "raster/util/huge_pages.h"

namespace {

constexpr size_t kMaxSetBytes = size_t(256) << 20;
constexpr int kStreams = 4;
constexpr int kGathersPerIteration = 1024;

// The largest working set, touched once so that its pages exist; smaller sets are its start.
const std::vector<uint32_t, raster::HugePageAllocator<uint32_t>>& workingSet() {
  static const std::vector<uint32_t, raster::HugePageAllocator<uint32_t>> data = [] {
    std::vector<uint32_t, raster::HugePageAllocator<uint32_t>> v(kMaxSetBytes / 4);
    for (size_t i = 0; i < v.size(); ++i) v[i] = uint32_t(i);
    return v;
  }();
  return data;
}

// One xorshift32 step per lane: random indices for the next gather, independent of the data.
inline __m256i xorshift(__m256i x) {
  x = _mm256_xor_si256(x, _mm256_slli_epi32(x, 13));
  x = _mm256_xor_si256(x, _mm256_srli_epi32(x, 17));
  return _mm256_xor_si256(x, _mm256_slli_epi32(x, 5));
}

__m256i seeds(int stream) {
  return _mm256_setr_epi32(0x9E3779B9 + stream, 0x7F4A7C15 + stream, 0x2545F491 + stream, 0x6C078965 + stream,
                           0x5851F42D + stream, 0x4C957F2D + stream, 0x14057B7E + stream, 0x3C6EF372 + stream);
}

void gatherDword(benchmark::State& state) {
  const size_t bytes = size_t(state.range(0)) << 10;
  const float* base = reinterpret_cast<const float*>(workingSet().data());
  const __m256i mask = _mm256_set1_epi32(int(bytes / 4 - 1));   // power-of-two sets
  __m256i index[kStreams];
  __m256 sum[kStreams];
  for (int k = 0; k < kStreams; ++k) index[k] = seeds(k), sum[k] = _mm256_setzero_ps();
  for (auto _ : state) {
    for (int g = 0; g < kGathersPerIteration; g += kStreams)
      for (int k = 0; k < kStreams; ++k) {
        index[k] = xorshift(index[k]);
        sum[k] = _mm256_add_ps(sum[k], _mm256_i32gather_ps(base, _mm256_and_si256(index[k], mask), 4));
      }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["gathers_per_ns"] = benchmark::Counter(double(state.iterations()) * kGathersPerIteration * 1e-9,
                                                        benchmark::Counter::kIsRate);
  micro::countItems(state, int64_t(kGathersPerIteration) * 8, "ns_per_element");
}

void gatherQword(benchmark::State& state) {
  const size_t bytes = size_t(state.range(0)) << 10;
  const long long* base = reinterpret_cast<const long long*>(workingSet().data());
  const __m256i mask = _mm256_set1_epi32(int(bytes / 8 - 1));
  __m256i index[kStreams], sum[kStreams];
  for (int k = 0; k < kStreams; ++k) index[k] = seeds(k), sum[k] = _mm256_setzero_si256();
  for (auto _ : state) {
    // Each xorshift step feeds two gathers of four (its low and high halves), as the
    // samplers split a Float8's indices.
    for (int g = 0; g < kGathersPerIteration; g += 2 * kStreams)
      for (int k = 0; k < kStreams; ++k) {
        index[k] = xorshift(index[k]);
        const __m256i i = _mm256_and_si256(index[k], mask);
        sum[k] = _mm256_add_epi64(sum[k], _mm256_i32gather_epi64(base, _mm256_castsi256_si128(i), 8));
        sum[k] = _mm256_add_epi64(sum[k], _mm256_i32gather_epi64(base, _mm256_extracti128_si256(i, 1), 8));
      }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["gathers_per_ns"] = benchmark::Counter(double(state.iterations()) * kGathersPerIteration * 1e-9,
                                                        benchmark::Counter::kIsRate);
  micro::countItems(state, int64_t(kGathersPerIteration) * 4, "ns_per_element");
}

// FMA chains: acc = acc * m + a, which stays finite (m < 1), kChains at a time.
template <int kChains>
void fma256(benchmark::State& state) {
  constexpr int kSteps = 1024;
  const __m256 m = _mm256_set1_ps(0.999f), a = _mm256_set1_ps(0.001f);
  __m256 acc[kChains];
  for (int c = 0; c < kChains; ++c) acc[c] = _mm256_set1_ps(float(c));
  for (auto _ : state) {
    for (int i = 0; i < kSteps; ++i)
      for (int c = 0; c < kChains; ++c) acc[c] = _mm256_fmadd_ps(acc[c], m, a);
    benchmark::DoNotOptimize(acc);
  }
  const double fmas = double(state.iterations()) * kSteps * kChains;
  state.counters["gflops"] = benchmark::Counter(fmas * 16 * 1e-9, benchmark::Counter::kIsRate);
  micro::countItems(state, int64_t(kSteps) * kChains, "ns_per_fma");
}

#if defined(__AVX512F__)
void fma512(benchmark::State& state) {
  constexpr int kSteps = 1024, kChains = 12;
  const __m512 m = _mm512_set1_ps(0.999f), a = _mm512_set1_ps(0.001f);
  __m512 acc[kChains];
  for (int c = 0; c < kChains; ++c) acc[c] = _mm512_set1_ps(float(c));
  for (auto _ : state) {
    for (int i = 0; i < kSteps; ++i)
      for (int c = 0; c < kChains; ++c) acc[c] = _mm512_fmadd_ps(acc[c], m, a);
    benchmark::DoNotOptimize(acc);
  }
  const double fmas = double(state.iterations()) * kSteps * kChains;
  state.counters["gflops"] = benchmark::Counter(fmas * 32 * 1e-9, benchmark::Counter::kIsRate);
  micro::countItems(state, int64_t(kSteps) * kChains, "ns_per_fma");
}
#endif

}  // namespace

BENCHMARK(gatherDword)->Name("peak/gather_dword")->ArgName("KiB")->RangeMultiplier(2)->Range(16, 256 << 10);
BENCHMARK(gatherQword)->Name("peak/gather_qword")->ArgName("KiB")->RangeMultiplier(2)->Range(16, 256 << 10);
BENCHMARK(fma256<1>)->Name("peak/fma/chains:1");
BENCHMARK(fma256<12>)->Name("peak/fma/chains:12");
#if defined(__AVX512F__)
BENCHMARK(fma512)->Name("peak/fma512/chains:12");
#endif
#endif
