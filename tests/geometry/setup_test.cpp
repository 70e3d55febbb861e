// Triangle setup (geometry/setup.h) against hand-worked expectations: the fill rule on shared
// edges through pixel centres (top-left for FBOs, bottom-left for window-system buffers),
// snapping to 8 sub-pixel bits (round half to even of (v - 0.5) * 256), exact pixel bounds,
// degenerate and back-facing triangles, the z / 1/w / varying planes, and polygon offset.
//
// Notation in the comments: "pixel (px, py)" is a pixel centre, window (px + 0.5, py + 0.5),
// fixed (256 px, 256 py). After setup orients a triangle (area > 0), edge i runs v[i] -> v[i+1]
// and at(px, py) = c - dcdx * px + dcdy * py with dcdx = (y_i - y_j) << 8, dcdy = (x_i - x_j) << 8,
// c = (y_i - y_j) x_i - (x_i - x_j) y_i, plus 1 for left edges and for the fill rule's
// horizontal edge.
#include <doctest/doctest.h>

#include <set>
#include <utility>
#include <vector>

#include "raster/methods.h"
#include "tests/geometry/geometry_test_helpers.h"

namespace {

using namespace geometry_test;
using Pixels = std::set<std::pair<int, int>>;

Pixels toSet(const std::vector<std::pair<int, int>>& v) { return Pixels(v.begin(), v.end()); }

// The pixels of a w x h framebuffer for which pred(px, py) holds.
template <class Pred>
Pixels pixelsWhere(int w, int h, Pred pred) {
  Pixels out;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (pred(x, y)) out.insert({x, y});
  return out;
}

// Sets up triangles that must all survive, and returns the coverage count of their union
// plus each one's covered pixels.
struct SharedEdgeResult {
  Coverage union_;
  std::vector<Pixels> each;
};
SharedEdgeResult coverTriangles(const raster::SetupState& state, const std::vector<std::vector<std::vector<float>>>& tris) {
  SharedEdgeResult r{Coverage(state.framebufferWidth, state.framebufferHeight), {}};
  for (const auto& t : tris) {
    SetupOutput out;
    REQUIRE(setUp(state, t[0], t[1], t[2], out));
    REQUIRE(out.triangles.size() == 1);
    r.union_.add(out.triangles[0]);
    r.each.push_back(toSet(coveredPixels(out.triangles[0], state.framebufferWidth, state.framebufferHeight)));
  }
  return r;
}

// Every pixel of `expected` covered exactly once, every other pixel not at all.
void checkCoveredOnce(const Coverage& c, const Pixels& expected) {
  checkCoverage(c, [&](int x, int y) { return expected.count({x, y}) ? 1 : 0; });
}

// A triangle whose fixed x at its leftmost vertices is what window x = X snaps to:
// window (X, 0.5), (16.5, 4.5), (X, 8.5) -> fixed (f, 0), (4096, 1024), (f, 2048).
// area = (f - 4096) * 2048 - 0 < 0, so v0 and v1 swap: v0 = (4096, 1024), v1 = (f, 0),
// v2 = (f, 2048). Edge 1 runs (f, 0) -> (f, 2048): dcdx = -2048 (a left edge, +1), dcdy = 0,
// c = -2048 f + 1. So edge[1].c = 1 - 2048 f and minX = max(f >> 8, 0).
SetupTriangle leftEdgeAt(float X) {
  SetupOutput out;
  REQUIRE(setUp(setupState(32, 16), windowVertex(X, 0.5f), windowVertex(16.5f, 4.5f), windowVertex(X, 8.5f), out));
  return out.triangles[0];
}

}  // namespace

