// A coarse-shaded tile against a full-rate one (issue 68; tile/coarse_tile.h): one 64x64
// tile of hdr's bright pass (shaders_cpp/hdr/bright.h: one bilinear RGBA16F lookup and a
// soft knee per invocation) into an RGBA16F target, as the post passes reach the tile stage.
//   full_rate  rasterizeTile<FastLanes>: the 1x1 walk the `gl` method set runs
//   coarse     rasterizeTileCoarse<FastLanes> at 2x1, 2x2 and 4x4 (--method shading=RATE):
//              coverage per pixel, one invocation per coarse pixel, its outputs broadcast
// Two triangles: `whole`, a fullscreen triangle over the tile (the post passes: the 1x1
// walk takes its covered-tile path, one virtual call a tile), and `edge`, a triangle whose
// long edge crosses the tile's diagonal (half the tile: groups with partial coverage, as
// at geometry edges under 2x2-all). One item is one pixel of the tile the triangle covers,
// so the ratio of two rows is the ratio of their costs per pixel; the `invocations` counter
// is fragment-shader lanes run per covered pixel.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "bench/micro/micro_common.h"
#include "raster/contract.h"
#include "raster/geometry/setup.h"
#include "raster/program_instance.h"
#include "raster/tile/coarse_tile.h"
#include "raster/tile/rasterize_tile.h"
#include "shaders_cpp/hdr/bright.h"

namespace {

constexpr int kTile = raster::limits::kTileSize;
const raster::TileBounds kWholeTile{0, 0, kTile - 1, kTile - 1};

// One tile of a post pass: the target, the bright pass bound to hdr's 1024x1024 RGBA16F
// texture, and one set-up triangle with its uv varyings.
struct PostTile {
  raster::Texture color{kTile, kTile, raster::TexelFormat::RGBA16F};
  raster::Framebuffer framebuffer;
  raster::TriangleList triangles;
  raster::PlaneList planes;
  std::vector<raster::DrawRecord> draws{1};
  std::vector<uint32_t> bin{0};
  raster::TileJob job;
  uint64_t coveredPixels = 0;

  PostTile(bool whole, int coarseWidth, int coarseHeight) {
    framebuffer.colors = {&color};
    framebuffer.width = framebuffer.height = kTile;
    shaders::hdr::BrightPass::Uniforms uniforms;
    uniforms.src0.texture = &micro::rgba16fTexture1024();
    uniforms.u_threshold = 0.5f;
    uniforms.u_soft_knee = 0.25f;
    auto shader = std::make_shared<raster::ProgramInstance<shaders::hdr::BrightPass>>(uniforms);
    raster::DrawRecord& draw = draws[0];
    draw.shader = shader;
    draw.samplesTextures = shader->samplesTextures();
    draw.varyingFloats = shader->varyingFloats();
    draw.colorOutputs = shader->colorOutputs();
    draw.lanesIndependent = shader->lanesIndependent();
    draw.samplesAroundPixel = shader->samplesAroundPixel();
    raster::SetupState setup;
    setup.framebufferWidth = setup.framebufferHeight = kTile;
    setup.varyingFloats = draw.varyingFloats;
    // Window positions (x, y, z, 1/w) and uv (a texel of the 1024x1024 texture per pixel).
    const float big = whole ? 3.0f * kTile : float(kTile);
    const float corners[3][2] = {{0, 0}, {big, 0}, {0, big}};
    float v[3][10];
    for (int i = 0; i < 3; ++i) {
      const float x = corners[i][0], y = corners[i][1];
      const float record[10] = {0, 0, 0, 1, x, y, 0.5f, 1, x / 1024.0f, y / 1024.0f};
      std::copy(record, record + 10, v[i]);
    }
    raster::setupTriangle(setup, v[0], v[1], v[2], raster::SetupLists{triangles, planes});
    job.framebuffer = &framebuffer;
    job.triangles = triangles;
    job.varyingPlanes = planes;
    job.draws = draws;
    job.coarseWidth = coarseWidth;
    job.coarseHeight = coarseHeight;
    coveredPixels = whole ? uint64_t(kTile) * kTile : uint64_t(kTile) * kTile / 2;   // the edge: half the tile
  }
};

// state.range(0): 1 for the fullscreen triangle, 0 for the edge; (w, h) the rate, 1x1 full rate.
template <int W, int H>
void tile(benchmark::State& state) {
  PostTile post(state.range(0) != 0, W, H);
  raster::PipelineCounters counters;
  for (auto _ : state) {
    if (W == 1 && H == 1) raster::rasterizeTile<raster::FastLanes>(post.job, kWholeTile, post.bin, counters);
    else raster::rasterizeTileCoarse<raster::FastLanes>(post.job, kWholeTile, post.bin, counters);
    benchmark::DoNotOptimize(post.color.half.data());
  }
  state.counters["invocations"] =
      double(counters.lanesShaded) / double(int64_t(state.iterations()) * int64_t(post.coveredPixels));
  micro::countItems(state, int64_t(post.coveredPixels), "ns_per_pixel");
}

}  // namespace

BENCHMARK(tile<1, 1>)->Name("coarse/full_rate")->ArgName("whole")->Arg(1)->Arg(0);
BENCHMARK(tile<2, 1>)->Name("coarse/2x1")->ArgName("whole")->Arg(1)->Arg(0);
BENCHMARK(tile<2, 2>)->Name("coarse/2x2")->ArgName("whole")->Arg(1)->Arg(0);
BENCHMARK(tile<4, 4>)->Name("coarse/4x4")->ArgName("whole")->Arg(1)->Arg(0);
