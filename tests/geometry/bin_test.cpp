// Binning (geometry/bin.h) against hand-worked expectations: triangles crossing tile corners
// go into exactly the tiles they cover (not into a tile their bounds touch but one edge rejects
// at all four corners of the overlap), a triangle inside one tile into it untested (as
// llvmpipe bins it), a triangle larger than the screen into every tile, tiles
// of a framebuffer whose size is not a multiple of 64 have clipped bounds, banded binning equals
// one pass, and each bin keeps API order. And the Hilbert order of tiles (util/hilbert.h)
// that passes sampling around their pixels are shaded in.
//
// Triangles are given by pixel-centre vertices (window px + 0.5, fixed 256 px) and set up with
// setupTriangle; tile (tx, ty) of an n-wide grid is tile index ty * n + tx.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "raster/geometry/assemble.h"
#include "raster/geometry/bin.h"
#include "raster/util/hilbert.h"
#include "tests/geometry/geometry_test_helpers.h"

namespace {

using namespace geometry_test;
using Bin = std::vector<uint32_t>;

SetupTriangle triangleAt(int width, int height, int x0, int y0, int x1, int y1, int x2, int y2) {
  SetupOutput out;
  REQUIRE(setUp(setupState(width, height), atPixelCentre(x0, y0), atPixelCentre(x1, y1), atPixelCentre(x2, y2), out));
  return out.triangles[0];
}

Bin binOf(const raster::TileBins& bins, int tile) {
  const auto b = bins.bin(tile);
  return Bin(b.begin(), b.end());
}

// Conservative binning must never miss: every pixel a triangle covers lies in a tile whose
// bin holds the triangle.
void checkNoCoveredPixelMissed(const raster::TileBins& bins, std::span<const SetupTriangle> tris, int width, int height) {
  int missed = 0;
  std::string first;
  for (uint32_t t = 0; t < tris.size(); ++t)
    for (const auto& [x, y] : coveredPixels(tris[t], width, height)) {
      const int tile = (y / 64) * bins.tilesX() + x / 64;
      const auto b = bins.bin(tile);
      if (std::find(b.begin(), b.end(), t) == b.end() && missed++ == 0)
        first = "triangle " + std::to_string(t) + " at " + pixelName(x, y);
    }
  INFO("first covered pixel whose tile's bin lacks its triangle: ", first);
  CHECK(missed == 0);
}

}  // namespace

