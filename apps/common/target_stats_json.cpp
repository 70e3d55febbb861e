// A target's metrics as JSON (target_stats_json.h).
#include "apps/common/target_stats_json.h"

#include "apps/common/number_text.h"

namespace cli {

const char* differenceUnit(const std::string& kind) {
  return kind == "depth" ? "depth LSBs" : kind == "half" ? "half ULPs" : kind == "float" ? "float ULPs" : "8-bit steps";
}

const char* ulpsKey(const std::string& floatKind) { return floatKind == "half" ? "max_half_ulps" : "max_float_ulps"; }

uint64_t largestDifference(const compare::TargetStats& s) {
  // An RGBA8 target's maxAbs counts whole 8-bit steps.
  return s.kind == "depth" ? s.maxDepthLsb : s.isFloatKind() ? s.maxUlps : uint64_t(s.maxAbs);
}

nlohmann::json targetStatsJson(const compare::TargetStats& s) {
  using nlohmann::json;
  const bool depth = s.kind == "depth";
  json j = {{"name", s.name},
            {"kind", s.kind},
            {"size", {s.width, s.height}},
            {"max_in_unit", largestDifference(s)},
            {"unit", differenceUnit(s.kind)},
            {"max_abs", s.maxAbs},
            {"rmse", s.rmse},
            {"psnr_db", dbOrNull(s.psnr)},
            {"share_differing", s.shareDiffering},
            {"share_over1", s.shareOver1},
            {"share_over4", s.shareOver4}};
  if (depth) {
    j["depth_texels_differing"] = s.depthTexelsDiffering;
    j["max_depth_lsb"] = s.maxDepthLsb;
  }
  if (s.isFloatKind()) {
    j["share_bit_identical"] = s.shareBitIdentical;
    j[ulpsKey(s.kind)] = s.maxUlps;
    j["nonfinite_pixels"] = s.nonFinitePixels;
  }
  if (s.flipMeasured) j["flip_mean"] = s.flipMean ? json(*s.flipMean) : json(nullptr);
  return j;
}

}  // namespace cli
