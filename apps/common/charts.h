// Charts are drawn by Python scripts in bench/ with Debian's matplotlib (tradeoff_chart.py,
// sweep_chart.py): this finds the script and the Python, checks both before a long run
// starts, and runs the script on a JSON result.
//
// The script is found in the source tree this binary was built from (or
// $RASTER_SOURCE_DIR); the Python is $RASTER_PYTHON, else Debian's /usr/bin/python3 (a
// python3 earlier in PATH, such as a pyenv shim, may lack the Debian packages), else
// python3 from PATH.
#pragma once

#include <string>

namespace cli {

// bench/SCRIPT in the source tree.
std::string chartScript(const std::string& script);

// Before any frame: the script exists and the Python can import matplotlib, so a long run
// does not end without its chart (std::runtime_error saying what to install otherwise).
void checkChartTools(const std::string& script);

// Runs `python SCRIPT JSON --out OUT_BASE` (OUT_BASE.png and .svg); throws on failure.
void drawChart(const std::string& script, const std::string& jsonPath, const std::string& outBase);

}  // namespace cli
