// Stage 5 under a coarse shading rate (methods.h, `shading`): one tile's triangles, in API
// order, with one fragment-shader invocation per coarse pixel, as Vulkan's
// VK_KHR_fragment_shading_rate defines coarse fragments:
//   - coverage and the early depth test stay per pixel, exactly the 1x1 walk's (walk.h's
//     depthTestBin, depth writes included);
//   - a lane stands for a coarse pixel of W x H pixels, so a 2x2 quad of lanes is a coarse
//     quad and dFdx / dFdy are differences across coarse pixels; the lanes are interpolated
//     at their coarse pixels' centres, gl_FragCoord included;
//   - a lane's outputs are written to every pixel of its coarse pixel that is covered and
//     passed its depth test (merge::writeCoarseColorOutput); the others keep their values.
//
// Input:  the pass's TileJob with coarseWidth x coarseHeight above 1x1, the tile's bin.
// Output: the tile's texels, through merge/.
//
// Coarse pixels are aligned to the framebuffer's memory origin. Their sides (1, 2 or 4)
// divide the 16-row bands and 64-pixel tiles a pass is cut into, so no coarse pixel spans
// two tasks, and the output does not depend on the thread count. Lanes are independent
// but for the quad differences, and a lane group is one or two whole coarse quads for
// either lane type, so ScalarLanes give the bytes of FastLanes.
//
// The renderer chooses this walk once per pass (Renderer::flush): the 1x1 walk
// (rasterize_tile.cpp) and its fast paths have no test of the rate in them.
#pragma once

#include <span>

#include "raster/contract.h"

namespace raster {

// Rasterizes one tile (or band) of a coarse-rate pass with lane type F. The tile's clear
// is done before (merge::clearRect): this walk leaves no clear out.
template <class F>
void rasterizeTileCoarse(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, PipelineCounters& counters);

}  // namespace raster
