// Clipping (raster/geometry/clip.h, a port of Mesa's draw_pipe_clip.c) and primitive assembly
// (raster/geometry/assemble.h): trivial rejection, near-plane crossings, two planes, w near
// 0 and behind the eye, non-finite positions, and the viewport planes that stand where a
// guard band would. Expected vertices are worked out by hand; the values chosen make every
// step exact in float.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "raster/geometry/assemble.h"
#include "raster/geometry/clip.h"
#include "raster/geometry/vertex_stage.h"
#include "tests/geometry/geometry_test_helpers.h"

namespace {

using geometry_test::clipVertex;
using raster::vertex_record::kClip;
using raster::vertex_record::kVaryings;
using raster::vertex_record::kWindow;

// x and y map [-1, 1] to [0, 64]; z to [0, 1].
raster::ViewportTransform viewport64() { return {{32.0f, 32.0f, 0.5f}, {32.0f, 32.0f, 0.5f}}; }

unsigned maskOf(const geometry_test::Vertex& v) { return raster::vertex_stage::clipMask(v.get() + kClip); }

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("clip flags: one bit per plane, none for NaN") {
    CHECK(maskOf(clipVertex(0, 0, 0, 1)) == 0u);
    CHECK(maskOf(clipVertex(2, 0, 0, 1)) == 1u << 0);    // x > w
    CHECK(maskOf(clipVertex(-2, 0, 0, 1)) == 1u << 1);   // x + w < 0
    CHECK(maskOf(clipVertex(0, 2, 0, 1)) == 1u << 2);
    CHECK(maskOf(clipVertex(0, -2, 0, 1)) == 1u << 3);
    CHECK(maskOf(clipVertex(0, 0, -2, 1)) == 1u << 4);   // near: z + w < 0
    CHECK(maskOf(clipVertex(0, 0, 2, 1)) == 1u << 5);    // far
    // Behind the eye (w < 0): outside x + w >= 0 and x <= w at once, and the near plane.
    CHECK(maskOf(clipVertex(0, 0, 0, -1)) == ((1u << 0) | (1u << 1) | (1u << 2) | (1u << 3) | (1u << 4) | (1u << 5)));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK(maskOf(clipVertex(nan, 0, 0, 1)) == 0u);   // ordered compares: no flag
  }

  // A = (0,0,-2,1) is outside the near plane (z + w = -1), B = (0,0,0,1) and C = (1,0,0,1)
  // inside (z + w = 1). Edge A->B is cut at t = 1/2 from B: (0,0,-1,1); edge C->A at t = 1/2
  // from C: (0.5,0,-1,1). Varyings 10, 20, 30 give 15 and 20 there. The polygon, in Mesa's
  // order: [AB, B, C, CA].
  TEST_CASE("clip: a triangle crossing the near plane") {
    raster::clip::Clipper clipper(1, viewport64());
    const auto a = clipVertex(0, 0, -2, 1, {10}), b = clipVertex(0, 0, 0, 1, {20}), c = clipVertex(1, 0, 0, 1, {30});
    const raster::clip::Polygon& p = clipper.clipTriangle(a.get(), b.get(), c.get(), maskOf(a) | maskOf(b) | maskOf(c));
    REQUIRE(p.count == 4);
    CHECK(p.vertex[1] == b.get());
    CHECK(p.vertex[2] == c.get());
    const float* ab = p.vertex[0];
    const float* ca = p.vertex[3];
    CHECK(ab[kClip + 0] == 0.0f);
    CHECK(ab[kClip + 2] == -1.0f);
    CHECK(ab[kClip + 3] == 1.0f);
    CHECK(ab[kVaryings] == 15.0f);
    CHECK(ca[kClip + 0] == 0.5f);
    CHECK(ca[kClip + 2] == -1.0f);
    CHECK(ca[kVaryings] == 20.0f);
    // Window positions of made vertices: x * (1/w) * scale + translate; z on the near plane
    // maps to 0; the fourth component is 1/w.
    CHECK(ca[kWindow + 0] == 0.5f * 32.0f + 32.0f);
    CHECK(ca[kWindow + 2] == 0.0f);
    CHECK(ca[kWindow + 3] == 1.0f);
  }

  // A = (0,0), B = (3,0), C = (0,3) (w = 1) against x <= w and then y <= w: the first cut
  // leaves [A, (1,0), (1,2), C] (t = 1/3: 3 * 0.33333334f rounds to exactly 1), the second
  // [A, (1,0), (1,1), (0,1)]: the unit square.
  TEST_CASE("clip: a triangle crossing two planes becomes the polygon inside both") {
    raster::clip::Clipper clipper(0, viewport64());
    const auto a = clipVertex(0, 0, 0, 1), b = clipVertex(3, 0, 0, 1), c = clipVertex(0, 3, 0, 1);
    const raster::clip::Polygon& p = clipper.clipTriangle(a.get(), b.get(), c.get(), maskOf(a) | maskOf(b) | maskOf(c));
    REQUIRE(p.count == 4);
    const float expected[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) {
      INFO("vertex " << i);
      CHECK(p.vertex[i][kClip + 0] == expected[i][0]);
      CHECK(p.vertex[i][kClip + 1] == expected[i][1]);
    }
  }

