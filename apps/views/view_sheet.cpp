// The stage view's sheet (view_sheet.h).
#include "apps/views/view_sheet.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "apps/common/sides.h"

namespace cli {
namespace {

using raster::ViewPass;

// How big a pass's picture is in its cell: its own size alone, else scaled to fit the
// cell's image box with its aspect kept.
std::pair<int, int> pictureSize(const SheetLayout& layout, const ViewPass& pass) {
  if (layout.native) return {pass.width, pass.height};
  const double s = std::min(double(layout.cellWidth) / pass.width, double(layout.cellHeight) / pass.height);
  return {std::max(1, int(std::lround(pass.width * s))), std::max(1, int(std::lround(pass.height * s)))};
}

// A cell with its top-left corner at (x, y): the pass's title and figures line, cut to the
// cell's width, then its picture.
void drawCell(Canvas& canvas, const SheetLayout& layout, const ViewPainter& painter, const ViewPass& pass,
              const PassFigures& figures, int x, int y) {
  const int labelWidth = std::max(layout.cellWidth, layout.native ? layout.textWidth : 0);
  const auto fit = [&](std::string text) {
    while (text.size() > 3 && Canvas::textWidth(text, layout.textScale) > labelWidth) text = text.substr(0, text.size() - 4) + "..";
    return text;
  };
  canvas.text(x, y, fit(passTitle(pass)), kInk, layout.textScale);
  canvas.text(x, y + layout.line, fit(figures.line), kDim, layout.textScale);
  const auto [width, height] = pictureSize(layout, pass);
  painter.drawPass(canvas, pass, x, y + layout.labelHeight, width, height);
}

}  // namespace

SheetLayout layoutSheet(const Frame& frame, const std::vector<const ViewPass*>& shown) {
  SheetLayout layout;
  layout.native = shown.size() == 1;
  layout.columns = shown.size() <= 2 ? int(shown.size()) : shown.size() <= 4 ? 2 : 3;
  layout.cellWidth = layout.native ? shown[0]->width : std::clamp(frame.width, 220, 480);   // room for the labels
  // The frame's aspect, but at most twice as tall as wide: a 1x16384 frame's cells were 220 px
  // wide and 3.6 million tall (gigabytes of sheet); its picture now narrows to fit instead.
  layout.cellHeight = layout.native ? shown[0]->height
                                    : std::clamp(int(std::lround(double(layout.cellWidth) * frame.height / frame.width)), 1,
                                                 2 * layout.cellWidth);
  layout.textScale = layout.columns * layout.cellWidth >= 1200 ? 2 : 1;   // readable on a wide sheet
  layout.margin = 8 * layout.textScale;
  layout.line = Canvas::kLineHeight * layout.textScale;
  layout.labelHeight = 2 * layout.line + layout.margin / 2;
  layout.width = std::max(layout.columns * layout.cellWidth + (layout.columns + 1) * layout.margin, 440 * layout.textScale);
  layout.textWidth = layout.width - 2 * layout.margin;
  return layout;
}

Sheet drawSheet(const StageView& view, const Frame& frame, const std::vector<const ViewPass*>& shown,
                const std::vector<PassFigures>& figures) {
  const SheetLayout layout = layoutSheet(frame, shown);
  const std::unique_ptr<ViewPainter> painter = view.painter(view, layout, {shown, figures});
  const std::string heading =
      viewTitle(view) + " - " + frame.scene + ", " + sizeAndTime(frame) + (frame.scalar ? ", --scalar" : "");
  const std::vector<std::string> headingLines = wrapText(heading, layout.textWidth, layout.textScale);
  const std::vector<std::string> notes = wrapText(view.about, layout.textWidth, layout.textScale);
  const int rows = (int(shown.size()) + layout.columns - 1) / layout.columns;
  const int rowHeight = layout.labelHeight + layout.cellHeight + layout.margin;
  const int gridTop = layout.margin + layout.line * int(headingLines.size() + notes.size()) + layout.margin;
  const int legendTop = gridTop + rows * rowHeight;
  Sheet sheet{Canvas(layout.width, legendTop + painter->legendHeight() + layout.margin, kSheetBackground), {}};

  int y = layout.margin;
  for (const std::string& line : headingLines) {
    sheet.canvas.text(layout.margin, y, line, kInk, layout.textScale);
    y += layout.line;
  }
  for (const std::string& line : notes) {
    sheet.canvas.text(layout.margin, y, line, kDim, layout.textScale);
    y += layout.line;
  }
  for (size_t i = 0; i < shown.size(); ++i) {
    const int x = layout.margin + int(i % size_t(layout.columns)) * (layout.cellWidth + layout.margin);
    drawCell(sheet.canvas, layout, *painter, *shown[i], figures[size_t(shown[i]->index)], x,
             gridTop + int(i / size_t(layout.columns)) * rowHeight);
  }
  sheet.legend = painter->drawLegend(sheet.canvas, legendTop);
  return sheet;
}

}  // namespace cli
