// Per-tile cost of each pass of a warm frame: what `raster render SCENE --view tile-cost`
// records (the cycle counter around each 64x64 tile's task, its clear and tile stage), but
// after WARM_FRAMES frames of the same scene in the same process, so that first-touch page
// faults and cold caches are not charged to the first tiles; with RECORDED_FRAMES > 1 each
// tile's least time over that many recorded frames (a tile takes well under a millisecond,
// so on a shared host most frames run it unpreempted; a busy host's lower clock and
// shared caches still slow it, so read the tiles' shares, not their times). Prints one
// JSON object:
// {"scene", "size", "threads", "tsc_ghz", "passes": [{"label", "width", "height", "tiles_x",
// "tiles_y", "triangles", "tile_cycles": [...], "tile_triangles": [...], "depth_ranges"}]}:
// each tile's cycles and its bin's triangles, and whether the pass's heavy tiles may be walked
// in triangle ranges (what the renderer cuts its work items by, with no recorder: the tiles
// here are timed whole). bench/scaling_model.py reads it (--tiles).
//
// Built with the rest (build/tile_costs).
//   build/tile_costs pbr 640x480 1 3 5 > pbr_tiles.json   # scene, size, threads, warm frames, recorded frames
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "backends/backends.h"
#include "raster/util/cycles.h"
#include "raster/view_recorder.h"
#include "scenes/registry.h"

namespace {

int run(int argc, char** argv);

// A whole number in [low, high], or -1.
int wholeNumber(const char* text, int low, int high) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return end != text && *end == '\0' && value >= low && value <= high ? int(value) : -1;
}

}  // namespace

// Bad arguments, an unknown scene or a bad asset: one line on stderr, exit 2.
int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tile_costs: %s\n", e.what());
    return 2;
  }
}

namespace {

int run(int argc, char** argv) {
  const char* usage = "usage: tile_costs SCENE WxH THREADS WARM_FRAMES [RECORDED_FRAMES]"
                      " (WxH 1..8192 a side, THREADS 0..1024, frames 0..1000 and 1..1000)\n";
  if (argc < 5 || argc > 6) {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  const std::string name = argv[1];
  int width = 0, height = 0;
  char tail = 0;
  const int threads = wholeNumber(argv[3], 0, 1024), warm = wholeNumber(argv[4], 0, 1000);
  const int recorded = argc > 5 ? wholeNumber(argv[5], 1, 1000) : 1;
  if (std::sscanf(argv[2], "%dx%d%c", &width, &height, &tail) != 2 || width < 1 || height < 1 || width > 8192 ||
      height > 8192 || threads < 0 || warm < 0 || recorded < 1) {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  scenes::SceneOptions options;
  options.width = width;
  options.height = height;
  std::unique_ptr<scenes::Scene> scene = scenes::makeScene(name, options);
  std::unique_ptr<scenes::Backend> backend = scenes::makeRasterBackend(threads);
  backend->resizeDefaultFramebuffer(width, height);
  scene->setup(*backend);
  backend->finish();
  for (int i = 0; i < warm; ++i) {
    scene->renderFrame(*backend, options.time);
    backend->finish();
  }
  // The first recorded frame's passes, each tile's cycles lowered to its least over the frames.
  std::vector<raster::ViewPass> passes;
  for (int f = 0; f < recorded; ++f) {
    raster::ViewRecorder recorder(raster::ViewRecorder::Record::TileTimes);
    scenes::setViewRecorder(*backend, &recorder);
    scene->renderFrame(*backend, options.time);
    backend->finish();
    scenes::setViewRecorder(*backend, nullptr);
    if (f == 0) {
      passes = recorder.passes();
      continue;
    }
    for (size_t p = 0; p < passes.size() && p < recorder.passes().size(); ++p)
      for (size_t t = 0; t < passes[p].tileCycles.size(); ++t)
        passes[p].tileCycles[t] = std::min(passes[p].tileCycles[t], recorder.passes()[p].tileCycles[t]);
  }
  // The counter's rate, against the steady clock over 200 ms.
  const auto t0 = std::chrono::steady_clock::now();
  const uint64_t c0 = raster::cycleCount();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  const double ghz = double(raster::cycleCount() - c0) / ns;
  std::printf("{\"scene\": \"%s\", \"size\": [%d, %d], \"threads\": %d, \"warm_frames\": %d, \"recorded_frames\": %d, \"tsc_ghz\": %.4f, \"passes\": [",
              name.c_str(), width, height, threads, warm, recorded, ghz);
  bool firstPass = true;
  for (const raster::ViewPass& p : passes) {
    std::printf("%s\n  {\"label\": \"%s\", \"width\": %d, \"height\": %d, \"tiles_x\": %d, \"tiles_y\": %d, \"triangles\": %llu, \"tile_cycles\": [",
                firstPass ? "" : ",", p.label.c_str(), p.width, p.height, p.tilesX, p.tilesY,
                static_cast<unsigned long long>(p.triangles));
    for (size_t i = 0; i < p.tileCycles.size(); ++i)
      std::printf("%s%llu", i ? ", " : "", static_cast<unsigned long long>(p.tileCycles[i]));
    std::printf("], \"tile_triangles\": [");
    for (size_t i = 0; i < p.tileTriangles.size(); ++i) std::printf("%s%u", i ? ", " : "", unsigned(p.tileTriangles[i]));
    std::printf("], \"depth_ranges\": %s}", p.depthRanges ? "true" : "false");
    firstPass = false;
  }
  std::printf("\n]}\n");
  return 0;
}

}  // namespace
