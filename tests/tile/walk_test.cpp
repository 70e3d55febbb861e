// The tile walk (tile/walk.h) visits exactly the pixels whose centres are inside all three
// edge functions, block by block in row-major order, for triangles of a fraction of a pixel
// to thousands of pixels: at block, region, tile and framebuffer edges, with both lane types'
// edge forms. The AVX-512 walk takes small triangles without the region level and large ones
// with it (walkSmallTriangleBlocks), so both are held to the same blocks. Bands of 16 rows
// of a tile, which small passes are walked in, are held to their own blocks too.
#include <doctest/doctest.h>

#include <cmath>
#include <iterator>
#include <random>
#include <vector>

#include "raster/geometry/setup.h"
#include "raster/tile/walk.h"

namespace {

struct VisitedBlock {
  int x, y;
  uint32_t coverage;
  bool operator==(const VisitedBlock&) const = default;
};

// The blocks a walk must visit: every 4x4 block of the tile (row-major) with a pixel centre
// inside all three edges, inside the triangle's bounds and the framebuffer.
std::vector<VisitedBlock> bruteForce(const raster::SetupTriangle& tri, const raster::TileBounds& tile, int width, int height) {
  std::vector<VisitedBlock> blocks;
  for (int by = tile.y0; by <= tile.y1; by += 4) {
    for (int bx = tile.x0; bx <= tile.x1; bx += 4) {
      uint32_t mask = 0;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
          const int x = bx + c, y = by + r;
          if (x >= width || y >= height || x < tri.minX || x > tri.maxX || y < tri.minY || y > tri.maxY) continue;
          bool inside = true;
          for (const raster::EdgeFunction& e : tri.edge) inside &= e.at(x, y) > 0;
          if (inside) mask |= 1u << (r * 4 + c);
        }
      if (mask) blocks.push_back({bx, by, mask});
    }
  }
  return blocks;
}

template <class F>
std::vector<VisitedBlock> walked(const raster::TileJob& job, const raster::SetupTriangle& tri, const raster::TileBounds& tile) {
  std::vector<VisitedBlock> blocks;
  raster::walkTriangleBlocks<F>(job, tri, tile, [&](int x, int y, uint32_t coverage) { blocks.push_back({x, y, coverage}); });
  return blocks;
}

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("the tile walk visits exactly the covered pixels, small triangles and large, at every kind of edge") {
    constexpr int kWidth = 150, kHeight = 133;   // partial tiles at the right and top
    raster::Framebuffer fb;
    fb.width = kWidth;
    fb.height = kHeight;
    std::vector<raster::DrawRecord> draws(1);
    draws[0].colorOutputs = 1;
    raster::Texture color(kWidth, kHeight, raster::TexelFormat::RGBA8);
    fb.colors = {&color};
    raster::SetupState setup;
    setup.framebufferWidth = kWidth;
    setup.framebufferHeight = kHeight;
    raster::TriangleList triangles;
    raster::PlaneList planes;
    std::mt19937 rng(26);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    // Legs from a fraction of a pixel to thousands of pixels, centred near block, region and
    // tile corners (multiples of 4, 16, 64) and the framebuffer's edges.
    const float sizes[] = {0.7f, 1.5f, 3.0f, 5.0f, 9.0f, 14.0f, 40.0f, 150.0f, 4000.0f};
    constexpr int kSizes = int(std::size(sizes));
    for (int i = 0; i < 7000; ++i) {
      const float size = sizes[i % kSizes];
      const int grid = (i / kSizes) % 4 == 0 ? 4 : (i / kSizes) % 4 == 1 ? 16 : (i / kSizes) % 4 == 2 ? 64 : 1;
      float cx = float(grid * int(unit(rng) * float(kWidth / grid + 1))) + (unit(rng) - 0.5f) * 4.0f;
      float cy = float(grid * int(unit(rng) * float(kHeight / grid + 1))) + (unit(rng) - 0.5f) * 4.0f;
      if (grid == 1) { cx = unit(rng) < 0.5f ? float(kWidth) - unit(rng) * 3.0f : unit(rng) * 3.0f; cy = unit(rng) * kHeight; }
      // Every third triangle has its corners on pixel centres, so its edges run through
      // pixel centres and the fill rule decides them.
      const bool onCentres = i % 3 == 0;
      auto corner = [&](float at) { return onCentres ? std::floor(at) + 0.5f : at; };
      float v[3][8];
      for (auto& p : v) {
        const float vertex[8] = {0, 0, 0, 1, corner(cx + (unit(rng) - 0.5f) * size), corner(cy + (unit(rng) - 0.5f) * size), 0.5f, 1};
        std::copy(vertex, vertex + 8, p);
      }
      raster::setupTriangle(setup, v[0], v[1], v[2], raster::SetupLists{triangles, planes});
    }
    REQUIRE(triangles.size() > 3000);
    raster::TileJob job;
    job.framebuffer = &fb;
    job.triangles = triangles;
    job.varyingPlanes = planes;
    job.draws = draws;
    int visits = 0;
    for (const raster::SetupTriangle& tri : triangles) {
      for (int ty = 0; ty < kHeight; ty += 64) {
        for (int tx = 0; tx < kWidth; tx += 64) {
          const raster::TileBounds tile{tx, ty, std::min(tx + 63, kWidth - 1), std::min(ty + 63, kHeight - 1)};
          if (tri.maxX < tile.x0 || tri.minX > tile.x1 || tri.maxY < tile.y0 || tri.minY > tile.y1) continue;
          const std::vector<VisitedBlock> expected = bruteForce(tri, tile, kWidth, kHeight);
          visits += int(expected.size());
          INFO("triangle bounds " << tri.minX << ".." << tri.maxX << " x " << tri.minY << ".." << tri.maxY << ", tile " << tx << "," << ty);
          CHECK(walked<raster::FastLanes>(job, tri, tile) == expected);
          CHECK(walked<raster::ScalarLanes>(job, tri, tile) == expected);
          // A pass of few tiles is walked in 16-row bands of a tile (renderer.cpp), each with
          // the tile's whole bin: a band must get only its own blocks, also from a triangle
          // that lies wholly beside it (another thread owns the next band).
          for (int y = tile.y0; y <= tile.y1; y += 16) {
            const raster::TileBounds band{tile.x0, y, tile.x1, std::min(y + 15, tile.y1)};
            INFO("band rows " << band.y0 << ".." << band.y1);
            const std::vector<VisitedBlock> inBand = bruteForce(tri, band, kWidth, kHeight);
            CHECK(walked<raster::FastLanes>(job, tri, band) == inBand);
            CHECK(walked<raster::ScalarLanes>(job, tri, band) == inBand);
          }
        }
      }
    }
    CHECK(visits > 10000);
  }
}
