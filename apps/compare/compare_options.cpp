// `raster compare`'s options and thresholds (compare.h).
#include "apps/compare/compare.h"

namespace cli {

void addCompareOptions(CLI::App& command, CompareArgs& args) {
  addFrameOptions(command, args);
  command.add_option("--out", args.out,
                     "Folder for NAME_ours.png, NAME_gl.png, NAME_diff.png and compare.json (default: compare-SCENE)")
      ->type_name("DIR");
  command.add_option("--reference", args.reference, "Reference GL driver")
      ->type_name("llvmpipe|softpipe")->capture_default_str();
  command.add_option("--test", args.test, "Tested side: this pipeline, or softpipe")
      ->type_name("raster|softpipe")->capture_default_str();
  command.add_option("--max-rmse", args.maxRmse, "Fail if an RGBA8 target's RMSE (8-bit steps) exceeds X")
      ->type_name("X");
  command.add_option("--min-psnr", args.minPsnr, "Fail if an RGBA8 target's PSNR (dB) is below X")
      ->type_name("X");
  command.add_option("--max-share-over1", args.maxShareOver1,
                     "Fail if an RGBA8 target has more than this fraction (0..1) of pixels off by > 1 step")
      ->type_name("X");
  command.add_option("--max-depth-lsb", args.maxDepthLsb,
                     "Fail if a depth target differs anywhere by more than N LSBs")
      ->type_name("N");
  command.add_flag("--exact", args.exact,
                   "Fail if any target differs at all: 8-bit steps, depth LSBs, half or float ULPs (+0 and -0 as one)");
}

Thresholds validateThresholds(const CompareArgs& args) {
  Thresholds limits;
  limits.exact = args.exact;
  if (!args.maxRmse.empty()) {
    limits.maxRmse = parseFiniteNumber("--max-rmse", args.maxRmse);
    if (*limits.maxRmse < 0) throw UsageError("--max-rmse: must be 0 or more");
  }
  if (!args.minPsnr.empty()) limits.minPsnr = parseFiniteNumber("--min-psnr", args.minPsnr);
  if (!args.maxShareOver1.empty()) {
    limits.maxShareOver1 = parseFiniteNumber("--max-share-over1", args.maxShareOver1);
    if (*limits.maxShareOver1 < 0 || *limits.maxShareOver1 > 1)
      throw UsageError("--max-share-over1: must be a fraction between 0 and 1");
  }
  if (!args.maxDepthLsb.empty()) {
    limits.maxDepthLsb = parseWholeNumber(args.maxDepthLsb);
    if (!limits.maxDepthLsb)
      throw UsageError("--max-depth-lsb: '" + args.maxDepthLsb + "' is not a whole number >= 0");
  }
  return limits;
}

}  // namespace cli
