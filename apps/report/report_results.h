// The report's tables of results, each rendered from the JSON it came from, so what the page
// shows is what the data file beside it holds (the Chromium test checks cells against it):
//   - a target's metrics: compare::compareImages' TargetStats (what `raster compare` prints),
//     as JSON (cli::targetStatsJson, apps/common/target_stats_json.h) and as a table;
//   - `raster tradeoff`'s tradeoff.json (one scene's object, or a list of them);
//   - `raster sweep`'s sweep.json;
//   - a stage view's sidecar JSON (`raster render --view`), whatever its fields.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "compare/metrics.h"

namespace report {

// One target's metrics, a row per metric (the PSNR row is "PSNR (dB)", shown with two
// decimals or "identical"). `id` names the table.
std::string metricsTable(const nlohmann::json& stats, const std::string& id);

// How a PSNR from the JSON reads in every table: two decimals, or "identical" for null.
std::string psnrText(const nlohmann::json& db);

// The tables of a tradeoff.json: per scene, its points sorted by speed (as tradeoff.md).
// `idPrefix` names them: idPrefix-SCENE.
std::string tradeoffTables(const nlohmann::json& tradeoff, const std::string& idPrefix);

// A sweep.json: the first failing value of each side, then every point (collapsed).
std::string sweepTables(const nlohmann::json& sweep, const std::string& idPrefix);

// A stage view's sidecar: its scalar fields as a table, anything nested as JSON text.
std::string sidecarTable(const nlohmann::json& sidecar, const std::string& id);

}  // namespace report
