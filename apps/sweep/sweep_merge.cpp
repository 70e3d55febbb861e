// `raster sweep-merge`: the shards of a sweep joined into the sweep.json an unsharded run
// writes, byte for byte, after checking that they belong together, are all there, and hold
// each point exactly once (sweep.h).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ios>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/common/charts.h"
#include "apps/sweep/sweep.h"
#include "apps/sweep/sweep_file.h"

namespace cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// What a field of a shard's sweep.json holds, as `raster sweep` writes it.
enum class Kind { Text, Number, Count, Flag, List, Object };

bool holds(const json& value, Kind kind) {
  switch (kind) {
    case Kind::Text: return value.is_string();
    case Kind::Number: return value.is_number();
    case Kind::Count: return value.is_number_unsigned();
    case Kind::Flag: return value.is_boolean();
    case Kind::List: return value.is_array();
    case Kind::Object: return value.is_object();
  }
  return false;
}

std::string kindName(Kind kind) {
  switch (kind) {
    case Kind::Text: return "a string";
    case Kind::Number: return "a number";
    case Kind::Count: return "a whole number, 0 or more";
    case Kind::Flag: return "true or false";
    case Kind::List: return "a list";
    case Kind::Object: return "an object";
  }
  return "";
}

// A field's JSON as the error quotes it: at most a line's worth (a field may hold a list).
std::string quoted(const json& value) {
  const std::string text = value.dump();
  return text.size() <= 40 ? text : text.substr(0, 37) + "...";
}

// The field `key` of `object`, which `where` names (the file, and the point); UsageError
// unless it is there and holds `kind` (or null, where `nullable`).
const json& field(const json& object, const std::string& key, Kind kind, const std::string& where, bool nullable = false) {
  const auto found = object.find(key);
  if (found == object.end()) throw UsageError(where + ": \"" + key + "\" is missing");
  if (!holds(*found, kind) && !(nullable && found->is_null()))
    throw UsageError(where + ": \"" + key + "\" is " + quoted(*found) + ", not " + kindName(kind) + (nullable ? " or null" : ""));
  return *found;
}

// field() for a list, each of whose items holds `kind`.
const json& listOf(const json& object, const std::string& key, Kind kind, const std::string& where) {
  const json& list = field(object, key, Kind::List, where);
  for (size_t i = 0; i < list.size(); ++i)
    if (!holds(list[i], kind))
      throw UsageError(where + ": \"" + key + "\"[" + std::to_string(i) + "] is " + quoted(list[i]) + ", not " + kindName(kind));
  return list;
}

// The header fields the merge, sweep.md and the chart read (its "points" too, as a list of
// objects), checked as `raster sweep` writes them: an edited shard is refused naming the
// field, not merged or thrown from the JSON library.
void checkShardHeader(const std::string& path, const json& shard) {
  for (const char* key : {"scene", "param", "shard"}) field(shard, key, Kind::Text, path);
  const json& range = field(shard, "range", Kind::Object, path);
  for (const char* key : {"from", "to"}) field(range, key, Kind::Number, path + ": \"range\"");
  field(range, "steps", Kind::Count, path + ": \"range\"");
  field(range, "log", Kind::Flag, path + ": \"range\"");
  if (listOf(shard, "size", Kind::Count, path).size() != 2) throw UsageError(path + ": \"size\" is not [width, height]");
  field(shard, "time", Kind::Number, path);
  field(shard, "instances", Kind::Count, path);
  listOf(shard, "sets", Kind::Text, path);
  field(shard, "threshold_db", Kind::Number, path);
  listOf(shard, "methods", Kind::Text, path);
  field(shard, "softpipe", Kind::Flag, path);
  listOf(shard, "shard_values", Kind::Count, path);
  listOf(shard, "points", Kind::Object, path);
}

// A point's fields, as scorePoint (sweep.cpp) writes them.
void checkPointFields(const std::string& where, const json& point) {
  field(point, "value", Kind::Number, where);
  field(point, "value_index", Kind::Count, where);
  field(point, "method", Kind::Text, where);
  field(point, "identical_to_llvmpipe", Kind::Flag, where);
  field(point, "psnr_vs_llvmpipe_db", Kind::Number, where, true);
  if (point.contains("flip_vs_llvmpipe")) field(point, "flip_vs_llvmpipe", Kind::Number, where, true);   // absent from sweeps before it
  field(point, "share_over1_vs_llvmpipe", Kind::Number, where);
  field(point, "max_diff_vs_llvmpipe", Kind::Number, where);
  field(point, "nonfinite_pixels", Kind::Count, where);
  field(point, "worst_target", Kind::Text, where, true);
  field(point, "worst_target_psnr_db", Kind::Number, where, true);
  field(point, "fails", Kind::Flag, where);
  field(point, "failure", Kind::Text, where);
}

}  // namespace

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
    std::error_code error;
    if (fs::exists(path, error) && !fs::is_regular_file(path, error))
      throw UsageError(path + ": not a file (is " + folder + " a sweep --shard folder?)");
    std::ifstream in(path);
    if (!in) throw UsageError(path + ": cannot be read (is " + folder + " a sweep --shard folder?)");
    json shard;
    try {
      shard = json::parse(in);
    } catch (const json::exception& e) {
      throw UsageError(path + ": not valid JSON (" + e.what() + ")");
    } catch (const std::ios_base::failure& e) {   // a read error: the parser reads the file's buffer itself
      throw UsageError(path + ": cannot be read (" + std::string(e.what()) + ")");
    }
    if (!shard.is_object() || !shard.contains("shard") || !shard.contains("points"))
      throw UsageError(path + ": not the sweep.json of a shard (no \"shard\" field)");
    checkShardHeader(path, shard);
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
    for (const json& v : shard.at("shard_values"))
      for (const std::string& side : order) expected.insert({v.get<size_t>(), side});
    for (size_t n = 0; n < shard.at("points").size(); ++n) {
      const json& p = shard.at("points")[n];
      checkPointFields(path + ": point " + std::to_string(n), p);
      if (!found.insert({p.at("value_index").get<size_t>(), p.at("method").get<std::string>()}).second)
        throw UsageError(path + ": holds value " + p.at("value").dump() + " of " + p.at("method").get<std::string>() + " twice");
      merged["points"].push_back(p);
    }
    if (found != expected)
      throw UsageError(path + ": its points are not its shard_values times the sides " +
                       "(an interrupted or edited shard; run that shard again)");
    valueCount += shard.at("shard_values").size();
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
