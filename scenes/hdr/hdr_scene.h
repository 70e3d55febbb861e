// "11 - HDR + Bloom" (seed 002_2011f151d1707bfd.txt): a thousand instanced cubes, one in
// nine emissive (8x), rendered into an RGBA16F target; a bright pass, a 5-level bloom
// pyramid (5-tap downsamples, 9-tap tent upsamples blended ONE/ONE), and an ACES tonemap
// with gamma to the default framebuffer.
#pragma once

#include "scenes/registry.h"

namespace scenes {

// The scene's registry row (scenes/registry.h).
SceneEntry hdrScene();

}  // namespace scenes
