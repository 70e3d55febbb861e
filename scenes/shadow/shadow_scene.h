// "08 - The Shadow Map" (seed 001_e52e56bd2ca24dc3.txt): a rotating cube over a checkered
// floor, lit by an orbiting directional light, shadowed through a 1024x1024 depth texture
// with hardware compare and 3x3 PCF.
#pragma once

#include "scenes/registry.h"

namespace scenes {

// The scene's registry row (scenes/registry.h).
SceneEntry shadowScene();

}  // namespace scenes
