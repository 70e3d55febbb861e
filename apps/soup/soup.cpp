// `raster soup` (soup.h): soups of seeds, or a reproducer, through both pipelines.
#include "apps/soup/soup.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps/common/cli_options.h"
#include "apps/soup/soup_file.h"
#include "io/output_file.h"
#include "backends/backends.h"
#include "scenes/soup/soup_check.h"

namespace cli {
namespace {

namespace fs = std::filesystem;
using scenes::soup::Soup;
using scenes::soup::Verdict;

constexpr int kMaxTriangleOption = 1000000;   // a million triangles a soup: far past any use
// Backends cannot free meshes (backends/backend.h), so a fresh pair every this many seeds keeps
// a long run's memory flat.
constexpr int kSeedsPerBackend = 64;
// The failing seeds --json describes in full (all of them are listed by number).
constexpr size_t kFailuresInFull = 100;
// A run's seeds: a million soups take hours (milliseconds each at 64x64), so a longer range
// is a typo (1:99999999999999 would never end), and a real search is split into runs.
constexpr uint64_t kMaxSeedsPerRun = 1000000;

struct Plan {
  bool replay = false;
  uint64_t first = 0, last = 0;   // seeds, inclusive
  int width = 0, height = 0, triangles = 0;
  Soup replayed;
};

Plan validate(const SoupArgs& args) {
  Plan plan;
  if (args.seeds.empty() == args.replay.empty())
    throw UsageError("soup: give --seeds A:B or --replay FILE (exactly one)");
  if (args.threads < 0 || args.threads > kMaxThreads)
    throw UsageError("--threads: " + std::to_string(args.threads) + " is out of range (0.." + std::to_string(kMaxThreads) + ")");
  if (!args.json.empty()) checkOutputFile("--json", args.json);
  if (!args.replay.empty()) {
    plan.replay = true;
    plan.replayed = readSoupFile(args.replay);
    plan.width = plan.replayed.width;
    plan.height = plan.replayed.height;
    plan.first = plan.last = plan.replayed.seed;
    return plan;
  }
  const size_t colon = args.seeds.find(':');
  const auto first = parseWholeNumber(args.seeds.substr(0, colon));
  const auto last = colon == std::string::npos ? first : parseWholeNumber(args.seeds.substr(colon + 1));
  if (!first || !last) throw UsageError("--seeds: '" + args.seeds + "' is not A:B (whole numbers, e.g. 0:99) or a single seed");
  if (*first > *last)
    throw UsageError("--seeds: " + args.seeds + " runs backwards (A:B takes seeds A through B, A <= B)");
  if (*last - *first >= kMaxSeedsPerRun)
    throw UsageError("--seeds: " + args.seeds + " is more than " + std::to_string(kMaxSeedsPerRun) +
                     " seeds (split the range into runs)");
  plan.first = *first;
  plan.last = *last;
  std::tie(plan.width, plan.height) = parseSize("--size", args.size);
  const auto triangles = parseWholeNumber(args.triangles);
  if (!triangles || *triangles > uint64_t(kMaxTriangleOption))
    throw UsageError("--triangles: '" + args.triangles + "' is not a whole number 0.." + std::to_string(kMaxTriangleOption));
  plan.triangles = int(*triangles);
  checkOutputFolder("--out", args.out);
  return plan;
}

// Both backends and a renderer on each, for one size.
struct Pair {
  std::unique_ptr<scenes::Backend> ours, reference;
  std::unique_ptr<scenes::soup::SoupRenderer> oursRenderer, referenceRenderer;
  Pair(int threads, bool scalar, int width, int height)
      : ours(scenes::makeRasterBackend(threads, scalar)), reference(scenes::makeGlBackend()),
        oursRenderer(std::make_unique<scenes::soup::SoupRenderer>(*ours, width, height)),
        referenceRenderer(std::make_unique<scenes::soup::SoupRenderer>(*reference, width, height)) {}
};

std::string meshProblems(const scenes::soup::MeshCheck& m) {
  return std::to_string(m.cracks) + " cracks, " + std::to_string(m.doubleHits) + " double hits, " +
         std::to_string(m.strays) + " strays; first: " + m.first;
}

// The seed's line and, when it fails, the lines below it. True when the seed passes.
bool report(const Soup& soup, const Verdict& v, const std::string& reference, std::ostream& out) {
  const bool passes = v.identical() && v.oursWatertight();
  out << "seed " << soup.seed << ": " << v.finiteTriangles << " triangles, " << v.covered << " px covered";
  out << ", " << soup.meshes.size() << " closed meshes, " << v.countedPixels << " px counted";
  if (v.nonFiniteTriangles > 0)
    out << ", " << v.nonFiniteTriangles << " non-finite (not compared: ours covered " << v.nonFiniteCoveredOurs
        << " px, " << reference << " " << v.nonFiniteCoveredReference << ")";
  if (passes) out << ": identical, watertight";
  else if (!v.identical())
    out << ": DIFFERS from " << reference << " (" << v.colorDiffs << " px of ID colour, " << v.depthDiffs
        << " of depth, " << v.countDiffs << " of closed-mesh counts)";
  else out << ": identical to " << reference << ", NOT WATERTIGHT";
  out << "\n";
  for (const std::string& line : v.firstDiffs) out << "  " << line << "\n";
  for (size_t m = 0; m < soup.meshes.size(); ++m) {
    const std::string name = "closed mesh " + std::to_string(m) + " (" + scenes::soup::meshKindName(soup.meshes[m].kind) +
                             ", " + soup.meshes[m].note + ")";
    if (!v.ours[m].watertight()) out << "  " << name << " on ours: " << meshProblems(v.ours[m]) << "\n";
    if (!v.reference[m].watertight())
      out << "  note: " << name << " on " << reference << " itself: " << meshProblems(v.reference[m]) << "\n";
  }
  return passes;
}

}  // namespace

void addSoupOptions(CLI::App& command, SoupArgs& args) {
  command.add_option("--seeds", args.seeds, "Seeds A through B (inclusive), or one seed")->type_name("A:B");
  command.add_option("--replay", args.replay, "Render a reproducer written by a failing run again")->type_name("FILE");
  command.add_option("--size", args.size, "Viewport size")->type_name("WxH")->capture_default_str();
  command.add_option("--triangles", args.triangles, "Random triangles a soup (besides its closed meshes)")
      ->type_name("N")->capture_default_str();
  command.add_option("--out", args.out, "Folder for the reproducers of failing seeds, soup-SEED.json")
      ->type_name("DIR")->capture_default_str();
  command.add_option("--json", args.json,
                     "Also write the results as JSON to FILE: the run, its counts, every failing seed, the first " +
                         std::to_string(kFailuresInFull) + " failures in full")
      ->type_name("FILE");
  command.add_option("--threads", args.threads, "Threads of this pipeline, 0..1024; 0: every core")
      ->type_name("N")->capture_default_str();
  command.add_flag("--scalar", args.scalar, "This pipeline with every SIMD fast path off (same bytes, slower)");
  // For the tests: proves the check can fail (this pipeline's triangles drawn a pixel right).
  command.add_flag("--inject-difference", args.injectDifference)->group("");
}

int runSoup(const SoupArgs& args) {
  const Plan plan = validate(args);
  scenes::checkGalliumEnvironment();

  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  Clock::time_point lastProgress = start;
  const bool terminal = isatty(STDERR_FILENO);
  const uint64_t total = plan.last - plan.first + 1;

  std::unique_ptr<Pair> pair;
  std::string reference;
  uint64_t done = 0, failed = 0, nonFinite = 0, referenceLeaks = 0;
  std::vector<uint64_t> failedSeeds;                     // every one (the error line names the first 20)
  nlohmann::json failures = nlohmann::json::array();   // the first kFailuresInFull, for --json
  for (uint64_t seed = plan.first;; ++seed) {
    if (!pair || done % kSeedsPerBackend == 0) {
      pair.reset();   // the old pair's GL context is gone before the next is made
      pair = std::make_unique<Pair>(args.threads, args.scalar, plan.width, plan.height);
      reference = pair->reference->name();
    }
    const Soup soup = plan.replay ? plan.replayed : scenes::soup::generate(seed, plan.width, plan.height, plan.triangles);
    const Soup oursSoup = args.injectDifference ? scenes::soup::shiftedOnePixel(soup) : soup;
    const scenes::soup::Rendering ours = pair->oursRenderer->render(oursSoup);
    const scenes::soup::Rendering theirs = pair->referenceRenderer->render(soup);
    const Verdict verdict = scenes::soup::compare(soup, ours, theirs);
    nonFinite += uint64_t(verdict.nonFiniteTriangles);
    referenceLeaks += !verdict.referenceWatertight();

    std::ostringstream lines;
    if (!report(soup, verdict, reference, lines)) {
      ++failed;
      failedSeeds.push_back(seed);
      nlohmann::json reproducer = nullptr;
      if (!plan.replay) {
        fs::create_directory(args.out);
        const std::string path = (fs::path(args.out) / ("soup-" + std::to_string(seed) + ".json")).string();
        compare::writeOutputFile(path, soupToJson(soup, verdict.firstDiffs));
        lines << "  reproducer: " << path << " (raster soup --replay " << path << ")\n";
        reproducer = path;
      }
      if (failures.size() < kFailuresInFull)
        failures.push_back({{"seed", seed},
                            {"identical", verdict.identical()},
                            {"watertight", verdict.oursWatertight()},
                            {"color_diffs", verdict.colorDiffs},
                            {"depth_diffs", verdict.depthDiffs},
                            {"count_diffs", verdict.countDiffs},
                            {"first_diffs", verdict.firstDiffs},
                            {"reproducer", reproducer}});
    }
    std::cout << lines.str() << std::flush;
    ++done;

    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - start).count();
    if (seconds > 3.0 && now - lastProgress > std::chrono::seconds(2) && done < total) {
      lastProgress = now;
      char line[160];
      std::snprintf(line, sizeof line, "soup: %llu/%llu seeds, %llu failed, %.0f s", (unsigned long long)done,
                    (unsigned long long)total, (unsigned long long)failed, seconds);
      std::cerr << (terminal ? "\r" : "") << line << (terminal ? "" : "\n") << std::flush;
    }
    if (seed == plan.last) break;
  }
  if (terminal && lastProgress != start) std::cerr << std::endl;

  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::cout << "soup: " << done << (plan.replay ? " replayed soup (" + args.replay + ")" : (done == 1 ? " seed (" : " seeds (") +
                                        std::to_string(plan.first) + ".." + std::to_string(plan.last) + ")")
            << " at " << plan.width << "x" << plan.height << " against " << reference << ": " << (done - failed)
            << " identical and watertight, " << failed << " failed";
  if (nonFinite > 0) std::cout << "; " << nonFinite << " non-finite triangles drawn apart, not compared (undefined in GL)";
  if (referenceLeaks > 0) std::cout << "; " << reference << " itself not watertight in " << referenceLeaks << " soups";
  char time[32];
  std::snprintf(time, sizeof time, "%.1f", seconds);
  std::cout << "; " << time << " s" << std::endl;
  if (!args.json.empty()) {   // no time in it: the same seeds give the same bytes
    const nlohmann::json record = {
        {"size", {plan.width, plan.height}},
        {"triangles", plan.replay ? nlohmann::json(nullptr) : nlohmann::json(plan.triangles)},
        {"seeds", {plan.first, plan.last}},
        {"replay", plan.replay ? nlohmann::json(args.replay) : nlohmann::json(nullptr)},
        {"reference", reference},
        {"soups", done},
        {"passed", done - failed},
        {"failed", failed},
        {"non_finite_triangles", nonFinite},
        {"reference_not_watertight", referenceLeaks},
        {"failed_seeds", failedSeeds},
        {"failures", failures}};
    compare::writeOutputFile(args.json, record.dump(1) + "\n");
  }
  if (failed > 0) {
    std::string list;
    for (size_t k = 0; k < std::min<size_t>(failedSeeds.size(), 20); ++k)
      list += (list.empty() ? "" : ", ") + std::to_string(failedSeeds[k]);
    std::cerr << "raster: soup: " << failed << " of " << done << " failed (seeds " << list << (failed > 20 ? ", ..." : "")
              << ")" << std::endl;
  }
  return failed == 0 ? 0 : 1;
}

}  // namespace cli
