// Rendering one side of a comparison: this pipeline or llvmpipe in this process, softpipe
// in a child process of this program (Mesa picks one Gallium driver per process), and the
// lossless dump of every target that carries a child's frame back.
#pragma once

#include <string>
#include <vector>

#include "apps/common/cli_options.h"
#include "scenes/scene.h"

namespace cli {

// The targets of one rendered frame and the name of the backend that made them.
struct Side {
  std::string backend;
  std::vector<scenes::Target> targets;
};

// "640x480, t=1.000"
std::string sizeAndTime(const Frame& frame);

// Renders one frame with a backend made in this process ("raster", with the frame's method
// set, or "gl"), and reads back every target, or only the final image when `finalOnly`.
Side renderInProcess(const Frame& frame, const std::string& backendKind, bool finalOnly = false);

// Renders one frame with GL under another Gallium driver, in a child process of this program.
Side renderInChild(const Frame& frame, const std::string& driver);

// One side of a comparison: "raster" or "llvmpipe" in this process, "softpipe" in a child.
Side renderSide(const Frame& frame, const std::string& which);

// Writes every target as NAME.png (+ NAME.exr for depth / float) and the manifest
// (io/target_dump.h), printing a "wrote PATH" line per file.
void dumpTargets(const std::string& folder, const std::vector<scenes::Target>& targets);

}  // namespace cli
