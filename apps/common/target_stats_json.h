// A target's metrics (compare::TargetStats, what `raster compare` prints a line of) as JSON:
// the one schema of `raster compare`'s compare.json and `raster report`'s report.json.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/metrics.h"

namespace cli {

// name, kind, size [w, h]; max_in_unit and unit, the largest difference in the kind's own unit
// (the `max` column of compare's line: "8-bit steps", "depth LSBs", "half ULPs" or "float
// ULPs"; 0 exactly when every pixel is the reference's, where a float target's +0 and -0 are
// one value and so are its NaNs); max_abs (the largest difference as a value: 8-bit steps,
// depth LSBs, or the float difference), rmse, psnr_db (null when identical), share_differing,
// share_over1, share_over4, and the kind's own fields (depth: depth_texels_differing,
// max_depth_lsb; half: share_bit_identical, max_half_ulps, nonfinite_pixels; float: the same
// with max_float_ulps), and flip_mean when FLIP was measured (compare::measureFlip; null for a
// target that is not rgba8).
nlohmann::json targetStatsJson(const compare::TargetStats& stats);

// The largest difference of a target in its kind's unit, a whole number (max_in_unit; the
// `max` of compare's line): 0 exactly when no pixel differs.
uint64_t largestDifference(const compare::TargetStats& stats);

// The key of a float target's largest ULP distance: "max_half_ulps" or "max_float_ulps" (the
// unit is named in the key).
const char* ulpsKey(const std::string& floatKind);

// The unit a target of `kind` counts its differences in (the JSON's `unit`): "8-bit steps",
// "depth LSBs", "half ULPs" or "float ULPs".
const char* differenceUnit(const std::string& kind);

}  // namespace cli
