// Triangle setup (raster/geometry/setup.h): snapping, the fill rule, orientation and
// culling, bounds, planes and polygon offset, each against values worked out by hand from
// the rules in setup.h's header comment.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "raster/geometry/setup.h"
#include "tests/geometry/geometry_test_helpers.h"

namespace {

using geometry_test::covers;
using geometry_test::windowVertex;

struct SetUp {
  std::vector<raster::SetupTriangle> triangles;
  std::vector<raster::Plane> planes;
  bool add(const raster::SetupState& state, const geometry_test::Vertex& a, const geometry_test::Vertex& b,
           const geometry_test::Vertex& c) {
    return raster::setupTriangle(state, a.get(), b.get(), c.get(), {triangles, planes});
  }
};

raster::SetupState stateFor(int width, int height, bool bottomEdgeRule = false) {
  raster::SetupState s;
  s.framebufferWidth = width;
  s.framebufferHeight = height;
  s.bottomEdgeRule = bottomEdgeRule;
  return s;
}

}  // namespace

TEST_SUITE("geometry") {
  // The square (0.5, 0.5)-(4.5, 4.5) has its edges and its diagonal on pixel centres. Worked
  // out from the edge functions: under top-left (FBOs) the left column px = 0 and the first
  // row py = 0 are in, px = 4 and py = 4 out, and the diagonal goes to the first triangle
  // (its edge a->c has dcdx < 0: a left edge, biased in); under bottom-left (window
  // buffers, rows stored top first) rows 1..4 are in instead. Either way each of the 16
  // centres is covered exactly once. Catches a fill rule applied to the wrong side, or to
  // neither (a crack) or both (a double hit) of a shared edge.
  TEST_CASE("setup: the fill rule covers every pixel centre on shared and outer edges exactly once") {
    for (bool bottom : {false, true}) {
      INFO((bottom ? "bottom-left rule" : "top-left rule"));
      const auto a = windowVertex(0.5f, 0.5f), b = windowVertex(4.5f, 0.5f), c = windowVertex(4.5f, 4.5f),
                 d = windowVertex(0.5f, 4.5f);
      SetUp set;
      REQUIRE(set.add(stateFor(16, 16, bottom), a, b, c));
      REQUIRE(set.add(stateFor(16, 16, bottom), a, c, d));
      const int firstRow = bottom ? 1 : 0;
      for (int py = 0; py < 8; ++py) {
        for (int px = 0; px < 8; ++px) {
          const int hits = int(covers(set.triangles[0], px, py)) + int(covers(set.triangles[1], px, py));
          const bool inside = px >= 0 && px <= 3 && py >= firstRow && py <= firstRow + 3;
          INFO("pixel " << px << "," << py);
          CHECK(hits == (inside ? 1 : 0));
        }
      }
      // The diagonal's centres (top-left: px = py) belong to the first triangle.
      if (!bottom)
        for (int i = 0; i < 4; ++i) CHECK(covers(set.triangles[0], i, i));
    }
  }

  // A vertical left edge at x = 2.5 + k/512: (x - 0.5) * 256 = 512 + k/2, rounded to nearest
  // even: k = 1 -> 512 (on pixel 2's centre: covered, left edges are inclusive); k = 2 -> 513
  // and k = 3 -> 514 (right of it: not covered); k = -1 -> 511.5 -> 512 (covered). Catches
  // truncation (k = -1 would give 511, still covered, but k = 1 gives 512 either way) and
  // rounding half up (k = 1 would give 513: not covered).
  TEST_CASE("setup: vertices snap to 8 sub-pixel bits, rounding to nearest even") {
    const struct { float k; bool covered; } cases[] = {{1, true}, {2, false}, {3, false}, {-1, true}, {0, true}};
    for (const auto& c : cases) {
      const float x = 2.5f + c.k / 512.0f;
      SetUp set;
      REQUIRE(set.add(stateFor(16, 16), windowVertex(x, 0.5f), windowVertex(8.5f, 0.5f), windowVertex(x, 8.5f)));
      INFO("left edge at x = 2.5 + " << c.k << "/512");
      CHECK(covers(set.triangles[0], 2, 3) == c.covered);
      CHECK(covers(set.triangles[0], 3, 3));
    }
    // Moving a vertex by less than half a sub-pixel leaves every edge function unchanged.
    SetUp a, b;
    REQUIRE(a.add(stateFor(16, 16), windowVertex(1.25f, 1.0f), windowVertex(9.0f, 2.0f), windowVertex(3.0f, 7.5f)));
    REQUIRE(b.add(stateFor(16, 16), windowVertex(1.25f + 1.0f / 1024, 1.0f), windowVertex(9.0f, 2.0f - 1.0f / 1024),
                  windowVertex(3.0f, 7.5f)));
    for (int i = 0; i < 3; ++i) {
      CHECK(a.triangles[0].edge[i].c == b.triangles[0].edge[i].c);
      CHECK(a.triangles[0].edge[i].dcdx == b.triangles[0].edge[i].dcdx);
      CHECK(a.triangles[0].edge[i].dcdy == b.triangles[0].edge[i].dcdy);
    }
  }

  // Bounds from the snapped vertices: min >> 8 and (max - 1) >> 8, so a vertex exactly on a
  // pixel centre bounds inclusively on the left and exclusively on the right; trimmed to
  // the framebuffer.
  TEST_CASE("setup: pixel bounds, and trimming to the framebuffer") {
    SetUp set;
    // x: 2.5 -> 512, 9.5 -> 2304 (2303 >> 8 = 8); y: 1.5 -> 256, 6.5 -> 1536 (1535 >> 8 = 5).
    REQUIRE(set.add(stateFor(32, 32), windowVertex(2.5f, 1.5f), windowVertex(9.5f, 1.5f), windowVertex(2.5f, 6.5f)));
    CHECK(set.triangles[0].minX == 2);
    CHECK(set.triangles[0].maxX == 8);
    CHECK(set.triangles[0].minY == 1);
    CHECK(set.triangles[0].maxY == 5);
    // Far larger than a 20x10 framebuffer: bounds are the framebuffer.
    REQUIRE(set.add(stateFor(20, 10), windowVertex(-1000, -1000), windowVertex(5000, -1000), windowVertex(-1000, 5000)));
    CHECK(set.triangles[1].minX == 0);
    CHECK(set.triangles[1].minY == 0);
    CHECK(set.triangles[1].maxX == 19);
    CHECK(set.triangles[1].maxY == 9);
    // Wholly outside: nothing to rasterize, not set up.
    CHECK_FALSE(set.add(stateFor(20, 10), windowVertex(30, 1), windowVertex(40, 1), windowVertex(30, 8)));
    CHECK(set.triangles.size() == 2);
  }

  TEST_CASE("setup: degenerate triangles are dropped") {
    SetUp set;
    // Collinear.
    CHECK_FALSE(set.add(stateFor(16, 16), windowVertex(0.5f, 0.5f), windowVertex(2.5f, 2.5f), windowVertex(4.5f, 4.5f)));
    // Three different points that snap to the same one ((1 - 0.5) * 256 = 128, 128.25 -> 128).
    CHECK_FALSE(set.add(stateFor(16, 16), windowVertex(1.0f, 1.0f), windowVertex(1.0f + 1.0f / 1024, 1.0f),
                        windowVertex(1.0f, 1.0f + 1.0f / 1024)));
    // Zero width after snapping although the float area is not zero.
    CHECK_FALSE(set.add(stateFor(16, 16), windowVertex(3.0f, 1.0f), windowVertex(3.0f + 1.0f / 1024, 9.0f),
                        windowVertex(3.0f, 9.0f)));
    CHECK(set.triangles.empty());
    CHECK(set.planes.empty());
  }

  // Found by the geometry fuzz target: a NaN window position (which passes the clip tests,
  // whose compares are ordered) snapped to INT_MIN and overflowed setup's int arithmetic.
  TEST_CASE("setup: a NaN or far-out window coordinate drops the triangle") {
    SetUp set;
    const float nan = std::nanf("");
    CHECK_FALSE(set.add(stateFor(16, 16), windowVertex(nan, 0.5f), windowVertex(4.5f, 0.5f), windowVertex(4.5f, 4.5f)));
    CHECK_FALSE(set.add(stateFor(16, 16), windowVertex(0.5f, 0.5f), windowVertex(4.5f, INFINITY), windowVertex(4.5f, 4.5f)));
    CHECK_FALSE(set.add(stateFor(16, 16), windowVertex(0.5f, 0.5f), windowVertex(1e30f, 0.5f), windowVertex(4.5f, 4.5f)));
    CHECK(set.add(stateFor(16, 16), windowVertex(0.5f, 0.5f), windowVertex(2.0e6f, 0.5f), windowVertex(4.5f, 4.5f)));
    CHECK(set.triangles.size() == 1);
  }

  // In memory rows (y down), (a, b, c) = (0.5,0.5), (4.5,0.5), (4.5,4.5) has area
  // dx01 * dy20 - dx20 * dy01 = -1024 * 1024 < 0: counter-clockwise in GL's y-up terms for
  // an FBO, so front-facing; on a window buffer (rows flipped) the same order is clockwise.
  TEST_CASE("setup: orientation, back-face culling and the window buffer's flip") {
    const auto a = windowVertex(0.5f, 0.5f), b = windowVertex(4.5f, 0.5f), c = windowVertex(4.5f, 4.5f);
    raster::SetupState state = stateFor(16, 16);
    SetUp set;
    REQUIRE(set.add(state, a, b, c));
    CHECK(set.triangles[0].frontFacing);
    REQUIRE(set.add(state, a, c, b));   // reversed: back-facing, kept without culling
    CHECK_FALSE(set.triangles[1].frontFacing);
    state.cullBack = true;
    CHECK(set.add(state, a, b, c));
    CHECK_FALSE(set.add(state, a, c, b));
    raster::SetupState flipped = stateFor(16, 16, /*bottomEdgeRule=*/true);
    flipped.cullBack = true;
    CHECK_FALSE(set.add(flipped, a, b, c));
    CHECK(set.add(flipped, a, c, b));
    CHECK(set.triangles.back().frontFacing);
    // Either orientation covers the same pixels.
    SetUp ccw, cw;
    REQUIRE(ccw.add(stateFor(16, 16), a, b, c));
    REQUIRE(cw.add(stateFor(16, 16), a, c, b));
    for (int py = 0; py < 6; ++py)
      for (int px = 0; px < 6; ++px) CHECK(covers(ccw.triangles[0], px, py) == covers(cw.triangles[0], px, py));
  }

  // z = 1 at (4.5, 0.5) and 0 at (0.5, 0.5) and (0.5, 4.5): the plane is z = (x - 0.5) / 4,
  // i.e. a0 = 0 at pixel (0, 0)'s centre, dz/dx = 0.25, dz/dy = 0 (every step exact in float:
  // 1/area = 1/16, the differences are 4 and 0).
  TEST_CASE("setup: planes, and polygon offset") {
    raster::SetupState state = stateFor(16, 16);
    state.varyingFloats = 1;
    SetUp set;
    REQUIRE(set.add(state, windowVertex(0.5f, 0.5f, 0.0f, 1.0f, {2.0f}), windowVertex(4.5f, 0.5f, 1.0f, 1.0f, {6.0f}),
                    windowVertex(0.5f, 4.5f, 0.0f, 1.0f, {2.0f})));
    const raster::SetupTriangle& tri = set.triangles[0];
    CHECK(tri.z.a0 == 0.0f);
    CHECK(tri.z.dadx == 0.25f);
    CHECK(tri.z.dady == 0.0f);
    CHECK(tri.w.a0 == 1.0f);
    CHECK(tri.w.dadx == 0.0f);
    // The varying (times 1/w = 1): 2 + x - 0.5 at centres, so a0 = 2, dadx = 1.
    REQUIRE(set.planes.size() == 1);
    CHECK(set.planes[tri.varyingBase].a0 == 2.0f);
    CHECK(set.planes[tri.varyingBase].dadx == 1.0f);
    CHECK(tri.depthOffset == 0.0f);

    // Polygon offset: units * 2 / (2^bits - 1) computed in double, plus the larger slope
    // (0.25 here) times the factor.
    CHECK(raster::polygonOffsetUnits(1.0f, 24) == float(2.0 / 16777215.0));
    CHECK(raster::polygonOffsetUnits(1.0f, 16) == float(2.0 / 65535.0));
    state.varyingFloats = 0;   // the vertices below carry none
    state.polygonOffset = true;
    state.offsetFactor = 2.0f;
    state.offsetUnitsScaled = raster::polygonOffsetUnits(4.0f, 24);
    REQUIRE(set.add(state, windowVertex(0.5f, 0.5f, 0.0f), windowVertex(4.5f, 0.5f, 1.0f), windowVertex(0.5f, 4.5f, 0.0f)));
    CHECK(set.triangles[1].depthOffset == float(8.0 / 16777215.0) + 0.5f);
  }
}
