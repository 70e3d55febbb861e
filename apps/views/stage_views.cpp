// The stage views, one record each (stage_views.h): each view's functions, then the table.
#include "apps/views/stage_views.h"

#include <map>

#include "apps/common/number_text.h"
#include "raster/limits.h"

namespace cli {
namespace {

using raster::ViewPass;
using Record = raster::ViewRecorder::Record;
using Json = nlohmann::json;

// The count views' scale reaches at least 1, so a pass of zeros and ones is not all yellow.
double atLeastOne(double largest) { return largest < 1 ? 1 : largest; }

// ---- overdraw -------------------------------------------------------------------------------

Field overdrawField(const ViewPass& pass) { return countField(pass, pass.counts.shaded); }

PassFigures overdrawFigures(const ViewPass& pass) {
  PassFigures f = passFigures(pass);
  const raster::FragmentCounts& c = pass.counts;
  const Stats s = statsOf(c.shaded);
  f.json["fragments_shaded"] = statsJson(s);
  f.json["depth_only_fragments"] = total(c.depthOnly);
  f.scaleMax = s.max;
  f.line = pass.colorTargets == 0   // a depth-only pass runs no shader
               ? "depth only, no shader: " + std::to_string(total(c.depthOnly)) + " fragments passed"
               : "shaded " + std::to_string(uint64_t(s.total)) + ", max " + sixDigits(s.max) + ", mean " + fixedDigits(s.mean, 2);
  return f;
}

void overdrawTotals(const std::vector<ViewPass>& passes, Json& totals) {
  uint64_t shaded = 0, depthOnly = 0;
  for (const ViewPass& p : passes) {
    shaded += total(p.counts.shaded);
    depthOnly += total(p.counts.depthOnly);
  }
  totals["fragments_shaded"] = shaded;
  totals["depth_only_fragments"] = depthOnly;
}

// ---- invocations ----------------------------------------------------------------------------

Field invocationsField(const ViewPass& pass) { return countField(pass, pass.counts.invocations); }

// The pass's invocations that wrote, summed in double (each pixel holds a share of one).
PassFigures invocationsFigures(const ViewPass& pass) {
  PassFigures f = passFigures(pass);
  const Stats s = statsOf(pass.counts.invocations);
  const Stats fragments = statsOf(pass.counts.shaded);
  f.json["invocations"] = statsJson(s);
  f.json["fragments_shaded"] = uint64_t(fragments.total);
  f.json["invocations_per_fragment"] = fragments.total > 0 ? s.total / fragments.total : 0.0;
  f.scaleMax = s.max;
  f.line = pass.colorTargets == 0 ? "depth only, no shader"
                                  : "invocations " + std::to_string(uint64_t(s.total + 0.5)) + ", max " + sixDigits(s.max) +
                                        ", mean " + fixedDigits(s.mean, 2);
  return f;
}

void invocationsTotals(const std::vector<ViewPass>& passes, Json& totals) {
  double invocations = 0;
  uint64_t fragments = 0;
  for (const ViewPass& p : passes) {
    invocations += statsOf(p.counts.invocations).total;
    fragments += total(p.counts.shaded);
  }
  totals["invocations"] = uint64_t(invocations + 0.5);
  totals["fragments_shaded"] = fragments;
}

// ---- depth-kills ----------------------------------------------------------------------------

Field depthKillsField(const ViewPass& pass) { return countField(pass, pass.counts.depthKills); }

// Every depth test here is early (no shader writes gl_FragDepth or discards): late is 0.
PassFigures depthKillsFigures(const ViewPass& pass) {
  PassFigures f = passFigures(pass);
  const Stats s = statsOf(pass.counts.depthKills);
  f.json["depth_kills"] = statsJson(s);
  f.json["early"] = uint64_t(s.total);
  f.json["late"] = 0;
  f.scaleMax = s.max;
  f.line = "rejected " + std::to_string(uint64_t(s.total)) + " (all early), max " + sixDigits(s.max) + ", mean " +
           fixedDigits(s.mean, 2);
  return f;
}

void depthKillsTotals(const std::vector<ViewPass>& passes, Json& totals) {
  uint64_t kills = 0;
  for (const ViewPass& p : passes) kills += total(p.counts.depthKills);
  totals["depth_kills"] = kills;
  totals["early"] = kills;
  totals["late"] = 0;
}

// ---- helpers --------------------------------------------------------------------------------

// Each pixel shows its 2x2 quad's sums (quads start at even texels): helpers over lanes shaded.
Field helpersField(const ViewPass& pass) {
  Field f{pass.width, pass.height, {}, {}};
  const size_t n = size_t(pass.width) * size_t(pass.height);
  f.num.assign(n, 0.0);
  f.den.assign(n, 1.0);
  const raster::FragmentCounts& c = pass.counts;
  for (int y = 0; y < pass.height; ++y)
    for (int x = 0; x < pass.width; ++x) {
      const int qx = x & ~1, row = memoryRow(pass, y) & ~1;
      double helpers = 0, lanes = 0;
      for (int dy = 0; dy < 2 && row + dy < pass.height; ++dy)
        for (int dx = 0; dx < 2 && qx + dx < pass.width; ++dx) {
          const size_t t = size_t(row + dy) * size_t(pass.width) + size_t(qx + dx);
          helpers += c.helpersUncovered[t] + c.helpersKilled[t];
          lanes += c.helpersUncovered[t] + c.helpersKilled[t] + c.shaded[t];
        }
      const size_t at = size_t(y) * size_t(pass.width) + size_t(x);
      f.num[at] = helpers;
      f.den[at] = lanes;
    }
  return f;
}

// Helper lanes that fall off the framebuffer's edge have no pixel: they are the pass's
// helper lanes less those counted per pixel.
PassFigures helpersFigures(const ViewPass& pass) {
  PassFigures f = passFigures(pass);
  const raster::FragmentCounts& c = pass.counts;
  const uint64_t uncovered = total(c.helpersUncovered), killed = total(c.helpersKilled), shaded = total(c.shaded);
  const uint64_t helperLanes = pass.counters.lanesShaded - pass.counters.lanesCovered;
  const double share = pass.counters.lanesShaded ? double(helperLanes) / double(pass.counters.lanesShaded) : 0.0;
  f.json["helpers"] = {{"uncovered", uncovered},
                       {"depth_failed", killed},
                       {"off_framebuffer", helperLanes - uncovered - killed},
                       {"total", helperLanes},
                       {"fragments_shaded", shaded},
                       {"lanes_shaded", pass.counters.lanesShaded},
                       {"share", share}};
  f.scaleMax = 0.75;
  f.line = pass.counters.lanesShaded ? "helpers " + fixedDigits(100.0 * share, 1) + "% of " +
                                           std::to_string(pass.counters.lanesShaded) + " lanes shaded"
                                     : "no lane shaded";
  return f;
}

void helpersTotals(const std::vector<ViewPass>& passes, Json& totals) {
  uint64_t uncovered = 0, killed = 0, lanesCovered = 0, lanesShaded = 0;
  for (const ViewPass& p : passes) {
    uncovered += total(p.counts.helpersUncovered);
    killed += total(p.counts.helpersKilled);
    lanesCovered += p.counters.lanesCovered;
    lanesShaded += p.counters.lanesShaded;
  }
  totals["helpers"] = {{"uncovered", uncovered},
                       {"depth_failed", killed},
                       {"off_framebuffer", lanesShaded - lanesCovered - uncovered - killed},
                       {"total", lanesShaded - lanesCovered}};
}

// At most 3 of a quad's 4 lanes are helpers: the scale is fixed at 75%.
double quarterToThreeQuarters(double) { return 0.75; }

std::string percentTickText(double v) { return fixedDigits(100.0 * v, 0) + "%"; }

// ---- tile-cost ------------------------------------------------------------------------------

// Each pixel shows its tile's time, in kcyc.
Field tileCostField(const ViewPass& pass) {
  Field f{pass.width, pass.height, {}, {}};
  const size_t n = size_t(pass.width) * size_t(pass.height);
  f.num.assign(n, 0.0);
  f.den.assign(n, 1.0);
  for (int y = 0; y < pass.height; ++y)
    for (int x = 0; x < pass.width; ++x) {
      const size_t tile = size_t(memoryRow(pass, y) / raster::limits::kTileSize) * size_t(pass.tilesX) +
                          size_t(x / raster::limits::kTileSize);
      f.num[size_t(y) * size_t(pass.width) + size_t(x)] = double(pass.tileCycles[tile]) / 1000.0;
    }
  return f;
}

PassFigures tileCostFigures(const ViewPass& pass) {
  PassFigures f = passFigures(pass);
  const Stats s = statsOf(pass.tileCycles);
  f.json["tile_cycles"] = statsJson(s);
  f.json["tiles"] = {pass.tilesX, pass.tilesY};
  f.scaleMax = s.max / 1000.0;
  f.line = std::to_string(pass.tileCycles.size()) + (pass.tileCycles.size() == 1 ? " tile, max " : " tiles, max ") +
           fixedDigits(s.max / 1000.0, 0) + " kcyc, mean " + fixedDigits(s.mean / 1000.0, 0) + " kcyc";
  return f;
}

void tileCostTotals(const std::vector<ViewPass>& passes, Json& totals) {
  uint64_t tileCycles = 0;
  for (const ViewPass& p : passes)
    for (uint64_t c : p.tileCycles) tileCycles += c;
  totals["tile_cycles"] = tileCycles;
  totals["varies"] = "timing: differs from run to run";
}

// A frame whose tiles took no measurable time still gets a scale.
double positiveOrOne(double largest) { return largest > 0 ? largest : 1; }

std::string kcycTickText(double v) { return v >= 10 ? fixedDigits(v, 0) : plainTickText(v); }

// ---- triangles ------------------------------------------------------------------------------

PassFigures trianglesFigures(const ViewPass& pass) {
  PassFigures f = passFigures(pass);
  std::map<std::string, uint64_t> perProgram;
  for (const raster::ViewTriangle& t : pass.triangleList) ++perProgram[pass.drawPrograms[t.drawIndex]];
  f.json["triangles_per_program"] = perProgram;
  f.json["triangles_drawn"] = pass.triangleList.size();
  f.line = std::to_string(pass.triangles) + " triangles, " + std::to_string(pass.drawPrograms.size()) + " draws";
  return f;
}

// The sidecar's totals already hold the frame's triangles.
void noMoreTotals(const std::vector<ViewPass>&, Json&) {}

}  // namespace

// ---- the table --------------------------------------------------------------------------------

const std::vector<StageView>& stageViews() {
  static const std::vector<StageView> views = {
      {.name = "overdraw",
       .shows = "fragments shaded per pixel",
       .about = "Fragments that were covered, passed the depth test and ran the fragment shader, per pixel, "
                "counted with GL semantics (every fragment in API order); this pipeline's visibility-first and "
                "covered-tile paths skip some of them without changing a byte. Helper lanes are not counted "
                "(see --view helpers); depth-only draws run no shader and count 0. In a pass shaded at a coarse "
                "rate (--method shading=2x2) a fragment is a pixel an invocation's outputs reached; "
                "--view invocations counts the invocations.",
       .record = Record::Fragments,
       .figures = overdrawFigures,
       .totals = overdrawTotals,
       .painter = heatMapPainter,
       .heatMap = {.field = overdrawField,
                   .quantity = "fragments shaded per pixel",
                   .top = atLeastOne,
                   .wholeTicks = true,
                   .tickText = plainTickText}},
      {.name = "depth-kills",
       .shows = "fragments rejected by the depth test per pixel",
       .about = "Covered fragments the depth test rejected, per pixel, every fragment in API order. Every depth "
                "test here is early (before shading: no shader writes gl_FragDepth or discards), so all rejects "
                "are early and late rejects are 0.",
       .record = Record::Fragments,
       .figures = depthKillsFigures,
       .totals = depthKillsTotals,
       .painter = heatMapPainter,
       .heatMap = {.field = depthKillsField,
                   .quantity = "depth-test rejects per pixel",
                   .top = atLeastOne,
                   .wholeTicks = true,
                   .tickText = plainTickText}},
      {.name = "helpers",
       .shows = "share of shaded lanes that were helper lanes, per 2x2 quad",
       .about = "Helper lanes are shaded only so dFdx/dFdy see whole quads: pixels outside the triangle, and "
                "covered pixels that failed the depth test while a quad neighbour passed. Share = helpers / all "
                "lanes shaded in the quad over the pass (at most 75%); grey: no lane shaded there.",
       .record = Record::Fragments,
       .figures = helpersFigures,
       .totals = helpersTotals,
       .painter = heatMapPainter,
       .heatMap = {.field = helpersField,
                   .quantity = "helper lanes / lanes shaded, per quad",
                   .top = quarterToThreeQuarters,
                   .tickText = percentTickText,
                   .noData = "no lane",
                   .noDataNote = "grey: no lane shaded in the quad"}},
      {.name = "tile-cost",
       .shows = "time per 64x64 tile, per pass",
       .about = "Time-stamp-counter cycles (kcyc) each tile's task took: its share of the clear and the tile "
                "stage (coverage, depth, shading, output merge), on this pipeline's own path with its fast "
                "paths. Timing: it varies from run to run and with --threads.",
       .record = Record::TileTimes,
       .figures = tileCostFigures,
       .totals = tileCostTotals,
       .painter = heatMapPainter,
       // Tile times span decades (a tile of a fullscreen pass against one crossed by a
       // thousand cubes), so their scale is logarithmic.
       .heatMap = {.field = tileCostField,
                   .quantity = "kcyc per tile (1000 time-stamp-counter cycles), log scale",
                   .top = positiveOrOne,
                   .logarithmic = true,
                   .tickText = kcycTickText}},
      {.name = "triangles",
       .shows = "the set-up triangles of each pass (wireframe)",
       .about = "Every triangle that reached the rasterizer, after clipping (a clipped triangle is a fan) and "
                "culling, coloured by its draw's program; corners recovered from the edge functions.",
       .record = Record::Triangles,
       .figures = trianglesFigures,
       .totals = noMoreTotals,
       .painter = wireframePainter,
       .heatMap = {}},
      {.name = "invocations",
       .shows = "fragment-shader invocations per pixel",
       .about = "Fragment-shader invocations whose outputs reached a pixel, each shared out evenly over the "
                "pixels it wrote: 1 per fragment at the GL shading rate, so it equals overdraw there; under "
                "--method shading=2x2 a post pass's invocation writes its whole 2x2 coarse pixel and each "
                "pixel reads 1/4. Helper lanes and invocations that wrote no pixel are not counted (see "
                "--view helpers for 1x1 passes; a coarse pass's are only in its lane counters).",
       .record = Record::Fragments,
       .figures = invocationsFigures,
       .totals = invocationsTotals,
       .painter = heatMapPainter,
       .heatMap = {.field = invocationsField,
                   .quantity = "fragment-shader invocations per pixel",
                   .top = atLeastOne,
                   .tickText = plainTickText}},
  };
  return views;
}

const StageView* findStageView(const std::string& name) {
  for (const StageView& view : stageViews())
    if (name == view.name) return &view;
  return nullptr;
}

std::string stageViewList() {
  std::string list;
  for (const StageView& view : stageViews()) list += (list.empty() ? "" : ", ") + std::string(view.name);
  return list;
}

std::string viewTitle(const StageView& view) { return std::string(view.name) + ": " + view.shows; }

}  // namespace cli
