// `raster report`: the HTML report (report.h).
#include "apps/report/report.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps/common/child_process.h"
#include "apps/common/progress.h"
#include "apps/report/report_html.h"
#include "apps/report/report_pixels.h"
#include "apps/report/report_results.h"
#include "apps/report/report_trace_panel.h"
#include "apps/common/sides.h"
#include "apps/views/stage_views.h"
#include "compare/exr_io.h"
#include "compare/image_io.h"
#include "compare/metrics.h"
#include "compare/output_file.h"
#include "scenes/backends.h"
#include "scenes/registry.h"

namespace cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kMaxPixels = 16;   // each pixel is a child process tracing a whole frame

// ---- checks before anything renders ---------------------------------------------------------

// The folder the report replaces: nothing, an empty folder, or a previous report (it holds
// report.json). Anything else is refused, so a mistyped --out never replaces a user's folder.
void checkReportFolder(const std::string& out) {
  checkOutputFolder("--out", out);
  fs::path folder = fs::path(out).lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();
  if (folder.empty() || folder == "." || folder == "..")
    throw UsageError("--out: '" + out + "' must name a folder of its own (it is replaced as a whole)");
  struct stat info {};
  if (lstat(folder.c_str(), &info) == 0) {
    if (S_ISLNK(info.st_mode)) throw UsageError("--out: " + out + " is a symbolic link; name the folder itself");
    if (!S_ISDIR(info.st_mode)) throw UsageError("--out: " + out + " exists and is not a folder");
    std::error_code error;
    if (!fs::is_empty(folder, error) && !fs::is_regular_file(folder / "report.json", error))
      throw UsageError("--out: " + out + " is not empty and holds no earlier report (report.json); name a new folder");
  }
  // The report is made beside DIR and renamed onto it: the parent must be writable too.
  const fs::path parent = folder.has_parent_path() ? folder.parent_path() : fs::path(".");
  if (access(parent.c_str(), W_OK | X_OK) != 0)
    throw UsageError("--out: cannot write into " + parent.string() + " (the report is made beside " + out + ")");
}

// A name that becomes part of a file name and an HTML attribute: letters, digits, - _ . only.
std::string fileSafe(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
  return out.empty() ? "_" : out;
}

// ---- child processes: stage views and traces ------------------------------------------------

// A child run of this program with its stdout and stderr captured.
struct ChildRun {
  int status = -1;
  std::string output;
};

ChildRun runThisProgram(std::vector<std::string> args, const std::string& what, const fs::path& logFolder) {
  args.insert(args.begin(), "/proc/self/exe");
  ChildOptions options;
  options.outputPath = (logFolder / "child.log").string();
  ChildRun run;
  run.status = runChildProcess(args, what, options);
  std::ifstream in(options.outputPath);
  std::stringstream text;
  text << in.rdbuf();
  run.output = text.str();
  return run;
}

// The last non-empty line of a child's output (its error line), for a note.
std::string lastLine(const std::string& output) {
  std::istringstream lines(output);
  std::string line, last;
  while (std::getline(lines, line))
    if (!line.empty()) last = line;
  return last;
}

// The options that make a child render the same frame, with the same method set.
std::vector<std::string> frameOptions(const Frame& frame, const ReportArgs& given) {
  char time[32];
  std::snprintf(time, sizeof time, "%.9g", frame.time);   // 9 digits: the same float back
  std::vector<std::string> args = {"--size", std::to_string(frame.width) + "x" + std::to_string(frame.height),
                                   "--time", time};
  if (!frame.assets.empty()) args.insert(args.end(), {"--assets", frame.assets});
  for (const std::string& set : frame.sets) args.insert(args.end(), {"--set", set});
  if (!(frame.methods == raster::MethodSet{})) args.insert(args.end(), {"--preset", given.preset});
  if (!given.method.empty()) args.insert(args.end(), {"--method", given.method});
  return args;
}

// What this build offers: `raster trace`, and the stage views of its registry.
struct Tools {
  bool trace = false;
  std::vector<std::string> viewNames;
};

Tools probeTools(const fs::path& scratch) {
  Tools tools;
  // `raster trace --help` succeeds even without the command (the program's own --help
  // answers): the command is there when its help names its --pixel option.
  const ChildRun traceHelp = runThisProgram({"trace", "--help"}, "raster trace --help", scratch);
  tools.trace = traceHelp.status == 0 && traceHelp.output.find("--pixel") != std::string::npos;
  for (const StageView& view : stageViews()) tools.viewNames.push_back(view.name);
  return tools;
}

