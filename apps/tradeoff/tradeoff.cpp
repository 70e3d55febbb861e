// `raster tradeoff`: method sets raced and scored against llvmpipe (tradeoff.h).
#include "apps/tradeoff/tradeoff.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/bench/bench.h"
#include "apps/common/charts.h"
#include "apps/common/progress.h"
#include "apps/common/number_text.h"
#include "apps/common/child_process.h"
#include "apps/common/sides.h"
#include "apps/common/temporary_folder.h"
#include "compare/metrics.h"
#include "io/output_file.h"
#include "raster/methods.h"
#include "backends/backends.h"
#include "io/memory_budget.h"
#include "scenes/registry.h"

namespace cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// What a race writes into --out, checked there before it starts.
const std::vector<std::string> kTradeoffFiles = {"tradeoff.json", "tradeoff.md", "tradeoff.png", "tradeoff.svg"};

// One point of the chart: a method set of this pipeline, or a GL driver.
struct Point {
  std::string name;                 // gl, precise, fast, math=fast, ..., llvmpipe, softpipe
  std::string kind;                 // preset, method, driver
  std::optional<raster::MethodSet> methods;   // absent for drivers
  std::vector<double> ms;
  double medianMs = 0;
  scenes::ImageData image;          // the final image
};

// The presets, then every single-step change from gl, each set once (a preset that is one
// step away from gl keeps its preset name).
std::vector<Point> methodPoints() {
  std::vector<Point> points;
  auto add = [&](const std::string& name, const std::string& kind, const raster::MethodSet& set) {
    for (const Point& p : points)
      if (p.methods && *p.methods == set) return;
    points.push_back({name, kind, set, {}, 0, {}});
  };
  for (const std::string& preset : raster::presetNames()) add(preset, "preset", raster::presetMethods(preset));
  for (const raster::StepInfo& step : raster::methodCatalog())
    for (size_t i = 1; i < step.methods.size(); ++i) {
      raster::MethodSet set;
      raster::setMethod(set, step.name, step.methods[i].name);
      add(step.name + "=" + step.methods[i].name, "method", set);
    }
  return points;
}

