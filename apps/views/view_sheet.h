// A stage view's PNG (view_render.h): the sheet. From the top: the view's title with the
// frame, its notes (what the numbers are), a grid of cells, one per pass shown (its title
// and figures line, then its picture), and the view's legend. The view's painter
// (view_painters.h) draws the pictures and the legend; this lays them out and draws the rest.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/common/cli_options.h"
#include "apps/views/stage_views.h"
#include "apps/views/view_canvas.h"

namespace cli {

// The grid for the passes shown: one pass alone keeps its own size, more are scaled into
// cells of one size, up to three a row.
SheetLayout layoutSheet(const Frame& frame, const std::vector<const raster::ViewPass*>& shown);

struct Sheet {
  Canvas canvas;
  nlohmann::json legend;   // what the painter says of its legend, for the sidecar
};

// Draws the sheet of `view` for the passes shown; `figures` holds every pass's, by index.
Sheet drawSheet(const StageView& view, const Frame& frame, const std::vector<const raster::ViewPass*>& shown,
                const std::vector<PassFigures>& figures);

}  // namespace cli