TEST_SUITE("geometry") {
  // A 256 x 256 framebuffer: 4 x 4 tiles; tile 0 = (0,0), 1 = (1,0), 4 = (0,1), 5 = (1,1).
  //  0: (40,40), (88,40), (40,88): hypotenuse px + py = 128, a right edge (exclusive). Bounds
  //     40..87 touch tiles 0, 1, 4, 5; tile 5's overlap 64..87 x 64..87 has its nearest corner
  //     (64,64) exactly on the hypotenuse (edge value 0) and the rest beyond: rejected.
  //  1: (40,40), (89,40), (40,89): px + py < 129, so (64,64) is inside: tiles 0, 1, 4, 5.
  //  2: the sliver (10,10), (120,118), (118,120) along the diagonal, bounds 10..119 (all four
  //     tiles). Edge (10,10)->(120,118), inside where 108 (x - 10) - 110 (y - 10) < 0: tile 1's
  //     overlap 64..119 x 10..63 has corners at 108*54 - 110*53 = 2, 5832, 5942, 11772, all
  //     outside. Edge (10,10)->(118,120), inside where 110 (x - 10) - 108 (y - 10) > 0: tile 4's
  //     overlap 10..63 x 64..119 has (63,64) at 5830 - 5832 = -2 and the others lower. Tiles 0, 5.
  //  3: (70,70), (80,70), (70,80): inside tile 5 only.
  //  4: (63,0), (127,0), (62,127): the left edge is inside where 127 px + py >= 8001, so in tile 0
  //     only column 63 is covered (column 62 needs py >= 127); bounds 62..126 make tile 0's
  //     overlap 62..63 x 0..63, and only its corners at x = 63 are inside: tiles 0, 1, 4, 5.
  TEST_CASE("tile corners: a triangle goes into exactly the tiles its edges reach") {
    const std::vector<SetupTriangle> tris = {
        triangleAt(256, 256, 40, 40, 88, 40, 40, 88),
        triangleAt(256, 256, 40, 40, 89, 40, 40, 89),
        triangleAt(256, 256, 10, 10, 120, 118, 118, 120),
        triangleAt(256, 256, 70, 70, 80, 70, 70, 80),
        triangleAt(256, 256, 63, 0, 127, 0, 62, 127),
    };
    CHECK(tris[0].maxX == 87);   // (88 * 256 - 1) >> 8
    CHECK(tris[2].minX == 10);
    CHECK(tris[2].maxX == 119);
    // The corner pixel of triangle 0 is exactly on its hypotenuse; of triangle 1, inside.
    CHECK(!insideEdges(tris[0], 64, 64));
    CHECK(insideEdges(tris[1], 64, 64));

    raster::TileBins bins;
    bins.reset(256, 256);
    REQUIRE(bins.tileCount() == 16);
    const uint64_t entries = bins.binTriangles(tris, 0, uint32_t(tris.size()));
    CHECK(tris[4].minX == 62);
    int leftmostInTopRow = 256;
    for (const auto& [x, y] : coveredPixels(tris[4], 256, 256))
      if (y < 64) leftmostInTopRow = std::min(leftmostInTopRow, x);
    CHECK(leftmostInTopRow == 63);
    CHECK(insideEdges(tris[4], 63, 63));
    CHECK(entries == 3 + 4 + 2 + 1 + 4);
    CHECK(binOf(bins, 0) == Bin{0, 1, 2, 4});
    CHECK(binOf(bins, 1) == Bin{0, 1, 4});
    CHECK(binOf(bins, 4) == Bin{0, 1, 4});
    CHECK(binOf(bins, 5) == Bin{1, 2, 3, 4});
    for (int tile : {2, 3, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}) CHECK(bins.bin(tile).empty());
    checkNoCoveredPixelMissed(bins, tris, 256, 256);
  }

  TEST_CASE("tiles of a framebuffer whose size is not a multiple of 64 have clipped bounds") {
    raster::TileBins bins;
    bins.reset(200, 150);   // ceil(200 / 64) = 4 columns, ceil(150 / 64) = 3 rows
    CHECK(bins.tilesX() == 4);
    CHECK(bins.tilesY() == 3);
    CHECK(bins.tileCount() == 12);
    auto same = [](raster::TileBounds a, raster::TileBounds b) { return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1; };
    CHECK(same(bins.bounds(0), {0, 0, 63, 63}));
    CHECK(same(bins.bounds(5), {64, 64, 127, 127}));
    CHECK(same(bins.bounds(3), {192, 0, 199, 63}));       // last column: 192 + 64 > 200
    CHECK(same(bins.bounds(8), {0, 128, 63, 149}));       // last row: 128 + 64 > 150
    CHECK(same(bins.bounds(11), {192, 128, 199, 149}));   // the corner tile, 8 x 22 pixels
    // One pixel past a multiple of 64: a second column one pixel wide.
    bins.reset(65, 64);
    CHECK(bins.tileCount() == 2);
    CHECK(same(bins.bounds(1), {64, 0, 64, 63}));
    // A triangle wholly in the 200 x 150 corner tile goes there only.
    bins.reset(200, 150);
    const std::vector<SetupTriangle> tris = {triangleAt(200, 150, 193, 130, 199, 130, 193, 149)};
    CHECK(bins.binTriangles(tris, 0, uint32_t(tris.size())) == 1);
    CHECK(binOf(bins, 11) == Bin{0});
  }

  // llvmpipe bins a triangle whose bounds lie in one tile there without testing its edges
  // (lp_setup_bin_triangle), and so does this pipeline: a sliver between pixel centres,
  // bounds 70..71 x 70..70 in tile 5, covers none and still gets the one entry; the walk
  // then finds no pixel of it.
  TEST_CASE("a triangle whose bounds lie in one tile is binned there, covered pixels or not") {
    SetupOutput out;
    REQUIRE(setUp(setupState(256, 256), windowVertex(70.6f, 70.2f), windowVertex(72.4f, 70.3f), windowVertex(71.5f, 70.45f), out));
    const SetupTriangle& sliver = out.triangles[0];
    REQUIRE(coveredPixels(sliver, 256, 256).empty());
    REQUIRE(sliver.minX / 64 == sliver.maxX / 64);
    REQUIRE(sliver.minY / 64 == sliver.maxY / 64);
    raster::TileBins bins;
    bins.reset(256, 256);
    CHECK(bins.binTriangles(out.triangles, 0, 1) == 1);
    CHECK(binOf(bins, 5) == Bin{0});
  }

  TEST_CASE("a triangle larger than the screen lands in every tile") {
    // Set up directly: window (-100, -100), (1000, -100), (-100, 1000) on 200 x 150, bounds
    // trimmed to 0..199 x 0..149; the hypotenuse x + y = 900 is beyond every tile corner.
    {
      SetupOutput out;
      REQUIRE(setUp(setupState(200, 150), windowVertex(-100, -100), windowVertex(1000, -100), windowVertex(-100, 1000), out));
      CHECK(out.triangles[0].maxX == 199);
      CHECK(out.triangles[0].maxY == 149);
      raster::TileBins bins;
      bins.reset(200, 150);
      CHECK(bins.binTriangles(out.triangles, 0, uint32_t(out.triangles.size())) == 12);
      for (int tile = 0; tile < 12; ++tile) CHECK(binOf(bins, tile) == Bin{0});
    }
    // Through clipping: clip (-1, -1), (7, -1), (-1, 7) covers the whole viewport (x + y = 6 is
    // beyond the corner (1, 1)); it becomes the square (-1,-1), (1,-1), (1,1), (-1,1), a fan of
    // two that covers every pixel of 200 x 150 once and reaches every tile.
    {
      const raster::ViewportTransform vp = fboViewport(200, 150);
      const raster::ShadedVertices s = shadeByHand({{{-1, -1, 0, 1}, {}}, {{7, -1, 0, 1}, {}}, {{-1, 7, 0, 1}, {}}}, 0, vp);
      const raster::SetupState state = setupState(200, 150);
      const std::vector<uint32_t> indices{0, 1, 2};
      SetupOutput out;
      raster::PipelineCounters counters;
      raster::assemblePrimitives(raster::AssemblyInput{state, s, indices, 3, vp}, 0, 1, out.lists(), counters);
      CHECK(counters.trianglesClipped == 1);
      REQUIRE(out.triangles.size() == 2);
      Coverage c(200, 150);
      for (const SetupTriangle& t : out.triangles) c.add(t);
      CHECK(c.pixels().size() == 200 * 150);
      checkCoverage(c, [](int, int) { return 1; });
      raster::TileBins bins;
      bins.reset(200, 150);
      bins.binTriangles(out.triangles, 0, uint32_t(out.triangles.size()));
      for (int tile = 0; tile < 12; ++tile) CHECK(!bins.bin(tile).empty());
      checkNoCoveredPixelMissed(bins, out.triangles, 200, 150);
    }
  }

  TEST_CASE("binning in parts of the triangle list, appended in order, gives the bins of one pass") {
    // 40 triangles scattered over a 300 x 200 framebuffer (5 x 4 tiles), from a fixed LCG.
    std::vector<SetupTriangle> tris;
    uint32_t state = 12345;
    auto next = [&](int n) {
      state = state * 1664525u + 1013904223u;
      return int((state >> 8) % uint32_t(n));
    };
    while (tris.size() < 40) {
      const int x = next(300), y = next(200), w = 1 + next(150), h = 1 + next(150);
      SetupOutput out;
      if (setUp(setupState(300, 200), atPixelCentre(x, y), atPixelCentre(x + w, y + next(20)), atPixelCentre(x + next(30), y + h), out))
        tris.push_back(out.triangles[0]);
    }
    raster::TileBins whole;
    whole.reset(300, 200);
    const uint64_t n = whole.binTriangles(tris, 0, 40);
    CHECK(n > 40);   // triangles up to 150 pixels wide span several tiles
    // Parts [0, 7), [7, 25), [25, 40), the first binned straight into the result, the
    // others into their own bins (binned last to first) and appended in order.
    raster::TileBins parts, second, third;
    parts.reset(300, 200);
    second.reset(300, 200);
    third.reset(300, 200);
    const uint64_t p = third.binTriangles(tris, 25, 40) + second.binTriangles(tris, 7, 25) + parts.binTriangles(tris, 0, 7);
    parts.append(second);
    parts.append(third);
    CHECK(p == n);
    for (int tile = 0; tile < whole.tileCount(); ++tile) {
      CAPTURE(tile);
      CHECK(binOf(parts, tile) == binOf(whole, tile));
    }
    // A part holds only its own triangles, by their indices in the whole list.
    for (int tile = 0; tile < second.tileCount(); ++tile)
      for (uint32_t t : second.bin(tile)) CHECK((t >= 7 && t < 25));
    checkNoCoveredPixelMissed(whole, tris, 300, 200);
  }

  TEST_CASE("bins keep API order across draws; binTriangles from `first` appends only the new triangles") {
    // A 128 x 64 framebuffer: tiles 0 (x 0..63) and 1 (x 64..127).
    //   0: in tile 0;  1: in tile 1;  2: across both;  then a second draw:  3: across both;  4: in tile 0.
    std::vector<SetupTriangle> tris = {
        triangleAt(128, 64, 10, 10, 30, 10, 10, 30),
        triangleAt(128, 64, 80, 10, 100, 10, 80, 30),
        triangleAt(128, 64, 50, 20, 90, 20, 50, 40),
    };
    raster::TileBins bins;
    bins.reset(128, 64);
    CHECK(bins.binTriangles(tris, 0, 3) == 4);
    tris.push_back(triangleAt(128, 64, 40, 40, 100, 40, 40, 60));
    tris.push_back(triangleAt(128, 64, 5, 50, 20, 50, 5, 60));
    CHECK(bins.binTriangles(tris, 3, 5) == 3);   // triangles 3 and 4 only, by their pass-wide indices
    CHECK(binOf(bins, 0) == Bin{0, 2, 3, 4});
    CHECK(binOf(bins, 1) == Bin{1, 2, 3});

    // clear() empties every bin and keeps the tiles; reset() to the same size does too.
    bins.clear();
    CHECK(bins.tileCount() == 2);
    CHECK(bins.bin(0).empty());
    CHECK(bins.bin(1).empty());
    bins.binTriangles(tris, 0, 5);
    bins.reset(128, 64);
    CHECK(bins.bin(0).empty());
    CHECK(bins.bin(1).empty());
    bins.reset(64, 192);
    CHECK(bins.tilesX() == 1);
    CHECK(bins.tilesY() == 3);
    for (int tile = 0; tile < 3; ++tile) CHECK(bins.bin(tile).empty());
  }

  // What Renderer::orderAlongHilbertCurve relies on: every tile of the grid gets its own
  // index (so the order is total, the same every run), and the tile after each is beside
  // it, so tiles shaded one after another share their surroundings.
  TEST_CASE("Hilbert order: every cell of the grid once, each beside the one before") {
    CHECK(raster::hilbertSide(1) == 1);
    CHECK(raster::hilbertSide(10) == 16);
    CHECK(raster::hilbertSide(16) == 16);
    CHECK(raster::hilbertSide(30) == 32);
    for (uint32_t side : {1u, 2u, 4u, 8u, 32u}) {
      CAPTURE(side);
      std::vector<std::pair<uint32_t, uint32_t>> cellAt(size_t(side) * side, {~0u, ~0u});
      for (uint32_t y = 0; y < side; ++y)
        for (uint32_t x = 0; x < side; ++x) {
          const uint64_t index = raster::hilbertIndex(x, y, side);
          REQUIRE(index < cellAt.size());
          REQUIRE(cellAt[index].first == ~0u);   // no index given twice
          cellAt[index] = {x, y};
        }
      CHECK(cellAt.front() == std::pair(0u, 0u));
      CHECK(cellAt.back() == std::pair(side - 1, 0u));
      for (size_t i = 1; i < cellAt.size(); ++i) {
        const auto [x0, y0] = cellAt[i - 1];
        const auto [x1, y1] = cellAt[i];
        const uint32_t step = (x0 > x1 ? x0 - x1 : x1 - x0) + (y0 > y1 ? y0 - y1 : y1 - y0);
        CAPTURE(i);
        CHECK(step == 1);
      }
    }
  }
}
