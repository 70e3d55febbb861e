// A scene's targets in `raster report` (report.h): per target, this pipeline's image and
// GL's side by side, the difference heat map, and the metrics table. RGBA8 targets are PNGs
// as they are; float, half and depth targets get a PNG preview (compare::writePng: floats
// clamped to [0, 1] with gamma 1/2.2 and alpha dropped, depth contrast-stretched) linked to
// their lossless OpenEXR file.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "scenes/backend.h"
#include "scenes/scene.h"

namespace report {

// One target's row: ours and GL's previews, the heat map and the metrics, written into
// `reportFolder`/`folder`; `stats` is the target's metrics JSON (report_results.h). `gl` names
// GL's side in the captions.
std::string targetRow(const scenes::Target& ours, const scenes::Target& theirs, const std::string& gl,
                      const std::string& folder, const std::filesystem::path& reportFolder, const nlohmann::json& stats);

}  // namespace report
