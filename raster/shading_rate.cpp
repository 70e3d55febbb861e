// Which passes a shading rate applies to (shading_rate.h).
#include "raster/shading_rate.h"

#include <vector>

#include "raster/methods.h"
#include "raster/shader/shader_instance.h"
#include "raster/texture/finite_texels.h"

namespace raster {

std::pair<int, int> passShadingRate(std::span<const DrawRecord> draws, const Framebuffer& framebuffer) {
  const ShadingMethod method = methods::active().shading;
  const int width = methods::coarsePixelWidth(method), height = methods::coarsePixelHeight(method);
  if (width == 1 && height == 1) return {1, 1};
  bool writesColor = false, depthTested = false, aroundPixel = false;
  for (const DrawRecord& draw : draws) {
    if (colorOutputsWritten(draw, framebuffer) == 0) continue;
    writesColor = true;
    depthTested |= draw.state.depthTest && framebuffer.depth;
    aroundPixel |= draw.samplesAroundPixel;
  }
  if (!writesColor) return {1, 1};
  switch (methods::coarsePasses(method)) {
    case CoarsePasses::All: return {width, height};
    case CoarsePasses::Post: break;
    // A shader that samples around its pixel (program.h, samplesAroundPixel: SSAO) rotates
    // its samples per pixel: a coarse centre draws a new rotation, and that noise is the
    // whole of its target's detail (16 dB at 2x2 in deferred; shading-rate note).
    case CoarsePasses::Local:
      if (aroundPixel) return {1, 1};
      break;
    // The pass into the window makes the final image: a coarse pixel there steps every edge
    // it reads from a full-size target (deferred's G-buffer, hdr's cubes). Offscreen post
    // passes (blurs, bloom) feed filters that smooth a coarse pixel's steps away.
    case CoarsePasses::Offscreen:
      if (aroundPixel || framebuffer.flipY) return {1, 1};
      break;
    // Of those, only passes that filter what is already at their scale. A pass that reads a
    // texture larger than its target (a bright pass, a downsample) reads detail finer than
    // its pixels: one sample per coarse pixel aliases it, and a threshold after it (hdr's
    // bright pass) turns that into blobs the bloom spreads (STABILITY.md, "Coarse bloom").
    // A non-finite texel spreads through a filter to every pixel whose footprint holds it;
    // a coarse centre alone would decide which pixels of the coarse one that is, so a pass
    // reading one keeps 1x1 and the NaNs of the frame land where GL's rules put them.
    case CoarsePasses::Smooth: {
      if (aroundPixel || framebuffer.flipY || depthTested) return {1, 1};
      std::vector<const Texture*> sampled;
      for (const DrawRecord& draw : draws)
        if (colorOutputsWritten(draw, framebuffer) != 0) draw.shader->appendSampledTextures(sampled);
      for (const Texture* texture : sampled)
        if (texture->width > framebuffer.width || texture->height > framebuffer.height) return {1, 1};
      for (const Texture* texture : sampled)
        if (holdsNonFiniteTexels(*texture)) return {1, 1};
      break;
    }
  }
  if (depthTested) return {1, 1};
  return {width, height};
}

}  // namespace raster