TEST_SUITE("geometry") {
  // Square of pixel centres (0,0)-(4,4) cut along its diagonal:
  //   A = (0,0), (4,0), (4,4); B = (0,0), (4,4), (0,4).
  // A in fixed: (0,0), (1024,0), (1024,1024); area = (-1024)(1024) - (1024)(0) < 0 -> swap:
  //   e0 (1024,0)->(0,0):    dcdx 0, dcdy 1024, c 0        horizontal: +1 under top-left -> py >= 0
  //                                                       (no +1 under bottom-left -> py >= 1)
  //   e1 (0,0)->(1024,1024): dcdx -1024 (left, +1), c 1   -> px >= py
  //   e2 (1024,1024)->(1024,0): dcdx 1024, c 1048576      -> px < 4
  // B after the swap: v0 (1024,1024), v1 (0,0), v2 (0,1024):
  //   e0 (1024,1024)->(0,0): dcdx 1024, dcdy 1024, c 0     -> py > px (the diagonal, exclusive)
  //   e1 (0,0)->(0,1024):    dcdx -1024 (left, +1), c 1   -> px >= 0
  //   e2 (0,1024)->(1024,1024): dcdx 0, dcdy -1024, c 1048576: +1 only under bottom-left
  //                                                       -> py < 4 (top-left), py <= 4 (bottom-left)
  TEST_CASE("fill rule: a diagonal shared edge through pixel centres, top-left (FBO)") {
    const auto A = std::vector<std::vector<float>>{atPixelCentre(0, 0), atPixelCentre(4, 0), atPixelCentre(4, 4)};
    const auto B = std::vector<std::vector<float>>{atPixelCentre(0, 0), atPixelCentre(4, 4), atPixelCentre(0, 4)};
    const auto r = coverTriangles(setupState(8, 8, false), {A, B});
    // A: 0 <= py <= px <= 3 (10 pixels); B: 0 <= px < py <= 3 (6 pixels).
    CHECK(r.each[0] == pixelsWhere(8, 8, [](int x, int y) { return 0 <= y && y <= x && x <= 3; }));
    CHECK(r.each[1] == pixelsWhere(8, 8, [](int x, int y) { return 0 <= x && x < y && y <= 3; }));
    CHECK(r.each[0].size() == 10);
    CHECK(r.each[1].size() == 6);
    // The union: columns 0..3 (left edge in, right out), rows 0..3 (top edge y=0 in, bottom
    // y=4 out), each pixel once. Catches: the diagonal in both or neither triangle, the wrong
    // horizontal edge inclusive.
    checkCoveredOnce(r.union_, pixelsWhere(8, 8, [](int x, int y) { return x <= 3 && y <= 3; }));

    // The edge functions of A exactly as worked above (dcdx, dcdy scaled by 256).
    SetupOutput out;
    REQUIRE(setUp(setupState(8, 8, false), A[0], A[1], A[2], out));
    const SetupTriangle& t = out.triangles[0];
    CHECK(sameEdge(t.edge[0], {1, 0, 1024 * 256}));
    CHECK(sameEdge(t.edge[1], {1, -1024 * 256, -1024 * 256}));
    CHECK(sameEdge(t.edge[2], {1048576, 1024 * 256, 0}));
  }

  TEST_CASE("fill rule: a diagonal shared edge through pixel centres, bottom-left (window buffer)") {
    const auto A = std::vector<std::vector<float>>{atPixelCentre(0, 0), atPixelCentre(4, 0), atPixelCentre(4, 4)};
    const auto B = std::vector<std::vector<float>>{atPixelCentre(0, 0), atPixelCentre(4, 4), atPixelCentre(0, 4)};
    const auto r = coverTriangles(setupState(8, 8, true), {A, B});
    // A: 1 <= py <= px <= 3 (6 pixels); B: 0 <= px < py <= 4 (10 pixels).
    CHECK(r.each[0] == pixelsWhere(8, 8, [](int x, int y) { return 1 <= y && y <= x && x <= 3; }));
    CHECK(r.each[1] == pixelsWhere(8, 8, [](int x, int y) { return 0 <= x && x < y && y <= 4; }));
    // The union: columns 0..3, rows 1..4 (memory row 0 is now the exclusive top), once each.
    checkCoveredOnce(r.union_, pixelsWhere(8, 8, [](int x, int y) { return x <= 3 && 1 <= y && y <= 4; }));

    SetupOutput out;
    REQUIRE(setUp(setupState(8, 8, true), A[0], A[1], A[2], out));
    CHECK(sameEdge(out.triangles[0].edge[0], {0, 0, 1024 * 256}));   // the horizontal edge loses its +1
    // Bounds: minY = (0 + 1) >> 8 = 0, maxY = (1024 - 1 + 1) >> 8 = 4 (top-left: 1023 >> 8 = 3).
    CHECK(out.triangles[0].maxY == 4);
  }

  // Diamond of pixel centres (2,0), (4,2), (2,4), (0,2) cut along the vertical x = 2:
  //   T1 = (2,0), (2,4), (0,2) (left half), T2 = (2,0), (4,2), (2,4) (right half).
  // T1 after the swap, fixed v0 (512,1024), v1 (512,0), v2 (0,512):
  //   e0: dcdx 1024, c 524288                 -> px < 2   (the shared edge is T1's right edge)
  //   e1: dcdx -512 (left), dcdy 512, c -262143 -> px + py >= 2
  //   e2: dcdx -512 (left), dcdy -512, c 262145 -> py - px <= 2
  // T1 covers (1,1), (0,2), (1,2), (1,3): the left vertex (0,2) sits on two left edges.
  // T2 covers the shared edge (2,1), (2,2), (2,3) (its left edge) and (3,2); the top, right and
  // bottom vertices each touch a right edge and are nobody's. No horizontal edge: both rules agree.
  TEST_CASE("fill rule: a vertical shared edge through pixel centres, both conventions") {
    for (bool bottomLeft : {false, true}) {
      CAPTURE(bottomLeft);
      const auto T1 = std::vector<std::vector<float>>{atPixelCentre(2, 0), atPixelCentre(2, 4), atPixelCentre(0, 2)};
      const auto T2 = std::vector<std::vector<float>>{atPixelCentre(2, 0), atPixelCentre(4, 2), atPixelCentre(2, 4)};
      const auto r = coverTriangles(setupState(8, 8, bottomLeft), {T1, T2});
      CHECK(r.each[0] == Pixels{{1, 1}, {0, 2}, {1, 2}, {1, 3}});
      CHECK(r.each[1] == Pixels{{2, 1}, {2, 2}, {2, 3}, {3, 2}});
      checkCoveredOnce(r.union_, Pixels{{1, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 1}, {2, 2}, {2, 3}, {3, 2}});
    }
  }

  // The same diamond cut along the horizontal y = 2:
  //   T3 = (0,2), (2,0), (4,2) (upper in memory), T4 = (0,2), (4,2), (2,4) (lower).
  // T3 after the swap, v0 (512,0), v1 (0,512), v2 (1024,512):
  //   e0: left, -> px + py >= 2;  e2: c 262144 -> px - py < 2;
  //   e1 (0,512)->(1024,512): dcdx 0, dcdy -1024, c 524288: +1 only under bottom-left
  //       -> py < 2 (top-left) or py <= 2 (bottom-left).
  // T4 after the swap, v0 (1024,512), v1 (0,512), v2 (512,1024):
  //   e0 (1024,512)->(0,512): dcdx 0, dcdy 1024, c -524288: +1 only under top-left
  //       -> py >= 2 (top-left) or py > 2 (bottom-left);
  //   e1: left, c 262145 -> py - px <= 2;  e2: c 786432 -> px + py < 6.
  // So the shared row y = 2, (0,2) to (3,2), belongs to T4 under top-left and to T3 under
  // bottom-left; (4,2) touches the right edges of both and is nobody's.
  TEST_CASE("fill rule: a horizontal shared edge through pixel centres goes to the rule's side") {
    const auto T3 = std::vector<std::vector<float>>{atPixelCentre(0, 2), atPixelCentre(2, 0), atPixelCentre(4, 2)};
    const auto T4 = std::vector<std::vector<float>>{atPixelCentre(0, 2), atPixelCentre(4, 2), atPixelCentre(2, 4)};
    const Pixels sharedRow{{0, 2}, {1, 2}, {2, 2}, {3, 2}};
    const Pixels unionPixels{{1, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}, {1, 3}, {2, 3}};
    {
      const auto r = coverTriangles(setupState(8, 8, false), {T3, T4});
      CHECK(r.each[0] == Pixels{{1, 1}, {2, 1}});
      CHECK(r.each[1] == Pixels{{0, 2}, {1, 2}, {2, 2}, {3, 2}, {1, 3}, {2, 3}});
      checkCoveredOnce(r.union_, unionPixels);
      for (const auto& p : sharedRow) CHECK(r.each[1].count(p) == 1);
    }
    {
      const auto r = coverTriangles(setupState(8, 8, true), {T3, T4});
      CHECK(r.each[0] == Pixels{{1, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}});
      CHECK(r.each[1] == Pixels{{1, 3}, {2, 3}});
      checkCoveredOnce(r.union_, unionPixels);
      for (const auto& p : sharedRow) CHECK(r.each[0].count(p) == 1);
    }
  }

  // snap(v) = roundToNearestEven((v - 0.5) * 256); each X below has X - 0.5 and the product
  // exact in float, so f is decided by the rounding alone.
  TEST_CASE("snapping: window x to 8 sub-pixel bits, round half to even") {
    struct Case {
      float x;
      int fixed;
    };
    const Case cases[] = {
        {1.5f, 256},                                 // a pixel centre: exact
        {1.5f + 1.0f / 512, 256},                    // 256.5 -> 256 (half-up would give 257)
        {1.5f + 3.0f / 512, 258},                    // 257.5 -> 258 (truncation would give 257)
        {1.5f - 1.0f / 512, 256},                    // 255.5 -> 256 (floor would give 255, minX 0)
        {1.5f - 3.0f / 512, 254},                    // 254.5 -> 254
        {1.5f + 1.0f / 512 + 1.0f / 1048576, 257},   // 256.5 + 2^-12: just past the tie
        {0.5f + 1.0f / 512, 0},                      // 0.5 -> 0
        {0.5f + 5.0f / 512, 2},                      // 2.5 -> 2
        {0.5f - 1.0f / 512, 0},                      // -0.5 -> -0
        {0.5f - 3.0f / 512, -2},                     // -1.5 -> -2 (truncation toward 0 gives -1)
        {1.0f, 128},                                 // a pixel edge: half a pixel left of centre 1
    };
    for (const Case& k : cases) {
      CAPTURE(k.x);
      const SetupTriangle t = leftEdgeAt(k.x);
      CHECK(t.edge[1].c == 1 - 2048 * int64_t(k.fixed));
      CHECK(t.edge[1].dcdx == -2048 * 256);
      CHECK(t.edge[1].dcdy == 0);
      CHECK(t.minX == std::max(k.fixed >> 8, 0));
    }
  }

  // Right triangle window (0.5, 0.5), (X, 0.5), (0.5, 8.5) -> fixed (0,0), (f,0), (0,2048).
  // After the swap edge 2 runs (0,2048) -> (f,0): dcdx 2048, dcdy -f, c = 2048 f, so
  // at(1, 0) = 2048 f - 2048 * 256 = 2048 (f - 256): pixel (1, 0) sits on the hypotenuse
  // (a right edge, exclusive) when f = 256 and is inside when f = 257.
  TEST_CASE("snapping decides coverage: a vertex half a sub-pixel right of a pixel centre") {
    SetupOutput tie, past;
    REQUIRE(setUp(setupState(16, 16), windowVertex(0.5f, 0.5f), windowVertex(1.5f + 1.0f / 512, 0.5f), windowVertex(0.5f, 8.5f), tie));
    REQUIRE(setUp(setupState(16, 16), windowVertex(0.5f, 0.5f), windowVertex(1.5f + 1.0f / 512 + 1.0f / 1048576, 0.5f),
                  windowVertex(0.5f, 8.5f), past));
    CHECK(tie.triangles[0].edge[2].at(1, 0) == 0);
    CHECK(past.triangles[0].edge[2].at(1, 0) == 2048);
    CHECK(tie.triangles[0].maxX == 0);    // (256 - 1) >> 8
    CHECK(past.triangles[0].maxX == 1);   // (257 - 1) >> 8
    const Pixels tiePixels = toSet(coveredPixels(tie.triangles[0], 16, 16));
    const Pixels pastPixels = toSet(coveredPixels(past.triangles[0], 16, 16));
    CHECK(tiePixels.count({1, 0}) == 0);
    CHECK(pastPixels.count({1, 0}) == 1);
    // Column 0, rows 0..7: the left edge x = 0 is inclusive, the vertex (0, 2048) row 8 is not
    // (py = 8 sits on the hypotenuse's end, c - 0 + (-f * 256) * 8 = 2048 f - 2048 f = 0).
    CHECK(tiePixels == pixelsWhere(16, 16, [](int x, int y) { return x == 0 && y <= 7; }));
  }

  // Vertices at exact sub-pixel positions, fixed P0 (805, 517), P1 (5220, 2504), P2 (1795, 4863),
  // moved by +-127/65536 window units (0.496 sub-pixel) in every sign pattern: the snapped
  // positions, so the edges, bounds and coverage, do not change. Floor or truncation instead of
  // round-to-nearest would move the negative cases by one sub-pixel.
  TEST_CASE("snapping: moves of less than half a sub-pixel change nothing") {
    const float base[3][2] = {{3.5f + 37.0f / 256, 2.5f + 5.0f / 256},
                              {20.5f + 100.0f / 256, 9.5f + 200.0f / 256},
                              {7.5f + 3.0f / 256, 18.5f + 255.0f / 256}};
    const float d = 127.0f / 65536;
    auto triangle = [&](unsigned signs, float amount) {
      std::vector<std::vector<float>> v;
      for (int i = 0; i < 3; ++i) {
        const float sx = (signs >> (2 * i)) & 1 ? -1.0f : 1.0f, sy = (signs >> (2 * i + 1)) & 1 ? -1.0f : 1.0f;
        v.push_back(windowVertex(base[i][0] + sx * amount, base[i][1] + sy * amount));
      }
      SetupOutput out;
      REQUIRE(setUp(setupState(32, 32), v[0], v[1], v[2], out));
      return out.triangles[0];
    };
    const SetupTriangle reference = triangle(0, 0.0f);
    // Bounds: minX 805 >> 8 = 3, maxX (5220 - 1) >> 8 = 20, minY 517 >> 8 = 2, maxY (4863 - 1) >> 8 = 18.
    CHECK(reference.minX == 3);
    CHECK(reference.maxX == 20);
    CHECK(reference.minY == 2);
    CHECK(reference.maxY == 18);
    const Pixels referencePixels = toSet(coveredPixels(reference, 32, 32));
    CHECK(!referencePixels.empty());
    for (unsigned signs = 0; signs < 64; ++signs) {
      CAPTURE(signs);
      const SetupTriangle moved = triangle(signs, d);
      for (int e = 0; e < 3; ++e) CHECK(sameEdge(moved.edge[e], reference.edge[e]));
      CHECK(moved.minX == reference.minX);
      CHECK(moved.maxX == reference.maxX);
      CHECK(moved.minY == reference.minY);
      CHECK(moved.maxY == reference.maxY);
      CHECK(toSet(coveredPixels(moved, 32, 32)) == referencePixels);
    }
    // Control: half a sub-pixel right from the odd 805 is 805.5 -> 806, a different edge.
    SetupOutput half;
    REQUIRE(setUp(setupState(32, 32), windowVertex(base[0][0] + 0.5f / 256, base[0][1]), windowVertex(base[1][0], base[1][1]),
                  windowVertex(base[2][0], base[2][1]), half));
    bool anyDifferent = false;
    for (int e = 0; e < 3; ++e) anyDifferent = anyDifferent || !sameEdge(half.triangles[0].edge[e], reference.edge[e]);
    CHECK(anyDifferent);
  }

  // minX = min >> 8, maxX = (max - 1) >> 8, minY = (min + adj) >> 8, maxY = (max - 1 + adj) >> 8,
  // adj = 1 under the bottom-left rule (lp_setup_tri.c), then trimmed to the framebuffer.
  TEST_CASE("bounds: exact pixel bounds from the snapped vertices, both conventions") {
    struct Case {
      float lo, hi;                  // window x and y of the right triangle (lo,lo), (hi,lo), (lo,hi)
      int minX, maxX;                // both conventions
      int minYTopLeft, maxYTopLeft;  // adj 0
      int minYBottomLeft, maxYBottomLeft;
    };
    const Case cases[] = {
        // lo 1.5 - 1/256 -> 255, hi 5.5 -> 1280: x 255>>8 = 0, 1279>>8 = 4; y adj 1: 256>>8 = 1, 1280>>8 = 5.
        {1.5f - 1.0f / 256, 5.5f, 0, 4, 0, 4, 1, 5},
        // lo 1.5 -> 256, hi 5.5 - 1/256 -> 1279: 1, 1278>>8 = 4; adj 1: 257>>8 = 1, 1279>>8 = 4.
        {1.5f, 5.5f - 1.0f / 256, 1, 4, 1, 4, 1, 4},
        // hi 5.5 + 1/256 -> 1281: maxX 1280>>8 = 5; adj 1: 1281>>8 = 5.
        {1.5f, 5.5f + 1.0f / 256, 1, 5, 1, 5, 1, 5},
    };
    for (const Case& k : cases) {
      CAPTURE(k.lo);
      CAPTURE(k.hi);
      for (bool bottomLeft : {false, true}) {
        CAPTURE(bottomLeft);
        SetupOutput out;
        REQUIRE(setUp(setupState(16, 16, bottomLeft), windowVertex(k.lo, k.lo), windowVertex(k.hi, k.lo), windowVertex(k.lo, k.hi), out));
        const SetupTriangle& t = out.triangles[0];
        CHECK(t.minX == k.minX);
        CHECK(t.maxX == k.maxX);
        CHECK(t.minY == (bottomLeft ? k.minYBottomLeft : k.minYTopLeft));
        CHECK(t.maxY == (bottomLeft ? k.maxYBottomLeft : k.maxYTopLeft));
        Coverage c(16, 16);
        c.add(t);   // and the bounds hold every covered pixel
      }
    }
  }

  TEST_CASE("bounds: trimmed to the framebuffer; a triangle wholly outside it is dropped") {
    // Window (-10.5,-10.5), (100.5,-10.5), (-10.5,100.5): fixed -2816 and 25600, bounds
    // -11..99 trimmed to 0..15 x 0..7 of a 16 x 8 framebuffer; every pixel covered (x + y < 89).
    SetupOutput big;
    REQUIRE(setUp(setupState(16, 8), windowVertex(-10.5f, -10.5f), windowVertex(100.5f, -10.5f), windowVertex(-10.5f, 100.5f), big));
    const SetupTriangle& t = big.triangles[0];
    CHECK(t.minX == 0);
    CHECK(t.maxX == 15);
    CHECK(t.minY == 0);
    CHECK(t.maxY == 7);
    Coverage c(16, 8);
    c.add(t);
    CHECK(c.pixels().size() == 16 * 8);

    // Right of the framebuffer: minX 20 > maxX 15 after trimming.
    SetupOutput right;
    CHECK_FALSE(setUp(setupState(16, 8), windowVertex(20.5f, 0.5f), windowVertex(30.5f, 0.5f), windowVertex(20.5f, 5.5f), right));
    // Left of it: maxX = (-3 * 256 - 1) >> 8 = -4 < 0.
    CHECK_FALSE(setUp(setupState(16, 8), windowVertex(-10.5f, 0.5f), windowVertex(-2.5f, 0.5f), windowVertex(-10.5f, 5.5f), right));
    // Below it (memory rows past the last): minY 9 > maxY 7.
    CHECK_FALSE(setUp(setupState(16, 8), windowVertex(0.5f, 9.5f), windowVertex(5.5f, 9.5f), windowVertex(0.5f, 15.5f), right));
    CHECK(right.triangles.empty());
    CHECK(right.planes.empty());
    // Touching the last column: max x at 16.5 -> 4096, maxX (4096 - 1) >> 8 = 15.
    SetupOutput edge;
    REQUIRE(setUp(setupState(16, 8), windowVertex(10.5f, 0.5f), windowVertex(16.5f, 0.5f), windowVertex(10.5f, 5.5f), edge));
    CHECK(edge.triangles[0].maxX == 15);
  }

  TEST_CASE("degenerate triangles are dropped: zero area before or after snapping") {
    for (bool bottomLeft : {false, true}) {
      CAPTURE(bottomLeft);
      const raster::SetupState state = setupState(32, 32, bottomLeft, 1);
      SetupOutput out;
      // All three vertices the same.
      CHECK_FALSE(setUp(state, windowVertex(3.5f, 3.5f, 0.5f, 1.0f, {1}), windowVertex(3.5f, 3.5f, 0.5f, 1.0f, {2}),
                        windowVertex(3.5f, 3.5f, 0.5f, 1.0f, {3}), out));
      // Collinear: (0,0), (512,512), (1024,1024): area 0.
      CHECK_FALSE(setUp(state, windowVertex(0.5f, 0.5f, 0.5f, 1.0f, {1}), windowVertex(2.5f, 2.5f, 0.5f, 1.0f, {2}),
                        windowVertex(4.5f, 4.5f, 0.5f, 1.0f, {3}), out));
      // Distinct floats, one point after snapping: 1/1024 is a quarter sub-pixel, 256.25 -> 256.
      CHECK_FALSE(setUp(state, windowVertex(1.5f, 1.5f, 0.5f, 1.0f, {1}), windowVertex(1.5f + 1.0f / 1024, 1.5f, 0.5f, 1.0f, {2}),
                        windowVertex(1.5f, 1.5f + 1.0f / 1024, 0.5f, 1.0f, {3}), out));
      // Non-zero float area, collinear after snapping: y 0.25 sub-pixel -> 0, all on y = 0.
      // (An area computed from the unsnapped floats would keep it.)
      CHECK_FALSE(setUp(state, windowVertex(0.5f, 0.5f, 0.5f, 1.0f, {1}), windowVertex(8.5f, 0.5f + 1.0f / 1024, 0.5f, 1.0f, {2}),
                        windowVertex(16.5f, 0.5f, 0.5f, 1.0f, {3}), out));
      CHECK(out.triangles.empty());
      CHECK(out.planes.empty());
      // Control: 3/1024 is 0.75 sub-pixel -> 1, area (0 - 4096)(-1) = 4096 != 0: kept.
      CHECK(setUp(state, windowVertex(0.5f, 0.5f, 0.5f, 1.0f, {1}), windowVertex(8.5f, 0.5f + 3.0f / 1024, 0.5f, 1.0f, {2}),
                  windowVertex(16.5f, 0.5f, 0.5f, 1.0f, {3}), out));
      CHECK(out.triangles.size() == 1);
      CHECK(out.planes.size() == 1);
    }
  }

  // In an FBO window y is GL's y, so (0,0), (4,0), (0,4) in pixel centres is counter-clockwise:
  // fixed area (-1024)(1024) - 0 < 0 = front. A window-system buffer's window y is mirrored
  // (memory rows), so the same window positions are clockwise in GL: area < 0 = back.
  TEST_CASE("facing and culling: back faces culled with cullBack, kept and marked without; flipped by the bottom-left rule") {
    const auto a = atPixelCentre(0, 0), b = atPixelCentre(4, 0), c = atPixelCentre(0, 4);
    for (bool bottomLeft : {false, true}) {
      CAPTURE(bottomLeft);
      raster::SetupState state = setupState(8, 8, bottomLeft);
      const bool ccwIsFront = !bottomLeft;
      // a, b, c and its reverse a, c, b.
      SetupOutput kept;
      REQUIRE(setUp(state, a, b, c, kept));
      REQUIRE(setUp(state, a, c, b, kept));
      CHECK(kept.triangles[0].frontFacing == ccwIsFront);
      CHECK(kept.triangles[1].frontFacing == !ccwIsFront);
      // Orientation does not change coverage: pixels px + py < 4 (the hypotenuse is a right
      // edge), rows from 0 under top-left (10 pixels) or from 1 under bottom-left (6).
      const Pixels p0 = toSet(coveredPixels(kept.triangles[0], 8, 8));
      CHECK(p0 == toSet(coveredPixels(kept.triangles[1], 8, 8)));
      CHECK(p0 == pixelsWhere(8, 8, [&](int x, int y) { return x + y < 4 && y >= (bottomLeft ? 1 : 0); }));

      state.cullBack = true;
      SetupOutput culled;
      CHECK(setUp(state, a, b, c, culled) == ccwIsFront);
      CHECK(setUp(state, a, c, b, culled) == !ccwIsFront);
      REQUIRE(culled.triangles.size() == 1);
      CHECK(culled.triangles[0].frontFacing);
    }
  }

  // Window (0.5,0.5) z 0.25 1/w 1 varying 8; (4.5,0.5) z 0.75 1/w 0.5 varying 4;
  // (0.5,4.5) z 0.5 1/w 0.25 varying 16. Referenced to pixel (0,0)'s centre:
  //   z:   a0 0.25, dadx (0.75 - 0.25) / 4 = 0.125, dady (0.5 - 0.25) / 4 = 0.0625
  //   1/w: a0 1,    dadx -0.5 / 4 = -0.125,       dady -0.75 / 4 = -0.1875
  //   varying * 1/w: 8, 2, 4 -> a0 8, dadx (2 - 8) / 4 = -1.5, dady (4 - 8) / 4 = -1
  // In setup's order (after the swap p0 = (4.5,0.5)): ooa = 1 / (4 * 4) = 1/16, every step a
  // product or sum of short dyadic numbers: exact.
  TEST_CASE("planes: z, 1/w and perspective varyings exact at pixel centres") {
    raster::SetupState state = setupState(8, 8, false, 1);
    state.drawIndex = 7;
    SetupOutput out;
    out.planes.resize(3);   // earlier triangles' planes: varyingBase must point past them
    REQUIRE(setUp(state, windowVertex(0.5f, 0.5f, 0.25f, 1.0f, {8}), windowVertex(4.5f, 0.5f, 0.75f, 0.5f, {4}),
                  windowVertex(0.5f, 4.5f, 0.5f, 0.25f, {16}), out));
    const SetupTriangle& t = out.triangles[0];
    CHECK(t.z.a0 == 0.25f);
    CHECK(t.z.dadx == 0.125f);
    CHECK(t.z.dady == 0.0625f);
    CHECK(t.w.a0 == 1.0f);
    CHECK(t.w.dadx == -0.125f);
    CHECK(t.w.dady == -0.1875f);
    CHECK(t.varyingBase == 3);
    CHECK(t.drawIndex == 7);
    CHECK(t.depthOffset == 0.0f);
    REQUIRE(out.planes.size() == 4);
    const raster::Plane v = out.planes[3];
    CHECK(v.a0 == 8.0f);
    // Without the premultiply by 1/w the plane of 8, 4, 16 would read dadx -1, dady 2.
    CHECK(v.dadx == -1.5f);
    CHECK(v.dady == -1.0f);
    // Evaluated at pixel centres as the tiles do: fma(dady, py, fma(dadx, px, a0)).
    auto eval = [](const raster::Plane& p, int px, int py) { return std::fma(p.dady, float(py), std::fma(p.dadx, float(px), p.a0)); };
    CHECK(eval(t.z, 3, 0) == 0.625f);    // 0.25 + 3 * 0.125
    CHECK(eval(t.z, 0, 3) == 0.4375f);   // 0.25 + 3 * 0.0625
    CHECK(eval(t.z, 1, 2) == 0.5f);      // 0.25 + 0.125 + 0.125
    CHECK(eval(t.z, 4, 0) == 0.75f);     // at the vertex (4.5, 0.5)
    // Perspective-correct varying = plane(v / w) / plane(1 / w): back to the vertex values.
    CHECK(eval(v, 4, 0) / eval(t.w, 4, 0) == 4.0f);   // (8 - 6) / (1 - 0.5)
    CHECK(eval(v, 0, 4) / eval(t.w, 0, 4) == 16.0f);  // (8 - 4) / (1 - 0.75)
    CHECK(eval(v, 0, 0) / eval(t.w, 0, 0) == 8.0f);
    // Midway along the far edge: (8 - 3 - 2) / (1 - 0.25 - 0.375) = 3 / 0.375 = 8, the
    // perspective mean (0.5 * 4 * 0.5 + 0.5 * 16 * 0.25) / (0.5 * 0.5 + 0.5 * 0.25); the screen-space
    // mean would be 10.
    CHECK(eval(v, 2, 2) / eval(t.w, 2, 2) == 8.0f);
  }

  // The interp=affine method (raster/methods.h): the same triangle's varying plane made of
  // the plain values 8, 4, 16, read without the divide; z and 1/w are untouched.
  TEST_CASE("planes: interp=affine makes screen-linear varying planes, z and 1/w as GL") {
    raster::MethodSet affine;
    affine.interp = raster::InterpMethod::Affine;
    const raster::ScopedMethods scoped(affine);
    raster::SetupState state = setupState(8, 8, false, 1);
    SetupOutput out;
    REQUIRE(setUp(state, windowVertex(0.5f, 0.5f, 0.25f, 1.0f, {8}), windowVertex(4.5f, 0.5f, 0.75f, 0.5f, {4}),
                  windowVertex(0.5f, 4.5f, 0.5f, 0.25f, {16}), out));
    const SetupTriangle& t = out.triangles[0];
    CHECK(t.z.dadx == 0.125f);
    CHECK(t.w.dady == -0.1875f);
    const raster::Plane v = out.planes[0];
    CHECK(v.a0 == 8.0f);
    CHECK(v.dadx == -1.0f);
    CHECK(v.dady == 2.0f);
    auto eval = [](const raster::Plane& p, int px, int py) { return std::fma(p.dady, float(py), std::fma(p.dadx, float(px), p.a0)); };
    CHECK(eval(v, 4, 0) == 4.0f);    // exact at the vertices
    CHECK(eval(v, 0, 4) == 16.0f);
    CHECK(eval(v, 2, 2) == 10.0f);   // the screen-space mean, where perspective gives 8
  }

  TEST_CASE("polygon offset: units in depth-buffer steps, factor times the larger depth slope") {
    // units * 2 * mrd in double, mrd = 1 / (2^bits - 1), rounded once to float.
    CHECK(raster::polygonOffsetUnits(1.0f, 24) == float(2.0 / 16777215.0));
    CHECK(raster::polygonOffsetUnits(1.0f, 24) == 0x1.000002p-23f);   // 2^-23 (1 + 2^-24 + ...) -> 2^-23 (1 + 2^-23)
    CHECK(raster::polygonOffsetUnits(1.0f, 24) != 0x1p-23f);          // 2 / 2^24 would be the 2^bits bug
    CHECK(raster::polygonOffsetUnits(1.0f, 16) == float(2.0 / 65535.0));
    CHECK(raster::polygonOffsetUnits(-2.0f, 24) == float(-4.0 / 16777215.0));
    CHECK(raster::polygonOffsetUnits(0.0f, 24) == 0.0f);

    // The z triangle of the planes test: |dz/dx| = 0.125, |dz/dy| = 0.0625.
    //   dx01 4, dy01 0, dz01 0.5; dx20 -4, dy20 4, dz20 -0.25 (after the swap);
    //   res1 = dz20 dy01 - dy20 dz01 = -2, res2 = dx20 dz01 - dz20 dx01 = -1; ooa 1/16.
    raster::SetupState state = setupState(8, 8);
    state.polygonOffset = true;
    state.offsetFactor = 2.0f;
    state.offsetUnitsScaled = 0.5f;
    SetupOutput out;
    REQUIRE(setUp(state, windowVertex(0.5f, 0.5f, 0.25f), windowVertex(4.5f, 0.5f, 0.75f), windowVertex(0.5f, 4.5f, 0.5f), out));
    CHECK(out.triangles[0].depthOffset == 0.75f);   // 0.5 + 0.125 * 2
    // z steeper in y: (0.5,4.5) at 0.75, (4.5,0.5) at 0.5 -> |dz/dx| 0.0625, |dz/dy| 0.125.
    REQUIRE(setUp(state, windowVertex(0.5f, 0.5f, 0.25f), windowVertex(4.5f, 0.5f, 0.5f), windowVertex(0.5f, 4.5f, 0.75f), out));
    CHECK(out.triangles[1].depthOffset == 0.75f);   // 0.5 + 0.125 * 2 (the x slope would give 0.625)
    // z falling in x (0.75, 0.25, 0.5): the same 0.125 slope. (The first triangle's res1 * ooa
    // is -0.125, so a missing fabs already fails there: max(-0.125, -0.0625) * 2 + 0.5 = 0.375.)
    REQUIRE(setUp(state, windowVertex(0.5f, 0.5f, 0.75f), windowVertex(4.5f, 0.5f, 0.25f), windowVertex(0.5f, 4.5f, 0.5f), out));
    CHECK(out.triangles[2].depthOffset == 0.75f);   // |dz/dx| = 0.125
    // Off: no offset whatever the factor and units.
    state.polygonOffset = false;
    REQUIRE(setUp(state, windowVertex(0.5f, 0.5f, 0.25f), windowVertex(4.5f, 0.5f, 0.75f), windowVertex(0.5f, 4.5f, 0.5f), out));
    CHECK(out.triangles[3].depthOffset == 0.0f);
  }
}

