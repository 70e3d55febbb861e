// The report's last section (report.h): the tradeoff and sweep results found under the
// --include folders, each with its chart (PNG, else SVG) and its tables, copied into the
// report with its JSON.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace report {

struct ChartResult {
  std::string kind;                 // "tradeoff" or "sweep"
  std::filesystem::path folder;     // where tradeoff.json / sweep.json lies
  std::string label;                // the folder, relative to its --include folder
};

// Every tradeoff.json and sweep.json under the folders, in the same order on every machine.
std::vector<ChartResult> findChartResults(const std::vector<std::string>& includes);

// Copies a result's JSON and chart into the report (charts/INDEX-LABEL/); returns its
// section's HTML and sets `record` to what report.json says of it.
std::string chartSection(const ChartResult& result, const std::filesystem::path& reportFolder, int index,
                         nlohmann::json& record);

}  // namespace report
