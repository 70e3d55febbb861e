// How the reports of the `raster` program (compare lines, tradeoff and sweep tables, their
// JSON) write numbers, so the same value reads the same everywhere.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace cli {

// 6 significant digits ("0.0001", "1e+06"): a value a user can type back into an option.
inline std::string sixDigits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// A fixed number of decimals, for table columns ("48.3").
inline std::string fixedDigits(double value, int digits) {
  char text[352];   // %.*f of the largest double with a few decimals
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

// A PSNR in dB for the JSON: null when the images are identical (+inf), as the schemas ask.
inline nlohmann::json dbOrNull(double psnr) { return std::isfinite(psnr) ? nlohmann::json(psnr) : nlohmann::json(nullptr); }

}  // namespace cli
