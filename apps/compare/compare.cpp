// `raster compare` (compare.h).
#include "apps/compare/compare.h"

#include <filesystem>
#include <iostream>
#include <vector>

#include "apps/common/number_text.h"
#include "apps/common/pixels_to_trace.h"
#include "apps/common/sides.h"
#include "apps/common/target_stats_json.h"
#include "io/image_io.h"
#include "io/output_file.h"
#include "compare/metrics.h"
#include "backends/backends.h"

namespace cli {
namespace {

namespace fs = std::filesystem;
using scenes::Target;

// The thresholds a target exceeds, one message each (colour ones for rgba8, depth for depth).
std::vector<std::string> exceeded(const compare::TargetStats& s, const Thresholds& limits) {
  std::vector<std::string> failures;
  if (s.kind == "rgba8") {
    if (limits.maxRmse && s.rmse > *limits.maxRmse)
      failures.push_back(s.name + ": rmse " + sixDigits(s.rmse) + " exceeds --max-rmse " + sixDigits(*limits.maxRmse));
    if (limits.minPsnr && s.psnr < *limits.minPsnr)
      failures.push_back(s.name + ": psnr " + sixDigits(s.psnr) + " is below --min-psnr " + sixDigits(*limits.minPsnr));
    if (limits.maxShareOver1 && s.shareOver1 > *limits.maxShareOver1)
      failures.push_back(s.name + ": share of pixels off by more than 1 step " + sixDigits(s.shareOver1) +
                         " exceeds --max-share-over1 " + sixDigits(*limits.maxShareOver1));
  }
  if (s.kind == "depth" && limits.maxDepthLsb && s.maxDepthLsb > *limits.maxDepthLsb)
    failures.push_back(s.name + ": depth differs by up to " + std::to_string(s.maxDepthLsb) +
                       " LSBs, over --max-depth-lsb " + std::to_string(*limits.maxDepthLsb));
  if (limits.exact && s.shareDiffering > 0)
    failures.push_back(s.name + ": " + fixedDigits(100.0 * s.shareDiffering, 3) + "% of its pixels differ (by up to " +
                       std::to_string(largestDifference(s)) + " " + differenceUnit(s.kind) + "), under --exact");
  return failures;
}

// A word as a POSIX shell reads it back: as it is when it holds only characters no shell
// treats specially, else in single quotes (a quote inside as '\'').
std::string shellWord(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                             "0123456789_-+=.,:/@%") == std::string::npos;
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The `raster trace` that shows this pipeline's history of pixel (x, y) of the final image in
// this frame, with the same method set (the trace follows the window's image, so a
// --float-final compare's pixel is traced there; the thread count changes no byte).
std::vector<std::string> traceCommand(const CompareArgs& args, const Frame& frame, const ChosenPixel& pixel) {
  std::vector<std::string> words = {"raster", "trace", frame.scene, "--pixel",
                                    std::to_string(pixel.x) + "," + std::to_string(pixel.y)};
  const std::vector<std::string> options = childFrameOptions(frame);
  for (size_t i = 0; i + 1 < options.size(); i += 2)   // option and value pairs
    if (options[i] != "--instances" || frame.instances != FrameArgs{}.instances)
      words.insert(words.end(), {options[i], options[i + 1]});
  const std::vector<std::string> methods = childMethodOptions(args);
  words.insert(words.end(), methods.begin(), methods.end());
  return words;
}

}  // namespace

int runCompare(const CompareArgs& args) {
  const Frame frame = validateFrame(args);
  if (args.test != "raster" && args.test != "softpipe")
    throw UsageError("--test: '" + args.test + "' is neither raster nor softpipe");
  if (args.reference != "llvmpipe" && args.reference != "softpipe")
    throw UsageError("--reference: '" + args.reference + "' is neither llvmpipe nor softpipe");
  if (args.test != "raster") refuseOwnOptionsOnGl(frame, "--test " + args.test);
  const Thresholds limits = validateThresholds(args);
  const std::string outFolder = args.out.empty() ? "compare-" + frame.scene : args.out;
  // compare.json's path too: a folder or link of that name would otherwise be found only
  // after both renders. (The images' names are the targets', checked once they are known.)
  checkOutputFolder("--out", outFolder, {"compare.json"});
  const std::string numbers = (fs::path(outFolder) / "compare.json").string();
  scenes::checkGalliumEnvironment();

  // Render both sides; they must expose the same targets in the same order.
  const Side test = renderSide(frame, args.test);
  const Side reference = renderSide(frame, args.reference);
  const auto names = [](const Side& side) {
    std::string list;
    for (const Target& t : side.targets) list += (list.empty() ? "" : ",") + t.name;
    return list;
  };
  if (names(test) != names(reference))
    throw std::runtime_error("the sides expose different targets: " + test.backend + " {" + names(test) +
                             "}, " + reference.backend + " {" + names(reference) + "}");

  // Per target: three images, one stats line, and the thresholds it exceeds. Every name is
  // checked before the first file is written, so a taken one leaves the folder as it was.
  std::vector<std::string> files;
  for (const Target& t : test.targets)
    for (const char* suffix : {"_ours.png", "_gl.png", "_diff.png"}) files.push_back(t.name + suffix);
  checkOutputFolder("--out", outFolder, files);
  fs::create_directory(outFolder);
  std::cout << "test: " << test.backend;
  if (args.test == "raster") std::cout << " (methods: " << raster::methodLabel(frame.methods) << ")";
  std::cout << "  reference: " << reference.backend << "  scene: " << frame.scene << " at " << sizeAndTime(frame)
            << std::endl;
  std::vector<std::string> failures;
  nlohmann::json record = {{"scene", frame.scene},
                           {"size", {frame.width, frame.height}},
                           {"time", frame.time},
                           {"sets", frame.sets},
                           {"float_final", frame.floatFinal},
                           {"test", test.backend},
                           {"reference", reference.backend},
                           {"targets", nlohmann::json::array()}};
  if (args.test == "raster") record["methods"] = raster::methodLabel(frame.methods);
  for (size_t i = 0; i < test.targets.size(); ++i) {
    const Target& ours = test.targets[i];
    const Target& theirs = reference.targets[i];
    compare::TargetStats stats = compare::compareImages(ours.name, ours.image, theirs.image);
    compare::measureFlip(stats, ours.image, theirs.image);
    const std::string base = (fs::path(outFolder) / ours.name).string();
    compare::writePng(base + "_ours.png", ours.image);
    compare::writePng(base + "_gl.png", theirs.image);
    compare::writeHeatmapPng(base + "_diff.png", ours.image, theirs.image);
    std::cout << compare::formatStatsLine(stats) << std::endl;
    record["targets"].push_back(targetStatsJson(stats));
    for (const std::string& failure : exceeded(stats, limits)) failures.push_back(failure);
  }
  // Where this pipeline's final image differs, the pixel to trace first: the worst, and the
  // command that shows why this pipeline made it what it is.
  record["worst_pixel"] = nullptr;
  const Target& finalOurs = test.targets.back();
  const std::vector<ChosenPixel> worst =
      args.test == "raster" ? choosePixels(finalOurs.image, reference.targets.back().image, 1) : std::vector<ChosenPixel>{};
  if (!worst.empty() && worst[0].difference > 0) {
    const ChosenPixel& pixel = worst[0];
    const std::vector<std::string> trace = traceCommand(args, frame, pixel);
    const char* unit = differenceUnit(compare::imageKind(finalOurs.image));
    std::string command;
    for (const std::string& word : trace) command += (command.empty() ? "" : " ") + shellWord(word);
    std::cout << finalOurs.name << " differs most at (" << pixel.x << "," << pixel.y << "), by " << pixel.difference << " "
              << unit << "; its history: " << command << std::endl;
    record["worst_pixel"] = {{"target", finalOurs.name}, {"x", pixel.x},   {"y", pixel.y},
                             {"difference", pixel.difference}, {"unit", unit}, {"trace", trace}};
  }
  // The numbers of the lines above, for scripts: written last, whole (io/output_file.h).
  record["failures"] = failures;
  compare::writeOutputFile(numbers, record.dump(1) + "\n");
  std::cout << "images: " << outFolder << "/NAME_{ours,gl,diff}.png  numbers: " << numbers << std::endl;
  for (const std::string& failure : failures) std::cerr << "raster: " << failure << std::endl;
  return failures.empty() ? 0 : 1;
}

}  // namespace cli
