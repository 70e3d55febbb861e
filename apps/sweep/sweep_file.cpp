// sweep.json and its table and chart (sweep_file.h).
#include "apps/sweep/sweep_file.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "apps/common/charts.h"
#include "apps/common/cli_options.h"
#include "apps/common/number_text.h"
#include "io/output_file.h"

namespace cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// For each side, the first value (in sweep order) at which it fails, or null.
json firstFailures(const json& sweep) {
  json first = json::object();
  for (const std::string& side : sweepSides(sweep)) {
    json value = nullptr;
    for (const json& p : sweep.at("points"))
      if (p.at("method") == side && p.at("fails").get<bool>()) {
        value = p.at("value");
        break;
      }
    first.emplace(side, std::move(value));
  }
  return first;
}

std::string markdown(const json& sweep) {
  std::ostringstream md;
  const json& r = sweep.at("range");
  const std::string param = sweep.at("param").get<std::string>();
  // The base size and time it records, unless the sweep moves that one (a size's height
  // follows its width at 4:3).
  const std::string size = param == "size" ? std::string("each width at 4:3")
                                           : sweep.at("size")[0].dump() + "x" + sweep.at("size")[1].dump();
  const std::string time = param == "time" ? std::string("each value's time") : "t=" + sixDigits(sweep.at("time"));
  // The scene parameters it was run with, as typed, so that the table can be made again.
  std::string sets;
  for (const json& set : sweep.at("sets")) sets += std::string(sets.empty() ? "" : " ") + "--set " + set.get<std::string>();
  md << "# Sweep of `" << param << "` in " << sweep.at("scene").get<std::string>() << "\n\nFrom "
     << sixDigits(r.at("from")) << " to " << sixDigits(r.at("to")) << " in " << r.at("steps")
     << (r.at("log").get<bool>() ? " log" : "") << " steps, " << size << ", " << time
     << (sets.empty() ? "" : ", with `" + sets + "`") << ". Each side against llvmpipe; a side fails at a final image below "
     << sixDigits(sweep.at("threshold_db")) << " dB or any non-finite pixel.\n\n";
  if (sweep.contains("first_failure")) {
    md << "| side | first failing value |\n|---|---|\n";
    for (const auto& [side, value] : sweep.at("first_failure").items())
      md << "| " << side << " | " << (value.is_null() ? std::string("none") : sixDigits(value.get<double>())) << " |\n";
    md << "\n";
  }
  md << "| value | side | identical | PSNR (dB) | FLIP | >1 step | max step | non-finite | worst target (dB) | fails |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const json& p : sweep.at("points")) {
    const json& db = p.at("psnr_vs_llvmpipe_db");
    const json& worst = p.at("worst_target");
    const json flip = p.value("flip_vs_llvmpipe", json(nullptr));   // absent from sweeps before it
    md << "| " << sixDigits(p.at("value")) << " | " << p.at("method").get<std::string>() << " | "
       << (p.at("identical_to_llvmpipe").get<bool>() ? "yes" : "no") << " | "
       << (db.is_null() ? std::string("-") : fixedDigits(db.get<double>(), 1)) << " | "
       << (flip.is_null() ? std::string("-") : fixedDigits(flip.get<double>(), 6)) << " | "
       << fixedDigits(100.0 * p.at("share_over1_vs_llvmpipe").get<double>(), 3) << "% | "
       << p.at("max_diff_vs_llvmpipe").get<double>() << " | " << p.at("nonfinite_pixels").get<uint64_t>() << " | "
       << (worst.is_null() ? std::string("-")
                           : worst.get<std::string>() + " (" +
                                 (p.at("worst_target_psnr_db").is_null() ? std::string("-")
                                                                         : fixedDigits(p.at("worst_target_psnr_db").get<double>(), 1)) +
                                 ")")
       << " | " << (p.at("fails").get<bool>() ? p.at("failure").get<std::string>() : std::string("")) << " |\n";
  }
  return md.str();
}

}  // namespace

