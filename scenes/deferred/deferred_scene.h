// "10 - Deferred Shading + MRT" (seed 000_a9faaef907542225.txt): a cat statue on a brick
// floor; shadow map, G-buffer (3 MRT + depth), SSAO, lighting with 5x5 PCF, point lights
// and image-based lighting, and a filmstrip of the G-buffer along the bottom.
#pragma once

#include "scenes/registry.h"

namespace scenes {

// The scene's registry row (scenes/registry.h).
SceneEntry deferredScene();

}  // namespace scenes
