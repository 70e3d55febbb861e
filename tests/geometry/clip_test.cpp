// Clipping (geometry/clip.h, vertex_stage::clipMask and its lane form) and primitive assembly
// (geometry/assemble.h) against hand-worked expectations: clip masks, trivial rejection,
// triangles wholly inside, crossing the near plane, crossing two planes, with a vertex at
// tiny positive or negative w, NaN / Inf positions, and the missing guard band (x and y are
// clipped to the viewport planes, as llvmpipe does).
//
// Every case uses a 64 x 64 FBO viewport: window = clip / w * 32 + 32 for x and y, and
// clip z / w * 0.5 + 0.5 for z. Values are chosen so each interpolation parameter t is a
// short dyadic fraction: the new vertices are then exact whichever end the clipper
// interpolates from, and are checked with ==.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "raster/geometry/assemble.h"
#include "raster/geometry/clip.h"
#include "raster/geometry/vertex_stage.h"
#include "tests/float_bits.h"
#include "tests/geometry/geometry_test_helpers.h"

namespace {

using namespace geometry_test;
constexpr float kEps = 1.0f / 1048576;   // 2^-20
using testing_support::kInf;
using testing_support::kNaN;

// Checks a record's clip position, window position and varyings.
void checkRecord(const float* r, std::array<float, 4> clip, std::array<float, 4> window, std::vector<float> varyings = {}) {
  for (int k = 0; k < 4; ++k) {
    CAPTURE(k);
    CHECK(r[record::kClip + k] == clip[size_t(k)]);
    CHECK(r[record::kWindow + k] == window[size_t(k)]);
  }
  for (size_t v = 0; v < varyings.size(); ++v) CHECK(r[record::kVaryings + int(v)] == varyings[v]);
}

// Assembles triangles (0,1,2), (3,4,5), ... of the shaded vertices into a 64 x 64 FBO.
struct Assembled {
  SetupOutput out;
  raster::PipelineCounters counters;
};
Assembled assemble(const raster::ShadedVertices& shaded, const raster::ViewportTransform& vp, int width = 64, int height = 64) {
  Assembled a;
  const raster::SetupState state = setupState(width, height, false, shaded.varyingFloats);
  std::vector<uint32_t> indices;
  for (int i = 0; i < shaded.count(); ++i) indices.push_back(uint32_t(i));
  const raster::AssemblyInput in{state, shaded, indices, shaded.count(), vp};
  raster::assemblePrimitives(in, 0, indices.size() / 3, a.out.lists(), a.counters);
  return a;
}

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("clip masks: one bit per plane, the boundary inside, NaN sets none") {
    using raster::vertex_stage::clipMask;
    // The vertex stage computes a lane group's masks at once (clipMaskLanes): every lane of
    // both lane types must give clipMask's bits.
    auto lanesAgree = []<class F>(F, float x, float y, float z, float w, int expected) {
      alignas(64) float flags[F::kCount];
      raster::vertex_stage::clipMaskLanes(raster::glsl::vec4<F>(F(x), F(y), F(z), F(w))).store(flags);
      for (float flag : flags) CHECK(int(flag) == expected);
    };
    auto mask = [&](float x, float y, float z, float w) {
      const float c[4] = {x, y, z, w};
      const int bits = int(clipMask(c));
      lanesAgree(raster::FastLanes(0.0f), x, y, z, w, bits);
      lanesAgree(raster::ScalarLanes(0.0f), x, y, z, w, bits);
      return bits;
    };
    CHECK(mask(2, 0, 0, 1) == 1);      // x > w
    CHECK(mask(-2, 0, 0, 1) == 2);     // x + w < 0
    CHECK(mask(0, 2, 0, 1) == 4);      // y > w
    CHECK(mask(0, -2, 0, 1) == 8);     // y + w < 0
    CHECK(mask(0, 0, -2, 1) == 16);    // z + w < 0 (near)
    CHECK(mask(0, 0, 2, 1) == 32);     // z > w (far)
    CHECK(mask(2, -2, 2, 1) == 1 + 8 + 32);
    // On the planes is inside: x = w, y + w = 0, z = w (a >= in place of > would flag them).
    CHECK(mask(1, -1, 1, 1) == 0);
    CHECK(mask(-1, 1, -1, 1) == 0);
    // Behind the eye (w < 0) every vertex is outside one plane of each pair: with x = y = z = 0,
    // 0 > -eps and 0 - eps < 0 for all three pairs.
    CHECK(mask(0, 0, 0, -kEps) == 63);
    CHECK(mask(-0.5f, -0.5f, -0.5f, -1) == 63);   // x/w = 0.5 would look inside after the divide
    // Ordered compares: NaN flags nothing; Inf compares like a huge number.
    CHECK(mask(kNaN, 0, 0, 1) == 0);
    CHECK(mask(0, 0, 0, kNaN) == 0);
    CHECK(mask(kInf, 0, 0, 1) == 1);
    CHECK(mask(0, -kInf, 0, 1) == 8);
  }

