// The tile walk of small triangles (raster/tile/walk.h), as hdr's many instances reach it:
// 256 triangles of a few pixels each (right triangles, legs of 2, 4 or 8 pixels, at random
// sub-pixel places and orientations) in one 64x64 tile, set up by geometry/setup.h.
//   walk        walkTriangle<FastLanes>: regions, blocks, coverage, lane groups
//   walk_depth  depthTestBin<FastLanes>: the same walk with each group's early depth test
//               and write (LEQUAL on a Depth16 buffer, a colour-writing draw, as hdr's
//               scene pass), which is what rasterizeTile runs before shading
// One item is one triangle.
#include <benchmark/benchmark.h>

#include <vector>

#include "bench/micro/micro_common.h"
#include "raster/contract.h"
#include "raster/geometry/setup.h"
#include "raster/tile/walk.h"

namespace {

constexpr int kTile = raster::limits::kTileSize;
constexpr int kTriangles = 256;

// A tile's worth of set-up small triangles, with the framebuffer and draw they belong to.
struct SmallTriangles {
  raster::Texture color{kTile, kTile, raster::TexelFormat::RGBA16F};
  raster::Texture depth{kTile, kTile, raster::TexelFormat::Depth16};
  raster::Framebuffer framebuffer;
  raster::TriangleList triangles;
  raster::PlaneList planes;
  std::vector<raster::DrawRecord> draws{1};
  std::vector<uint32_t> bin;
  raster::TileJob job;

  explicit SmallTriangles(float leg) {
    framebuffer.colors = {&color};
    framebuffer.depth = &depth;
    framebuffer.width = framebuffer.height = kTile;
    draws[0].state.depthFunc = raster::DepthFunc::Lequal;
    draws[0].colorOutputs = 1;
    raster::SetupState setup;
    setup.framebufferWidth = setup.framebufferHeight = kTile;
    micro::Random random(5);
    while (int(triangles.size()) < kTriangles) {
      // Vertex records: clip position, then window position (x, y, z, 1/w); no varyings.
      const float x = 1.0f + random.unit() * (kTile - 2.0f - leg), y = 1.0f + random.unit() * (kTile - 2.0f - leg);
      const float z = 0.2f + 0.6f * random.unit();
      const float sx = random.unit() < 0.5f ? leg : -leg, sy = random.unit() < 0.5f ? leg : -leg;
      const float ox = sx < 0 ? leg : 0.0f, oy = sy < 0 ? leg : 0.0f;
      const float v[3][8] = {{0, 0, 0, 1, x + ox, y + oy, z, 1},
                             {0, 0, 0, 1, x + ox + sx, y + oy, z, 1},
                             {0, 0, 0, 1, x + ox, y + oy + sy, z, 1}};
      raster::setupTriangle(setup, v[0], v[1], v[2], raster::SetupLists{triangles, planes});
    }
    for (uint32_t i = 0; i < uint32_t(triangles.size()); ++i) bin.push_back(i);
    job.framebuffer = &framebuffer;
    job.triangles = triangles;
    job.varyingPlanes = planes;
    job.draws = draws;
  }
};

const raster::TileBounds kWholeTile{0, 0, kTile - 1, kTile - 1};

void walk(benchmark::State& state) {
  const SmallTriangles scene(float(state.range(0)));
  const raster::LaneLayout<raster::FastLanes> layout(false, kTile);
  uint64_t groups = 0;
  for (auto _ : state) {
    for (const raster::SetupTriangle& tri : scene.triangles)
      raster::walkTriangle<raster::FastLanes>(scene.job, tri, layout, kWholeTile,
                                              [&](raster::GroupAt at) { groups += at.laneMask != 0; });
    benchmark::DoNotOptimize(groups);
  }
  state.counters["groups_per_triangle"] = double(groups) / double(int64_t(state.iterations()) * kTriangles);
  micro::countItems(state, kTriangles, "ns_per_triangle");
}

void walkDepth(benchmark::State& state) {
  SmallTriangles scene(float(state.range(0)));
  const raster::LaneLayout<raster::FastLanes> layout(false, kTile);
  uint64_t passed = 0;
  for (auto _ : state) {
    raster::depthTestBin<raster::FastLanes>(scene.job, kWholeTile, scene.bin, layout,
                                            [&](uint32_t, const raster::SetupTriangle&, raster::GroupAt at,
                                                raster::FastLanes) { passed += at.laneMask != 0; });
    benchmark::DoNotOptimize(passed);
  }
  micro::countItems(state, kTriangles, "ns_per_triangle");
}

}  // namespace

BENCHMARK(walk)->Name("tile_walk/walk")->ArgName("leg_px")->Arg(2)->Arg(4)->Arg(8);
BENCHMARK(walkDepth)->Name("tile_walk/walk_depth")->ArgName("leg_px")->Arg(2)->Arg(4)->Arg(8);
