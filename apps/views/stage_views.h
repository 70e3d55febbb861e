// The stage views of `raster render SCENE --view NAME`: one record per view, in the order
// `raster views` lists them. A view's record is all there is of it: what the renderer keeps
// of each pass for it (raster/view_recorder.h), its figures per pass and its totals over the
// frame (the sidecar JSON), and how its passes and its legend are drawn (view_painters.h).
//
// Adding a view is writing its functions and adding one row to the table in
// stage_views.cpp: `render --view` (view_render.h), `raster views`, the error that lists the
// names and `raster report` all read the table, and nothing else lists the views.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/views/view_figures.h"
#include "apps/views/view_painters.h"
#include "raster/view_recorder.h"

namespace cli {

// A heat map's value per pixel and its colour scale (heatMapPainter draws it); a view drawn
// another way leaves this empty.
struct HeatMap {
  Field (*field)(const raster::ViewPass& pass) = nullptr;   // the value at every pixel of the pass
  const char* quantity = "";                  // what a colour means, in the legend and the sidecar
  double (*top)(double largest) = nullptr;    // the ramp's top value, from the largest value shown
  bool logarithmic = false;                   // log10(1 + value): for values that span decades
  bool wholeTicks = false;                    // counts: ticks fall on whole numbers
  std::string (*tickText)(double value) = nullptr;   // a tick's label in the view's unit
  const char* noData = nullptr;               // the swatch label for pixels with nothing to show, if any can
  const char* noDataNote = nullptr;           // ... and what the sidecar's legend says of them
};

struct StageView {
  const char* name;    // as typed after --view
  const char* shows;   // one line: the PNG's title after "NAME: ", and `raster views`
  const char* about;   // what the numbers are and how they were counted: under the title, and the sidecar's "about"
  raster::ViewRecorder::Record record;   // what the renderer keeps of each pass for this view
  // The pass's sidecar entry, the line under its cell, and the largest value it shows.
  PassFigures (*figures)(const raster::ViewPass& pass);
  // The view's own sums over the frame, added to the sidecar's "totals" (which already
  // holds the passes, lanes covered and shaded, and triangles).
  void (*totals)(const std::vector<raster::ViewPass>& passes, nlohmann::json& totals);
  MakePainter painter;   // how each pass and the legend are drawn: heatMapPainter, wireframePainter
  HeatMap heatMap;       // heatMapPainter's settings
};

// Every view, in order.
const std::vector<StageView>& stageViews();

// The view named `name`, or nullptr.
const StageView* findStageView(const std::string& name);

// "overdraw, depth-kills, ...": the names for a message.
std::string stageViewList();

// "overdraw: fragments shaded per pixel": the PNG's first line.
std::string viewTitle(const StageView& view);

}  // namespace cli
