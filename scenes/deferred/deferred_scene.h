// "10 - Deferred Shading + MRT" (seed 000_a9faaef907542225.txt): a cat statue on a brick
// floor; shadow map, G-buffer (3 MRT + depth), SSAO, lighting with 5x5 PCF, point lights
// and image-based lighting, and a filmstrip of the G-buffer along the bottom.
#pragma once

#include <memory>

#include "scenes/scene.h"

namespace scenes {

std::unique_ptr<Scene> makeDeferredScene(const SceneOptions& options);

}  // namespace scenes