double elapsedMs(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A scene set up on one backend, rendering frames at one time.
struct Stage {
  std::unique_ptr<scenes::Backend> backend;
  std::unique_ptr<scenes::Scene> scene;
  double frame(float time) {
    const auto start = std::chrono::steady_clock::now();
    scene->renderFrame(*backend, time);
    backend->finish();
    return elapsedMs(start);
  }
};

Stage makeStage(std::unique_ptr<scenes::Backend> backend, const Frame& frame) {
  const scenes::SceneOptions options = sceneOptions(frame);
  Stage stage{std::move(backend), scenes::makeScene(frame.scene, options)};
  stage.backend->resizeDefaultFramebuffer(frame.width, frame.height);
  stage.scene->setup(*stage.backend);
  return stage;
}

// Softpipe, timed in a child `raster bench --gl-driver softpipe` against this pipeline's
// gl set: returns {softpipe median, gl median} of the child, in ms.
// Its warm-up is --warmup's, but at most one frame: softpipe runs at 1-5% of llvmpipe's speed.
std::pair<double, double> timeSoftpipe(const Frame& frame, int threads, int frames, int warmup, const std::string& jsonPath) {
  std::vector<std::string> args = {"raster", "bench", frame.scene, "--gl-driver", "softpipe", "--threads", std::to_string(threads),
                                   "--frames", std::to_string(frames), "--warmup", std::to_string(std::min(warmup, 1)),
                                   "--no-pin", "--json", jsonPath};
  const std::vector<std::string> frameOptions = childFrameOptions(frame);
  args.insert(args.end(), frameOptions.begin(), frameOptions.end());
  if (frame.quiet) args.push_back("--quiet");
  else std::cerr << "  softpipe: timing it in a child process (" << frames << " frames) ..." << std::endl;
  runThisProgram(args, "the softpipe timing child (raster bench --gl-driver softpipe)");
  std::ifstream in(jsonPath);
  const json report = json::parse(in);
  double softpipe = 0, gl = 0;
  for (const json& backend : report.at("backends")) {
    const std::string name = backend.at("name");
    (name == "softpipe" ? softpipe : gl) = backend.at("median_ms").get<double>();
  }
  if (softpipe <= 0 || gl <= 0) throw std::runtime_error("the softpipe timing child reported no times");
  return {softpipe, gl};
}

bool identical(const compare::TargetStats& s) { return s.maxAbs == 0; }

// Pareto-optimal: no other point is at least as fast and at least as accurate, and better
// in one of the two. Identical images count as infinitely accurate.
std::vector<bool> paretoFront(const std::vector<double>& speed, const std::vector<double>& accuracy) {
  std::vector<bool> front(speed.size(), true);
  for (size_t i = 0; i < speed.size(); ++i)
    for (size_t j = 0; j < speed.size(); ++j)
      if (j != i && speed[j] >= speed[i] && accuracy[j] >= accuracy[i] &&
          (speed[j] > speed[i] || accuracy[j] > accuracy[i]))
        front[i] = false;
  return front;
}

// The markdown table of one scene's result, sorted by speed, Pareto-optimal rows marked.
std::string markdownTable(const json& result) {
  std::vector<json> points(result.at("points").begin(), result.at("points").end());
  std::sort(points.begin(), points.end(), [](const json& a, const json& b) {
    return a.at("speedup_vs_llvmpipe").get<double>() > b.at("speedup_vs_llvmpipe").get<double>();
  });
  std::ostringstream md;
  md << "### " << result.at("scene").get<std::string>() << ", " << result.at("size")[0] << "x" << result.at("size")[1]
     << ", t=" << result.at("time") << ", " << result.at("threads") << " threads\n\n"
     << "| point | kind | median ms | speed-up vs llvmpipe | PSNR vs llvmpipe (dB) | FLIP vs llvmpipe | pixels off > 1 "
        "| max diff | PSNR vs precise (dB) | Pareto |\n|---|---|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
  auto flip = [](const json& p) {
    const json v = p.value("flip_vs_llvmpipe", json(nullptr));
    return v.is_null() ? std::string("-") : fixedDigits(v.get<double>(), 6);
  };
  auto db = [](const json& v) { return v.is_null() ? std::string("identical") : fixedDigits(v.get<double>(), 1); };
  for (const json& p : points)
    md << "| " << p.at("name").get<std::string>() << " | " << p.at("kind").get<std::string>() << " | "
       << fixedDigits(p.at("median_ms").get<double>(), 2) << " | " << fixedDigits(p.at("speedup_vs_llvmpipe").get<double>(), 2)
       << "x | " << db(p.at("psnr_vs_llvmpipe_db")) << " | " << flip(p) << " | "
       << fixedDigits(100.0 * p.at("share_over1_vs_llvmpipe").get<double>(), 3) << "% | "
       << p.at("max_diff_vs_llvmpipe").get<double>() << " | " << db(p.at("psnr_vs_precise_db")) << " | "
       << (p.at("pareto").get<bool>() ? "*" : "") << " |\n";
  md << "\n";
  return md.str();
}

// The command that makes these results again, with every option that shapes them: the frame
// as a child process gets it (a --set time or size as its own option), the rounds, softpipe's.
std::string commandLine(const TradeoffArgs& args, const Frame& frame, int threads) {
  std::string line = "raster tradeoff " + args.scene;
  for (const std::string& option : childFrameOptions(frame)) line += " " + option;
  line += " --threads " + std::to_string(threads) + " --frames " + std::to_string(args.frames) + " --warmup " +
          std::to_string(args.warmup);
  line += args.noSoftpipe ? " --no-softpipe" : " --softpipe-frames " + std::to_string(args.softpipeFrames);
  return line;
}

json runScene(const TradeoffArgs& args, const Frame& frame, int threads, const std::string& outFolder) {
  std::vector<Point> points = methodPoints();
  if (!frame.quiet)
    std::cerr << "tradeoff " << frame.scene << " " << sizeAndTime(frame) << " threads=" << threads << ": "
              << points.size() << " method sets and llvmpipe, " << args.warmup << " warm-up + " << args.frames
              << " timed rounds" << std::endl;

  // One stage for every method set of this pipeline, one for llvmpipe.
  Stage ours = makeStage(scenes::makeRasterBackend(threads, false), frame);
  Stage llvmpipe = makeStage(scenes::makeGlBackend(), frame);
  Point gl{"llvmpipe", "driver", std::nullopt, {}, 0, {}};

  // Every frame of this pipeline follows one of llvmpipe's, as in `raster bench`. A frame
  // that followed another of ours found the scene's buffers still in the cache: with one
  // llvmpipe frame per round, only the round's first method set (gl) was timed after it,
  // and read 3-9% slower than method sets with the same bytes and the same work.
  auto round = [&](bool timed) {
    for (Point& p : points) {
      const double reference = llvmpipe.frame(frame.time);
      if (timed) gl.ms.push_back(reference);
      const raster::ScopedMethods methods(*p.methods);
      const double ms = ours.frame(frame.time);
      if (timed) p.ms.push_back(ms);
    }
  };
  for (int i = 0; i < args.warmup; ++i) round(false);
  {
    Progress progress("  " + frame.scene + " rounds", args.frames, frame.quiet);
    for (int i = 0; i < args.frames; ++i) {
      round(true);
      progress.update(i + 1, "");
    }
  }

  // The final images, one more frame each (the timed frames were not read back).
  for (Point& p : points) {
    const raster::ScopedMethods methods(*p.methods);
    ours.scene->renderFrame(*ours.backend, frame.time);
    p.image = ours.scene->readFinal(*ours.backend).image;
  }
  llvmpipe.scene->renderFrame(*llvmpipe.backend, frame.time);
  gl.image = llvmpipe.scene->readFinal(*llvmpipe.backend).image;
  for (Point& p : points) p.medianMs = median(p.ms);
  gl.medianMs = median(gl.ms);
  const double glSetMs = points.front().medianMs;   // the gl preset is always first

  std::vector<Point> all = std::move(points);
  all.push_back(std::move(gl));
  if (!args.noSoftpipe) {
    const TemporaryFolder scratch;
    const std::string jsonPath = (fs::path(scratch.path) / "softpipe-bench.json").string();
    const auto [softpipeMs, childGlMs] = timeSoftpipe(frame, threads, args.softpipeFrames, args.warmup, jsonPath);
    Point softpipe{"softpipe", "driver", std::nullopt, {}, 0, {}};
    // Carried over through the gl set, the same work in both processes.
    softpipe.medianMs = softpipeMs * (glSetMs / childGlMs);
    if (!frame.quiet) std::cerr << "  softpipe: rendering its final image in a child process ..." << std::endl;
    softpipe.image = renderInChild(frame, "softpipe").targets.back().image;
    all.push_back(std::move(softpipe));
  }

  const Point& llvmpipeRef = *std::find_if(all.begin(), all.end(), [](const Point& p) { return p.name == "llvmpipe"; });
  const Point& preciseRef = *std::find_if(all.begin(), all.end(), [](const Point& p) { return p.name == "precise"; });
  json result = {{"scene", frame.scene},
                 {"size", {frame.width, frame.height}},
                 {"threads", threads},
                 {"time", frame.time},
                 {"sets", frame.sets},
                 {"frames", args.frames},
                 {"points", json::array()}};
  std::vector<double> speed, accuracy;
  for (const Point& p : all) {
    compare::TargetStats vsGl = compare::compareImages("final", p.image, llvmpipeRef.image);
    compare::measureFlip(vsGl, p.image, llvmpipeRef.image);
    compare::TargetStats vsPrecise = compare::compareImages("final", p.image, preciseRef.image);
    compare::measureFlip(vsPrecise, p.image, preciseRef.image);
    json methods = nullptr;
    if (p.methods) {
      methods = json::object();
      for (const auto& [step, name] : raster::methodNames(*p.methods)) methods[step] = name;
    }
    const double speedup = llvmpipeRef.medianMs / p.medianMs;
    result["points"].push_back({{"name", p.name},
                                {"kind", p.kind},
                                {"methods", methods},
                                {"median_ms", p.medianMs},
                                {"speedup_vs_llvmpipe", speedup},
                                {"identical_to_llvmpipe", identical(vsGl)},
                                {"psnr_vs_llvmpipe_db", dbOrNull(vsGl.psnr)},
                                {"flip_vs_llvmpipe", vsGl.flipMean ? json(*vsGl.flipMean) : json(nullptr)},
                                {"share_over1_vs_llvmpipe", vsGl.shareOver1},
                                {"max_diff_vs_llvmpipe", vsGl.maxAbs},
                                {"psnr_vs_precise_db", dbOrNull(vsPrecise.psnr)},
                                {"flip_vs_precise", vsPrecise.flipMean ? json(*vsPrecise.flipMean) : json(nullptr)},
                                {"nonfinite_pixels", vsGl.nonFinitePixels}});
    speed.push_back(speedup);
    accuracy.push_back(std::isfinite(vsGl.psnr) ? vsGl.psnr : HUGE_VAL);
  }
  const std::vector<bool> front = paretoFront(speed, accuracy);
  for (size_t i = 0; i < front.size(); ++i) result["points"][i]["pareto"] = bool(front[i]);
  return result;
}

}  // namespace

