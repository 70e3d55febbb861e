// Factories for the two Backend implementations.
#pragma once

#include <memory>

#include "backends/backend.h"
#include "raster/pixel_history.h"

namespace raster {
class ViewRecorder;   // raster/view_recorder.h
}

namespace scenes {

// This project's pipeline. threads = 0 uses every core; any count gives the same bytes.
// scalarOnly turns every SIMD fast path off (plain C++ lanes); visibilityFirst = false
// shades every fragment that passes its depth test, in order, instead of only the visible
// ones (raster::Renderer::setVisibilityFirst). The bytes are the same either way.
std::unique_ptr<Backend> makeRasterBackend(int threads = 0, bool scalarOnly = false, bool visibilityFirst = true);

// Turns pixel history on (null: off) in a backend made by makeRasterBackend
// (raster::Renderer::setPixelHistory); passes get the labels the scene gives them.
// Throws std::invalid_argument for any other backend.
void setPixelHistory(Backend& rasterBackend, raster::PixelHistory* history);

// Records every pass from now on for the stage views (raster/view_recorder.h; null: off) in
// a backend made by makeRasterBackend; passes get the labels the scene gives them. The
// recorder must outlive the backend or be turned off first. Throws std::invalid_argument
// for any other backend.
void setViewRecorder(Backend& rasterBackend, raster::ViewRecorder* recorder);

// Real OpenGL 3.3 core through OSMesa. The Gallium driver is chosen by GALLIUM_DRIVER
// (llvmpipe when unset; softpipe works too) and LP_NUM_THREADS sets llvmpipe's threads;
// both must be set before the first GL backend of the process is made. name() reports the
// driver actually in use ("llvmpipe" or "softpipe"). Throws std::runtime_error when no
// context can be made.
std::unique_ptr<Backend> makeGlBackend();

// How many GL backends this process has made so far. llvmpipe's rasterizer threads belong
// to the process, not to a context, and carry state from one backend to the next: after a
// draw into a half-float target in which a block failed its depth test everywhere, those
// that shaded that block no longer flush denormals (Mesa 22.3, lp_state_fs.c; raster/simd/
// gl_math.h).
// A check of llvmpipe's flushing of denormals needs the first backend of its process.
int glBackendsMade();

// Throws SceneError when GALLIUM_DRIVER names a driver other than llvmpipe or softpipe, or
// LP_NUM_THREADS is not a whole number 0..1024 (Mesa crashes on an unknown driver).
// makeGlBackend checks this first; commands call it before rendering anything.
void checkGalliumEnvironment();

}  // namespace scenes
