// The report's sections that child processes of this program make (report.h): a scene's
// stage views (`raster render --view NAME`, one child per view of the registry,
// apps/views/stage_views.h) and the pixel histories of its chosen pixels (`raster trace
// --json`, one child per pixel). A child renders the same frame as the report (its size,
// time, --set values and methods); one that fails leaves a note in its place and the report
// goes on.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/common/cli_options.h"
#include "apps/report/report.h"
#include "apps/common/pixels_to_trace.h"

namespace report {

// What one scene's sections need: its frame, the report's options, where its files go
// (`folder`, relative to the report being made in `work`), where the children's logs go,
// and the progress (called with what runs next).
struct SceneWork {
  const cli::Frame& frame;
  const cli::ReportArgs& args;
  std::string folder;
  std::filesystem::path work, scratch;
  std::function<void(const std::string&)> step;
};

// Every stage view of the scene with its sidecar's figures; `record` gets an entry per view.
std::string viewsHtml(const SceneWork& scene, nlohmann::json& record);

// The pixel histories of `pixels`, against `reference` (GL's backend, for the text); `record`
// gets an entry per pixel.
std::string tracesHtml(const SceneWork& scene, const std::vector<cli::ChosenPixel>& pixels, const std::string& reference,
                       nlohmann::json& record);

}  // namespace report
