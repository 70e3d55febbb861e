// Stage views (views.h): render with a ViewRecorder, then draw each pass and its legend.
#include "apps/views/views.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "apps/common/number_text.h"
#include "apps/common/sides.h"
#include "apps/views/view_canvas.h"
#include "apps/views/view_figures.h"
#include "compare/image_io.h"
#include "compare/output_file.h"
#include "raster/view_recorder.h"
#include "scenes/backends.h"
#include "scenes/memory_budget.h"
#include "scenes/registry.h"

namespace cli {
namespace {

using raster::ViewPass;
using raster::ViewRecorder;
using Json = nlohmann::json;

struct ViewInfo {
  View view;
  const char* name;
  const char* title;   // the PNG's first line
  ViewRecorder::Record record;
  const char* notes;   // what the numbers are, printed under the title
};

constexpr ViewInfo kViews[] = {
    {View::Overdraw, "overdraw", "overdraw: fragments shaded per pixel", ViewRecorder::Record::Fragments,
     "Fragments that were covered, passed the depth test and ran the fragment shader, per pixel, "
     "counted with GL semantics (every fragment in API order); this pipeline's visibility-first and "
     "covered-tile paths skip some of them without changing a byte. Helper lanes are not counted "
     "(see --view helpers); depth-only draws run no shader and count 0."},
    {View::DepthKills, "depth-kills", "depth-kills: fragments rejected by the depth test per pixel",
     ViewRecorder::Record::Fragments,
     "Covered fragments the depth test rejected, per pixel, every fragment in API order. Every depth "
     "test here is early (before shading: no shader writes gl_FragDepth or discards), so all rejects "
     "are early and late rejects are 0."},
    {View::Helpers, "helpers", "helpers: share of shaded lanes that were helper lanes, per 2x2 quad",
     ViewRecorder::Record::Fragments,
     "Helper lanes are shaded only so dFdx/dFdy see whole quads: pixels outside the triangle, and "
     "covered pixels that failed the depth test while a quad neighbour passed. Share = helpers / all "
     "lanes shaded in the quad over the pass (at most 75%); grey: no lane shaded there."},
    {View::TileCost, "tile-cost", "tile-cost: time per 64x64 tile, per pass", ViewRecorder::Record::TileTimes,
     "Time-stamp-counter cycles (kcyc) each tile's task took: its share of the clear and the tile "
     "stage (coverage, depth, shading, output merge), on this pipeline's own path with its fast "
     "paths. Timing: it varies from run to run and with --threads."},
    {View::Triangles, "triangles", "triangles: the set-up triangles of each pass (wireframe)",
     ViewRecorder::Record::Triangles,
     "Every triangle that reached the rasterizer, after clipping (a clipped triangle is a fan) and "
     "culling, coloured by its draw's program; corners recovered from the edge functions."},
};

const ViewInfo* findView(const std::string& name) {
  for (const ViewInfo& v : kViews)
    if (name == v.name) return &v;
  return nullptr;
}

std::string viewList() {
  std::string list;
  for (const ViewInfo& v : kViews) list += (list.empty() ? "" : ", ") + std::string(v.name);
  return list;
}

// ---- the sheet --------------------------------------------------------------------------------

struct Layout {
  int scale = 1;          // text scale
  int margin = 8;
  int columns = 1;
  int cellWidth = 0, cellHeight = 0;   // the image box of a cell
  int labelHeight = 0;
  int width = 0;
};

// How big pass p's image is in its cell: scaled to fit the box, aspect kept.
std::pair<int, int> cellImageSize(const Layout& layout, const ViewPass& pass, bool native) {
  if (native) return {pass.width, pass.height};
  const double s = std::min(double(layout.cellWidth) / pass.width, double(layout.cellHeight) / pass.height);
  return {std::max(1, int(std::lround(pass.width * s))), std::max(1, int(std::lround(pass.height * s)))};
}

// Renders the frame with a recorder of the view's kind; returns the targets read back (the
// final image, or every target for --dump).
std::vector<scenes::Target> recordFrame(const Frame& frame, const ViewInfo& info, bool everyTarget, ViewRecorder& recorder) {
  // Passes drawn while the scene sets up (none today) are not the frame's.
  std::vector<scenes::Target> targets;
  const raster::ScopedMethods methods(frame.methods);
  std::unique_ptr<scenes::Scene> scene = scenes::makeScene(frame.scene, sceneOptions(frame));
  std::unique_ptr<scenes::Backend> backend = scenes::makeRasterBackend(frame.threads, frame.scalar);
  scenes::setViewRecorder(*backend, &recorder);
  if (!frame.quiet)
    std::cerr << "rendering " << frame.scene << " with raster at " << sizeAndTime(frame) << ", recording the "
              << info.name << " view ..." << std::endl;
  backend->resizeDefaultFramebuffer(frame.width, frame.height);
  scene->setup(*backend);
  backend->finish();
  if (!recorder.passes().empty())
    throw std::runtime_error("scene " + frame.scene + " drew while setting up; the views cannot tell those passes from the frame's");
  scene->renderFrame(*backend, frame.time);
  if (everyTarget) targets = scene->readTargets(*backend);
  else targets.push_back(scene->readFinal(*backend));
  scenes::setViewRecorder(*backend, nullptr);
  return targets;
}

// The sidecar: the frame, every pass's figures, the legend, and the totals over the frame.
Json sidecarOf(const ViewInfo* info, const Frame& frame, const std::vector<ViewPass>& passes,
               const std::vector<const ViewPass*>& shown, const std::vector<PassFigures>& figures, const Json& legend) {
  Json json;
  json["view"] = info->name;
  json["about"] = info->notes;
  json["scene"] = frame.scene;
  json["size"] = {frame.width, frame.height};
  json["time"] = frame.time;
  json["threads"] = frame.threads;
  json["scalar"] = frame.scalar;
  json["methods"] = raster::methodLabel(frame.methods);
  json["semantics"] = info->record == ViewRecorder::Record::Fragments
                          ? "GL: every fragment in API order, one 2x2 quad per lane group (the instrumented walk)"
                          : "this pipeline's own path, fast paths included";
  json["passes_shown"] = Json::array();
  for (const ViewPass* p : shown) json["passes_shown"].push_back(p->index);
  json["legend"] = legend;
  json["passes"] = Json::array();
  for (const PassFigures& f : figures) json["passes"].push_back(f.json);
  Json totals = {{"passes", passes.size()}};
  uint64_t lanesCovered = 0, lanesShaded = 0, triangles = 0, tileCycles = 0, shaded = 0, depthOnly = 0, kills = 0,
           uncovered = 0, killed = 0;
  for (const ViewPass& p : passes) {
    lanesCovered += p.counters.lanesCovered;
    lanesShaded += p.counters.lanesShaded;
    triangles += p.triangles;
    for (uint64_t c : p.tileCycles) tileCycles += c;
    shaded += total(p.counts.shaded);
    depthOnly += total(p.counts.depthOnly);
    kills += total(p.counts.depthKills);
    uncovered += total(p.counts.helpersUncovered);
    killed += total(p.counts.helpersKilled);
  }
  totals["lanes_covered"] = lanesCovered;
  totals["lanes_shaded"] = lanesShaded;
  totals["triangles"] = triangles;
  switch (info->view) {
    case View::Overdraw: totals["fragments_shaded"] = shaded; totals["depth_only_fragments"] = depthOnly; break;
    case View::DepthKills: totals["depth_kills"] = kills; totals["early"] = kills; totals["late"] = 0; break;
    case View::Helpers:
      totals["helpers"] = {{"uncovered", uncovered}, {"depth_failed", killed}, {"off_framebuffer", lanesShaded - lanesCovered - uncovered - killed},
                           {"total", lanesShaded - lanesCovered}};
      break;
    case View::TileCost: totals["tile_cycles"] = tileCycles; totals["varies"] = "timing: differs from run to run"; break;
    case View::Triangles: break;
  }
  json["totals"] = totals;

  return json;
}

}  // namespace

const std::vector<std::string>& viewNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const ViewInfo& v : kViews) list.push_back(v.name);
    return list;
  }();
  return names;
}

