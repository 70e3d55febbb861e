// Setup 16 triangles at a time (geometry/setup_avx512.h, in builds with AVX-512) appends
// exactly what setupTriangle appends one by one: the same triangles in the same order,
// every record field and varying plane bit for bit, the same origins and counters. Random
// draws mix pixel-sized and screen-sized triangles, both windings, zero areas, coordinates
// at and past the fixed-point limit, NaN and infinite positions and depths, polygon offset, culling,
// both fill rules and clipped triangles between unclipped ones (which make the batch set
// up what waits before them). In a build without the batch both runs take the scalar path.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/geometry/assemble.h"
#include "tests/geometry/geometry_test_helpers.h"

namespace {

using namespace geometry_test;

// Equal bits, or both NaN (a NaN's payload may follow either operand of a product).
bool sameFloat(float a, float b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}
bool samePlane(const raster::Plane& a, const raster::Plane& b) {
  return sameFloat(a.a0, b.a0) && sameFloat(a.dadx, b.dadx) && sameFloat(a.dady, b.dady);
}

struct Run {
  SetupOutput out;
  std::vector<uint32_t> origins;
  raster::PipelineCounters counters;
};

Run assembled(const raster::SetupState& state, const raster::ShadedVertices& shaded, const std::vector<uint32_t>& indices,
              const raster::ViewportTransform& vp, bool batched) {
  Run run;
  raster::AssemblyInput in{state, shaded, indices, shaded.count(), vp, batched};
  raster::SetupLists lists{run.out.triangles, run.out.planes, &run.origins};
  raster::assemblePrimitives(in, 0, indices.size() / 3, lists, run.counters);
  return run;
}

// A window coordinate along an axis of `extent` pixels, from one of several families.
float windowCoordinate(std::mt19937& rng, int extent) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float limit = raster::limits::kMaxWindowCoordinate;
  switch (rng() % 16) {
    case 0: return float(int(unit(rng) * float(extent))) + 0.5f;   // a pixel centre
    case 1: return float(int(unit(rng) * float(extent))) + 0.5f + (unit(rng) - 0.5f) * 0x1p-8f;
    case 2: return (unit(rng) < 0.5f ? -1.0f : 1.0f) * limit;        // at the limit: kept
    case 3: return (unit(rng) < 0.5f ? -1.0f : 1.0f) * std::nextafter(limit, 2.0f * limit);   // past it
    case 4: return unit(rng) < 0.5f ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
    case 5: return (unit(rng) - 0.5f) * limit * 1.5f;                // far off screen
    default: return -40.0f + unit(rng) * float(extent + 80);         // on screen and a little past it
  }
}

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("setup 16 at a time appends exactly what setup one at a time appends") {
    std::mt19937 rng(2611);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int compared = 0, setUp = 0;
    for (int draw = 0; draw < 96; ++draw) {
      const int width = 1 + int(rng() % 700), height = 1 + int(rng() % 500);
      const int varyings = int(rng() % 3) * 4;   // 0, 4 or 8 floats
      raster::SetupState state = setupState(width, height, draw % 2 == 1, varyings);
      state.cullBack = draw % 4 >= 2;
      state.polygonOffset = draw % 8 >= 4;
      state.offsetFactor = (unit(rng) - 0.3f) * 4.0f;
      state.offsetUnitsScaled = raster::polygonOffsetUnits((unit(rng) - 0.3f) * 8.0f, 24);
      state.drawIndex = uint32_t(draw);
      const raster::ViewportTransform vp = fboViewport(width, height);

      // Vertices: most with window positions set directly (clip mask 0), some from clip
      // positions outside the frustum, which send their triangles through the clipper.
      const int vertexCount = 60 + int(rng() % 200);
      std::vector<ClipVertex> clipVertices(static_cast<size_t>(vertexCount));
      for (ClipVertex& v : clipVertices) {
        const float w = 0.5f + unit(rng) * 2.0f;
        v.clip = {(unit(rng) * 2.4f - 1.2f) * w, (unit(rng) * 2.4f - 1.2f) * w, (unit(rng) * 2.0f - 1.0f) * w, w};
        for (int i = 0; i < varyings; ++i) v.varyings.push_back((unit(rng) - 0.5f) * 100.0f);
      }
      raster::ShadedVertices shaded = shadeByHand(clipVertices, varyings, vp);
      for (int i = 0; i < vertexCount; ++i) {
        if (rng() % 8 == 0) continue;   // keeps its clip position (and mask, often nonzero)
        float* r = shaded.record(i);
        r[record::kWindow + 0] = windowCoordinate(rng, width);
        r[record::kWindow + 1] = windowCoordinate(rng, height);
        // z at times infinite or NaN: a slope of the polygon offset then NaN, the other not.
        const uint32_t zKind = rng() % 32;
        r[record::kWindow + 2] = zKind == 0   ? std::numeric_limits<float>::infinity()
                                 : zKind == 1 ? std::numeric_limits<float>::quiet_NaN()
                                              : unit(rng) * 1.4f - 0.2f;
        r[record::kWindow + 3] = rng() % 32 == 0 ? 0.0f : 0.05f + unit(rng) * 3.0f;
        shaded.clipMask[size_t(i)] = 0;
      }
      // Triangles: random vertices, often neighbours (small triangles), sometimes repeated
      // (zero area); a count that leaves a partial batch.
      std::vector<uint32_t> indices;
      const int triangles = 17 + int(rng() % 300);
      for (int t = 0; t < triangles; ++t) {
        const uint32_t a = uint32_t(rng() % uint32_t(vertexCount));
        for (int k = 0; k < 3; ++k)
          indices.push_back(rng() % 24 == 0 ? a : rng() % 2 ? uint32_t(a + uint32_t(k)) % uint32_t(vertexCount) : uint32_t(rng() % uint32_t(vertexCount)));
      }

      const Run one = assembled(state, shaded, indices, vp, false);
      const Run batched = assembled(state, shaded, indices, vp, true);
      CAPTURE(draw);
      REQUIRE(batched.out.triangles.size() == one.out.triangles.size());
      CHECK(batched.origins == one.origins);
      CHECK(batched.counters.trianglesSetUp == one.counters.trianglesSetUp);
      CHECK(batched.counters.trianglesClipped == one.counters.trianglesClipped);
      REQUIRE(batched.out.planes.size() == one.out.planes.size());
      for (size_t t = 0; t < one.out.triangles.size(); ++t) {
        const SetupTriangle &a = one.out.triangles[t], &b = batched.out.triangles[t];
        CAPTURE(t);
        for (int e = 0; e < 3; ++e) CHECK(sameEdge(a.edge[e], b.edge[e]));
        CHECK(a.minX == b.minX);
        CHECK(a.minY == b.minY);
        CHECK(a.maxX == b.maxX);
        CHECK(a.maxY == b.maxY);
        CHECK(samePlane(a.z, b.z));
        CHECK(samePlane(a.w, b.w));
        CHECK(sameFloat(a.depthOffset, b.depthOffset));
        CHECK(a.varyingBase == b.varyingBase);
        CHECK(a.drawIndex == b.drawIndex);
        CHECK(a.frontFacing == b.frontFacing);
        ++compared;
      }
      for (size_t p = 0; p < one.out.planes.size(); ++p) {
        CAPTURE(p);
        CHECK(samePlane(one.out.planes[p], batched.out.planes[p]));
      }
      setUp += int(one.counters.trianglesSetUp);
    }
    // The draws must reach setup's every outcome, not reject everything.
    CHECK(compared > 5000);
    CHECK(setUp == compared);
  }
}
