// Drawing charts with bench/*.py (charts.h).
#include "apps/common/charts.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "apps/common/child_process.h"

namespace cli {
namespace {

namespace fs = std::filesystem;

std::string python() {
  if (const char* chosen = std::getenv("RASTER_PYTHON"); chosen && *chosen) return chosen;
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

// Runs python with `args`, its stdout silenced; returns its exit status (-1: it did not run).
int runPython(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {python()};
  argv.insert(argv.end(), args.begin(), args.end());
  ChildOptions options;
  options.searchPath = true;
  try {
    return runChildProcess(argv, python(), options);
  } catch (const std::runtime_error&) {
    return -1;
  }
}

}  // namespace

std::string chartScript(const std::string& script) {
  const char* sourceDir = std::getenv("RASTER_SOURCE_DIR");
  return (fs::path(sourceDir ? sourceDir : RASTER_SOURCE_DIR) / "bench" / script).string();
}

void checkChartTools(const std::string& script) {
  std::error_code unreadable;   // a status that cannot be read (a link that loops) is a missing script too
  if (!fs::is_regular_file(chartScript(script), unreadable))
    throw std::runtime_error("the chart script is missing: " + chartScript(script));
  if (runPython({"-c", "import matplotlib"}) != 0)
    throw std::runtime_error(python() + " cannot import matplotlib, which draws the chart "
                             "(Debian: python3-matplotlib, which ./setup.sh installs; or set RASTER_PYTHON)");
}

void drawChart(const std::string& script, const std::string& jsonPath, const std::string& outBase) {
  const std::string command = python() + " " + chartScript(script) + " " + jsonPath;
  // Each chart file is removed first and must be there after: an interpreter that exits 0
  // without drawing (RASTER_PYTHON=/bin/true) would otherwise leave none, or the last run's.
  std::error_code ignored;
  for (const char* extension : {".png", ".svg"}) fs::remove(outBase + extension, ignored);
  if (runPython({chartScript(script), jsonPath, "--out", outBase}) != 0)
    throw std::runtime_error("the chart script failed: " + command);
  for (const char* extension : {".png", ".svg"})
    if (!fs::is_regular_file(outBase + extension))
      throw std::runtime_error("the chart script wrote no " + outBase + extension + ": " + command);
}

}  // namespace cli
