// The filter a colour lookup (sampler2D) runs under the active method set: the texture's
// own, or NEAREST for every lookup under `lookup=nearest` (methods.h). NEAREST reads the
// texel the coordinate lands in, which is the texel of largest weight in the LINEAR
// footprint (at least 1/4 of it; on a tie, the right or lower one), so the method needs no
// path of its own: every colour lookup path, scalar and vector, asks here instead of
// reading texture.sampler.filter. The texel layouts (footprint_strips.h) still follow the
// texture's own filter: they are made once, before any method set is installed.
#pragma once

#include "raster/methods.h"
#include "raster/texture/texture.h"

namespace raster::sampling {

inline Filter lookupFilter(const Texture& t) {
  return methods::nearestLookup(methods::active().lookup) ? Filter::Nearest : t.sampler.filter;
}

}  // namespace raster::sampling