// ---- the tradeoff and sweep results ---------------------------------------------------------

struct ChartResult {
  std::string kind;     // "tradeoff" or "sweep"
  fs::path folder;      // where tradeoff.json / sweep.json lies
  std::string label;    // the folder, relative to its --include folder
};

std::vector<ChartResult> findChartResults(const std::vector<std::string>& includes) {
  std::vector<ChartResult> found;
  for (const std::string& include : includes) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(include, fs::directory_options::skip_permission_denied)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file() && (name == "tradeoff.json" || name == "sweep.json")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());   // the same order on every machine
    for (const fs::path& file : files) {
      const fs::path relative = fs::relative(file.parent_path(), include);
      const std::string label = (fs::path(include).filename().empty() ? fs::path(include).parent_path().filename()
                                                                     : fs::path(include).filename()) /
                                relative;
      found.push_back({file.stem().string(), file.parent_path(), fs::path(label).lexically_normal().string()});
    }
  }
  return found;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// Copies a result's JSON and chart (PNG, else SVG) into the report; returns its section HTML.
std::string chartSection(const ChartResult& result, const fs::path& reportFolder, int index, json& record) {
  const std::string base = "charts/" + std::to_string(index) + "-" + fileSafe(result.label);
  fs::create_directories(reportFolder / base);
  const std::string jsonFile = result.kind + ".json";
  const std::string jsonText = readFile(result.folder / jsonFile);
  json data;
  try {
    data = json::parse(jsonText);
  } catch (const json::exception& e) {
    throw std::runtime_error("cannot read " + (result.folder / jsonFile).string() + ": " + e.what());
  }
  compare::writeOutputFile((reportFolder / base / jsonFile).string(), jsonText);
  std::string html = "<h3>" + report::escape(result.kind + ": " + result.label) + "</h3>\n";
  std::string image;
  for (const char* extension : {".png", ".svg"}) {
    const fs::path chart = result.folder / (result.kind + extension);
    if (!fs::is_regular_file(chart)) continue;
    image = base + "/" + result.kind + extension;
    compare::writeOutputFile((reportFolder / image).string(), readFile(chart));
    break;
  }
  if (!image.empty())
    html += "<figure class=\"chart\"><a href=\"" + report::escape(image) + "\"><img src=\"" + report::escape(image) +
            "\" alt=\"" + report::escape(result.kind + " chart") + "\"></a><figcaption>" +
            report::escape("from " + result.label + "; the data: ") + "<a href=\"" + report::escape(base + "/" + jsonFile) +
            "\">" + report::escape(jsonFile) + "</a></figcaption></figure>\n";
  else
    html += report::note("No chart (" + result.kind + ".png or .svg) beside " + jsonFile + " in " + result.label + ".");
  const std::string id = result.kind + "-" + std::to_string(index);
  try {
    html += result.kind == "tradeoff" ? report::tradeoffTables(data, id) : report::sweepTables(data, id);
  } catch (const json::exception& e) {
    throw std::runtime_error("cannot read " + (result.folder / jsonFile).string() + ": " + e.what());
  }
  record = {{"kind", result.kind}, {"source", result.label}, {"json", base + "/" + jsonFile}, {"image", image}, {"id", id}};
  return html;
}

// ---- one scene ------------------------------------------------------------------------------


// The figure of one target image: the preview PNG and, for float / depth targets, its EXR.
std::string targetFigure(const std::string& folder, const std::string& base, const std::string& side,
                         const scenes::ImageData& image, const fs::path& reportFolder, const std::string& caption) {
  const std::string png = folder + "/" + base + "_" + side + ".png";
  compare::writePng((reportFolder / png).string(), image);
  if (image.format == scenes::TexelFormat::RGBA8) return report::figure(png, caption);
  const std::string exr = folder + "/" + base + "_" + side + ".exr";
  compare::writeExr((reportFolder / exr).string(), image);
  const bool depth = image.format == scenes::TexelFormat::Depth16 || image.format == scenes::TexelFormat::Depth24;
  const std::string how = depth ? " (preview: depth codes as grey, stretched between the nearest and farthest code present)"
                                : " (preview: clamped to [0, 1], gamma 1/2.2, alpha dropped)";
  return report::figure(png, caption + how + "; the data:", exr, base + "_" + side + ".exr");
}

