// "Deferred PBR with cascaded shadow maps" (seed 004_c2461eff6b055266.txt): the cat statue
// on the brick floor through a four-attachment G-buffer, three cascaded shadow maps, SSAO
// with a 64-sample kernel and a separable blur, Cook-Torrance lighting and ACES tone mapping.
#pragma once

#include "scenes/registry.h"

namespace scenes {

// The scene's registry row (scenes/registry.h).
SceneEntry pbrScene();

}  // namespace scenes