TEST_SUITE("geometry") {
  // Found by the geometry fuzz target: a NaN window position (which passes the clip tests,
  // whose compares are ordered) snapped to INT_MIN and overflowed setup's int arithmetic.
  // Setup drops a triangle with a window coordinate that is NaN, infinite or beyond
  // limits::kMaxWindowCoordinate (2^21), and keeps one just inside it.
  TEST_CASE("setup: a NaN or far-out window coordinate drops the triangle; 2^21 is the bound") {
    using namespace geometry_test;
    SetupOutput out;
    const raster::SetupState state = setupState(16, 16);
    CHECK_FALSE(setUp(state, windowVertex(std::nanf(""), 0.5f), windowVertex(4.5f, 0.5f), windowVertex(4.5f, 4.5f), out));
    CHECK_FALSE(setUp(state, windowVertex(0.5f, 0.5f), windowVertex(4.5f, INFINITY), windowVertex(4.5f, 4.5f), out));
    CHECK_FALSE(setUp(state, windowVertex(0.5f, 0.5f), windowVertex(1e30f, 0.5f), windowVertex(4.5f, 4.5f), out));
    CHECK_FALSE(setUp(state, windowVertex(0.5f, 0.5f), windowVertex(2097152.5f, 0.5f), windowVertex(4.5f, 4.5f), out));
    CHECK(setUp(state, windowVertex(0.5f, 0.5f), windowVertex(2097152.0f, 0.5f), windowVertex(4.5f, 4.5f), out));
    CHECK(out.triangles.size() == 1);
  }
}