std::vector<double> sweepValues(const SweepRange& range, bool integer) {
  std::vector<double> values;
  for (int i = 0; i < range.steps; ++i) {
    const double f = range.steps == 1 ? 0.0 : double(i) / double(range.steps - 1);
    double v = range.log ? range.from * std::pow(range.to / range.from, f) : range.from + (range.to - range.from) * f;
    char rounded[32];
    std::snprintf(rounded, sizeof rounded, "%.6g", v);
    v = std::strtod(rounded, nullptr);
    if (i == range.steps - 1) v = range.to;
    if (integer) v = std::round(v);
    if (values.empty() || values.back() != v) values.push_back(v);
  }
  return values;
}

std::string sweepFailure(uint64_t nonFinitePixels, double finalPsnrDb, double thresholdDb) {
  char text[96];
  if (nonFinitePixels > 0) {
    std::snprintf(text, sizeof text, "%llu non-finite pixels", static_cast<unsigned long long>(nonFinitePixels));
    return text;
  }
  if (finalPsnrDb < thresholdDb) {
    std::snprintf(text, sizeof text, "final %.1f dB < %g dB", finalPsnrDb, thresholdDb);
    return text;
  }
  return "";
}

ShardSpec parseShard(const std::string& text) {
  ShardSpec shard;
  if (text.empty()) return shard;
  std::vector<std::string> parts;   // K and N, when there is exactly one '/'
  const size_t slash = text.find('/');
  if (slash != std::string::npos && text.find('/', slash + 1) == std::string::npos) {
    parts.push_back(text.substr(0, slash));
    parts.push_back(text.substr(slash + 1));
  }
  // Plain decimal digits only (parseWholeNumber): strtol took ' 1/+2' as 1/2.
  const std::optional<uint64_t> parsedK = parts.size() == 2 ? parseWholeNumber(parts[0]) : std::nullopt;
  const std::optional<uint64_t> parsedN = parts.size() == 2 ? parseWholeNumber(parts[1]) : std::nullopt;
  if (!parsedK || !parsedN) throw UsageError("--shard: '" + text + "' is not K/N (e.g. 2/8)");
  const uint64_t k = *parsedK, n = *parsedN;
  if (n < 1 || n > uint64_t(kMaxSweepSteps))
    throw UsageError("--shard: N = " + parts[1] + " is out of range (1.." + std::to_string(kMaxSweepSteps) + ")");
  if (k < 1 || k > n) throw UsageError("--shard: K = " + parts[0] + " is outside 1.." + std::to_string(n));
  shard.index = int(k);
  shard.count = int(n);
  shard.sharded = true;
  return shard;
}

std::vector<size_t> shardValueIndexes(const ShardSpec& shard, size_t valueCount) {
  std::vector<size_t> indexes;
  for (size_t i = size_t(shard.index - 1); i < valueCount; i += size_t(shard.count)) indexes.push_back(i);
  return indexes;
}

// The sides of every value, in the order their points are written.
std::vector<std::string> sweepSides(const json& sweep) {
  std::vector<std::string> order = {"llvmpipe"};
  for (const json& m : sweep.at("methods")) order.push_back(m.get<std::string>());
  if (sweep.at("softpipe").get<bool>()) order.push_back("softpipe");
  return order;
}

std::vector<std::string> sweepFiles(bool shard) {
  std::vector<std::string> files = {"sweep.json", "sweep.md"};
  if (!shard) files.insert(files.end(), {"sweep.png", "sweep.svg"});
  return files;
}

// Writes sweep.json and sweep.md into `folder`, and the chart unless it is a shard.
void writeSweep(json sweep, const std::string& folder) {
  const bool shard = sweep.contains("shard");
  if (!shard) sweep["first_failure"] = firstFailures(sweep);
  fs::create_directories(folder);
  const std::string jsonPath = (fs::path(folder) / "sweep.json").string();
  compare::writeOutputFile(jsonPath, sweep.dump(2) + "\n");
  compare::writeOutputFile((fs::path(folder) / "sweep.md").string(), markdown(sweep));
  if (!shard) drawChart(kSweepChartScript, jsonPath, (fs::path(folder) / "sweep").string());
  if (sweep.contains("first_failure"))
    for (const auto& [side, value] : sweep.at("first_failure").items())
      std::cout << side << ": " << (value.is_null() ? "does not fail" : "first fails at " + sixDigits(value.get<double>()))
                << "\n";
  for (const std::string& file : sweepFiles(shard)) std::cout << "wrote " << (fs::path(folder) / file).string() << "\n";
}


}  // namespace cli