// What one scene's sections need: its frame, the report's options, the tools this build has,
// where its files go (folder, relative to the report being made in `work`), and the progress.
struct SceneWork {
  const Frame& frame;
  const ReportArgs& args;
  const Tools& tools;
  std::string folder;
  fs::path work, scratch;
  std::function<void(const std::string&)> step;
};

// The stage views, as `raster render --view` lists them, each with its sidecar JSON.
std::string viewsHtml(const SceneWork& scene, json& record) {
  const Frame& frame = scene.frame;
  const ReportArgs& args = scene.args;
  const Tools& tools = scene.tools;
  const std::string& folder = scene.folder;
  const fs::path& work = scene.work;
  const fs::path& scratch = scene.scratch;
  const auto& step = scene.step;
  std::string html;
  html += "<h3>Stage views</h3>\n";
  for (const std::string& view : tools.viewNames) {
    step(frame.scene + ": view " + view);
    const std::string png = folder + "/view-" + fileSafe(view) + ".png";
    std::vector<std::string> childArgs = {"render", frame.scene, "--view", view, "--out", (work / png).string(),
                                          "--quiet", "--threads", std::to_string(frame.threads)};
    const std::vector<std::string> options = frameOptions(frame, args);
    childArgs.insert(childArgs.end(), options.begin(), options.end());
    const ChildRun run = runThisProgram(childArgs, "raster render --view " + view, scratch);
    const fs::path sidecar = (work / png).replace_extension(".json");
    if (run.status != 0 || !fs::is_regular_file(work / png)) {
      html += report::note("View " + view + ": `raster render --view " + view + "` failed (exit status " +
                           std::to_string(run.status) + "): " + lastLine(run.output));
      continue;
    }
    std::string viewHtml = "<div class=\"row\">" + report::figure(png, view) + "<div>";
    json sidecarRecord;
    if (fs::is_regular_file(sidecar)) {
      try {
        sidecarRecord = json::parse(readFile(sidecar));
        viewHtml += report::sidecarTable(sidecarRecord, "view-" + folder + "-" + fileSafe(view));
      } catch (const json::exception& e) {
        viewHtml += report::note("The sidecar " + sidecar.filename().string() + " is not JSON: " + e.what());
      }
      viewHtml += "<p><a href=\"" + report::escape(folder + "/" + sidecar.filename().string()) + "\">" +
                  report::escape(sidecar.filename().string()) + "</a></p>";
    }
    html += "<h4>" + report::escape(view) + "</h4>" + viewHtml + "</div></div>\n";
    record.push_back({{"view", view}, {"image", png}, {"sidecar", sidecarRecord}});
  }

  return html;
}

