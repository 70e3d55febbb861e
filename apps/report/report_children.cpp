// The report's stage views and pixel histories, from child processes (report_children.h).
#include "apps/report/report_children.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "apps/common/child_process.h"
#include "apps/report/report_folder.h"
#include "apps/report/report_html.h"
#include "apps/report/report_results.h"
#include "apps/report/report_trace_panel.h"
#include "apps/views/stage_views.h"

namespace report {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A child run of this program with its stdout and stderr captured.
struct ChildRun {
  int status = -1;
  std::string output;
};

ChildRun runThisProgram(std::vector<std::string> args, const std::string& what, const fs::path& logFolder) {
  args.insert(args.begin(), "/proc/self/exe");
  cli::ChildOptions options;
  options.outputPath = (logFolder / "child.log").string();
  ChildRun run;
  run.status = cli::runChildProcess(args, what, options);
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

// `command` with the options that make a child render the same frame, with the same method set.
std::vector<std::string> withFrameOptions(std::vector<std::string> command, const SceneWork& scene) {
  const cli::Frame& frame = scene.frame;
  const std::vector<std::string> frameOptions = cli::childFrameOptions(frame);
  command.insert(command.end(), frameOptions.begin(), frameOptions.end());
  const std::vector<std::string> methods = cli::childMethodOptions(scene.args);
  command.insert(command.end(), methods.begin(), methods.end());
  return command;
}

// One view: its picture, and its sidecar's figures as a table with a link to the JSON.
std::string viewHtml(const SceneWork& scene, const std::string& view, json& record) {
  const std::string png = scene.folder + "/view-" + fileSafe(view) + ".png";
  const ChildRun run = runThisProgram(withFrameOptions({"render", scene.frame.scene, "--view", view, "--out",
                                                        (scene.work / png).string(), "--quiet", "--threads",
                                                        std::to_string(scene.frame.threads)},
                                                       scene),
                                      "raster render --view " + view, scene.scratch);
  const fs::path sidecar = (scene.work / png).replace_extension(".json");
  if (run.status != 0 || !fs::is_regular_file(scene.work / png))
    return note("View " + view + ": `raster render --view " + view + "` failed (exit status " + std::to_string(run.status) +
                "): " + lastLine(run.output));
  std::string html = "<div class=\"row\">" + figure(png, view) + "<div>";
  json sidecarRecord;
  if (fs::is_regular_file(sidecar)) {
    try {
      sidecarRecord = json::parse(readFile(sidecar));
      html += sidecarTable(sidecarRecord, "view-" + scene.folder + "-" + fileSafe(view));
    } catch (const json::exception& e) {
      html += note("The sidecar " + sidecar.filename().string() + " is not JSON: " + e.what());
    }
    html += "<p><a href=\"" + escape(scene.folder + "/" + sidecar.filename().string()) + "\">" +
            escape(sidecar.filename().string()) + "</a></p>";
  }
  record.push_back({{"view", view}, {"image", png}, {"sidecar", sidecarRecord}});
  return "<h4>" + escape(view) + "</h4>" + html + "</div></div>\n";
}

// One pixel's history, as a collapsible panel.
std::string traceHtml(const SceneWork& scene, const cli::ChosenPixel& pixel, json& record) {
  const std::string at = std::to_string(pixel.x) + "," + std::to_string(pixel.y);
  const std::string file = scene.folder + "/trace-" + std::to_string(pixel.x) + "-" + std::to_string(pixel.y) + ".json";
  const ChildRun run = runThisProgram(
      withFrameOptions({"trace", scene.frame.scene, "--pixel", at, "--json", (scene.work / file).string()}, scene),
      "raster trace " + scene.frame.scene + " --pixel " + at, scene.scratch);
  const std::string label = "pixel (" + at + "), difference " + std::to_string(pixel.difference);
  if (run.status != 0 || !fs::is_regular_file(scene.work / file))
    return note(label + ": `raster trace` failed (exit status " + std::to_string(run.status) + "): " + lastLine(run.output));
  json trace;
  try {
    trace = json::parse(readFile(scene.work / file));
  } catch (const json::exception& e) {
    throw std::runtime_error("raster trace wrote " + file + ", which is not JSON: " + e.what());
  }
  record.push_back({{"pixel", {pixel.x, pixel.y}}, {"difference", pixel.difference}, {"json", file}});
  return "<p>" + escape(label) + " (<a href=\"" + escape(file) + "\">JSON</a>)</p>\n" +
         tracePanel(trace, "trace-" + scene.folder + "-" + std::to_string(pixel.x) + "-" + std::to_string(pixel.y));
}

}  // namespace

std::string viewsHtml(const SceneWork& scene, json& record) {
  std::string html = "<h3>Stage views</h3>\n";
  for (const cli::StageView& view : cli::stageViews()) {
    scene.step(scene.frame.scene + ": view " + view.name);
    html += viewHtml(scene, view.name, record);
  }
  return html;
}

std::string tracesHtml(const SceneWork& scene, const std::vector<cli::ChosenPixel>& pixels, const std::string& reference,
                       json& record) {
  std::string html = "<h3>Pixel histories</h3>\n";
  if (!pixels.empty())
    html += "<p>The worst differing pixels of the final image first (largest channel difference against " +
            escape(reference) + "), then interior pixels. Open a pixel, then a pass.</p>\n";
  for (const cli::ChosenPixel& pixel : pixels) {
    scene.step(scene.frame.scene + ": trace " + std::to_string(pixel.x) + "," + std::to_string(pixel.y));
    html += traceHtml(scene, pixel, record);
  }
  return html;
}

}  // namespace report
