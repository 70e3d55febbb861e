// `raster sweep` (sweep.h); `raster sweep-merge` is sweep_merge.cpp.
#include "apps/sweep/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps/common/charts.h"
#include "apps/common/progress.h"
#include "apps/common/number_text.h"
#include "apps/common/sides.h"
#include "apps/sweep/sweep_file.h"
#include "compare/metrics.h"
#include "io/asset_file.h"
#include "io/assets.h"
#include "io/memory_budget.h"
#include "io/output_file.h"
#include "scenes/registry.h"
#include "scenes/scene_params.h"

namespace cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

SweepRange parseRange(const std::string& scene, const std::string& text) {
  const std::string usage = "--param: '" + text + "' is not NAME=FROM:TO:STEPS[:log] (e.g. near=0.1:0.0001:12:log)";
  const size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0) throw UsageError(usage);
  SweepRange range;
  range.name = text.substr(0, equals);
  const std::vector<std::string> parts = split(text.substr(equals + 1), ':');
  if (parts.size() != 3 && parts.size() != 4) throw UsageError(usage);
  if (parts.size() == 4) {
    if (parts[3] != "log") throw UsageError(usage + ": the fourth field may only be 'log'");
    range.log = true;
  }
  try {
    scenes::findParam(scene, range.name);
    if (range.name == "size") {   // widths: the height follows at 4:3 (scene_params.h)
      int w = 0, h = 0;
      if (!scenes::parseSizeValue(parts[0], w, h) || !scenes::parseSizeValue(parts[1], w, h) ||
          parts[0].find('x') != std::string::npos || parts[1].find('x') != std::string::npos)
        throw scenes::ParamError("size: sweep widths (1..16384), not WxH: '" + parts[0] + "', '" + parts[1] + "'");
    }
    range.from = scenes::parseParamValue(scene, range.name, parts[0]);
    range.to = scenes::parseParamValue(scene, range.name, parts[1]);
  } catch (const scenes::ParamError& e) {
    throw UsageError(std::string("--param: ") + e.what());
  }
  const std::optional<uint64_t> steps = parseWholeNumber(parts[2]);   // plain digits: not ' 3' or '+3'
  if (!steps || *steps < 1 || *steps > uint64_t(kMaxSweepSteps))
    throw UsageError("--param: STEPS '" + parts[2] + "' is not a whole number in 1.." + std::to_string(kMaxSweepSteps));
  range.steps = int(*steps);
  if (range.log && (range.from <= 0 || range.to <= 0))
    throw UsageError("--param: a log range needs FROM and TO above 0 (got " + parts[0] + " and " + parts[1] + ")");
  return range;
}

