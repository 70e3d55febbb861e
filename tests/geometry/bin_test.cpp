// Binning (raster/geometry/bin.h): which tiles a triangle lands in, tile bounds at the
// framebuffer's edges, API order, and bands of tile rows binned apart giving the same bins.
#include <doctest/doctest.h>

#include <random>
#include <vector>

#include "raster/geometry/bin.h"
#include "raster/geometry/setup.h"
#include "tests/geometry/geometry_test_helpers.h"

namespace {

using geometry_test::windowVertex;

std::vector<raster::SetupTriangle> setUp(int width, int height, const std::vector<std::array<float, 6>>& corners) {
  std::vector<raster::SetupTriangle> triangles;
  std::vector<raster::Plane> planes;
  raster::SetupState state;
  state.framebufferWidth = width;
  state.framebufferHeight = height;
  for (const auto& c : corners)
    raster::setupTriangle(state, windowVertex(c[0], c[1]).get(), windowVertex(c[2], c[3]).get(),
                          windowVertex(c[4], c[5]).get(), {triangles, planes});
  return triangles;
}

std::vector<int> tilesHolding(const raster::TileBins& bins, uint32_t triangle) {
  std::vector<int> tiles;
  for (int t = 0; t < bins.tileCount(); ++t)
    for (uint32_t index : bins.bin(t))
      if (index == triangle) tiles.push_back(t);
  return tiles;
}

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("bin: tiles of 64 pixels, clipped at the framebuffer's right and top edges") {
    raster::TileBins bins;
    bins.reset(130, 70);
    CHECK(bins.tilesX() == 3);
    CHECK(bins.tilesY() == 2);
    const raster::TileBounds last = bins.bounds(5);
    CHECK(last.x0 == 128);
    CHECK(last.x1 == 129);
    CHECK(last.y0 == 64);
    CHECK(last.y1 == 69);
    const raster::TileBounds first = bins.bounds(0);
    CHECK((first.x0 == 0 && first.y0 == 0 && first.x1 == 63 && first.y1 == 63));
  }

  // The right triangle (10.5,10.5), (100.5,10.5), (10.5,100.5) has pixel bounds 10..99 on
  // both axes, touching tiles (0,0), (1,0), (0,1), (1,1). Its hypotenuse is x + y = 111 at
  // pixel centres; tile (1,1)'s overlap with the bounds starts at pixel (64,64), whose centre
  // sums to 129 > 111: all four corners outside that edge, so the tile gets nothing. Tile
  // (1,0)'s corner (64,10) sums to 75: binned.
  TEST_CASE("bin: a triangle crossing tile corners lands only in the tiles it can cover") {
    const auto triangles = setUp(192, 192, {{10.5f, 10.5f, 100.5f, 10.5f, 10.5f, 100.5f}});
    REQUIRE(triangles.size() == 1);
    raster::TileBins bins;
    bins.reset(192, 192);
    CHECK(bins.binRows(triangles, 0, 0, bins.tilesY() - 1) == 3);
    CHECK(tilesHolding(bins, 0) == std::vector<int>{0, 1, 3});
  }

  TEST_CASE("bin: a triangle larger than the screen lands in every tile") {
    const auto triangles = setUp(200, 150, {{-1000, -1000, 5000, -1000, -1000, 5000}});
    REQUIRE(triangles.size() == 1);
    raster::TileBins bins;
    bins.reset(200, 150);
    CHECK(bins.binRows(triangles, 0, 0, bins.tilesY() - 1) == uint64_t(bins.tileCount()));
    CHECK(int(tilesHolding(bins, 0).size()) == bins.tileCount());
  }

  // Many random triangles: every bin lists its triangles in increasing (API) order, and
  // binning two bands of tile rows apart fills the same bins as one call (the renderer bins
  // bands in parallel).
  TEST_CASE("bin: API order in every bin, and bands binned apart give the same bins") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coord(-40.0f, 300.0f);
    std::vector<std::array<float, 6>> corners(300);
    for (auto& c : corners)
      for (float& v : c) v = coord(rng);
    const auto triangles = setUp(257, 193, corners);
    REQUIRE(triangles.size() > 100);
    raster::TileBins whole, banded;
    whole.reset(257, 193);
    banded.reset(257, 193);
    const uint64_t entries = whole.binRows(triangles, 0, 0, whole.tilesY() - 1);
    const uint64_t bandEntries = banded.binRows(triangles, 0, 0, 1) + banded.binRows(triangles, 0, 2, banded.tilesY() - 1);
    CHECK(entries == bandEntries);
    for (int t = 0; t < whole.tileCount(); ++t) {
      const auto a = whole.bin(t), b = banded.bin(t);
      CHECK(std::vector<uint32_t>(a.begin(), a.end()) == std::vector<uint32_t>(b.begin(), b.end()));
      for (size_t i = 1; i < a.size(); ++i) CHECK(a[i - 1] < a[i]);
    }
    // Appending later triangles (a later draw) keeps earlier entries first.
    raster::TileBins twice;
    twice.reset(257, 193);
    twice.binRows(triangles, 0, 0, twice.tilesY() - 1);
    twice.clear();
    twice.binRows(std::span(triangles).first(50), 0, 0, twice.tilesY() - 1);
    twice.binRows(triangles, 50, 0, twice.tilesY() - 1);
    for (int t = 0; t < whole.tileCount(); ++t) {
      const auto a = whole.bin(t), b = twice.bin(t);
      CHECK(std::vector<uint32_t>(a.begin(), a.end()) == std::vector<uint32_t>(b.begin(), b.end()));
    }
  }
}
