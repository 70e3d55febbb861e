// Rendering a whole scene with a backend, for the scene, determinism and benchmark tests.
#pragma once

#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "backends/backends.h"
#include "compare/metrics.h"
#include "io/target_dump.h"
#include "scenes/registry.h"

namespace testing_support {

// The scenes the suites that cover every scene run: every row of the registry, or those
// named in $RASTER_TEST_SCENES (comma-separated), to run a new scene through them alone.
inline std::vector<std::string> scenesUnderTest() {
  const char* only = std::getenv("RASTER_TEST_SCENES");
  if (!only || !*only) return scenes::sceneNames();
  std::vector<std::string> names;
  std::string list = only;
  for (size_t start = 0; start <= list.size();) {
    const size_t comma = std::min(list.find(',', start), list.size());
    if (comma > start) names.push_back(scenes::sceneEntry(list.substr(start, comma - start)).name);
    start = comma + 1;
  }
  return names;
}

// Renders one frame of `scene` at time t and size w x h, and reads every target back.
inline std::vector<scenes::Target> renderScene(scenes::Backend& backend, const std::string& scene, float t, int w,
                                               int h, bool floatFinal = false) {
  scenes::SceneOptions options;
  options.time = t;
  options.width = w;
  options.height = h;
  options.floatFinal = floatFinal;
  std::unique_ptr<scenes::Scene> s = scenes::makeScene(scene, options);
  backend.resizeDefaultFramebuffer(w, h);
  s->setup(backend);
  s->renderFrame(backend, t);
  return s->readTargets(backend);
}

// Every target of `a` and `b` the same, byte for byte (colour, depth and float texels).
inline void checkSameBytes(const std::vector<scenes::Target>& a, const std::vector<scenes::Target>& b) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    INFO("target " << a[i].name);
    CHECK(a[i].image.rgba8 == b[i].image.rgba8);
    CHECK(a[i].image.depth == b[i].image.depth);
    CHECK(a[i].image.floats == b[i].image.floats);
  }
}

// One scene set up on a backend of its own, to be drawn again and again (under each method
// set in turn, say): setting a scene up costs more than a frame of it at a small size
// (deferred's assets take longer to load than to render).
struct PreparedScene {
  std::string name;   // which backend: "3 threads, scalar lanes"
  std::unique_ptr<scenes::Backend> backend;
  std::unique_ptr<scenes::Scene> scene;
  std::vector<scenes::Target> render(float t) {
    scene->renderFrame(*backend, t);
    return scene->readTargets(*backend);
  }
};

// `scene` prepared on one backend per (threads, scalar lanes) pair, in that order, each
// sized and set up for `options`.
inline std::vector<PreparedScene> prepareScene(const std::string& scene, const scenes::SceneOptions& options,
                                               std::initializer_list<std::pair<int, bool>> backends) {
  std::vector<PreparedScene> prepared;
  for (const auto& [threads, scalar] : backends) {
    PreparedScene& p = prepared.emplace_back(PreparedScene{std::to_string(threads) + " threads, " + (scalar ? "scalar" : "SIMD") + " lanes",
                                                           scenes::makeRasterBackend(threads, scalar), scenes::makeScene(scene, options)});
    p.backend->resizeDefaultFramebuffer(options.width, options.height);
    p.scene->setup(*p.backend);
  }
  return prepared;
}

inline std::vector<scenes::Target> renderWithLlvmpipe(const std::string& scene, float t, int w, int h,
                                                       bool floatFinal = false) {
  std::unique_ptr<scenes::Backend> gl = scenes::makeGlBackend();
  return renderScene(*gl, scene, t, w, h, floatFinal);
}

// The final pass of both backends into RGBA32F (SceneOptions::floatFinal): the shaders'
// outputs before 8-bit rounding, which hides nearly every one-step difference of a port
// from the code Mesa compiles. The stats of that final target.
inline compare::TargetStats compareFloatFinal(const std::string& scene, float t, int w, int h) {
  auto ours = scenes::makeRasterBackend(0);
  const std::vector<scenes::Target> mine = renderScene(*ours, scene, t, w, h, true);
  const std::vector<scenes::Target> gl = renderWithLlvmpipe(scene, t, w, h, true);
  const compare::TargetStats stats = compare::compareImages("final", mine.back().image, gl.back().image);
  MESSAGE(compare::formatStatsLine(stats));
  return stats;
}

// Renders a frame with this pipeline and with llvmpipe and compares every target (in the
// scene's order, final last), printing one stats line per target.
inline std::vector<compare::TargetStats> compareWithLlvmpipe(const std::string& scene, float t, int w, int h) {
  auto ours = scenes::makeRasterBackend(0);
  const std::vector<scenes::Target> mine = renderScene(*ours, scene, t, w, h);
  const std::vector<scenes::Target> gl = renderWithLlvmpipe(scene, t, w, h);
  if (mine.size() != gl.size()) throw std::runtime_error(scene + ": the backends expose different targets");
  std::vector<compare::TargetStats> stats;
  for (size_t i = 0; i < mine.size(); ++i) {
    if (mine[i].name != gl[i].name) throw std::runtime_error(scene + ": target " + mine[i].name + " vs " + gl[i].name);
    stats.push_back(compare::compareImages(mine[i].name, mine[i].image, gl[i].image));
    MESSAGE(compare::formatStatsLine(stats.back()));
  }
  return stats;
}

// The same frame rendered by softpipe, for scale. Mesa picks one Gallium driver per
// process, so softpipe runs in a child (`raster render --backend gl --dump`) and its
// lossless dump is loaded back (io/target_dump.h); its targets must be those of `like`.
inline std::vector<scenes::Target> renderWithSoftpipe(const std::string& scene, const std::vector<scenes::Target>& like) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("raster-softpipe-" + scene + "-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string command = "GALLIUM_DRIVER=softpipe '" RASTER_CLI_PATH "' render " + scene + " --backend gl --dump '" +
                              dir.string() + "' --out '" + (dir / "out.png").string() + "' > /dev/null 2>&1";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("softpipe render of " + scene + " failed");
  std::vector<scenes::Target> targets;
  try {
    targets = compare::loadTargetDump(dir.string());
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
  if (targets.size() != like.size()) throw std::runtime_error(scene + ": softpipe dumped another number of targets");
  for (size_t i = 0; i < like.size(); ++i)
    if (targets[i].name != like[i].name) throw std::runtime_error(scene + ": softpipe target " + targets[i].name + " vs " + like[i].name);
  return targets;
}

}  // namespace testing_support
