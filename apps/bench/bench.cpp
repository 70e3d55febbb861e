// `raster bench`: side-by-side frame times of this pipeline and a GL driver (bench.h).
//
// Method: both backends set the scene up once (assets and resources are outside the
// timing), then frames alternate A B A B: each timed frame is everything the tutorial's
// update() does, plus finish() (glFinish for GL), on the same thread count (LP_NUM_THREADS
// for llvmpipe). Medians are reported, and the ratio of the medians: on shared, noisy
// machines the ratio is the figure to quote, not the absolute times.
#include "apps/bench/bench.h"

#include "apps/common/progress.h"

#include "io/output_file.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>
#include <vector>

#include <sched.h>

#include <nlohmann/json.hpp>

#include "apps/bench/pass_timer.h"
#include "raster/util/cycles.h"
#include "backends/backends.h"
#include "scenes/registry.h"

namespace cli {
namespace {

struct Timed {
  std::string backend;
  std::vector<double> ms;
  double median() const { return cli::median(ms); }
};

// A backend, its scene set up through a pass timer (timing off unless --passes asks), and
// its frame times.
struct Contender {
  std::unique_ptr<scenes::Backend> backend;
  std::unique_ptr<PassTimer> passTimer;
  std::unique_ptr<scenes::Scene> scene;
  Timed timed;
};

double renderOnce(Contender& c, float time) {
  const auto start = std::chrono::steady_clock::now();
  c.scene->renderFrame(*c.passTimer, time);
  c.passTimer->finish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// One pass of both contenders: its first program and the medians of its times.
struct PassRow {
  std::string program;
  double oursMs, theirsMs;
};

std::vector<PassRow> passRows(const Contender (&contenders)[2]) {
  const std::vector<PassTimer::Pass>& ours = contenders[0].passTimer->passes();
  const std::vector<PassTimer::Pass>& theirs = contenders[1].passTimer->passes();
  std::vector<PassRow> rows;
  for (size_t k = 0; k < std::min(ours.size(), theirs.size()); ++k)
    rows.push_back({ours[k].program, median(ours[k].ms), median(theirs[k].ms)});
  return rows;
}

// Both contenders' passes side by side: medians, and the ratio GL / this pipeline.
void printPasses(const std::vector<PassRow>& rows, const std::string& gl, int frames) {
  std::printf("per pass (%d frames alternating, each pass finished before the next; medians):\n", frames);
  std::printf("  pass  %-24s %10s %11s %10s\n", "program", "raster ms", (gl + " ms").c_str(), "ratio");
  for (size_t k = 0; k < rows.size(); ++k) {
    const PassRow& row = rows[k];
    std::printf("  %4zu  %-24s %10.3f %11.3f %10.2f\n", k + 1, row.program.empty() ? "(clear only)" : row.program.c_str(),
                row.oursMs, row.theirsMs, row.oursMs > 0 ? row.theirsMs / row.oursMs : 0.0);
  }
}

// Where this pipeline's time goes, per frame: stages in milliseconds of CPU time (the tile
// stages summed over threads), and the counters that explain them.
void printBreakdown(const std::vector<std::pair<std::string, double>>& stats, int frames, double cyclesPerMs,
                    int pixels) {
  auto get = [&](const std::string& name) {
    for (const auto& [key, value] : stats)
      if (key == name) return value / frames;
    return 0.0;
  };
  const char* stages[][2] = {{"vertex shading", "cycles_vertex"},         {"clip + setup", "cycles_clip_setup"},
                             {"binning", "cycles_bin"},                   {"rasterization", "cycles_raster"},
                             {"fragment shading", "cycles_fragment_shading"}, {"output merge", "cycles_output_merge"}};
  double total = 0;
  for (const auto& stage : stages) total += get(stage[1]);
  std::printf("per frame, this pipeline (CPU ms, tile stages summed over threads):\n");
  for (const auto& stage : stages)
    std::printf("  %-18s %9.3f ms  %5.1f%%\n", stage[0], get(stage[1]) / cyclesPerMs, 100.0 * get(stage[1]) / total);
  const double lanes = get("lanes_shaded"), covered = get("lanes_covered");
  std::printf("  triangles in %.0f, rejected %.0f, clipped %.0f, set up %.0f, tile bin entries %.0f, "
              "later depth-only ranges %.0f, texel-plane texels %.0f\n",
              get("triangles_in"), get("triangles_rejected"), get("triangles_clipped"), get("triangles_set_up"),
              get("tile_bin_entries"), get("depth_range_walks"), get("texel_plane_texels"));
  std::printf("  lane groups shaded %.0f, lanes %.0f, helper-lane share %.1f%%, shaded fragments per pixel %.2f\n",
              get("lane_groups_shaded"), lanes, lanes > 0 ? 100.0 * (lanes - covered) / lanes : 0.0, covered / pixels);
}

}  // namespace

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

// Restricts the process to `threads` of the cores it may run on, before either backend
// starts a thread (threads inherit the mask), so both render on the same cores. Unpinned,
// one rendering thread on a 2-core host wanders between cores: our 1-thread shadow medians
// at 1920x1080 read 25 ms in some runs and 35-47 ms in others; pinned, within 3%. (Mesa's
// shader disk-cache thread sets its own mask back to every core; it idles while frames run.)
// Returns how many cores the process is now on.
int pinToCores(int threads) {
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return 0;
  const int available = CPU_COUNT(&allowed);
  if (threads >= available) return available;
  // The core this thread is on now first, then the next allowed ones.
  cpu_set_t pinned;
  CPU_ZERO(&pinned);
  int kept = 0;
  const int current = sched_getcpu();
  if (current >= 0 && CPU_ISSET(current, &allowed)) CPU_SET(current, &pinned), ++kept;
  for (int cpu = 0; cpu < CPU_SETSIZE && kept < threads; ++cpu)
    if (CPU_ISSET(cpu, &allowed) && !CPU_ISSET(cpu, &pinned)) CPU_SET(cpu, &pinned), ++kept;
  return sched_setaffinity(0, sizeof pinned, &pinned) == 0 ? kept : available;
}

void addBenchOptions(CLI::App& command, BenchArgs& args) {
  command.add_option("scene", args.scene, "Scene")->required()->type_name("SCENE");
  command.add_option("--time", args.time, "Time in seconds")->type_name("T")->capture_default_str();
  command.add_option("--size", args.size, "Image size")->type_name("WxH")->capture_default_str();
  command.add_option("--threads", args.threads, "Threads for both (LP_NUM_THREADS for llvmpipe); 0: every core")
      ->type_name("N")->capture_default_str();
  command.add_option("--frames", args.frames, "Timed frames per backend (1..10000)")->capture_default_str();
  command.add_option("--warmup", args.warmup, "Untimed frames per backend first (0..1000)")->capture_default_str();
  command.add_option("--gl-driver", args.glDriver, "GL driver to race: llvmpipe or softpipe")->capture_default_str();
  command.add_option("--json", args.json, "Also write the results as JSON to FILE")->type_name("FILE");
  command.add_option("--assets", args.assets, "Asset folder")->type_name("DIR");
  command.add_option("--max-memory", args.maxMemory, "Refuse (exit 2) a run that would take more than SIZE (e.g. 8G)")
      ->type_name("SIZE");
  command.add_option("--instances", args.instances, "Cubes in the hdr scene (1..200000)")->capture_default_str();
  addMethodOptions(command, args.preset, args.method);
  addSetOption(command, args.sets);
  addQuietOption(command, args.quiet);
  command.add_flag("--no-pin", args.noPin,
                    "Do not pin the process to --threads cores (by default both backends share the same N cores)");
  command.add_flag("--passes", args.passes,
                    "Then time each pass of both backends, finishing after each (up to 9 more frames each)");
}

int runBench(const BenchArgs& args) {
  const Frame frame = validateFrame(args);
  const raster::ScopedMethods methods(frame.methods);   // this pipeline's frames use them
  if (args.frames < 1 || args.frames > 10000) throw UsageError("--frames: out of range (1..10000)");
  if (args.warmup < 0 || args.warmup > 1000) throw UsageError("--warmup: out of range (0..1000)");
  if (args.glDriver != "llvmpipe" && args.glDriver != "softpipe")
    throw UsageError("--gl-driver: " + args.glDriver + " is not llvmpipe or softpipe");
  if (!args.json.empty()) checkOutputFile("--json", args.json);

  // Same thread count for both: 0 means every core, which is also llvmpipe's default.
  const int threads = frame.threads > 0 ? frame.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  setenv("GALLIUM_DRIVER", args.glDriver.c_str(), 1);
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
  const int cores = args.noPin ? 0 : pinToCores(threads);

  const scenes::SceneOptions options = sceneOptions(frame);
  Contender contenders[2];
  contenders[0].backend = scenes::makeRasterBackend(threads, frame.scalar);
  contenders[1].backend = scenes::makeGlBackend();
  for (Contender& c : contenders) {
    c.timed.backend = c.backend->name();
    c.passTimer = std::make_unique<PassTimer>(*c.backend);
    c.scene = scenes::makeScene(frame.scene, options);
    c.passTimer->resizeDefaultFramebuffer(frame.width, frame.height);
    c.scene->setup(*c.passTimer);
  }

  // What this pipeline was compiled for (CMakeLists.txt: RASTER_AVX2, RASTER_AVX512), so a
  // figure can be read against the build that made it.
#if defined(__AVX512VL__) && RASTER_AVX2
  const char* builtFor = "AVX2/FMA/F16C + AVX-512";
#elif RASTER_AVX2
  const char* builtFor = "AVX2/FMA/F16C";
#else
  const char* builtFor = "plain C++ lanes";
#endif
  const std::string onCores = cores > 0 ? ", on " + std::to_string(cores) + (cores == 1 ? " core" : " cores") : "";
  if (!frame.quiet)
    std::fprintf(stderr, "bench %s %dx%d t=%.3f threads=%d%s: %d warm-up + %d timed frames each (raster built for %s, methods %s)\n",
               frame.scene.c_str(), frame.width, frame.height, frame.time, threads, onCores.c_str(), args.warmup,
               args.frames, builtFor, raster::methodLabel(frame.methods).c_str());
  for (int i = 0; i < args.warmup; ++i)
    for (Contender& c : contenders) renderOnce(c, frame.time);
  // The timed frames run without the stage timers: reading the cycle counter per lane group
  // costs this pipeline time that llvmpipe does not pay.
  {
    Progress progress("  frames", args.frames, frame.quiet);
    for (int i = 0; i < args.frames; ++i) {
      for (Contender& c : contenders) c.timed.ms.push_back(renderOnce(c, frame.time));
      progress.update(i + 1, "");
    }
  }

  // The breakdown comes from a few more frames of this pipeline alone, timers on.
  const int breakdownFrames = std::min(args.frames, 5);
  contenders[0].backend->resetStatistics(/*timeStages=*/true);
  const uint64_t tscStart = raster::cycleCount();
  const auto clockStart = std::chrono::steady_clock::now();
  for (int i = 0; i < breakdownFrames; ++i) renderOnce(contenders[0], frame.time);
  const double elapsedMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - clockStart).count();
  const double cyclesPerMs = double(raster::cycleCount() - tscStart) / elapsedMs;
  printBreakdown(contenders[0].backend->statistics(), breakdownFrames, cyclesPerMs, frame.width * frame.height);

