// A scene's targets in the report (report_targets.h).
#include "apps/report/report_targets.h"

#include "apps/report/report_html.h"
#include "apps/report/report_results.h"
#include "io/exr_io.h"
#include "io/image_io.h"

namespace report {
namespace {

namespace fs = std::filesystem;

// The same size and format, no pixels yet.
scenes::ImageData blankLike(const scenes::ImageData& image) {
  scenes::ImageData out;
  out.width = image.width;
  out.height = image.height;
  out.channels = 4;
  out.format = scenes::TexelFormat::RGBA8;
  out.rgba8.resize(image.rgba8.size());
  return out;
}

// One side's figures: its colour preview, then (RGBA8) its alpha, or (float and depth) the
// link to its EXR. Files are FOLDER/NAME_SIDE.png, _SIDE_alpha.png and _SIDE.exr.
std::string sideFigures(const std::string& folder, const std::string& base, const std::string& side,
                        const scenes::ImageData& image, const fs::path& reportFolder, const std::string& caption) {
  const std::string png = folder + "/" + base + "_" + side + ".png";
  if (image.format == scenes::TexelFormat::RGBA8) {
    compare::writePng((reportFolder / png).string(), opaqueColour(image));
    std::string html = figure(png, caption + " (colour, opaque)");
    if (alphaIsData(image)) {
      const std::string alpha = folder + "/" + base + "_" + side + "_alpha.png";
      compare::writePng((reportFolder / alpha).string(), alphaAsGrey(image));
      html += figure(alpha, caption + ": alpha channel as grey (black 0, white 255)");
    }
    return html;
  }
  compare::writePng((reportFolder / png).string(), image);
  const std::string exr = folder + "/" + base + "_" + side + ".exr";
  compare::writeExr((reportFolder / exr).string(), image);
  const bool depth = image.format == scenes::TexelFormat::Depth16 || image.format == scenes::TexelFormat::Depth24;
  const std::string how = depth ? " (preview: depth codes as grey, stretched between the nearest and farthest code present)"
                                : " (preview: clamped to [0, 1], gamma 1/2.2, alpha dropped)";
  return figure(png, caption + how + "; the data:", exr, base + "_" + side + ".exr");
}

}  // namespace

bool alphaIsData(const scenes::ImageData& image) {
  return image.format == scenes::TexelFormat::RGBA8 && image.channels == 4;
}

scenes::ImageData opaqueColour(const scenes::ImageData& rgba8) {
  scenes::ImageData out = blankLike(rgba8);
  for (size_t i = 0; i + 3 < rgba8.rgba8.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) out.rgba8[i + c] = rgba8.rgba8[i + c];
    out.rgba8[i + 3] = 255;
  }
  return out;
}

scenes::ImageData alphaAsGrey(const scenes::ImageData& rgba8) {
  scenes::ImageData out = blankLike(rgba8);
  for (size_t i = 0; i + 3 < rgba8.rgba8.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) out.rgba8[i + c] = rgba8.rgba8[i + 3];
    out.rgba8[i + 3] = 255;
  }
  return out;
}

std::string targetRow(const scenes::Target& ours, const scenes::Target& theirs, const std::string& gl,
                      const std::string& folder, const fs::path& reportFolder, const nlohmann::json& stats) {
  const std::string base = fileSafe(ours.name);
  std::string row = "<div class=\"row\">";
  row += sideFigures(folder, base, "ours", ours.image, reportFolder, "this pipeline");
  row += sideFigures(folder, base, "gl", theirs.image, reportFolder, gl);
  const std::string diff = folder + "/" + base + "_diff.png";
  compare::writeHeatmapPng((reportFolder / diff).string(), ours.image, theirs.image);
  row += figure(diff, "difference heat map");
  row += metricsTable(stats, "metrics-" + folder + "-" + base);
  return row + "</div>\n";
}

}  // namespace report
