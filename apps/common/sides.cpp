// One side of a comparison, rendered here or in a child process (sides.h).
#include "apps/common/sides.h"

#include "apps/common/child_process.h"
#include "apps/common/temporary_folder.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>

#include "io/target_dump.h"
#include "backends/backends.h"
#include "io/memory_budget.h"
#include "scenes/registry.h"

namespace cli {
namespace fs = std::filesystem;
using scenes::Target;

// "640x480, t=1.000"
std::string sizeAndTime(const Frame& frame) {
  char text[64];
  std::snprintf(text, sizeof text, "%dx%d, t=%.3f", frame.width, frame.height, frame.time);
  return text;
}

// Renders one frame with a backend made in this process ("raster" or "gl"), and reads back
// every target, or only the final image when `finalOnly` (a render without --dump).
Side renderInProcess(const Frame& frame, const std::string& backendKind, bool finalOnly) {
  const scenes::SceneOptions options = sceneOptions(frame);
  std::unique_ptr<scenes::Scene> scene = scenes::makeScene(frame.scene, options);
  std::unique_ptr<scenes::Backend> backend;
  // This pipeline renders with the frame's method set (GL ignores it: it has its own).
  const raster::ScopedMethods methods(frame.methods);
  if (backendKind == "raster") {
    backend = scenes::makeRasterBackend(frame.threads, frame.scalar);
  } else {
    if (frame.threads > 0) setenv("LP_NUM_THREADS", std::to_string(frame.threads).c_str(), 1);
    backend = scenes::makeGlBackend();
  }
  const std::string methodNote = backendKind == "raster" && !(frame.methods == raster::MethodSet{})
                                     ? " (methods: " + raster::methodLabel(frame.methods) + ")" : "";
  if (!frame.quiet)
    std::cerr << "rendering " << frame.scene << " with " << backend->name() << methodNote << " at "
            << sizeAndTime(frame) << " ..." << std::endl;
  backend->resizeDefaultFramebuffer(frame.width, frame.height);
  scene->setup(*backend);
  scene->renderFrame(*backend, frame.time);
  Side side{backend->name(), {}};
  if (finalOnly) side.targets.push_back(scene->readFinal(*backend));
  else side.targets = scene->readTargets(*backend);
  if (side.targets.empty()) throw std::runtime_error("scene " + frame.scene + " exposed no targets");
  return side;
}

// Writes every target as NAME.png (+ NAME.exr for depth / float) and the manifest, and
// says so on stdout, a line per file.
void dumpTargets(const std::string& folder, const std::vector<Target>& targets) {
  compare::writeTargetDump(folder, targets, [](const std::string& path) { std::cout << "wrote " << path << std::endl; });
}

// Renders one frame with GL under another Gallium driver, in a child process of this program.
Side renderInChild(const Frame& frame, const std::string& driver) {
  TemporaryFolder dump;
  std::vector<std::string> args = {"raster", "render", frame.scene, "--backend", "gl", "--threads", std::to_string(frame.threads),
                                   "--dump", dump.path, "--out", dump.path + "/out.png"};
  const std::vector<std::string> frameOptions = childFrameOptions(frame);
  args.insert(args.end(), frameOptions.begin(), frameOptions.end());
  // The child gets what this process has left of the cap (its targets are loaded back here).
  const uint64_t left = scenes::memory::cap() - std::min(scenes::memory::cap(), scenes::memory::reserved());
  args.insert(args.end(), {"--max-memory", std::to_string(std::max<uint64_t>(left / 2, 1))});
  if (frame.quiet) args.push_back("--quiet");
  if (frame.floatFinal) args.push_back("--float-final");

  // Run it with stdout (its "wrote" lines) silenced; its progress and errors go to stderr.
  if (!frame.quiet)
    std::cerr << "starting a child process for " << driver << " (GALLIUM_DRIVER=" << driver << ") ..."
            << std::endl;
  ChildOptions options;
  options.setEnvironment = {"GALLIUM_DRIVER=" + driver};
  // Its failure is ours, in one line with its reason: bad input stays bad input (2).
  runThisProgram(args, "the " + driver + " render (child process)", options);
  return {driver, compare::loadTargetDump(dump.path)};
}

// One side of a comparison: "raster" or "llvmpipe" in this process, "softpipe" in a child.
Side renderSide(const Frame& frame, const std::string& which) {
  if (which == "softpipe") return renderInChild(frame, which);
  if (which == "llvmpipe") setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  return renderInProcess(frame, which == "raster" ? "raster" : "gl");
}


}  // namespace cli
