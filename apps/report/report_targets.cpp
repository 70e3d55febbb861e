// A scene's targets in the report (report_targets.h).
#include "apps/report/report_targets.h"

#include "apps/report/report_html.h"
#include "apps/report/report_results.h"
#include "compare/exr_io.h"
#include "compare/image_io.h"

namespace report {
namespace {

namespace fs = std::filesystem;

// The figure of one target image: the preview PNG and, for float / depth targets, its EXR.
std::string targetFigure(const std::string& folder, const std::string& base, const std::string& side,
                         const scenes::ImageData& image, const fs::path& reportFolder, const std::string& caption) {
  const std::string png = folder + "/" + base + "_" + side + ".png";
  compare::writePng((reportFolder / png).string(), image);
  if (image.format == scenes::TexelFormat::RGBA8) return figure(png, caption);
  const std::string exr = folder + "/" + base + "_" + side + ".exr";
  compare::writeExr((reportFolder / exr).string(), image);
  const bool depth = image.format == scenes::TexelFormat::Depth16 || image.format == scenes::TexelFormat::Depth24;
  const std::string how = depth ? " (preview: depth codes as grey, stretched between the nearest and farthest code present)"
                                : " (preview: clamped to [0, 1], gamma 1/2.2, alpha dropped)";
  return figure(png, caption + how + "; the data:", exr, base + "_" + side + ".exr");
}

}  // namespace

std::string targetRow(const scenes::Target& ours, const scenes::Target& theirs, const std::string& gl,
                      const std::string& folder, const fs::path& reportFolder, const nlohmann::json& stats) {
  const std::string base = fileSafe(ours.name);
  std::string row = "<div class=\"row\">";
  row += targetFigure(folder, base, "ours", ours.image, reportFolder, "this pipeline");
  row += targetFigure(folder, base, "gl", theirs.image, reportFolder, gl);
  const std::string diff = folder + "/" + base + "_diff.png";
  compare::writeHeatmapPng((reportFolder / diff).string(), ours.image, theirs.image);
  row += figure(diff, "difference heat map");
  row += metricsTable(stats, "metrics-" + folder + "-" + base);
  return row + "</div>\n";
}

}  // namespace report
