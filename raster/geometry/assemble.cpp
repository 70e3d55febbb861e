// Primitive assembly, trivial rejection, clipping and setup of a run of primitives (see assemble.h).
#include "raster/geometry/assemble.h"

#include "raster/geometry/clip.h"
#include "raster/simd/prefetch.h"

namespace raster {
namespace {

// Where the triangle just set up came from, when pixel history keeps it (kClippedOrigin).
void labelLast(SetupLists out, size_t primitive, bool clipped) {
  if (out.origins) out.origins->push_back(uint32_t(primitive) | (clipped ? kClippedOrigin : 0u));
}

// How many instances ahead of the one being assembled its records are prefetched, and up to
// what size of an instance's records (a small mesh drawn many times, as hdr's 1,000 cubes).
// The vertex stage wrote the records in a loop of its own, so by now they are out of the
// nearer caches (hdr: 24,000 records of 72 bytes, half of them written by the other core),
// and the batched setup's gathers waited on them.
constexpr int kInstancesAhead = 2;
constexpr size_t kPrefetchedInstanceBytes = 4096;

// Every line of instance `instance`'s records, if it is one of the draw's.
void prefetchInstance(const AssemblyInput& in, size_t instance) {
  const size_t instanceFloats = size_t(in.vertexCount) * size_t(in.shaded.stride);
  if (instanceFloats * (instance + 1) > in.shaded.data.size()) return;
  simd::prefetchLines(in.shaded.data.data() + instance * instanceFloats, instanceFloats * sizeof(float));
}

}  // namespace

void assemblePrimitives(const AssemblyInput& in, size_t first, size_t end, SetupLists out, PipelineCounters& counters) {
  const size_t perInstance = in.indices.size() / 3;
  clip::Clipper clipper(in.setup.varyingFloats, in.viewport);
#if RASTER_ZMM_PAIRS
  // Unclipped triangles wait in a batch of 16, set up together (setup_avx512.h); a clipped
  // one first sets up those waiting, so the list keeps primitive order. The batch names
  // records by 32-bit offsets.
  const bool batched = in.batched && in.shaded.data.size() < (size_t(1) << 31);
  TriangleBatch batch;
  uint32_t batchPrimitive[kSetupBatch];
  const auto setUpBatch = [&] {
    for (uint32_t lanes = setupTriangleBatch(in.setup, in.shaded.data.data(), batch, out); lanes; lanes &= lanes - 1) {
      counters.trianglesSetUp++;
      labelLast(out, batchPrimitive[__builtin_ctz(lanes)], /*clipped=*/false);
    }
    batch.count = 0;
  };
#endif
  const bool prefetching = size_t(in.vertexCount) * size_t(in.shaded.stride) * sizeof(float) <= kPrefetchedInstanceBytes;
  if (prefetching && first < end)
    for (int ahead = 0; ahead < kInstancesAhead; ++ahead) prefetchInstance(in, first / perInstance + size_t(ahead));
  for (size_t p = first; p < end; ++p) {
    const int base = int(p / perInstance) * in.vertexCount;
    const size_t t = (p % perInstance) * 3;
    if (prefetching && t == 0) prefetchInstance(in, p / perInstance + kInstancesAhead);
    const int r0 = base + int(in.indices[t]), r1 = base + int(in.indices[t + 1]), r2 = base + int(in.indices[t + 2]);
    const unsigned m0 = in.shaded.clipMask[size_t(r0)], m1 = in.shaded.clipMask[size_t(r1)], m2 = in.shaded.clipMask[size_t(r2)];
    counters.trianglesIn++;
    if (m0 & m1 & m2) {   // all three outside one plane
      counters.trianglesRejected++;
      continue;
    }
    if ((m0 | m1 | m2) == 0) {
#if RASTER_ZMM_PAIRS
      if (batched) {
        const int lane = batch.count++;
        batch.vertex[0][lane] = r0 * in.shaded.stride;
        batch.vertex[1][lane] = r1 * in.shaded.stride;
        batch.vertex[2][lane] = r2 * in.shaded.stride;
        batchPrimitive[lane] = uint32_t(p);
        if (batch.count == kSetupBatch) setUpBatch();
        continue;
      }
#endif
      if (setupTriangle(in.setup, in.shaded.record(r0), in.shaded.record(r1), in.shaded.record(r2), out)) {
        counters.trianglesSetUp++;
        labelLast(out, p, /*clipped=*/false);
      }
      continue;
    }
    counters.trianglesClipped++;
#if RASTER_ZMM_PAIRS
    if (batch.count) setUpBatch();
#endif
    const clip::Polygon& polygon =
        clipper.clipTriangle(in.shaded.record(r0), in.shaded.record(r1), in.shaded.record(r2), m0 | m1 | m2);
    // The fan (p[i-1], p[i], p[0]) keeps GL's last-vertex convention.
    for (int i = 2; i < polygon.count; ++i) {
      if (!setupTriangle(in.setup, polygon.vertex[i - 1], polygon.vertex[i], polygon.vertex[0], out)) continue;
      counters.trianglesSetUp++;
      labelLast(out, p, /*clipped=*/true);
    }
  }
#if RASTER_ZMM_PAIRS
  if (batch.count) setUpBatch();
#endif
}

}  // namespace raster