void addTradeoffOptions(CLI::App& command, TradeoffArgs& args) {
  command.add_option("scene", args.scene, "Scene, or all (one chart panel per scene)")->required()->type_name("SCENE|all");
  command.add_option("--time", args.time, "Time in seconds")->type_name("T")->capture_default_str();
  command.add_option("--size", args.size, "Image size")->type_name("WxH")->capture_default_str();
  command.add_option("--threads", args.threads, "Threads of this pipeline and llvmpipe; 0: every core")
      ->type_name("N")->capture_default_str();
  command.add_option("--frames", args.frames, "Timed rounds (each: every method set once, each after an llvmpipe frame), 1..1000")
      ->capture_default_str();
  command.add_option("--warmup", args.warmup, "Untimed rounds first (0..100; softpipe's timing child takes at most 1)")->capture_default_str();
  command.add_option("--softpipe-frames", args.softpipeFrames, "Timed softpipe frames (1..100)")->capture_default_str();
  command.add_flag("--no-softpipe", args.noSoftpipe, "Leave softpipe out (it is slow)");
  command.add_option("--out", args.out,
                      "Folder for tradeoff.json (one object per scene; a list of them for several scenes), "
                      "tradeoff.md, tradeoff.png, tradeoff.svg")
      ->required()->type_name("DIR");
  command.add_option("--assets", args.assets, "Asset folder")->type_name("DIR");
  command.add_option("--max-memory", args.maxMemory, "Refuse (exit 2) a run that would take more than SIZE")
      ->type_name("SIZE");
  command.add_option("--instances", args.instances, "Cubes in the hdr scene (1..200000)")->capture_default_str();
  addSetOption(command, args.sets);
  addQuietOption(command, args.quiet);
}

