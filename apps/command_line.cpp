// raster: the command line (cli::run; apps/main.cpp calls it, and so do programs that
// register more scenes first, as the registry test does).
//   raster render SCENE ...   one frame with this pipeline or GL; the final image as PNG,
//                             and with --dump every target (PNG preview + lossless dump);
//                             with --view NAME a stage view instead (views.h);
//   raster compare SCENE ...  one frame with a test and a reference backend; per target a
//                             stats line and ours / gl / heat-map PNGs; optional thresholds;
//   raster bench SCENE ...    frame times of this pipeline and a GL driver (bench.h);
//   raster tradeoff SCENE ... every method set against llvmpipe and softpipe (tradeoff.h);
//   raster sweep SCENE ...    one parameter moved toward failure, every side scored (sweep.h);
//   raster sweep-merge DIR... the shards of a sweep joined into one;
//   raster report SCENE...    an HTML page: ours, GL and heat maps, metrics, views, traces (report.h);
//   raster soup --seeds A:B   random triangle soups, this pipeline against llvmpipe (soup.h);
//   raster trace SCENE --pixel X,Y   pixel history: every fragment of every pass behind one pixel (trace.h);
//   raster methods, scenes    the methods of each step and the presets; the scene names;
//   raster params SCENE       the scene's parameters, set with --set NAME=VALUE.
// Options and their checks live in cli_options.*; everything is validated before rendering.
// A side of a comparison is rendered by sides.h: softpipe in a child process, because Mesa
// picks one Gallium driver per process.
//
// Exit status: 0 success; 1 internal failure or a compare threshold exceeded; 2 bad input.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/bench/bench.h"
#include "apps/report/report.h"
#include "apps/common/number_text.h"
#include "apps/common/sides.h"
#include "apps/soup/soup.h"
#include "apps/sweep/sweep.h"
#include "apps/trace/trace.h"
#include "apps/tradeoff/tradeoff.h"
#include "apps/views/views.h"
#include "apps/common/cli_options.h"
#include "apps/command_line.h"
#include "compare/image_io.h"
#include "compare/metrics.h"
#include "compare/output_file.h"
#include "scenes/backends.h"
#include "scenes/memory_budget.h"
#include "scenes/registry.h"

