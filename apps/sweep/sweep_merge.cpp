// `raster sweep-merge`: the shards of a sweep joined into the sweep.json an unsharded run
// writes, byte for byte, after checking that they belong together, are all there, and hold
// each point exactly once (sweep.h).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "apps/common/charts.h"
#include "apps/sweep/sweep.h"
#include "apps/sweep/sweep_file.h"

namespace cli {

namespace fs = std::filesystem;
using nlohmann::json;

void addSweepMergeOptions(CLI::App& command, SweepMergeArgs& args) {
  command.add_option("shards", args.shards, "The shards' --out folders")->required()->type_name("DIR...");
  command.add_option("--out", args.out, "Folder for the merged sweep.json, sweep.md, sweep.png, sweep.svg")
      ->required()->type_name("DIR");
}

int runSweepMerge(const SweepMergeArgs& args) {
  // The merge writes sweep.json into --out: into a shard's folder it would replace that
  // shard's own, and the shards could not be merged again.
  for (const std::string& folder : args.shards) {
    std::error_code error;
    if (fs::equivalent(args.out, folder, error))
      throw UsageError("--out: " + args.out + " is the shard folder " + folder +
                       ", whose sweep.json the merge would replace; name another folder");
  }
  json merged;
  std::map<int, std::string> seen;   // shard index -> folder
  int count = 0;
  size_t valueCount = 0;
  for (const std::string& folder : args.shards) {
    const std::string path = (fs::path(folder) / "sweep.json").string();
    std::ifstream in(path);
    if (!in) throw UsageError(path + ": cannot be read (is " + folder + " a sweep --shard folder?)");
    json shard;
    try {
      shard = json::parse(in);
    } catch (const json::exception& e) {
      throw UsageError(path + ": not valid JSON (" + e.what() + ")");
    }
    if (!shard.is_object() || !shard.contains("shard") || !shard.contains("points"))
      throw UsageError(path + ": not the sweep.json of a shard (no \"shard\" field)");
    ShardSpec spec;
    try {
      spec = parseShard(shard.at("shard").get<std::string>());
    } catch (const std::exception&) {
      throw UsageError(path + ": its \"shard\" field is not K/N");
    }
    json header = shard;
    for (const char* key : {"shard", "shard_values", "points"}) header.erase(key);
    if (merged.is_null()) {
      merged = header;
      merged["points"] = json::array();
      count = spec.count;
    } else {
      json common = merged;
      common.erase("points");
      for (const auto& [key, value] : common.items())
        if (!header.contains(key) || header.at(key) != value)
          throw UsageError(path + ": a shard of a different sweep (its \"" + key + "\" is " +
                           (header.contains(key) ? header.at(key).dump() : std::string("missing")) + ", not " +
                           value.dump() + ")");
      if (header.size() != common.size()) throw UsageError(path + ": a shard of a different sweep (other fields)");
      if (spec.count != count)
        throw UsageError(path + ": shard of " + std::to_string(spec.count) + ", the others are of " + std::to_string(count));
    }
    if (seen.count(spec.index))
      throw UsageError(path + ": shard " + std::to_string(spec.index) + "/" + std::to_string(count) + " is also in " +
                       seen.at(spec.index));
    seen[spec.index] = folder;
    // Its points are exactly its values times the sides: none lost, none extra.
    const std::vector<std::string> order = sweepSides(merged);
    std::set<std::pair<size_t, std::string>> expected, found;
    for (const json& v : shard.value("shard_values", json::array()))
      for (const std::string& side : order) expected.insert({v.get<size_t>(), side});
    for (const json& p : shard.at("points")) {
      if (!found.insert({p.at("value_index").get<size_t>(), p.at("method").get<std::string>()}).second)
        throw UsageError(path + ": holds value " + p.at("value").dump() + " of " + p.at("method").get<std::string>() + " twice");
      merged["points"].push_back(p);
    }
    if (found != expected)
      throw UsageError(path + ": its points are not its shard_values times the sides " +
                       "(an interrupted or edited shard; run that shard again)");
    valueCount += shard.value("shard_values", json::array()).size();
  }
  std::string missing;
  for (int k = 1; k <= count; ++k)
    if (!seen.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(count);
  if (!missing.empty()) throw UsageError("shards missing: " + missing);

  // The unsharded order: value by value, each value's sides in the run's order.
  const std::vector<std::string> order = sweepSides(merged);
  auto rank = [&](const json& p) {
    const auto at = std::find(order.begin(), order.end(), p.at("method").get<std::string>());
    return std::make_pair(p.at("value_index").get<size_t>(), size_t(at - order.begin()));
  };
  std::vector<json> points = merged.at("points").get<std::vector<json>>();
  std::stable_sort(points.begin(), points.end(), [&](const json& a, const json& b) { return rank(a) < rank(b); });
  for (size_t i = 1; i < points.size(); ++i)
    if (rank(points[i]) == rank(points[i - 1]))
      throw UsageError("the shards hold value " + points[i].at("value").dump() + " of " +
                       points[i].at("method").get<std::string>() + " twice");
  for (size_t i = 0; i < points.size(); ++i)
    if (rank(points[i]).first >= valueCount)
      throw UsageError("the shards' values are not 0.." + std::to_string(valueCount) + " (value index " +
                       std::to_string(rank(points[i]).first) + ")");
  merged["points"] = points;
  checkOutputFolder("--out", args.out);
  checkChartTools(kSweepChartScript);
  writeSweep(std::move(merged), args.out);
  return 0;
}

}  // namespace cli