// 17 significant digits: the same double back, so a shard and the whole run agree.
std::string valueText(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// A method set named as a preset (gl, fast, ...) or as single steps changed from gl
// (math=fast, or math=fast+div=approx).
struct MethodSide {
  std::string name;
  raster::MethodSet set;
};

std::vector<MethodSide> parseMethodList(const std::string& text) {
  std::vector<MethodSide> sides;
  for (const std::string& name : split(text, ',')) {
    if (name.empty()) throw UsageError("--methods: '" + text + "' has an empty name");
    if (name == "llvmpipe" || name == "softpipe")
      throw UsageError("--methods: " + name + " is a GL driver, not a method set (llvmpipe is the reference; softpipe "
                       "is always swept unless --no-softpipe)");
    raster::MethodSet set;
    try {
      if (name.find('=') == std::string::npos) {
        set = raster::presetMethods(name);
      } else {
        std::string overrides = name;
        std::replace(overrides.begin(), overrides.end(), '+', ',');
        raster::applyMethodOverrides(set, overrides);
      }
    } catch (const raster::MethodError& e) {
      throw UsageError(std::string("--methods: ") + e.what());
    }
    for (const MethodSide& s : sides)
      if (s.name == name) throw UsageError("--methods: " + name + " is named twice");
    sides.push_back({name, set});
  }
  if (sides.empty()) throw UsageError("--methods: names no method set");
  return sides;
}

// Pixels of float targets with a NaN or infinite channel, over every target of a side.
uint64_t nonFinitePixels(const std::vector<scenes::Target>& targets) {
  uint64_t count = 0;
  for (const scenes::Target& t : targets) {
    const scenes::ImageData& image = t.image;
    if (image.floats.empty() || image.channels < 1) continue;
    const size_t channels = size_t(image.channels);
    for (size_t p = 0; p + channels <= image.floats.size(); p += channels) {
      bool finite = true;
      for (size_t c = 0; c < channels; ++c) finite = finite && std::isfinite(image.floats[p + c]);
      count += finite ? 0 : 1;
    }
  }
  return count;
}

// One point: `side`'s targets against llvmpipe's.
json scorePoint(double value, size_t valueIndex, const std::string& name, const std::vector<scenes::Target>& side,
                const std::vector<scenes::Target>& reference, double thresholdDb) {
  if (side.size() != reference.size())
    throw std::runtime_error(name + " exposed " + std::to_string(side.size()) + " targets, llvmpipe " +
                             std::to_string(reference.size()));
  bool identical = true;
  compare::TargetStats final;
  std::string worst;
  double worstPsnr = HUGE_VAL;
  for (size_t i = 0; i < side.size(); ++i) {
    compare::TargetStats s = compare::compareImages(side[i].name, side[i].image, reference[i].image);
    identical = identical && s.shareDiffering == 0;
    if (i + 1 == side.size()) {
      compare::measureFlip(s, side[i].image, reference[i].image);   // the final image only: it costs
      final = s;
    } else if (s.shareDiffering > 0 && (worst.empty() || s.psnr < worstPsnr)) {
      worst = side[i].name;
      worstPsnr = s.psnr;
    }
  }
  const uint64_t nonFinite = nonFinitePixels(side);
  const std::string failure = sweepFailure(nonFinite, final.psnr, thresholdDb);
  return {{"value", value},
          {"value_index", valueIndex},
          {"method", name},
          {"identical_to_llvmpipe", identical},
          {"psnr_vs_llvmpipe_db", identical ? json(nullptr) : dbOrNull(final.psnr)},
          {"flip_vs_llvmpipe", final.flipMean ? json(*final.flipMean) : json(nullptr)},
          {"share_over1_vs_llvmpipe", final.shareOver1},
          {"max_diff_vs_llvmpipe", final.maxAbs},
          {"nonfinite_pixels", nonFinite},
          {"worst_target", worst.empty() ? json(nullptr) : json(worst)},
          {"worst_target_psnr_db", worst.empty() ? json(nullptr) : dbOrNull(worstPsnr)},
          {"fails", !failure.empty()},
          {"failure", failure}};
}

// Every value's scene, made but not set up: a scene checks its parameters as it is made
// (pbr: its cascade splits must rise) and reads or draws nothing then, so a value the scene
// refuses stops the sweep here, not after the values before it rendered, and --check says so.
void checkSceneAtEveryValue(const std::vector<Frame>& frames, const std::string& param, const std::vector<double>& values) {
  for (size_t i = 0; i < frames.size(); ++i) {
    try {
      scenes::makeScene(frames[i].scene, sceneOptions(frames[i]));
    } catch (const scenes::SceneError& e) {
      throw UsageError("--param " + param + "=" + valueText(values[i]) + ": " + e.what());
    }
  }
}

// The files the scene reads (its registry row's assets) are looked for, not read: a missing
// one stops the sweep here rather than at its first render, in the loaders' own words
// (io/assets.h). What a file holds is checked as it loads, as for every command.
void checkAssetsPresent(const Frame& frame) {
  const scenes::SceneOptions options = sceneOptions(frame);
  for (const std::string& asset : scenes::sceneEntry(frame.scene).assets)
    scenes::checkAssetFileExists(scenes::assetPath(options, asset));
}

// The least memory a value needs: the final images of llvmpipe and of the side scored
// against it, both held while it is scored (RGBA8, 4 bytes a pixel, reserved as each is read
// back). What a scene's textures and targets take is counted only as they are made, so a cap
// above this may still stop a frame as it renders; below it, no frame can.
void checkMemoryFloor(const std::vector<Frame>& frames) {
  auto pixels = [](const Frame& frame) { return uint64_t(frame.width) * uint64_t(frame.height); };
  const Frame* largest = &frames.front();
  for (const Frame& frame : frames)
    if (pixels(frame) > pixels(*largest)) largest = &frame;
  const uint64_t floor = pixels(*largest) * 4 * 2;
  if (floor > scenes::memory::cap())
    throw UsageError("--max-memory: the cap of " + scenes::memory::formatBytes(scenes::memory::cap()) + " is below the " +
                     scenes::memory::formatBytes(floor) + " that llvmpipe's and one side's final images of a " +
                     std::to_string(largest->width) + "x" + std::to_string(largest->height) + " frame take at once");
}

}  // namespace

void addSweepOptions(CLI::App& command, SweepArgs& args) {
  command.add_option("scene", args.scene, "Scene")->required()->type_name("SCENE");
  command.add_option("--param", args.param,
                      "The parameter and its values, e.g. near=0.1:0.0001:12:log (raster params SCENE lists them)")
      ->required()->type_name("NAME=FROM:TO:STEPS[:log]");
  command.add_option("--methods", args.methods,
                      "Method sets of this pipeline: presets, or steps changed from gl (math=fast, math=fast+div=approx)")
      ->type_name("SET[,SET...]")->capture_default_str();
  command.add_option("--time", args.time, "Time in seconds")->type_name("T")->capture_default_str();
  command.add_option("--size", args.size, "Image size")->type_name("WxH")->capture_default_str();
  command.add_option("--threads", args.threads, "Threads of this pipeline and the GL drivers; 0: every core")
      ->type_name("N")->capture_default_str();
  command.add_option("--threshold", args.threshold, "A final image below this PSNR (dB) against llvmpipe fails")
      ->type_name("DB")->capture_default_str();
  command.add_option("--shard", args.shard, "Render only shard K of N (values i with i % N == K - 1); sweep-merge joins them")
      ->type_name("K/N");
  command.add_flag("--no-softpipe", args.noSoftpipe, "Leave softpipe out (it is slow)");
  command.add_flag("--check", args.check,
                    "Check every option and value (exit 2 on bad input), render nothing: for a cluster runner");
  command.add_option("--out", args.out, "Folder for sweep.json, sweep.md, sweep.png, sweep.svg")->required()->type_name("DIR");
  command.add_option("--assets", args.assets, "Asset folder")->type_name("DIR");
  command.add_option("--max-memory", args.maxMemory, "Refuse (exit 2) a run that would take more than SIZE")->type_name("SIZE");
  command.add_option("--instances", args.instances, "Cubes in the hdr scene (1..200000)")->capture_default_str();
  addSetOption(command, args.sets);
  addQuietOption(command, args.quiet);
}

