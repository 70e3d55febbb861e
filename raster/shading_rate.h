// The coarse pixel each pass is shaded at, under the `shading` method (methods.h): which
// passes a rate above 1x1 applies to. Renderer::flush asks once per pass and hands the
// answer to the tile walk (tile/coarse_tile.h).
#pragma once

#include <span>
#include <utility>

#include "raster/contract.h"

namespace raster {

// The coarse pixel a pass is shaded at (methods.h, `shading`), chosen from the pass's draws
// alone, never its scene: a rate above 1x1 applies to a post pass, one with a colour draw
// and no colour draw that tests depth (a fullscreen triangle over earlier passes' targets:
// lighting, SSAO and its blur, bloom, tone mapping), where the image is already smooth at
// the scale of a pixel; a geometry pass (a colour draw tests depth) keeps 1x1, as its
// edges and texture detail are what the frame shows, unless the method asks for every
// pass. A depth-only pass shades nothing either way.
std::pair<int, int> passShadingRate(std::span<const DrawRecord> draws, const Framebuffer& framebuffer);

}  // namespace raster