  TEST_CASE("a triangle wholly inside is untouched: same records, same order, set up directly") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s = shadeByHand({{{-0.5f, -0.5f, 0, 1}, {}}, {{0.5f, -0.5f, 0.5f, 1}, {}}, {{0, 0.5f, -0.5f, 1}, {}}}, 0, vp);
    CHECK(s.clipMask[0] == 0);
    CHECK(s.clipMask[1] == 0);
    CHECK(s.clipMask[2] == 0);
    raster::clip::Clipper clipper(0, vp);
    // With no plane to clip against, and with one it does not cross (x <= w: distances 1.5,
    // 0.5, 1): the polygon is the input's three record pointers in order.
    for (unsigned m : {0u, 1u, 63u}) {
      CAPTURE(m);
      const raster::clip::Polygon& p = clipper.clipTriangle(s.record(0), s.record(1), s.record(2), m);
      REQUIRE(p.count == 3);
      CHECK(p.vertex[0] == s.record(0));
      CHECK(p.vertex[1] == s.record(1));
      CHECK(p.vertex[2] == s.record(2));
    }
    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesIn == 1);
    CHECK(a.counters.trianglesClipped == 0);
    CHECK(a.counters.trianglesRejected == 0);
    CHECK(a.counters.trianglesSetUp == 1);
    REQUIRE(a.out.triangles.size() == 1);
    SetupOutput direct;
    REQUIRE(raster::setupTriangle(setupState(64, 64), s.record(0), s.record(1), s.record(2), direct.lists()));
    for (int e = 0; e < 3; ++e) CHECK(sameEdge(a.out.triangles[0].edge[e], direct.triangles[0].edge[e]));
  }

  TEST_CASE("trivial rejection: all three vertices outside one plane; outside different planes is clipped") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s = shadeByHand(
        {
            // 0: all right of x = w (masks 1, 1 + 4... share bit 0): rejected without clipping.
            {{2, 0, 0, 1}, {}}, {{3, 1.5f, 0, 1}, {}}, {{1.5f, -0.5f, 0, 1}, {}},
            // 1: masks 1, 4, 5 share no bit, but the triangle lies in x + y >= 2.5, beyond the
            // corner (1, 1): clipping x <= w leaves the small triangle (1, 1.5), (0.5, 2), (1, 2),
            // wholly above y = w, which clipping y <= w empties.
            {{2, 0.5f, 0, 1}, {}}, {{0.5f, 2, 0, 1}, {}}, {{2, 2, 0, 1}, {}},
            // 2: around the whole viewport (masks 2, 1, 4): the clipped polygon is the square
            // (-1,-1), (1,-1), (1,1), (-1,1), a fan of 2.
            {{-3, -1, 0, 1}, {}}, {{3, -1, 0, 1}, {}}, {{0, 3, 0, 1}, {}},
        },
        0, vp);
    CHECK((s.clipMask[0] & s.clipMask[1] & s.clipMask[2]) == 1);
    CHECK((s.clipMask[3] & s.clipMask[4] & s.clipMask[5]) == 0);
    CHECK((s.clipMask[6] & s.clipMask[7] & s.clipMask[8]) == 0);
    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesIn == 3);
    CHECK(a.counters.trianglesRejected == 1);
    CHECK(a.counters.trianglesClipped == 2);
    CHECK(a.counters.trianglesSetUp == 2);
    CHECK(a.out.triangles.size() == 2);
    // The square is the whole 64 x 64 viewport: every pixel once.
    Coverage c(64, 64);
    for (const SetupTriangle& t : a.out.triangles) c.add(t);
    checkCoverage(c, [](int, int) { return 1; });
  }

  // v0 (0, 0, -3, 2) is in front of the near plane (z + w = -1 < 0); v1 (1, 0, 1, 2) and
  // v2 (0, 1, 1, 2) are inside (z + w = 3). Plane z + w, walking v0 -> v1 -> v2 -> v0:
  //   v0 -> v1 comes in: t = 1 / (3 + 1) = 1/4 from v0:
  //     A = v0 + (v1 - v0) / 4 = (0.25, 0, -2, 2), varyings (4 + 4/4, -8 + 8/4) = (5, -6);
  //   v1, v2 kept;
  //   v2 -> v0 goes out: t = -1 / (-1 - 3) = 1/4 from v0:
  //     B = v0 + (v2 - v0) / 4 = (0, 0.25, -2, 2), varyings (4 - 4/4, -8 + 24/4) = (3, -2).
  // Polygon A, v1, v2, B. Window of A: 1/w 0.5, x 0.25 * 0.5 * 32 + 32 = 36, y 32,
  // z -2 * 0.5 * 0.5 + 0.5 = 0 (on the near plane window z is 0).
  TEST_CASE("near plane: new vertices' clip and window positions and varyings, exactly") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s =
        shadeByHand({{{0, 0, -3, 2}, {4, -8}}, {{1, 0, 1, 2}, {8, 0}}, {{0, 1, 1, 2}, {0, 16}}}, 2, vp);
    CHECK(s.clipMask[0] == 16);
    CHECK(s.clipMask[1] == 0);
    CHECK(s.clipMask[2] == 0);
    raster::clip::Clipper clipper(2, vp);
    const raster::clip::Polygon& p = clipper.clipTriangle(s.record(0), s.record(1), s.record(2), 16);
    REQUIRE(p.count == 4);
    checkRecord(p.vertex[0], {0.25f, 0, -2, 2}, {36, 32, 0, 0.5f}, {5, -6});
    CHECK(p.vertex[1] == s.record(1));
    CHECK(p.vertex[2] == s.record(2));
    checkRecord(p.vertex[3], {0, 0.25f, -2, 2}, {32, 36, 0, 0.5f}, {3, -2});

    // Assembled: the fan (v1, v2, A), (v2, B, A). Window v1 (48, 32), v2 (32, 48), A (36, 32),
    // B (32, 36): both counter-clockwise like the input (32,32), (48,32), (32,48), so front.
    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesIn == 1);
    CHECK(a.counters.trianglesClipped == 1);
    CHECK(a.counters.trianglesSetUp == 2);
    REQUIRE(a.out.triangles.size() == 2);
    CHECK(a.out.triangles[0].frontFacing);
    CHECK(a.out.triangles[1].frontFacing);
    CHECK(a.out.planes.size() == 4);   // two varyings per set-up triangle
  }

  // Tiny positive w: v0 (1 + e, 0, 0, e), e = 2^-20, is right of x = w and its window x would
  // be about 2^25, too far for 8 sub-pixel bits in 32-bit fixed point. v1 (-1 - 3e, -1, 0, 2 - 3e),
  // v2 (-1 - 3e, 1, 0, 2 - 3e) are inside. Distances to -x + w: v0 -(1 + e) + e = -1, v1 and v2 3.
  //   A = v0 + (v1 - v0) / 4: x (1 + e) + (-2 - 4e) / 4 = 0.5, w e + (2 - 4e) / 4 = 0.5, y -0.25;
  //   B = v0 + (v2 - v0) / 4 = (0.5, 0.25, 0, 0.5). Varyings 4, 8, 0 -> A 5, B 3.
  // Window: 1/w = 2, x 0.5 * 2 * 32 + 32 = 64 (the right edge of the viewport), y 16 and 48.
  TEST_CASE("w near 0: a tiny positive w vertex is clipped to x = w, exactly") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s = shadeByHand(
        {{{1 + kEps, 0, 0, kEps}, {4}}, {{-1 - 3 * kEps, -1, 0, 2 - 3 * kEps}, {8}}, {{-1 - 3 * kEps, 1, 0, 2 - 3 * kEps}, {0}}}, 1, vp);
    CHECK(s.clipMask[0] == 1);
    CHECK(s.clipMask[1] == 0);
    CHECK(s.clipMask[2] == 0);
    raster::clip::Clipper clipper(1, vp);
    const raster::clip::Polygon& p = clipper.clipTriangle(s.record(0), s.record(1), s.record(2), 1);
    REQUIRE(p.count == 4);
    checkRecord(p.vertex[0], {0.5f, -0.25f, 0, 0.5f}, {64, 16, 0.5f, 2}, {5});
    CHECK(p.vertex[1] == s.record(1));
    CHECK(p.vertex[2] == s.record(2));
    checkRecord(p.vertex[3], {0.5f, 0.25f, 0, 0.5f}, {64, 48, 0.5f, 2}, {3});

    // Set up: v1 and v2 are within 2^-15 pixel of window (16, 16) and (16, 48), which snap to
    // pixel-centre coordinates 15.5 and 47.5: the fan covers columns 16..63, rows 16..47, once.
    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesSetUp == 2);
    Coverage c(64, 64);
    for (const SetupTriangle& t : a.out.triangles) c.add(t);
    checkCoverage(c, [](int x, int y) { return x >= 16 && y >= 16 && y <= 47 ? 1 : 0; });
  }

  // Tiny negative w: v0 (-1 + e, -1 + e, -1 + e, -e) is behind the eye, outside x + w, y + w and
  // z + w (distance -1 to each) (mask 2 + 8 + 16). Inside: v1 (1 - 3e, 1 - 3e, 1 - 3e, 2 + 3e),
  // distances 3, 3, 3; v2 (-1 - e, 1 - e, 1 - e, 2 + e), distances 1, 3, 3.
  // Plane x + w:
  //   v0 -> v1 comes in, t = 1/4: A = v0 + (v1 - v0) / 4: x (-1 + e) + (2 - 4e) / 4 = -0.5,
  //     w -e + (2 + 4e) / 4 = 0.5: A = (-0.5, -0.5, -0.5, 0.5), varying 4 + 4/4 = 5;
  //   v2 -> v0 goes out, |dp| = dpPrev = 1, so t = 1/2 from v2: B = v2 + (v0 - v2) / 2:
  //     x (-1 - e) + 2e / 2 = -1, y (1 - e) + (-2 + 2e) / 2 = 0, w (2 + e) + (-2 - 2e) / 2 = 1:
  //     B = (-1, 0, 0, 1), varying 0 + 4 / 2 = 2.
  // Planes y + w and z + w: A's distance is exactly 0 (a frustum corner), which counts as
  // inside, B's 1, v1's and v2's 3: nothing changes, no duplicate of A is made.
  TEST_CASE("w near 0: a tiny negative w vertex is clipped by three planes, exactly") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s = shadeByHand({{{-1 + kEps, -1 + kEps, -1 + kEps, -kEps}, {4}},
                                                  {{1 - 3 * kEps, 1 - 3 * kEps, 1 - 3 * kEps, 2 + 3 * kEps}, {8}},
                                                  {{-1 - kEps, 1 - kEps, 1 - kEps, 2 + kEps}, {0}}},
                                                 1, vp);
    CHECK(s.clipMask[0] == 2 + 8 + 16);
    CHECK(s.clipMask[1] == 0);
    CHECK(s.clipMask[2] == 0);
    raster::clip::Clipper clipper(1, vp);
    const raster::clip::Polygon& p = clipper.clipTriangle(s.record(0), s.record(1), s.record(2), 2 + 8 + 16);
    REQUIRE(p.count == 4);
    // A window: 1/w 2, x = y = -0.5 * 2 * 32 + 32 = 0, z = -0.5 * 2 * 0.5 + 0.5 = 0.
    checkRecord(p.vertex[0], {-0.5f, -0.5f, -0.5f, 0.5f}, {0, 0, 0, 2}, {5});
    CHECK(p.vertex[1] == s.record(1));
    CHECK(p.vertex[2] == s.record(2));
    // B window: x -1 * 32 + 32 = 0, y 32, z 0.5, 1/w 1.
    checkRecord(p.vertex[3], {-1, 0, 0, 1}, {0, 32, 0.5f, 1}, {2});
    for (int i = 0; i < p.count; ++i) CHECK(p.vertex[i][record::kClip + 3] > 0.0f);

    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesClipped == 1);
    CHECK(a.counters.trianglesSetUp == 2);
    // Window A (0, 0), v1 and v2 within 2^-14 pixel of (48, 48) and (16, 48), B (0, 32): snapped,
    // the quad A, v1, v2, B. Its edge A -> v1 (y = x) runs through pixel centres (k, k) and is a
    // right edge (exclusive); B <- v2 (y - x = 32) through centres with py - px = 32, a left edge
    // (inclusive); x = 0 and y = 48 pass between centres. So px < py <= 47, py - px <= 32.
    Coverage c(64, 64);
    for (const SetupTriangle& t : a.out.triangles) c.add(t);   // bounds inside, checked by add
    checkCoverage(c, [](int x, int y) { return x < y && y <= 47 && y - x <= 32 ? 1 : 0; });
  }

  TEST_CASE("behind the eye: all three w < 0 is rejected although x/w, y/w, z/w look inside") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s =
        shadeByHand({{{-0.5f, -0.5f, -0.5f, -1}, {}}, {{0.5f, -0.5f, -0.5f, -1}, {}}, {{0, 0.5f, -0.5f, -1}, {}}}, 0, vp);
    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesRejected == 1);
    CHECK(a.counters.trianglesSetUp == 0);
    CHECK(a.out.triangles.empty());
  }

  // v0 (-0.5, -0.5), v1 (1.5, -0.5), v2 (-0.5, 1.5) (z 0, w 1) cut by x <= w then y <= w:
  //   x <= w: distances 1.5, -0.5, 1.5. v0 kept; v0 -> v1 goes out, t = 0.5 / 2 = 1/4 from v1:
  //     P = v1 + (v0 - v1) / 4 = (1, -0.5); v1 -> v2 comes in, t = 1/4 from v1:
  //     Q = v1 + (v2 - v1) / 4 = (1, 0); v2 kept. -> v0, P, Q, v2.
  //   y <= w: distances 1.5, 1.5, 1, -0.5. Q -> v2 goes out, t = -0.5 / -1.5 from v2:
  //     R = v2 + t (Q - v2), t = float(1/3) = 11184811 * 2^-25, t * 1.5 = 0.5 + 2^-26 -> 0.5 in
  //     float, so R = (0, 1) exactly; v2 -> v0 comes in, t = 1/4 from v2: S = (-0.5, 1).
  //   -> pentagon v0, P, Q, R, S: 5 vertices, a fan of 3 triangles.
  TEST_CASE("two planes: the corner cut off gives a pentagon") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s = shadeByHand({{{-0.5f, -0.5f, 0, 1}, {}}, {{1.5f, -0.5f, 0, 1}, {}}, {{-0.5f, 1.5f, 0, 1}, {}}}, 0, vp);
    CHECK((s.clipMask[0] | s.clipMask[1] | s.clipMask[2]) == 1 + 4);
    raster::clip::Clipper clipper(0, vp);
    const raster::clip::Polygon& p = clipper.clipTriangle(s.record(0), s.record(1), s.record(2), 1 + 4);
    REQUIRE(p.count == 5);
    CHECK(p.vertex[0] == s.record(0));
    // Window: x * 32 + 32, y * 32 + 32.
    checkRecord(p.vertex[1], {1, -0.5f, 0, 1}, {64, 16, 0.5f, 1});
    checkRecord(p.vertex[2], {1, 0, 0, 1}, {64, 32, 0.5f, 1});
    checkRecord(p.vertex[3], {0, 1, 0, 1}, {32, 64, 0.5f, 1});
    checkRecord(p.vertex[4], {-0.5f, 1, 0, 1}, {16, 64, 0.5f, 1});

    // Coverage: window x 16..64, y 16..64 below the cut from (64, 32) to (32, 64), x + y < 96.
    // Pixel centres (px + 0.5, py + 0.5) on the cut have px + py = 95; it is a right edge, so
    // they are out: columns 16..63, rows 16..63 with px + py <= 94, each once.
    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesSetUp == 3);
    Coverage c(64, 64);
    for (const SetupTriangle& t : a.out.triangles) c.add(t);
    checkCoverage(c, [](int x, int y) { return x >= 16 && y >= 16 && x + y <= 94 ? 1 : 0; });
    const int covered = int(c.pixels().size());
    // 16 columns (16..31) of 48 rows, then columns 32..63 with 79 - px rows: 768 + (47 + ... + 16) = 768 + 1008.
    CHECK(covered == 1776);
  }

  // v0 (-1, -1), v1 (3, -1), v2 (-1, 3): the hypotenuse x + y = 2 passes through the corner (1, 1).
  //   x <= w: distances 2, -2, 2: P = (1, -1), Q = (1, 1) (t = 1/2). -> v0, P, Q, v2.
  //   y <= w: distances 2, 2, 0, -2. Q's distance 0 is inside, so Q is kept, and Q -> v2 still
  //     "goes out": t = -0 / -2 = 0 from Q makes a second (1, 1) (Mesa's draw_pipe_clip does the
  //     same); v2 -> v0 comes in at S = (-1, 1). -> v0, P, Q, Q', S: 5 vertices.
  // The fan's middle triangle (Q, Q', v0) has zero area and setup drops it: 2 set up, covering
  // the 64 x 64 viewport once.
  TEST_CASE("two planes: an edge through the viewport corner duplicates the corner, setup drops the sliver") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s = shadeByHand({{{-1, -1, 0, 1}, {}}, {{3, -1, 0, 1}, {}}, {{-1, 3, 0, 1}, {}}}, 0, vp);
    raster::clip::Clipper clipper(0, vp);
    const raster::clip::Polygon& p = clipper.clipTriangle(s.record(0), s.record(1), s.record(2), 1 + 4);
    REQUIRE(p.count == 5);
    checkRecord(p.vertex[1], {1, -1, 0, 1}, {64, 0, 0.5f, 1});
    checkRecord(p.vertex[2], {1, 1, 0, 1}, {64, 64, 0.5f, 1});
    checkRecord(p.vertex[3], {1, 1, 0, 1}, {64, 64, 0.5f, 1});
    checkRecord(p.vertex[4], {-1, 1, 0, 1}, {0, 64, 0.5f, 1});
    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesClipped == 1);
    CHECK(a.counters.trianglesSetUp == 2);
    Coverage c(64, 64);
    for (const SetupTriangle& t : a.out.triangles) c.add(t);
    checkCoverage(c, [](int, int) { return 1; });
  }

  TEST_CASE("NaN and Inf positions: discarded by the clipper, no crash anywhere") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    raster::clip::Clipper clipper(0, vp);
    struct Case {
      const char* what;
      std::vector<ClipVertex> v;
    };
    const Case discarded[] = {
        // x = +Inf is right of x = w (mask 1); its distance -Inf + 1 is not finite.
        {"+Inf x", {{{kInf, 0, 0, 1}, {}}, {{0, 0, 0, 1}, {}}, {{0, 0.5f, 0, 1}, {}}}},
        // y = -Inf below y + w (mask 8): distance -Inf.
        {"-Inf y", {{{0, 0, 0, 1}, {}}, {{0.5f, -kInf, 0, 1}, {}}, {{0, 0.5f, 0, 1}, {}}}},
        // NaN flags nothing, but another vertex is clipped: the NaN distance discards, whether
        // it is the walk's first vertex or met inside the loop.
        {"NaN x first", {{{kNaN, 0, 0, 1}, {}}, {{2, 0, 0, 1}, {}}, {{0, 0.5f, 0, 1}, {}}}},
        {"NaN x second", {{{2, 0, 0, 1}, {}}, {{kNaN, 0, 0, 1}, {}}, {{0, 0.5f, 0, 1}, {}}}},
        {"NaN w", {{{0, 0, 0, kNaN}, {}}, {{0, 2, 0, 1}, {}}, {{0.5f, 0, 0, 1}, {}}}},
        // x = w = Inf flags nothing (Inf > Inf is false); another vertex's y = 2 > 1 clips against
        // -y + w, where this vertex's distance Inf * 0 + ... is NaN.
        {"Inf x and w", {{{kInf, 0, 0, kInf}, {}}, {{0, 2, 0, 1}, {}}, {{0.5f, 0, 0, 1}, {}}}},
    };
    for (const Case& k : discarded) {
      CAPTURE(k.what);
      const raster::ShadedVertices s = shadeByHand(k.v, 0, vp);
      const unsigned mask = s.clipMask[0] | s.clipMask[1] | s.clipMask[2];
      REQUIRE(mask != 0);
      REQUIRE((s.clipMask[0] & s.clipMask[1] & s.clipMask[2]) == 0);
      CHECK(clipper.clipTriangle(s.record(0), s.record(1), s.record(2), mask).count == 0);
      const Assembled a = assemble(s, vp);
      CHECK(a.counters.trianglesClipped == 1);
      CHECK(a.counters.trianglesSetUp == 0);
    }
    // With no clip bit at all the triangle goes straight to setup, which drops a NaN window
    // position (limits::kMaxWindowCoordinate). w = Inf is finite in window space: 1/w = 0 puts
    // that vertex at the viewport centre (32, 32), and the triangle (32,32), (48,32), (32,48)
    // is set up. Whatever comes out stays inside the framebuffer.
    const struct {
      std::vector<ClipVertex> v;
      uint64_t setUp;
    } unclipped[] = {
        {{{{kNaN, 0, 0, 1}, {}}, {{0.5f, 0, 0, 1}, {}}, {{0, 0.5f, 0, 1}, {}}}, 0},
        {{{{0, 0, 0, kInf}, {}}, {{0.5f, 0, 0, 1}, {}}, {{0, 0.5f, 0, 1}, {}}}, 1},
        {{{{kNaN, kNaN, kNaN, kNaN}, {}}, {{kNaN, kNaN, kNaN, kNaN}, {}}, {{kNaN, kNaN, kNaN, kNaN}, {}}}, 0},
    };
    for (const auto& k : unclipped) {
      const raster::ShadedVertices s = shadeByHand(k.v, 0, vp);
      CHECK((s.clipMask[0] | s.clipMask[1] | s.clipMask[2]) == 0);
      const Assembled a = assemble(s, vp);
      CHECK(a.counters.trianglesIn == 1);
      CHECK(a.counters.trianglesClipped == 0);
      CHECK(a.counters.trianglesSetUp == k.setUp);
      for (const SetupTriangle& t : a.out.triangles) {
        CHECK(t.minX >= 0);
        CHECK(t.minY >= 0);
        CHECK(t.maxX <= 63);
        CHECK(t.maxY <= 63);
      }
    }
  }

  // No guard band: llvmpipe clips x and y to the viewport planes. v1 (2^20 - 1, -1, 0, 1) would
  // have window x 2^25, beyond 32-bit fixed point with 8 sub-pixel bits (2^33).
  //   x <= w: distances v0 (-1, -1) 2, v1 -(2^20 - 1) + 1 = 2 - 2^20, v2 (-1, 1) 2.
  //   v0 -> v1 goes out, t = 2 / 2^20 = 2^-19 from v0: P = (-1 + 2^-19 * 2^20, -1) = (1, -1);
  //   v1 -> v2 comes in, t = 2^-19 from v2: Q = (-1 + 2, 1 - 2^-19 * 2) = (1, 1 - 2^-18).
  //   -> v0, P, Q, v2. Window: P (64, 0), Q (64, 64 - 2^-13), every vertex inside [0, 64].
  TEST_CASE("guard band: a triangle far beyond the viewport in x is clipped to it") {
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const float far = 1048575.0f;   // 2^20 - 1
    const raster::ShadedVertices s = shadeByHand({{{-1, -1, 0, 1}, {}}, {{far, -1, 0, 1}, {}}, {{-1, 1, 0, 1}, {}}}, 0, vp);
    CHECK(s.clipMask[1] == 1);
    raster::clip::Clipper clipper(0, vp);
    const raster::clip::Polygon& p = clipper.clipTriangle(s.record(0), s.record(1), s.record(2), 1);
    REQUIRE(p.count == 4);   // a guard band would have left the triangle as it is
    CHECK(p.vertex[0] == s.record(0));
    checkRecord(p.vertex[1], {1, -1, 0, 1}, {64, 0, 0.5f, 1});
    checkRecord(p.vertex[2], {1, 1 - 1.0f / 262144, 0, 1}, {64, 64 - 1.0f / 8192, 0.5f, 1});
    CHECK(p.vertex[3] == s.record(2));
    for (int i = 0; i < p.count; ++i) {
      CHECK(p.vertex[i][record::kWindow + 0] >= 0.0f);
      CHECK(p.vertex[i][record::kWindow + 0] <= 64.0f);
    }

    // Set up as the fan (P, Q, v0), (Q, v2, v0): Q's y, 64 - 2^-13, snaps to (63.5 - 2^-13) * 256
    // = 16256 - 2^-5 -> 16256, the same row as v2. Every pixel of the framebuffer once, bounds
    // inside it.
    const Assembled a = assemble(s, vp);
    CHECK(a.counters.trianglesClipped == 1);
    CHECK(a.counters.trianglesSetUp == 2);
    Coverage c(64, 64);
    for (const SetupTriangle& t : a.out.triangles) {
      CHECK(t.maxX == 63);
      c.add(t);
    }
    checkCoverage(c, [](int, int) { return 1; });
  }

  TEST_CASE("primitive assembly: instances read their own records, in instance-major order") {
    // Two instances of one triangle, the second moved right by 1 in clip x (16 pixels):
    // records 0..2 are instance 0, 3..5 instance 1; indices address one instance's vertices.
    const raster::ViewportTransform vp = fboViewport(64, 64);
    const raster::ShadedVertices s = shadeByHand({{{-1, -1, 0, 1}, {}}, {{-0.5f, -1, 0, 1}, {}}, {{-1, -0.5f, 0, 1}, {}},
                                                  {{0, -1, 0, 1}, {}}, {{0.5f, -1, 0, 1}, {}}, {{0, -0.5f, 0, 1}, {}}},
                                                 0, vp);
    const raster::SetupState state = setupState(64, 64);
    const std::vector<uint32_t> indices{0, 1, 2};
    const raster::AssemblyInput in{state, s, indices, 3, vp};
    SetupOutput out;
    raster::PipelineCounters counters;
    raster::assemblePrimitives(in, 0, 2, out.lists(), counters);
    REQUIRE(out.triangles.size() == 2);
    // Window x: instance 0 spans 0..16 (fixed -128 >> 8 = -1, trimmed to 0), instance 1 spans
    // 32..48 (fixed (32 - 0.5) * 256 = 8064, 8064 >> 8 = 31).
    CHECK(out.triangles[0].minX == 0);
    CHECK(out.triangles[1].minX == 31);
    // A run [1, 2) is the second instance alone.
    SetupOutput second;
    raster::assemblePrimitives(in, 1, 2, second.lists(), counters);
    REQUIRE(second.triangles.size() == 1);
    CHECK(second.triangles[0].minX == 31);
    CHECK(counters.trianglesIn == 3);
  }
}