namespace {

namespace fs = std::filesystem;
using cli::Frame;
using cli::UsageError;
using scenes::Target;
using cli::Side;
using cli::dumpTargets;
using cli::renderInProcess;
using cli::renderSide;
using cli::sizeAndTime;
using cli::sixDigits;

int runRender(const cli::RenderArgs& args) {
  const Frame frame = cli::validateFrame(args);
  if (args.backend != "raster" && args.backend != "gl")
    throw UsageError("--backend: '" + args.backend + "' is neither raster nor gl");
  if (!args.view.empty()) return cli::runViewRender(args, frame);
  if (!args.pass.empty()) throw UsageError("--pass chooses the pass of a --view");
  if (args.backend == "gl" && !(frame.methods == raster::MethodSet{}))
    throw UsageError("--preset/--method choose this pipeline's methods; --backend gl renders with GL's own");
  const std::string out = args.out.empty() ? frame.scene + ".png" : args.out;
  cli::checkOutputFile("--out", out);
  if (!args.dump.empty()) cli::checkOutputFolder("--dump", args.dump);
  if (args.backend == "gl") scenes::checkGalliumEnvironment();

  const Side side = renderInProcess(frame, args.backend, /*finalOnly=*/args.dump.empty());
  compare::writePng(out, side.targets.back().image);
  std::cout << "wrote " << out << std::endl;
  if (!args.dump.empty()) dumpTargets(args.dump, side.targets);
  return 0;
}

// The thresholds a target exceeds, one message each (colour ones for rgba8, depth for depth).
std::vector<std::string> exceeded(const compare::TargetStats& s, const cli::Thresholds& limits) {
  std::vector<std::string> failures;
  if (s.kind == "rgba8") {
    if (limits.maxRmse && s.rmse > *limits.maxRmse)
      failures.push_back(s.name + ": rmse " + sixDigits(s.rmse) + " exceeds --max-rmse " + sixDigits(*limits.maxRmse));
    if (limits.minPsnr && s.psnr < *limits.minPsnr)
      failures.push_back(s.name + ": psnr " + sixDigits(s.psnr) + " is below --min-psnr " + sixDigits(*limits.minPsnr));
    if (limits.maxShareOver1 && s.shareOver1 > *limits.maxShareOver1)
      failures.push_back(s.name + ": share of pixels off by more than 1 step " + sixDigits(s.shareOver1) +
                         " exceeds --max-share-over1 " + sixDigits(*limits.maxShareOver1));
  }
  if (s.kind == "depth" && limits.maxDepthLsb && s.maxDepthLsb > *limits.maxDepthLsb)
    failures.push_back(s.name + ": depth differs by up to " + std::to_string(s.maxDepthLsb) +
                       " LSBs, over --max-depth-lsb " + std::to_string(*limits.maxDepthLsb));
  return failures;
}

int runCompare(const cli::CompareArgs& args) {
  const Frame frame = cli::validateFrame(args);
  if (args.test != "raster" && args.test != "softpipe")
    throw UsageError("--test: '" + args.test + "' is neither raster nor softpipe");
  if (args.reference != "llvmpipe" && args.reference != "softpipe")
    throw UsageError("--reference: '" + args.reference + "' is neither llvmpipe nor softpipe");
  if (args.test != "raster" && !(frame.methods == raster::MethodSet{}))
    throw UsageError("--preset/--method choose this pipeline's methods; --test " + args.test + " renders with GL's own");
  const cli::Thresholds limits = cli::validateThresholds(args);
  const std::string outFolder = args.out.empty() ? "compare-" + frame.scene : args.out;
  cli::checkOutputFolder("--out", outFolder);
  scenes::checkGalliumEnvironment();

  // Render both sides; they must expose the same targets in the same order.
  const Side test = renderSide(frame, args.test);
  const Side reference = renderSide(frame, args.reference);
  const auto names = [](const Side& side) {
    std::string list;
    for (const Target& t : side.targets) list += (list.empty() ? "" : ",") + t.name;
    return list;
  };
  if (names(test) != names(reference))
    throw std::runtime_error("the sides expose different targets: " + test.backend + " {" + names(test) +
                             "}, " + reference.backend + " {" + names(reference) + "}");

  // Per target: three images, one stats line, and the thresholds it exceeds.
  fs::create_directory(outFolder);
  std::cout << "test: " << test.backend;
  if (args.test == "raster") std::cout << " (methods: " << raster::methodLabel(frame.methods) << ")";
  std::cout << "  reference: " << reference.backend << "  scene: " << frame.scene << " at " << sizeAndTime(frame)
            << std::endl;
  std::vector<std::string> failures;
  for (size_t i = 0; i < test.targets.size(); ++i) {
    const Target& ours = test.targets[i];
    const Target& theirs = reference.targets[i];
    const compare::TargetStats stats = compare::compareImages(ours.name, ours.image, theirs.image);
    const std::string base = (fs::path(outFolder) / ours.name).string();
    compare::writePng(base + "_ours.png", ours.image);
    compare::writePng(base + "_gl.png", theirs.image);
    compare::writeHeatmapPng(base + "_diff.png", ours.image, theirs.image);
    std::cout << compare::formatStatsLine(stats) << std::endl;
    for (const std::string& failure : exceeded(stats, limits)) failures.push_back(failure);
  }
  std::cout << "images: " << outFolder << "/NAME_{ours,gl,diff}.png" << std::endl;
  for (const std::string& failure : failures) std::cerr << "raster: " << failure << std::endl;
  return failures.empty() ? 0 : 1;
}

// `raster methods`: every step, its methods (the default first) and what each trades; then
// the presets as step=method lists.
int listMethods() {
  for (const raster::StepInfo& step : raster::methodCatalog()) {
    std::cout << step.name << ": " << step.what << "\n";
    for (size_t i = 0; i < step.methods.size(); ++i)
      std::cout << "  " << step.name << "=" << step.methods[i].name << (i == 0 ? " (default)" : "") << "  "
                << step.methods[i].trade << "\n";
  }
  std::cout << "presets:\n";
  for (const std::string& preset : raster::presetNames()) {
    std::cout << "  " << preset << " ";
    for (const auto& [step, method] : raster::methodNames(raster::presetMethods(preset)))
      std::cout << " " << step << "=" << method;
    std::cout << "\n";
  }
  return 0;
}

// `raster params SCENE`: one line per parameter, its range, default and meaning; with
// --json the same as a list of objects.
nlohmann::json paramsJson(const std::vector<scenes::ParamSpec>& specs) {
  nlohmann::json list = nlohmann::json::array();
  for (const scenes::ParamSpec& p : specs)
    list.push_back({{"name", p.name}, {"min", p.min}, {"max", p.max}, {"integer", p.integer}, {"unit", p.unit},
                    {"default", p.byDefault}, {"meaning", p.meaning}});
  return list;
}

int listParams(const std::string& scene, bool asJson) {
  const std::vector<scenes::ParamSpec>& specs = scenes::sceneEntry(scene).params;   // SceneError: exit 2
  if (asJson) {
    std::cout << paramsJson(specs).dump(2) << "\n";
    return 0;
  }
  std::cout << "parameters of " << scene << " (set with --set NAME=VALUE on render, compare, bench, tradeoff, sweep):\n";
  for (const scenes::ParamSpec& p : specs) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-16s %-16s default %-8s ", p.name.c_str(),
                  (sixDigits(p.min) + ".." + sixDigits(p.max) + (p.unit.empty() ? "" : " " + p.unit)).c_str(), p.byDefault.c_str());
    std::cout << line << p.meaning << "\n";
  }
  return 0;
}

