// PCF as the shadow ports make it: textureCompareGrid<R> (raster/texture/sampler.h), the
// 3x3 grid of the shadow scene (shaders_cpp/shadow/main.h) and the 5x5 grid of the deferred
// lighting (shaders_cpp/deferred/lighting.h), one texel apart on the 1024x1024 Depth24 map,
// for 16 lanes (Float8x2). The map is read 1:1 from a 640x480 screen (coherent) or at
// scattered places. One item is one lane's whole grid (9 or 25 compare taps).
#include <benchmark/benchmark.h>

#include "bench/micro/micro_common.h"
#include "raster/texture/sampler.h"

namespace {

constexpr int kCallsPerIteration = 128;

template <int R, class Walk>
void pcf(benchmark::State& state, Walk walk) {
  using micro::Lanes16;
  constexpr int N = 2 * R + 1;
  const raster::Texture& map = micro::depth24Texture1024();
  const raster::Sampler2DShadow sampler{0, &map};
  const float texel = 1.0f / float(map.width);
  const Lanes16 ref(0.5f);
  Lanes16 sum(0.0f);
  for (auto _ : state) {
    for (int k = 0; k < kCallsPerIteration; ++k) {
      Lanes16 s, t;
      walk.next(s, t);
      Lanes16 taps[N][N];
      raster::textureCompareGrid<R>(sampler, raster::glsl::vec2<Lanes16>(s, t), 0.0f, texel, ref, taps);
      for (int j = 0; j < N; ++j)   // the shader's own sum of the taps
        for (int i = 0; i < N; ++i) sum = sum + taps[j][i];
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["taps"] = N * N;
  micro::countItems(state, int64_t(kCallsPerIteration) * Lanes16::kCount, "ns_per_lookup");
}

const raster::Texture& map() { return micro::depth24Texture1024(); }
void pcf3Coherent(benchmark::State& state) { pcf<1>(state, micro::CoherentWalk(map().width, map().height, 1.0f)); }
void pcf3Scattered(benchmark::State& state) { pcf<1>(state, micro::ScatteredWalk()); }
void pcf5Coherent(benchmark::State& state) { pcf<2>(state, micro::CoherentWalk(map().width, map().height, 1.0f)); }
void pcf5Scattered(benchmark::State& state) { pcf<2>(state, micro::ScatteredWalk()); }

}  // namespace

BENCHMARK(pcf3Coherent)->Name("pcf/3x3_x16/depth24_1024_coherent");
BENCHMARK(pcf3Scattered)->Name("pcf/3x3_x16/depth24_1024_scattered");
BENCHMARK(pcf5Coherent)->Name("pcf/5x5_x16/depth24_1024_coherent");
BENCHMARK(pcf5Scattered)->Name("pcf/5x5_x16/depth24_1024_scattered");
