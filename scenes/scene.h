// A scene: resources created once, then frames rendered at time t, through a Backend.
//
// The same Scene code runs on both backends; the comparison reads back the same named
// targets from each. A frame N of a tutorial renders at t = N / 60.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "scenes/scene_params.h"

namespace scenes {

struct SceneOptions {
  float time = 1.0f;      // seconds
  int width = 640;        // final image size
  int height = 480;
  std::string assetDir;   // empty: the default (see assetDirectory())
  int instances = 1000;   // the HDR scene's cube count (the seed's N_INSTANCES)
  SceneParams params;     // --set NAME=VALUE (scene_params.h); unset: the seed's scene
  // The final pass into an RGBA32F framebuffer of the final size instead of the RGBA8
  // window (--float-final): the shaders' outputs before 8-bit rounding, which hides nearly
  // every one-float-step difference. Every other pass is unchanged.
  bool floatFinal = false;
};

// One image the scene exposes for inspection and comparison.
struct Target {
  std::string name;       // e.g. "shadow_map", "final"
  ImageData image;
};

class Scene {
 public:
  virtual ~Scene() = default;
  virtual std::string name() const = 0;
  // Creates programs, meshes, textures and framebuffers. Throws SceneError on bad assets.
  virtual void setup(Backend& backend) = 0;
  // Everything the tutorial's update() does for one frame at time t (no finish()).
  virtual void renderFrame(Backend& backend, float time) = 0;
  // Every target of the last frame (finishes the backend first), the final image last.
  virtual std::vector<Target> readTargets(Backend& backend) = 0;
  // Only the final image (the window's colour), for a render that writes nothing else.
  Target readFinal(Backend& backend) {
    backend.finish();
    return {"final", backend.readColor(final_)};
  }

 protected:
  // Where the final pass draws: the window, or with options.floatFinal an RGBA32F
  // framebuffer (and a Depth24 buffer when the pass depth-tests) made here.
  void createFinalTarget(Backend& backend, const SceneOptions& options, bool depth);
  Handle final_ = kDefaultFramebuffer;
};

// A problem a user can fix (missing or corrupt asset, unknown scene): one clear line.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The asset folder: options.assetDir, else $RASTER_ASSETS, else the repository's assets/
// (checked against its SHA256SUMS: io/asset_manifest.h).
std::string assetDirectory(const SceneOptions& options);

}  // namespace scenes