// `raster scenes`: the registry's names, one a line; with --json every row (name,
// description, seed, parameters, programs, assets, stability sweeps), which the bench/
// runners, setup.sh and bench/stability_sweeps.sh read.
int listScenes(bool asJson) {
  if (!asJson) {
    for (const std::string& name : scenes::sceneNames()) std::cout << name << "\n";
    return 0;
  }
  nlohmann::json rows = nlohmann::json::array();
  for (const scenes::SceneEntry& row : scenes::sceneRegistry()) {
    nlohmann::json programs = nlohmann::json::array();
    for (const scenes::ProgramEntry& program : row.programs) programs.push_back(program.name);
    rows.push_back({{"name", row.name}, {"description", row.description}, {"seed", row.seed},
                    {"params", paramsJson(row.params)}, {"programs", programs}, {"assets", row.assets},
                    {"sweeps", row.sweeps}});
  }
  std::cout << rows.dump(2) << "\n";
  return 0;
}

// One line, as the single error line demands.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n') c = ' ';
  return text;
}

}  // namespace

int cli::run(int argc, char** argv) {
  CLI::App app{"A CPU software rasterizer for GL 3.3 scenes, checked against real OpenGL (OSMesa)",
               "raster"};
  app.require_subcommand(1);
  cli::RenderArgs renderArgs;
  cli::CompareArgs compareArgs;
  CLI::App* render = cli::addRenderCommand(app, renderArgs);
  cli::BenchArgs benchArgs;
  cli::addCompareCommand(app, compareArgs);
  CLI::App* bench = cli::addBenchCommand(app, benchArgs);
  CLI::App* list = app.add_subcommand("scenes", "List the scenes, one a line (--json: every registry row)");
  bool scenesJson = false;
  list->add_flag("--json", scenesJson, "Every scene's row as JSON: description, seed, parameters, programs, assets, sweeps");
  CLI::App* methods = app.add_subcommand("methods", "List the methods of each pipeline step, and the presets");
  CLI::App* params = app.add_subcommand("params", "List a scene's parameters (--set NAME=VALUE), with range and meaning");
  std::string paramsScene;
  bool paramsJson = false;
  params->add_option("scene", paramsScene, "Scene")->required()->type_name("SCENE");
  params->add_flag("--json", paramsJson, "As JSON");
  cli::TradeoffArgs tradeoffArgs;
  CLI::App* tradeoff = cli::addTradeoffCommand(app, tradeoffArgs);
  cli::SweepArgs sweepArgs;
  CLI::App* sweep = cli::addSweepCommand(app, sweepArgs);
  cli::SweepMergeArgs sweepMergeArgs;
  CLI::App* sweepMerge = cli::addSweepMergeCommand(app, sweepMergeArgs);
  cli::ReportArgs reportArgs;
  CLI::App* report = cli::addReportCommand(app, reportArgs);
  cli::SoupArgs soupArgs;
  CLI::App* soup = cli::addSoupCommand(app, soupArgs);
  cli::TraceArgs traceArgs;
  CLI::App* trace = cli::addTraceCommand(app, traceArgs);
  app.footer("Run 'raster COMMAND --help' for a command's options (render, compare, bench, tradeoff, sweep, sweep-merge, report, soup, trace, methods, params, scenes).");

  // Parse: --help prints and exits 0; a malformed command line is bad input.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "raster: " << oneLine(e.what()) << " (see raster --help)" << std::endl;
    return 2;
  }

  // Run: bad input and scene problems exit 2, anything else is an internal failure (1).
  try {
    if (list->parsed()) return listScenes(scenesJson);
    if (methods->parsed()) return listMethods();
    if (params->parsed()) return listParams(paramsScene, paramsJson);
    if (bench->parsed()) return cli::runBench(benchArgs);
    if (tradeoff->parsed()) return cli::runTradeoff(tradeoffArgs);
    if (sweep->parsed()) return cli::runSweep(sweepArgs);
    if (sweepMerge->parsed()) return cli::runSweepMerge(sweepMergeArgs);
    if (soup->parsed()) return cli::runSoup(soupArgs);
    if (trace->parsed()) return cli::runTrace(traceArgs);
    if (report->parsed()) return cli::runReport(reportArgs);
    return render->parsed() ? runRender(renderArgs) : runCompare(compareArgs);
  } catch (const UsageError& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 2;
  } catch (const scenes::SceneError& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 2;
  } catch (const compare::OutputPathError& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 1;
  }
}
