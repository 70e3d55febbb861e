// Primitive assembly: a draw's index list and shaded vertices in, set-up triangles out.
//
// Triangles are read instance-major (every triangle of instance 0, then of instance 1, ...).
// Each is trivially rejected when its three vertices lie outside one frustum plane (their
// clip masks share a bit), set up directly when no vertex is outside any plane, and
// otherwise clipped (clip.h) and its polygon set up as a fan, as Mesa's draw module does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "raster/contract.h"
#include "raster/geometry/setup.h"

namespace raster {

// A draw's primitives, as assemblePrimitives reads them.
struct AssemblyInput {
  const SetupState& setup;
  const ShadedVertices& shaded;        // records of every (instance, vertex)
  std::span<const uint32_t> indices;   // three per triangle, into one instance's vertices
  int vertexCount;                     // vertices per instance
  const ViewportTransform& viewport;   // for the window positions of vertices clipping makes
  // Unclipped triangles set up 16 at a time where the build has the batch (setup_avx512.h):
  // the same records; off for `raster --scalar`.
  bool batched = true;
};

// Assembles primitives [first, end) of the draw, appending what survives to `out` in that
// order and counting what it saw in `counters`.
void assemblePrimitives(const AssemblyInput& in, size_t first, size_t end, SetupLists out, PipelineCounters& counters);

}  // namespace raster
