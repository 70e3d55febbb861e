// A scene's targets in `raster report` (report.h): per target, this pipeline's image and
// GL's side by side, the difference heat map, and the metrics table.
//
// Previews: a colour preview is always opaque. An RGBA8 target's alpha is data the scene
// wrote (deferred's G-buffer keeps specular intensity there), not coverage for a browser
// to blend with, so its colour preview shows RGB with alpha 255 and its alpha gets a
// preview of its own, as grey. Float, half and depth targets get a PNG preview
// (compare::writePng: floats clamped to [0, 1] with gamma 1/2.2 and alpha dropped, depth
// contrast-stretched) linked to their lossless OpenEXR file.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "backends/backend.h"
#include "scenes/scene.h"

namespace report {

// Whether the image stores an alpha channel as data worth a preview of its own: RGBA8 with
// four channels (a float preview drops alpha; depth has none).
bool alphaIsData(const scenes::ImageData& image);

// An RGBA8 image with alpha 255 everywhere: the colour as stored, nothing see-through.
scenes::ImageData opaqueColour(const scenes::ImageData& rgba8);

// An RGBA8 image's alpha as an opaque grey image: grey level = alpha.
scenes::ImageData alphaAsGrey(const scenes::ImageData& rgba8);

// One target's row: ours and GL's previews, the heat map and the metrics, written into
// `reportFolder`/`folder`; `stats` is the target's metrics JSON (report_results.h). `gl` names
// GL's side in the captions.
std::string targetRow(const scenes::Target& ours, const scenes::Target& theirs, const std::string& gl,
                      const std::string& folder, const std::filesystem::path& reportFolder, const nlohmann::json& stats);

}  // namespace report
