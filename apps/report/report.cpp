// `raster report`: the HTML report (report.h), step by step: check everything, then per
// scene its targets, views and traces, then the charts, then the page, then into place.
#include "apps/report/report.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>

#include <nlohmann/json.hpp>

#include "apps/common/pixels_to_trace.h"
#include "apps/common/progress.h"
#include "apps/common/sides.h"
#include "apps/common/target_stats_json.h"
#include "apps/report/report_charts.h"
#include "apps/report/report_children.h"
#include "apps/report/report_folder.h"
#include "apps/report/report_html.h"
#include "apps/report/report_results.h"
#include "apps/report/report_targets.h"
#include "apps/views/stage_views.h"
#include "compare/metrics.h"
#include "io/output_file.h"
#include "backends/backends.h"
#include "scenes/registry.h"

namespace cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kMaxPixels = 16;   // each pixel is a child process tracing a whole frame

// What the report covers, checked: a frame per scene, and the folders searched for charts.
struct ReportPlan {
  std::vector<Frame> frames;
  std::vector<std::string> includes;
};

// Every check of the command line, before anything renders or is written.
ReportPlan planReport(const ReportArgs& args) {
  ReportPlan plan;
  std::vector<std::string> sceneList;   // "all" expanded, each scene once
  for (const std::string& scene : args.scenes) {
    const std::vector<std::string> names = scene == "all" ? scenes::sceneNames() : std::vector<std::string>{scene};
    for (const std::string& name : names)
      if (std::find(sceneList.begin(), sceneList.end(), name) == sceneList.end()) sceneList.push_back(name);
  }
  for (const std::string& scene : sceneList) {
    FrameArgs frameArgs = args;
    frameArgs.scene = scene;
    plan.frames.push_back(validateFrame(frameArgs));
    plan.frames.back().quiet = true;   // the progress bar speaks for the renders
  }
  if (args.pixels < 0 || args.pixels > kMaxPixels)
    throw UsageError("--pixels: " + std::to_string(args.pixels) + " is out of range (0.." + std::to_string(kMaxPixels) + ")");
  for (const std::string& include : args.include) {
    requireFolder("--include", include);
    plan.includes.push_back(include);
  }
  if (!args.noDefaultInclude) {
    const char* sourceDir = std::getenv("RASTER_SOURCE_DIR");
    const fs::path docs = fs::path(sourceDir ? sourceDir : RASTER_SOURCE_DIR) / "docs";
    std::error_code unreadable;   // the repository's docs/, where it can be read; else none
    if (fs::is_directory(docs, unreadable)) plan.includes.push_back(docs.string());
  }
  report::checkReportFolder(args.out);
  scenes::checkGalliumEnvironment();
  return plan;
}

// A scene's section: both sides rendered, a row per target, its views and its traces.
report::Section sceneSection(const report::SceneWork& scene, json& record) {
  const Frame& frame = scene.frame;
  fs::create_directory(scene.work / scene.folder);
  scene.step(frame.scene + ": this pipeline");
  const Side ours = renderSide(frame, "raster");
  scene.step(frame.scene + ": llvmpipe");
  const Side gl = renderSide(frame, "llvmpipe");
  if (ours.targets.size() != gl.targets.size())
    throw std::runtime_error("the sides of " + frame.scene + " expose different targets");

  scene.step(frame.scene + ": images and metrics");
  record = {{"scene", frame.scene}, {"size", {frame.width, frame.height}}, {"time", frame.time}, {"sets", frame.sets},
            {"targets", json::array()}, {"views", json::array()}, {"traces", json::array()}};
  std::string html = "<p>" + report::escape(frame.scene + " at " + sizeAndTime(frame) + "; this pipeline (methods: " +
                                            raster::methodLabel(frame.methods) + ") against " + gl.backend + ".") +
                     " Heat maps: black where equal, blue 1, yellow 4, red 16 or more units of the target's kind "
                     "(8-bit steps, depth LSBs, half ULPs).</p>\n";
  for (size_t i = 0; i < ours.targets.size(); ++i) {
    const scenes::Target& mine = ours.targets[i];
    const scenes::Target& theirs = gl.targets[i];
    if (mine.name != theirs.name) throw std::runtime_error("the sides of " + frame.scene + " expose different targets");
    compare::TargetStats stats = compare::compareImages(mine.name, mine.image, theirs.image);
    compare::measureFlip(stats, mine.image, theirs.image);
    const json statsRecord = cli::targetStatsJson(stats);
    html += "<h3>" + report::escape(mine.name + " (" + stats.kind + ")") + "</h3>\n" +
            report::targetRow(mine, theirs, gl.backend, scene.folder, scene.work, statsRecord);
    record["targets"].push_back(statsRecord);
  }

  html += report::viewsHtml(scene, record["views"]);
  const std::vector<cli::ChosenPixel> pixels =
      cli::choosePixels(ours.targets.back().image, gl.targets.back().image, scene.args.pixels);
  html += report::tracesHtml(scene, pixels, gl.backend, record["traces"]);
  return {"scene-" + scene.folder, "Scene " + frame.scene, html};
}

