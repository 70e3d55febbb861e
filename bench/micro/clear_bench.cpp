// Clears through merge::clearRect, the renderer's per-tile clear (raster/merge/clear.h):
//   depth24_1024        the shadow map's whole 1024x1024 Depth24 clear (4 MiB)
//   depth24_tile64      one 64x64 tile of it, as a tile's task clears its share
//   rgba8_1920x1080     a 1920x1080 RGBA8 window colour clear (8 MiB)
// One item is one texel; bytes/s counts the bytes stored.
#include <benchmark/benchmark.h>

#include "bench/micro/micro_common.h"
#include "raster/contract.h"
#include "raster/merge/clear.h"

namespace {

void clear(benchmark::State& state, raster::Texture& target, const raster::TileBounds& rect, bool depth) {
  raster::Framebuffer framebuffer;
  framebuffer.width = target.width;
  framebuffer.height = target.height;
  raster::ClearValues values;
  if (depth) {
    framebuffer.depth = &target;
    values.depth = true;
    values.depthValue = 1.0f;
  } else {
    framebuffer.colors.push_back(&target);
    values.color = true;
    values.colorValue[0] = 0.1f, values.colorValue[1] = 0.2f, values.colorValue[2] = 0.3f, values.colorValue[3] = 1.0f;
  }
  for (auto _ : state) {
    raster::merge::clearRect(framebuffer, values, rect, true);
    benchmark::ClobberMemory();
  }
  const int64_t texels = int64_t(rect.x1 + 1 - rect.x0) * int64_t(rect.y1 + 1 - rect.y0);
  micro::countItems(state, texels, "ns_per_texel");
  state.SetBytesProcessed(int64_t(state.iterations()) * texels * 4);
}

void depth24Whole(benchmark::State& state) {
  raster::Texture map(1024, 1024, raster::TexelFormat::Depth24);
  clear(state, map, {0, 0, 1023, 1023}, true);
}
void depth24Tile(benchmark::State& state) {
  raster::Texture map(1024, 1024, raster::TexelFormat::Depth24);
  clear(state, map, {320, 320, 383, 383}, true);
}
void rgba8Window(benchmark::State& state) {
  raster::Texture window(1920, 1080, raster::TexelFormat::RGBA8);
  clear(state, window, {0, 0, 1919, 1079}, false);
}

}  // namespace

BENCHMARK(depth24Whole)->Name("clear/depth24_1024");
BENCHMARK(depth24Tile)->Name("clear/depth24_tile64");
BENCHMARK(rgba8Window)->Name("clear/rgba8_1920x1080");
