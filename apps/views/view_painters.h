// How a stage view's passes and legend are drawn on its sheet (view_sheet.h lays the sheet
// out and draws the headings). A view's record (stage_views.h) names its painter:
//   heatMapPainter    one value per pixel (the record's HeatMap) on the viridis ramp, every
//                     cell on one colour scale; the legend is the scale with its ticks;
//   wireframePainter  the pass's set-up triangles as lines, coloured by the draw's program;
//                     the legend is a swatch per program.
// A painter is made once per sheet, from every pass shown, so that its cells share one
// scale (or one colour per program).
#pragma once

#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/views/view_canvas.h"
#include "apps/views/view_figures.h"
#include "raster/view_recorder.h"

namespace cli {

struct StageView;

// The sheet's colours.
constexpr Rgb kSheetBackground{24, 24, 24};
constexpr Rgb kInk{230, 230, 230};   // titles, legends
constexpr Rgb kDim{160, 160, 160};   // notes, the line under a cell
constexpr Rgb kNoData{64, 64, 64};   // a heat map's pixel with nothing to show

// The sheet's measures, in pixels: a grid of cells (a pass's two label lines, then its
// image box), then the legend.
struct SheetLayout {
  bool native = false;    // one pass alone at its own size; else each pass scaled into its cell
  int textScale = 1;      // each font pixel is textScale x textScale
  int margin = 8;
  int line = Canvas::kLineHeight;   // a line of text
  int columns = 1;
  int cellWidth = 0, cellHeight = 0;   // a cell's image box
  int labelHeight = 0;    // a cell's labels above its image
  int width = 0;          // the sheet
  int textWidth = 0;      // the sheet less its margins
};

// What the painter is given: the passes on the sheet, in order, and every pass's figures
// (indexed by ViewPass::index).
struct SheetPasses {
  const std::vector<const raster::ViewPass*>& shown;
  const std::vector<PassFigures>& figures;
};

class ViewPainter {
 public:
  virtual ~ViewPainter() = default;
  // The legend's height, for the sheet's size.
  virtual int legendHeight() const = 0;
  // The pass into its image box (x, y, width, height) on the canvas.
  virtual void drawPass(Canvas& canvas, const raster::ViewPass& pass, int x, int y, int width, int height) const = 0;
  // The legend with its top at y; returns what the sidecar's "legend" says of it.
  virtual nlohmann::json drawLegend(Canvas& canvas, int y) const = 0;
};

using MakePainter = std::unique_ptr<ViewPainter> (*)(const StageView& view, const SheetLayout& layout,
                                                     const SheetPasses& passes);

std::unique_ptr<ViewPainter> heatMapPainter(const StageView& view, const SheetLayout& layout, const SheetPasses& passes);
std::unique_ptr<ViewPainter> wireframePainter(const StageView& view, const SheetLayout& layout, const SheetPasses& passes);

}  // namespace cli