// The charts' section: each result copied in with its tables.
report::Section chartsSection(const std::vector<report::ChartResult>& charts, const fs::path& work,
                              const std::function<void(const std::string&)>& step, json& record) {
  std::string html;
  if (charts.empty()) html = report::note("No tradeoff.json or sweep.json under the --include folders.");
  for (size_t i = 0; i < charts.size(); ++i) {
    step("charts: " + charts[i].label);
    json chartRecord;
    html += report::chartSection(charts[i], work, int(i + 1), chartRecord);
    record.push_back(std::move(chartRecord));
  }
  return {"charts", "Speed against accuracy, and stability sweeps", html};
}

// The page's first paragraph: the command that made it, and where the numbers are.
std::string introHtml(const ReportArgs& args) {
  std::string intro = "<p>Made by <code>raster report";
  for (const std::string& scene : args.scenes) intro += " " + report::escape(scene);
  intro += " --size " + report::escape(args.size) + " --time " + report::escape(args.time);
  if (args.preset != "gl") intro += " --preset " + report::escape(args.preset);
  if (!args.method.empty()) intro += " --method " + report::escape(args.method);
  for (const std::string& set : args.sets) intro += " --set " + report::escape(set);
  return intro + "</code>. Images are files beside this page; the numbers are in <a href=\"report.json\">report.json</a>.</p>\n";
}

}  // namespace

void addReportOptions(CLI::App& command, ReportArgs& args) {
  std::string names;
  for (const auto& name : scenes::sceneNames()) names += (names.empty() ? "" : ", ") + name;
  command.add_option("scenes", args.scenes, "Scenes (" + names + "), or all")->required()->type_name("SCENE...");
  command.add_option("--out", args.out, "Folder for index.html and its files (replaced as a whole)")
      ->required()->type_name("DIR");
  command.add_option("--size", args.size, "Image size")->type_name("WxH")->capture_default_str();
  command.add_option("--time", args.time, "Time in seconds")->type_name("T")->capture_default_str();
  command.add_option("--threads", args.threads, "Threads of this pipeline and llvmpipe; 0: every core")
      ->type_name("N")->capture_default_str();
  command.add_option("--pixels", args.pixels,
                     "Pixels traced per scene (0.." + std::to_string(kMaxPixels) + "): the worst differing first")
      ->type_name("N")->capture_default_str();
  command.add_option("--include", args.include,
                     "Folder searched for tradeoff.json and sweep.json (repeatable; default: the repository's docs/)")
      ->type_name("DIR")->take_all()->allow_extra_args(false);
  command.add_flag("--no-default-include", args.noDefaultInclude, "Do not search the repository's docs/");
  command.add_option("--assets", args.assets, "Asset folder")->type_name("DIR");
  command.add_option("--max-memory", args.maxMemory, "Refuse (exit 2) a run that would take more than SIZE")
      ->type_name("SIZE");
  addMethodOptions(command, args.preset, args.method);
  addSetOption(command, args.sets);
  addQuietOption(command, args.quiet);
}

int runReport(const ReportArgs& args) {
  const ReportPlan plan = planReport(args);
  report::ReportFolder folder(args.out);
  const std::vector<report::ChartResult> charts = report::findChartResults(plan.includes);
  const int stepsPerScene = 3 + int(stageViews().size()) + args.pixels;   // two sides, the targets, views, traces
  Progress progress("report", int(plan.frames.size()) * stepsPerScene + int(charts.size()) + 1, args.quiet);
  int done = 0;
  const auto step = [&](const std::string& next) { progress.update(done++, next); };

  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  json record = {{"made_by", "raster report"}, {"scenes", json::array()}, {"charts", json::array()}};
  // The charts' section first, shown last: a result under --include that is not one is
  // refused before minutes of rendering, not after.
  report::Section chartSection = chartsSection(charts, folder.work(), step, record["charts"]);
  std::vector<report::Section> sections;
  for (const Frame& frame : plan.frames) {
    const report::SceneWork scene{frame, args, report::fileSafe(frame.scene), folder.work(), folder.scratch(), step};
    json sceneRecord;
    sections.push_back(sceneSection(scene, sceneRecord));
    record["scenes"].push_back(std::move(sceneRecord));
  }
  sections.push_back(std::move(chartSection));

  // The data, then the page last, then the whole folder into place.
  step("index.html");
  compare::writeOutputFile((folder.work() / "report.json").string(), record.dump(2) + "\n");
  compare::writeOutputFile((folder.work() / "index.html").string(), report::page("raster report", introHtml(args), sections));
  progress.update(done, "done");
  folder.moveIntoPlace();
  std::cout << "wrote " << (folder.target() / "index.html").string() << std::endl;
  return 0;
}

}  // namespace cli