int runSweep(const SweepArgs& args) {
  // Everything is checked before the first frame: the frame, the range and every value in
  // it (the scene made at each), the method sets, the shard, the assets, the memory the
  // final images need, the output folder and the chart's tools.
  const Frame base = validateFrame(args);
  const SweepRange range = parseRange(base.scene, args.param);
  for (const std::string& set : args.sets)
    if (set.substr(0, set.find('=')) == range.name)
      throw UsageError("--set " + set + ": " + range.name + " is the swept parameter");
  const bool integer = scenes::findParam(base.scene, range.name).integer;
  const std::vector<double> values = sweepValues(range, integer);
  const std::vector<MethodSide> methods = parseMethodList(args.methods);
  const ShardSpec shard = parseShard(args.shard);
  const double threshold = parseFiniteNumber("--threshold", args.threshold);   // dB
  std::vector<Frame> frames;   // one per value, through the same checks as --set
  for (double v : values) {
    FrameArgs frameArgs = args;
    frameArgs.sets.push_back(range.name + "=" + valueText(v));
    frameArgs.quiet = true;   // the sweep's own progress replaces the per-render lines
    frames.push_back(validateFrame(frameArgs));
  }
  checkSceneAtEveryValue(frames, range.name, values);
  checkAssetsPresent(base);
  checkMemoryFloor(frames);
  checkOutputFolder("--out", args.out, sweepFiles(shard.sharded));
  if (!shard.sharded) checkChartTools(kSweepChartScript);
  if (args.check) {
    std::cout << "sweep " << base.scene << " " << range.name << ": " << values.size() << " values x "
              << (1 + methods.size() + (args.noSoftpipe ? 0 : 1))
              << " sides; the options, the scene at every value and its asset files are valid (--max-memory: checked "
                 "here against the final images, in full as each frame is made)\n";
    return 0;
  }

  json sweep = {{"scene", base.scene},
                {"param", range.name},
                {"range", {{"from", range.from}, {"to", range.to}, {"steps", range.steps}, {"log", range.log}}},
                {"size", {base.width, base.height}},
                {"time", base.time},
                {"instances", base.instances},
                {"sets", args.sets},
                {"threshold_db", threshold},
                {"methods", json::array()},
                {"softpipe", !args.noSoftpipe},
                {"points", json::array()}};
  for (const MethodSide& m : methods) sweep["methods"].push_back(m.name);
  const std::vector<size_t> mine = shardValueIndexes(shard, values.size());
  if (shard.sharded) {
    sweep["shard"] = std::to_string(shard.index) + "/" + std::to_string(shard.count);
    sweep["shard_values"] = mine;
  }

  const int sidesPerValue = 1 + int(methods.size()) + (args.noSoftpipe ? 0 : 1);
  Progress progress("sweep " + base.scene + " " + range.name, int(mine.size()) * sidesPerValue, args.quiet);
  int done = 0;
  for (size_t i : mine) {
    const Frame& frame = frames[i];
    const std::string at = range.name + "=" + valueText(values[i]) + ": ";
    progress.update(done, at + "llvmpipe");
    const Side reference = renderSide(frame, "llvmpipe");
    sweep["points"].push_back(scorePoint(values[i], i, "llvmpipe", reference.targets, reference.targets, threshold));
    ++done;
    for (const MethodSide& m : methods) {
      Frame withMethods = frame;
      withMethods.methods = m.set;
      progress.update(done, at + m.name);
      const Side side = renderInProcess(withMethods, "raster");
      sweep["points"].push_back(scorePoint(values[i], i, m.name, side.targets, reference.targets, threshold));
      ++done;
    }
    if (!args.noSoftpipe) {
      progress.update(done, at + "softpipe");
      const Side side = renderInChild(frame, "softpipe");
      sweep["points"].push_back(scorePoint(values[i], i, "softpipe", side.targets, reference.targets, threshold));
      ++done;
    }
    progress.update(done, at + "done");
  }
  writeSweep(std::move(sweep), args.out);
  return 0;
}

}  // namespace cli