std::string sidecarPath(const std::string& pngPath) {
  const std::string ext = ".png";
  if (pngPath.size() > ext.size() && pngPath.compare(pngPath.size() - ext.size(), ext.size(), ext) == 0)
    return pngPath.substr(0, pngPath.size() - ext.size()) + ".json";
  return pngPath + ".json";
}

int runViewRender(const RenderArgs& args, const Frame& frame) {
  const ViewInfo* info = findView(args.view);
  if (!info) throw UsageError("--view: '" + args.view + "' is not a view (views: " + viewList() + ")");
  if (args.backend != "raster") throw UsageError("--view shows this pipeline's stages: it needs --backend raster");
  std::optional<uint64_t> onlyPass;
  if (!args.pass.empty() && args.pass != "all") {
    onlyPass = parseWholeNumber(args.pass);
    if (!onlyPass) throw UsageError("--pass: '" + args.pass + "' is neither a pass number nor all");
  }
  const std::string out = args.out.empty() ? frame.scene + "-" + args.view + ".png" : args.out;
  const std::string sidecar = sidecarPath(out);
  checkOutputFile("--out", out);
  checkOutputFile("--out (its sidecar JSON)", sidecar);
  if (!args.dump.empty()) checkOutputFolder("--dump", args.dump);

  // The records are charged to --max-memory like the targets they describe.
  std::vector<scenes::memory::Reservation> recordMemory;
  ViewRecorder recorder(info->record);
  recorder.setReserve([&](uint64_t bytes, const std::string& what) { recordMemory.emplace_back(bytes, what); });
  const std::vector<scenes::Target> targets = recordFrame(frame, *info, !args.dump.empty(), recorder);
  const std::vector<ViewPass>& passes = recorder.passes();
  if (passes.empty()) throw std::runtime_error("scene " + frame.scene + " flushed no pass");
  if (onlyPass && *onlyPass >= passes.size())
    throw UsageError("--pass: " + args.pass + " is not a pass of this frame (passes 0.." + std::to_string(passes.size() - 1) +
                     ", or all)");
  std::vector<const ViewPass*> shown;
  for (const ViewPass& p : passes)
    if (!onlyPass || size_t(p.index) == *onlyPass) shown.push_back(&p);

  // Figures of every pass (the sidecar has them all), and the scale of those shown.
  std::vector<PassFigures> figures;
  for (const ViewPass& p : passes) figures.push_back(figuresOf(info->view, p));
  double scaleMax = 0;
  for (const ViewPass* p : shown) scaleMax = std::max(scaleMax, figures[size_t(p->index)].scaleMax);
  if (info->view == View::Helpers) scaleMax = 0.75;
  if ((info->view == View::Overdraw || info->view == View::DepthKills) && scaleMax < 1) scaleMax = 1;
  if (info->view == View::TileCost && !(scaleMax > 0)) scaleMax = 1;
  // Where a value sits on the ramp, 0..1. Tile times span decades (a tile of a fullscreen
  // pass against one crossed by a thousand cubes), so their scale is logarithmic.
  const bool logScale = info->view == View::TileCost;
  auto position = [&](double v) {
    return logScale ? std::log10(1.0 + std::max(v, 0.0)) / std::log10(1.0 + scaleMax) : v / scaleMax;
  };

  // Layout: a cell per shown pass, in a grid; one pass alone keeps its own size.
  const bool native = shown.size() == 1;
  Layout layout;
  layout.columns = shown.size() <= 2 ? int(shown.size()) : shown.size() <= 4 ? 2 : 3;
  layout.cellWidth = native ? shown[0]->width : std::clamp(frame.width, 220, 480);   // room for the labels
  layout.cellHeight = native ? shown[0]->height : std::max(1, int(std::lround(double(layout.cellWidth) * frame.height / frame.width)));
  layout.scale = layout.columns * layout.cellWidth >= 1200 ? 2 : 1;
  layout.margin = 8 * layout.scale;
  const int line = Canvas::kLineHeight * layout.scale;
  layout.labelHeight = 2 * line + layout.margin / 2;
  layout.width = std::max(layout.columns * layout.cellWidth + (layout.columns + 1) * layout.margin, 440 * layout.scale);
  const int textWidth = layout.width - 2 * layout.margin;

  const Rgb background{24, 24, 24}, ink{230, 230, 230}, dim{160, 160, 160}, nothing{64, 64, 64};
  const std::string heading = std::string(info->title) + " - " + frame.scene + ", " + sizeAndTime(frame) +
                              (frame.scalar ? ", --scalar" : "");
  const std::vector<std::string> headingLines = wrapText(heading, textWidth, layout.scale);
  const std::vector<std::string> notes = wrapText(info->notes, textWidth, layout.scale);
  const int rows = (int(shown.size()) + layout.columns - 1) / layout.columns;
  const int headerHeight = layout.margin + line * int(headingLines.size() + notes.size()) + layout.margin;
  const int gridHeight = rows * (layout.labelHeight + layout.cellHeight + layout.margin);

  // The legend: a ramp with numbers for the heat maps, a swatch per program for triangles.
  std::vector<std::string> programs;   // in order of first appearance among the shown passes
  std::map<std::string, uint64_t> programTriangles;
  for (const ViewPass* p : shown)
    for (const raster::ViewTriangle& t : p->triangleList) {
      const std::string& name = p->drawPrograms[t.drawIndex];
      if (!programTriangles.count(name)) programs.push_back(name);
      ++programTriangles[name];
    }
  const char* unit = info->view == View::Overdraw     ? "fragments shaded per pixel"
                     : info->view == View::DepthKills ? "depth-test rejects per pixel"
                     : info->view == View::Helpers    ? "helper lanes / lanes shaded, per quad"
                                                      : "kcyc per tile (1000 time-stamp-counter cycles), log scale";
  const std::vector<std::string> scaleLines = wrapText(
      std::string("colour scale: ") + unit + (native ? "" : "; scaled-down cells show the mean of the pixels under them"),
      textWidth, layout.scale);
  const int legendHeight = info->view == View::Triangles ? line * (int(programs.size()) + 1) + layout.margin
                                                          : line * (int(scaleLines.size()) + 3) + layout.margin;
  Canvas canvas(layout.width, headerHeight + gridHeight + legendHeight + layout.margin, background);

  int y = layout.margin;
  for (const std::string& h : headingLines) {
    canvas.text(layout.margin, y, h, ink, layout.scale);
    y += line;
  }
  for (const std::string& n : notes) {
    canvas.text(layout.margin, y, n, dim, layout.scale);
    y += line;
  }
  const int gridTop = headerHeight;

  for (size_t i = 0; i < shown.size(); ++i) {
    const ViewPass& pass = *shown[i];
    const int cx = layout.margin + int(i % size_t(layout.columns)) * (layout.cellWidth + layout.margin);
    const int cy = gridTop + int(i / size_t(layout.columns)) * (layout.labelHeight + layout.cellHeight + layout.margin);
    // Labels, cut to the cell's width.
    const int labelWidth = std::max(layout.cellWidth, native ? textWidth : 0);
    auto fit = [&](std::string text) {
      while (text.size() > 3 && Canvas::textWidth(text, layout.scale) > labelWidth) text = text.substr(0, text.size() - 4) + "..";
      return text;
    };
    canvas.text(cx, cy, fit(passTitle(pass)), ink, layout.scale);
    canvas.text(cx, cy + line, fit(figures[size_t(pass.index)].line), dim, layout.scale);
    const auto [w, h] = cellImageSize(layout, pass, native);
    const int ix = cx, iy = cy + layout.labelHeight;
    if (info->view == View::Triangles) {
      canvas.fill(ix, iy, w, h, Rgb{0, 0, 0});
      const double sx = double(w) / pass.width, sy = double(h) / pass.height;
      for (const raster::ViewTriangle& t : pass.triangleList) {
        const Rgb colour = categoryColor(size_t(std::find(programs.begin(), programs.end(), pass.drawPrograms[t.drawIndex]) - programs.begin()));
        for (int e = 0; e < 3; ++e) {
          const int f = (e + 1) % 3;
          auto px = [&](float x) { return ix + double(x) * sx; };
          auto py = [&](float yv) { return iy + (pass.window ? double(yv) : double(pass.height) - double(yv)) * sy; };
          canvas.line(px(t.x[e]), py(t.y[e]), px(t.x[f]), py(t.y[f]), colour, ix, iy, ix + w, iy + h);
        }
      }
      continue;
    }
    const Field field = resample(fieldOf(info->view, pass), w, h);
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u) {
        const size_t at = size_t(v) * size_t(w) + size_t(u);
        canvas.set(ix + u, iy + v, field.den[at] > 0 ? rampColor(position(field.num[at] / field.den[at])) : nothing);
      }
  }

  // Legend.
  y = gridTop + gridHeight;
  Json legend;
  if (info->view == View::Triangles) {
    canvas.text(layout.margin, y, "colour: the draw's program (triangles in the passes shown)", ink, layout.scale);
    for (size_t i = 0; i < programs.size(); ++i) {
      y += line;
      canvas.fill(layout.margin, y, line - 2, line - 2, categoryColor(i));
      canvas.text(layout.margin + line + layout.margin / 2, y + layout.scale,
                  (programs[i].empty() ? "?" : programs[i]) + ": " + std::to_string(programTriangles[programs[i]]) + " triangles",
                  ink, layout.scale);
      legend["programs"].push_back({{"program", programs[i]}, {"triangles", programTriangles[programs[i]]}});
    }
    legend["background"] = "black";
  } else {
    for (size_t i = 0; i < scaleLines.size(); ++i) canvas.text(layout.margin, y + int(i) * line, scaleLines[i], ink, layout.scale);
    const int barX = layout.margin, barY = y + int(scaleLines.size()) * line + layout.scale * 2, barWidth = std::min(textWidth - 100 * layout.scale, 400 * layout.scale);
    for (int u = 0; u < barWidth; ++u) canvas.fill(barX + u, barY, 1, line, rampColor(double(u) / (barWidth - 1)));
    const bool whole = info->view == View::Overdraw || info->view == View::DepthKills;
    std::vector<double> ticks = ticksFor(scaleMax, whole);
    if (logScale) {   // 0, then each power of ten that leaves room before the largest value
      ticks = {0.0};
      for (double decade = 1; decade * 3 < scaleMax; decade *= 10) ticks.push_back(decade);
      ticks.push_back(scaleMax);
    }
    for (double t : ticks) {
      const int tx = barX + int(std::lround(position(t) * (barWidth - 1)));
      canvas.fill(tx, barY + line, layout.scale, layout.scale * 3, ink);
      const std::string label = tickText(info->view, t);
      canvas.text(std::clamp(tx - Canvas::textWidth(label, layout.scale) / 2, 0, layout.width - Canvas::textWidth(label, layout.scale)),
                  barY + line + layout.scale * 4, label, ink, layout.scale);
    }
    if (info->view == View::Helpers) {
      canvas.fill(barX + barWidth + 2 * layout.margin, barY, line, line, nothing);
      canvas.text(barX + barWidth + 3 * layout.margin + line, barY + layout.scale, "no lane", ink, layout.scale);
    }
    legend = {{"quantity", unit}, {"min", 0}, {"max", scaleMax}, {"ticks", ticks}, {"ramp", "viridis"},
              {"scale", logScale ? "log10(1 + value)" : "linear"}};
    if (info->view == View::Helpers) legend["no_data_colour"] = "grey: no lane shaded in the quad";
  }

  const Json json = sidecarOf(info, frame, passes, shown, figures, legend);
  compare::writePng(out, canvas.image());
  compare::writeOutputFile(sidecar, json.dump(2) + "\n");
  std::cout << "wrote " << out << " and " << sidecar << " (" << info->name << ", " << shown.size() << " of "
            << passes.size() << " passes)" << std::endl;
  if (!args.dump.empty()) dumpTargets(args.dump, targets);
  return 0;
}

}  // namespace cli
