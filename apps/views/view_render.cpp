// `raster render --view` (view_render.h): check the request, render with the view's
// recorder, draw the sheet, write it and its sidecar.
#include "apps/views/view_render.h"

#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "apps/common/sides.h"
#include "apps/views/stage_views.h"
#include "apps/views/view_sheet.h"
#include "io/image_io.h"
#include "io/output_file.h"
#include "raster/view_recorder.h"
#include "backends/backends.h"
#include "io/memory_budget.h"
#include "scenes/registry.h"

namespace cli {
namespace {

using raster::ViewPass;
using raster::ViewRecorder;
using Json = nlohmann::json;

// A --view request, checked: every mistake in it is found before the frame renders.
struct ViewRequest {
  const StageView* view = nullptr;
  std::optional<uint64_t> onlyPass;   // --pass N; none: every pass
  std::string out, sidecar;
};

ViewRequest checkRequest(const RenderArgs& args, const Frame& frame) {
  ViewRequest request;
  request.view = findStageView(args.view);
  if (!request.view) throw UsageError("--view: '" + args.view + "' is not a view (views: " + stageViewList() + ")");
  if (args.backend != "raster") throw UsageError("--view shows this pipeline's stages: it needs --backend raster");
  if (!args.pass.empty() && args.pass != "all") {
    request.onlyPass = parseWholeNumber(args.pass);
    if (!request.onlyPass) throw UsageError("--pass: '" + args.pass + "' is neither a pass number nor all");
  }
  request.out = args.out.empty() ? frame.scene + "-" + args.view + ".png" : args.out;
  request.sidecar = sidecarPath(request.out);
  checkOutputPng("--out", request.out);
  checkOutputFile("--out (its sidecar JSON)", request.sidecar);
  if (!args.dump.empty()) checkOutputFolder("--dump", args.dump);
  return request;
}

// Renders the frame with a recorder of the view's kind; returns the targets read back (the
// final image, or every target for --dump).
std::vector<scenes::Target> recordFrame(const Frame& frame, const StageView& view, bool everyTarget, ViewRecorder& recorder) {
  std::vector<scenes::Target> targets;
  const raster::ScopedMethods methods(frame.methods);
  std::unique_ptr<scenes::Scene> scene = scenes::makeScene(frame.scene, sceneOptions(frame));
  std::unique_ptr<scenes::Backend> backend = scenes::makeRasterBackend(frame.threads, frame.scalar);
  scenes::setViewRecorder(*backend, &recorder);
  if (!frame.quiet)
    std::cerr << "rendering " << frame.scene << " with raster at " << sizeAndTime(frame) << ", recording the "
              << view.name << " view ..." << std::endl;
  backend->resizeDefaultFramebuffer(frame.width, frame.height);
  scene->setup(*backend);
  backend->finish();
  // Passes drawn while the scene sets up (none today) are not the frame's.
  if (!recorder.passes().empty())
    throw std::runtime_error("scene " + frame.scene + " drew while setting up; the views cannot tell those passes from the frame's");
  scene->renderFrame(*backend, frame.time);
  if (everyTarget) targets = scene->readTargets(*backend);
  else targets.push_back(scene->readFinal(*backend));
  scenes::setViewRecorder(*backend, nullptr);
  return targets;
}

// The passes on the sheet: every pass, or the one --pass names (UsageError when the frame
// has no such pass).
std::vector<const ViewPass*> passesShown(const std::vector<ViewPass>& passes, const ViewRequest& request,
                                         const RenderArgs& args, const Frame& frame) {
  if (passes.empty()) throw std::runtime_error("scene " + frame.scene + " flushed no pass");
  if (request.onlyPass && *request.onlyPass >= passes.size())
    throw UsageError("--pass: " + args.pass + " is not a pass of this frame (passes 0.." + std::to_string(passes.size() - 1) +
                     ", or all)");
  std::vector<const ViewPass*> shown;
  for (const ViewPass& p : passes)
    if (!request.onlyPass || size_t(p.index) == *request.onlyPass) shown.push_back(&p);
  return shown;
}

// What the numbers follow: the instrumented walk's GL semantics, or this pipeline's path.
const char* semanticsOf(ViewRecorder::Record record) {
  return record == ViewRecorder::Record::Fragments
             ? "GL: every fragment in API order, one 2x2 quad per lane group (the instrumented walk)"
             : "this pipeline's own path, fast paths included";
}

// The sidecar: the frame, every pass's figures, the legend, and the totals over the frame.
Json sidecarOf(const StageView& view, const Frame& frame, const std::vector<ViewPass>& passes,
               const std::vector<const ViewPass*>& shown, const std::vector<PassFigures>& figures, const Json& legend) {
  Json json;
  json["view"] = view.name;
  json["about"] = view.about;
  json["scene"] = frame.scene;
  json["size"] = {frame.width, frame.height};
  json["time"] = frame.time;
  json["threads"] = frame.threads;
  json["scalar"] = frame.scalar;
  json["methods"] = raster::methodLabel(frame.methods);
  json["semantics"] = semanticsOf(view.record);
  json["passes_shown"] = Json::array();
  for (const ViewPass* p : shown) json["passes_shown"].push_back(p->index);
  json["legend"] = legend;
  json["passes"] = Json::array();
  for (const PassFigures& f : figures) json["passes"].push_back(f.json);
  uint64_t lanesCovered = 0, lanesShaded = 0, triangles = 0;
  for (const ViewPass& p : passes) {
    lanesCovered += p.counters.lanesCovered;
    lanesShaded += p.counters.lanesShaded;
    triangles += p.triangles;
  }
  Json totals = {{"passes", passes.size()}, {"lanes_covered", lanesCovered}, {"lanes_shaded", lanesShaded}, {"triangles", triangles}};
  view.totals(passes, totals);
  json["totals"] = totals;
  return json;
}

}  // namespace

std::string sidecarPath(const std::string& pngPath) {
  const std::string ext = ".png";
  if (pngPath.size() > ext.size() && pngPath.compare(pngPath.size() - ext.size(), ext.size(), ext) == 0)
    return pngPath.substr(0, pngPath.size() - ext.size()) + ".json";
  return pngPath + ".json";
}

int runViewRender(const RenderArgs& args, const Frame& frame) {
  const ViewRequest request = checkRequest(args, frame);
  const StageView& view = *request.view;

  // The records are charged to --max-memory like the targets they describe.
  std::vector<scenes::memory::Reservation> recordMemory;
  ViewRecorder recorder(view.record);
  recorder.setReserve([&](uint64_t bytes, const std::string& what) { recordMemory.emplace_back(bytes, what); });
  const std::vector<scenes::Target> targets = recordFrame(frame, view, !args.dump.empty(), recorder);
  const std::vector<ViewPass>& passes = recorder.passes();
  const std::vector<const ViewPass*> shown = passesShown(passes, request, args, frame);

  std::vector<PassFigures> figures;   // of every pass: the sidecar has them all
  for (const ViewPass& p : passes) figures.push_back(view.figures(p));
  const Sheet sheet = drawSheet(view, frame, shown, figures);
  const Json json = sidecarOf(view, frame, passes, shown, figures, sheet.legend);

  compare::writePng(request.out, sheet.canvas.image());
  compare::writeOutputFile(request.sidecar, json.dump(2) + "\n");
  std::cout << "wrote " << request.out << " and " << request.sidecar << " (" << view.name << ", " << shown.size() << " of "
            << passes.size() << " passes)" << std::endl;
  if (!args.dump.empty()) dumpTargets(args.dump, targets);
  return 0;
}

}  // namespace cli