// The pixel histories of the chosen pixels, by `raster trace` in a child process each.
std::string tracesHtml(const SceneWork& scene, const std::vector<report::ChosenPixel>& pixels,
                       const std::string& reference, json& record) {
  const Frame& frame = scene.frame;
  const ReportArgs& args = scene.args;
  const Tools& tools = scene.tools;
  const std::string& folder = scene.folder;
  const fs::path& work = scene.work;
  const fs::path& scratch = scene.scratch;
  const auto& step = scene.step;
  std::string html;
  html += "<h3>Pixel histories</h3>\n";
  if (!tools.trace)
    html += report::note("Pixel histories: this build has no `raster trace` command, so the report shows none.");
  else if (!pixels.empty())
    html += "<p>The worst differing pixels of the final image first (largest channel difference against " +
            report::escape(reference) + "), then interior pixels. Open a pixel, then a pass.</p>\n";
  for (const report::ChosenPixel& pixel : tools.trace ? pixels : std::vector<report::ChosenPixel>{}) {
    const std::string at = std::to_string(pixel.x) + "," + std::to_string(pixel.y);
    step(frame.scene + ": trace " + at);
    const std::string file = folder + "/trace-" + std::to_string(pixel.x) + "-" + std::to_string(pixel.y) + ".json";
    std::vector<std::string> childArgs = {"trace", frame.scene, "--pixel", at, "--json", (work / file).string()};
    const std::vector<std::string> options = frameOptions(frame, args);
    childArgs.insert(childArgs.end(), options.begin(), options.end());
    const ChildRun run = runThisProgram(childArgs, "raster trace " + frame.scene + " --pixel " + at, scratch);
    const std::string label = "pixel (" + at + "), difference " + std::to_string(pixel.difference);
    if (run.status != 0 || !fs::is_regular_file(work / file)) {
      html += report::note(label + ": `raster trace` failed (exit status " + std::to_string(run.status) + "): " +
                           lastLine(run.output));
      continue;
    }
    json trace;
    try {
      trace = json::parse(readFile(work / file));
    } catch (const json::exception& e) {
      throw std::runtime_error("raster trace wrote " + file + ", which is not JSON: " + e.what());
    }
    html += "<p>" + report::escape(label) + " (<a href=\"" + report::escape(file) + "\">JSON</a>)</p>\n" +
            report::tracePanel(trace, "trace-" + folder + "-" + std::to_string(pixel.x) + "-" + std::to_string(pixel.y));
    record.push_back({{"pixel", {pixel.x, pixel.y}}, {"difference", pixel.difference}, {"json", file}});
  }
  return html;
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
  // Everything is checked before the first frame.
  std::vector<std::string> sceneList;
  for (const std::string& scene : args.scenes) {
    const std::vector<std::string> names = scene == "all" ? scenes::sceneNames() : std::vector<std::string>{scene};
    for (const std::string& name : names)
      if (std::find(sceneList.begin(), sceneList.end(), name) == sceneList.end()) sceneList.push_back(name);
  }
  std::vector<Frame> frames;
  for (const std::string& scene : sceneList) {
    FrameArgs frameArgs = args;
    frameArgs.scene = scene;
    frames.push_back(validateFrame(frameArgs));
    frames.back().quiet = true;   // the progress bar speaks for the renders
  }
  if (args.pixels < 0 || args.pixels > kMaxPixels)
    throw UsageError("--pixels: " + std::to_string(args.pixels) + " is out of range (0.." + std::to_string(kMaxPixels) + ")");
  std::vector<std::string> includes;
  for (const std::string& include : args.include) {
    if (!fs::is_directory(include)) throw UsageError("--include: no such folder: " + include);
    includes.push_back(include);
  }
  if (!args.noDefaultInclude) {
    const char* sourceDir = std::getenv("RASTER_SOURCE_DIR");
    const fs::path docs = fs::path(sourceDir ? sourceDir : RASTER_SOURCE_DIR) / "docs";
    if (fs::is_directory(docs)) includes.push_back(docs.string());
  }
  checkReportFolder(args.out);
  scenes::checkGalliumEnvironment();

  // The report is made here, beside DIR, and renamed onto it at the end.
  fs::path target = fs::path(args.out).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string pattern = (parent / ("." + target.filename().string() + ".report-XXXXXX")).string();
  if (!mkdtemp(pattern.data()))
    throw std::runtime_error("cannot create a folder beside " + args.out + ": " + std::strerror(errno));
  struct Removed {
    fs::path path;
    bool keep = false;
    ~Removed() {
      std::error_code ignored;
      if (!keep) fs::remove_all(path, ignored);
    }
  } work{pattern};
  const fs::path scratch = work.path / ".scratch";   // child logs and probes; removed before the rename
  fs::create_directory(scratch);

  const Tools tools = probeTools(scratch);
  const std::vector<ChartResult> charts = findChartResults(includes);
  const int viewCount = int(tools.viewNames.size());
  const int traceCount = tools.trace ? args.pixels : 0;
  Progress progress("report", int(frames.size()) * (3 + viewCount + traceCount) + int(charts.size()) + 1, args.quiet);
  int done = 0;
  const auto step = [&](const std::string& next) { progress.update(done++, next); };

  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  json record = {{"made_by", "raster report"}, {"scenes", json::array()}, {"charts", json::array()}};
  std::vector<report::Section> sections;
  for (const Frame& frame : frames) {
    const std::string folder = fileSafe(frame.scene);
    fs::create_directory(work.path / folder);
    step(frame.scene + ": this pipeline");
    const Side ours = renderSide(frame, "raster");
    step(frame.scene + ": llvmpipe");
    const Side gl = renderSide(frame, "llvmpipe");
    if (ours.targets.size() != gl.targets.size())
      throw std::runtime_error("the sides of " + frame.scene + " expose different targets");

    // Per target: the three images side by side, and the metrics.
    step(frame.scene + ": images and metrics");
    json sceneRecord = {{"scene", frame.scene}, {"size", {frame.width, frame.height}}, {"time", frame.time},
                        {"sets", frame.sets}, {"targets", json::array()}, {"views", json::array()},
                        {"traces", json::array()}};
    std::string html = "<p>" + report::escape(frame.scene + " at " + sizeAndTime(frame) + "; this pipeline (methods: " +
                                              raster::methodLabel(frame.methods) + ") against " + gl.backend + ".") +
                       " Heat maps: black where equal, blue 1, yellow 4, red 16 or more units of the target's kind "
                       "(8-bit steps, depth LSBs, half ULPs).</p>\n";
    for (size_t i = 0; i < ours.targets.size(); ++i) {
      const scenes::Target& mine = ours.targets[i];
      const scenes::Target& theirs = gl.targets[i];
      if (mine.name != theirs.name) throw std::runtime_error("the sides of " + frame.scene + " expose different targets");
      const compare::TargetStats stats = compare::compareImages(mine.name, mine.image, theirs.image);
      const json statsRecord = report::statsJson(stats);
      const std::string base = fileSafe(mine.name);
      std::string row = "<div class=\"row\">";
      row += targetFigure(folder, base, "ours", mine.image, work.path, "this pipeline");
      row += targetFigure(folder, base, "gl", theirs.image, work.path, gl.backend);
      const std::string diff = folder + "/" + base + "_diff.png";
      compare::writeHeatmapPng((work.path / diff).string(), mine.image, theirs.image);
      row += report::figure(diff, "difference heat map");
      row += report::metricsTable(statsRecord, "metrics-" + folder + "-" + base);
      html += "<h3>" + report::escape(mine.name + " (" + stats.kind + ")") + "</h3>\n" + row + "</div>\n";
      sceneRecord["targets"].push_back(statsRecord);
    }

    const SceneWork scene{frame, args, tools, folder, work.path, scratch, step};
    html += viewsHtml(scene, sceneRecord["views"]);
    const std::vector<report::ChosenPixel> pixels =
        report::choosePixels(ours.targets.back().image, gl.targets.back().image, args.pixels);
    html += tracesHtml(scene, pixels, gl.backend, sceneRecord["traces"]);
    record["scenes"].push_back(std::move(sceneRecord));
    sections.push_back({"scene-" + folder, "Scene " + frame.scene, html});
  }

  // The tradeoff and sweep results found under the include folders.
  std::string chartsHtml;
  if (charts.empty()) chartsHtml = report::note("No tradeoff.json or sweep.json under the --include folders.");
  for (size_t i = 0; i < charts.size(); ++i) {
    step("charts: " + charts[i].label);
    json chartRecord;
    chartsHtml += chartSection(charts[i], work.path, int(i + 1), chartRecord);
    record["charts"].push_back(std::move(chartRecord));
  }
  sections.push_back({"charts", "Speed against accuracy, and stability sweeps", chartsHtml});

  // The data, then the page last, then the whole folder into place.
  step("index.html");
  compare::writeOutputFile((work.path / "report.json").string(), record.dump(2) + "\n");
  std::string intro = "<p>Made by <code>raster report";
  for (const std::string& scene : args.scenes) intro += " " + report::escape(scene);
  intro += " --size " + report::escape(args.size) + " --time " + report::escape(args.time);
  if (args.preset != "gl") intro += " --preset " + report::escape(args.preset);
  if (!args.method.empty()) intro += " --method " + report::escape(args.method);
  for (const std::string& set : args.sets) intro += " --set " + report::escape(set);
  intro += 
           "</code>. Images are files beside this page; the numbers are in <a href=\"report.json\">report.json</a>.</p>\n";
  compare::writeOutputFile((work.path / "index.html").string(), report::page("raster report", intro, sections));
  progress.update(done, "done");
  fs::remove_all(scratch);
  chmod(work.path.c_str(), 0755);   // mkdtemp made it private; a report is for reading

  // Into place: a previous report (checked above) is moved aside first, and removed after.
  std::error_code error;
  if (fs::exists(target, error) && !fs::is_empty(target, error)) {
    std::string aside = (parent / ("." + target.filename().string() + ".old-XXXXXX")).string();
    if (!mkdtemp(aside.data()) || rename(target.c_str(), aside.c_str()) != 0)
      throw std::runtime_error("cannot replace " + args.out + ": " + std::strerror(errno));
    if (rename(work.path.c_str(), target.c_str()) != 0) {
      const int why = errno;
      rename(aside.c_str(), target.c_str());
      throw std::runtime_error("cannot replace " + args.out + ": " + std::strerror(why));
    }
    fs::remove_all(aside, error);
  } else if (rename(work.path.c_str(), target.c_str()) != 0) {
    throw std::runtime_error("cannot write " + args.out + ": " + std::strerror(errno));
  }
  work.keep = true;
  std::cout << "wrote " << (target / "index.html").string() << std::endl;
  return 0;
}

}  // namespace cli