int runTradeoff(const TradeoffArgs& args) {
  // Everything is checked before the first frame.
  std::vector<std::string> sceneList;
  if (args.scene == "all") sceneList = scenes::sceneNames();
  else sceneList = {args.scene};
  std::vector<Frame> frames;
  for (const std::string& scene : sceneList) {
    FrameArgs frameArgs = args;
    frameArgs.scene = scene;
    frames.push_back(validateFrame(frameArgs));
  }
  if (args.frames < 1 || args.frames > 1000) throw UsageError("--frames: out of range (1..1000)");
  if (args.warmup < 0 || args.warmup > 100) throw UsageError("--warmup: out of range (0..100)");
  if (args.softpipeFrames < 1 || args.softpipeFrames > 100) throw UsageError("--softpipe-frames: out of range (1..100)");
  checkOutputFolder("--out", args.out, kTradeoffFiles);
  checkChartTools("tradeoff_chart.py");

  const int threads = args.threads > 0 ? args.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
  pinToCores(threads);

  json results = json::array();
  std::string markdown = "# Speed against accuracy\n\nMade by `" + commandLine(args, frames.front(), threads) + "`. Speed-up: llvmpipe's median frame time over the point's, each of this "
                         "pipeline's frames timed right after one of llvmpipe's; "
                         "PSNR and pixel shares on the final image (RGBA8, 8-bit steps); FLIP: its mean LDR-FLIP error "
                         "at 67 pixels per degree (0: no visible difference, 1: the most). `*`: Pareto-optimal.\n\n";
  for (const Frame& frame : frames) {
    json result = runScene(args, frame, threads, args.out);
    markdown += markdownTable(result);
    results.push_back(std::move(result));
  }
  // Made now, with the results: a run that fails as it renders leaves no folder (one whose
  // chart script fails after this leaves the folder with the table and the JSON).
  fs::create_directories(args.out);
  const std::string jsonPath = (fs::path(args.out) / "tradeoff.json").string();
  compare::writeOutputFile(jsonPath, (results.size() == 1 ? results[0] : results).dump(2) + "\n");
  compare::writeOutputFile((fs::path(args.out) / "tradeoff.md").string(), markdown);
  drawChart("tradeoff_chart.py", jsonPath, (fs::path(args.out) / "tradeoff").string());
  std::cout << markdown;
  for (const std::string& file : kTradeoffFiles) std::cout << "wrote " << (fs::path(args.out) / file).string() << "\n";
  return 0;
}

}  // namespace cli