  TEST_CASE("clip: w near 0 and behind the eye leave only vertices in front, with finite windows") {
    raster::clip::Clipper clipper(0, viewport64());
    for (float wBehind : {-1.0f, -1e-30f, 0.0f, 1e-30f}) {
      INFO("w = " << wBehind);
      const auto a = clipVertex(0, 0, -1, wBehind), b = clipVertex(0.5f, 0, 0.5f, 1), c = clipVertex(0, 0.5f, 0.5f, 1);
      const unsigned mask = maskOf(a) | maskOf(b) | maskOf(c);
      REQUIRE(mask != 0u);
      const raster::clip::Polygon& p = clipper.clipTriangle(a.get(), b.get(), c.get(), mask);
      CHECK(p.count >= 3);
      for (int i = 0; i < p.count; ++i) {
        const float* v = p.vertex[i];
        CHECK(v[kClip + 3] > 0.0f);                                   // in front of the eye
        CHECK(v[kClip + 2] + v[kClip + 3] >= 0.0f);                   // inside the near plane
        for (int k = 0; k < 4; ++k) CHECK(std::isfinite(v[kWindow + k]));
      }
    }
  }

  TEST_CASE("clip: a NaN or infinite position discards the triangle") {
    raster::clip::Clipper clipper(0, viewport64());
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
      const auto a = clipVertex(bad, 0, 0, 1), b = clipVertex(3, 0, 0, 1), c = clipVertex(0, 0.5f, 0, 1);
      const raster::clip::Polygon& p = clipper.clipTriangle(a.get(), b.get(), c.get(), 1u << 0);
      CHECK(p.count < 3);
    }
  }

  // Primitive assembly over a draw of records: trivial reject by the AND of clip masks,
  // direct setup by none, clipping otherwise; the viewport planes stand where a guard band
  // would (llvmpipe clips x and y), so a triangle reaching far beyond the viewport is cut to
  // it and its set-up bounds stay inside the framebuffer.
  TEST_CASE("assemble: trivial reject, direct setup, and clipping to the viewport planes") {
    const raster::ViewportTransform vp = viewport64();
    raster::ShadedVertices shaded;
    shaded.varyingFloats = 0;
    shaded.stride = kVaryings;
    shaded.data.reserve(7 * 8);
    shaded.clipMask.reserve(7);   // (and GCC 12 then sees push_back has room: no -Wstringop-overflow)
    auto add = [&](float x, float y, float z, float w) {
      float record[8] = {x, y, z, w, 0, 0, 0, 0};
      const float oow = 1.0f / w;
      for (int k = 0; k < 3; ++k) record[kWindow + k] = record[k] * oow * vp.scale[k] + vp.translate[k];
      record[kWindow + 3] = oow;
      shaded.data.insert(shaded.data.end(), record, record + 8);
      shaded.clipMask.push_back(raster::vertex_stage::clipMask(record));
    };
    add(2, 0, 0, 1);      // 0: right of x = w
    add(3, 0.5f, 0, 1);   // 1: right of x = w
    add(2, 0.9f, 0, 1);   // 2: right of x = w
    add(-0.5f, -0.5f, 0, 1);   // 3: inside
    add(0.5f, -0.5f, 0, 1);    // 4: inside
    add(0.0f, 0.5f, 0, 1);     // 5: inside
    add(-100, -0.9f, 0, 1);    // 6: far left (a guard band would keep it)
    const std::vector<uint32_t> indices = {0, 1, 2, 3, 4, 5, 6, 4, 5};
    raster::SetupState setup;
    setup.framebufferWidth = 64;
    setup.framebufferHeight = 64;
    std::vector<raster::SetupTriangle> triangles;
    std::vector<raster::Plane> planes;
    raster::PipelineCounters counters;
    const raster::AssemblyInput in{setup, shaded, indices, 7, vp};
    raster::assemblePrimitives(in, 0, 3, {triangles, planes}, counters);
    CHECK(counters.trianglesIn == 3);
    CHECK(counters.trianglesRejected == 1);
    CHECK(counters.trianglesClipped == 1);
    REQUIRE(triangles.size() >= 2);
    CHECK(counters.trianglesSetUp == triangles.size());
    for (const raster::SetupTriangle& tri : triangles) {
      CHECK(tri.minX >= 0);
      CHECK(tri.maxX <= 63);
      CHECK(tri.minY >= 0);
      CHECK(tri.maxY <= 63);
    }
    // The clipped triangle's pieces reach the left edge of the viewport.
    int leftmost = 64;
    for (size_t i = 1; i < triangles.size(); ++i) leftmost = std::min(leftmost, triangles[i].minX);
    CHECK(leftmost == 0);
  }
}