  const int passFrames = args.passes ? std::min(args.frames, 9) : 0;
  std::vector<PassRow> passes;
  if (passFrames > 0) {
    contenders[0].backend->resetStatistics(/*timeStages=*/false);
    for (Contender& c : contenders) c.passTimer->setTiming(true);
    for (int i = 0; i < passFrames; ++i)
      for (Contender& c : contenders) renderOnce(c, frame.time);
    for (Contender& c : contenders) c.passTimer->setTiming(false);
    passes = passRows(contenders);
    printPasses(passes, contenders[1].timed.backend, passFrames);
  }

  const double ratio = contenders[1].timed.median() / contenders[0].timed.median();
  for (const Contender& c : contenders)
    std::printf("scene=%s backend=%s threads=%d size=%dx%d median_ms=%.3f\n", frame.scene.c_str(),
                c.timed.backend.c_str(), threads, frame.width, frame.height, c.timed.median());
  std::printf("ratio_%s_over_raster=%.3f\n", contenders[1].timed.backend.c_str(), ratio);

  if (!args.json.empty()) {
    nlohmann::json json = {{"scene", frame.scene},
                           {"size", {frame.width, frame.height}},
                           {"time", frame.time},
                           {"instances", frame.instances},
                           {"sets", frame.sets},
                           {"threads", threads},
                           {"methods", raster::methodLabel(frame.methods)},
                           {"backends", nlohmann::json::array()},
                           {"ratio", ratio}};
    for (const Contender& c : contenders)
      json["backends"].push_back({{"name", c.timed.backend}, {"median_ms", c.timed.median()}, {"frames_ms", c.timed.ms}});
    if (passFrames > 0) {
      json["passes"] = nlohmann::json::array();
      for (const PassRow& row : passes)
        json["passes"].push_back({{"program", row.program},
                                  {contenders[0].timed.backend + "_ms", row.oursMs},
                                  {contenders[1].timed.backend + "_ms", row.theirsMs}});
    }
    compare::writeOutputFile(args.json, json.dump() + "\n");
  }
  return 0;
}

}  // namespace cli
