// 16-lane bilinear colour lookups, GLSL's texture(sampler2D, uv) as the shader ports call it
// (raster/texture/sampler.h, with Float8x2 lanes as paired shading passes them):
//   RGBA8 2048x2048, REPEAT     the deferred G-buffer's 2K JPEGs, minified about 2:1
//   RGBA16F 1024x1024, CLAMP    an hdr colour target or bloom level, read 1:1 (the composite's
//                               scene lookup) or magnified 2:1 (its bloom lookup: a texture of
//                               half the target's size)
// each with coherent and scattered coordinates (micro_common.h). One item is one lane's
// lookup; ns_per_lookup is per lane, so a 16-lane call costs 16 times that.
#include <benchmark/benchmark.h>

#include "bench/micro/micro_common.h"
#include "raster/texture/sampler.h"

namespace {

constexpr int kCallsPerIteration = 256;

template <class Walk>
void lookups(benchmark::State& state, const raster::Texture& texture, Walk walk) {
  using micro::Lanes16;
  const raster::Sampler2D sampler{0, &texture};
  Lanes16 sum(0.0f);
  for (auto _ : state) {
    for (int k = 0; k < kCallsPerIteration; ++k) {
      Lanes16 s, t;
      walk.next(s, t);
      const raster::glsl::vec4<Lanes16> texel = raster::texture(sampler, raster::glsl::vec2<Lanes16>(s, t));
      sum = sum + texel.x + texel.w;   // two channels kept: the whole lookup stays live
    }
    benchmark::DoNotOptimize(sum);
  }
  micro::countItems(state, int64_t(kCallsPerIteration) * Lanes16::kCount, "ns_per_lookup");
}

void rgba8Coherent(benchmark::State& state) {
  const raster::Texture& texture = micro::rgba8Texture2048();
  lookups(state, texture, micro::CoherentWalk(texture.width, texture.height, 2.0f));
}
void rgba8Scattered(benchmark::State& state) { lookups(state, micro::rgba8Texture2048(), micro::ScatteredWalk()); }
void rgba16fCoherent(benchmark::State& state) {
  const raster::Texture& texture = micro::rgba16fTexture1024();
  lookups(state, texture, micro::CoherentWalk(texture.width, texture.height, 1.0f));
}
void rgba16fMagnified(benchmark::State& state) {
  const raster::Texture& texture = micro::rgba16fTexture1024();
  lookups(state, texture, micro::CoherentWalk(texture.width, texture.height, 0.5f));
}
void rgba16fScattered(benchmark::State& state) { lookups(state, micro::rgba16fTexture1024(), micro::ScatteredWalk()); }

}  // namespace

BENCHMARK(rgba8Coherent)->Name("texture/rgba8_bilinear_x16/2048_min2_coherent");
BENCHMARK(rgba8Scattered)->Name("texture/rgba8_bilinear_x16/2048_scattered");
BENCHMARK(rgba16fCoherent)->Name("texture/rgba16f_bilinear_x16/1024_coherent");
BENCHMARK(rgba16fMagnified)->Name("texture/rgba16f_bilinear_x16/1024_mag2_coherent");
BENCHMARK(rgba16fScattered)->Name("texture/rgba16f_bilinear_x16/1024_scattered");
