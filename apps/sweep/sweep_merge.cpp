// `raster sweep-merge`: the shards of a sweep joined into the sweep.json an unsharded run
// writes, byte for byte, after checking that they belong together, are all there, and hold
// each point exactly once, each field as `raster sweep` writes it: a value the range gives,
// flags its numbers give (sweep.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
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
#include "scenes/scene.h"
#include "scenes/scene_params.h"

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

// A field's JSON as the error quotes it: at most a line's worth (a field may hold a list),
// non-ASCII escaped so that the cut falls between characters.
std::string quoted(const json& value) {
  const std::string text = value.dump(-1, ' ', true);
  return text.size() <= 40 ? text : text.substr(0, 37) + "...";
}

// The field `key` of `object`, which `where` names (the file, and the point); UsageError
// unless it is there and holds `kind` (or null, where `nullable`).
const json& field(const json& object, const std::string& key, Kind kind, const std::string& where, bool nullable = false) {
  const auto found = object.find(key);
  if (found == object.end()) throw UsageError(where + ": \"" + key + "\" is missing");
  if (!holds(*found, kind) && !(nullable && found->is_null()))
    throw UsageError(where + ": \"" + key + "\" is " + quoted(*found) + ", not " + kindName(kind) +
                     (nullable ? " or null" : ""));
  return *found;
}

// field() for a list, each of whose items holds `kind`.
const json& listOf(const json& object, const std::string& key, Kind kind, const std::string& where) {
  const json& list = field(object, key, Kind::List, where);
  for (size_t i = 0; i < list.size(); ++i)
    if (!holds(list[i], kind))
      throw UsageError(where + ": \"" + key + "\"[" + std::to_string(i) + "] is " + quoted(list[i]) + ", not " +
                       kindName(kind));
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

// The values of a shard's range (its header checked), as `raster sweep` computes them: the
// values its points and shard_values must hold.
std::vector<double> shardRangeValues(const std::string& path, const json& shard) {
  const json& r = shard.at("range");
  SweepRange range;
  range.name = shard.at("param").get<std::string>();
  range.from = r.at("from").get<double>();
  range.to = r.at("to").get<double>();
  range.log = r.at("log").get<bool>();
  const uint64_t steps = r.at("steps").get<uint64_t>();
  if (steps < 1 || steps > uint64_t(kMaxSweepSteps))
    throw UsageError(path + ": \"range\": \"steps\" is " + std::to_string(steps) + ", not 1.." +
                     std::to_string(kMaxSweepSteps));
  range.steps = int(steps);
  if (range.log && (range.from <= 0 || range.to <= 0))
    throw UsageError(path + ": \"range\" is log, but its \"from\" or \"to\" is not above 0");
  bool integer = false;
  try {
    integer = scenes::findParam(shard.at("scene").get<std::string>(), range.name).integer;
  } catch (const scenes::ParamError& e) {
    throw UsageError(path + ": " + e.what());
  } catch (const scenes::SceneError& e) {
    throw UsageError(path + ": " + e.what());
  }
  return sweepValues(range, integer);
}

// A point's fields, as scorePoint (sweep.cpp) writes them.
void checkPointFields(const std::string& where, const json& point) {
  field(point, "value", Kind::Number, where);
  field(point, "value_index", Kind::Count, where);
  field(point, "method", Kind::Text, where);
  field(point, "identical_to_llvmpipe", Kind::Flag, where);
  field(point, "psnr_vs_llvmpipe_db", Kind::Number, where, true);
  if (point.contains("flip_vs_llvmpipe"))   // absent from sweeps before it
    field(point, "flip_vs_llvmpipe", Kind::Number, where, true);
  field(point, "share_over1_vs_llvmpipe", Kind::Number, where);
  field(point, "max_diff_vs_llvmpipe", Kind::Number, where);
  field(point, "nonfinite_pixels", Kind::Count, where);
  field(point, "worst_target", Kind::Text, where, true);
  field(point, "worst_target_psnr_db", Kind::Number, where, true);
  field(point, "fails", Kind::Flag, where);
  field(point, "failure", Kind::Text, where);
}

// A point against its shard's header: its value is the one its index has in the range, its
// numbers are not negative, and "fails" and "failure" are what its numbers give
// (sweepFailure), so a point edited, or copied from another sweep, is refused, not merged.
void checkPointValues(const std::string& where, const json& point, const std::vector<double>& values, double thresholdDb) {
  const uint64_t index = point.at("value_index").get<uint64_t>();
  if (index >= values.size())
    throw UsageError(where + ": \"value_index\" is " + std::to_string(index) + ", outside 0.." +
                     std::to_string(values.size() - 1) + " (its range's " + std::to_string(values.size()) + " values)");
  if (point.at("value").get<double>() != values[index])
    throw UsageError(where + ": \"value\" is " + quoted(point.at("value")) + ", not " + json(values[index]).dump() +
                     ", the value at index " + std::to_string(index) + " of its range");
  for (const char* key : {"share_over1_vs_llvmpipe", "max_diff_vs_llvmpipe"})
    if (point.at(key).get<double>() < 0)
      throw UsageError(where + ": \"" + key + "\" is " + quoted(point.at(key)) + ", below 0");
  // null is +inf, identical final images: a sweep's final images are RGBA8, whose PSNR is never NaN or -inf.
  const json& psnr = point.at("psnr_vs_llvmpipe_db");
  const double psnrDb = psnr.is_null() ? HUGE_VAL : psnr.get<double>();
  const std::string failure = sweepFailure(point.at("nonfinite_pixels").get<uint64_t>(), psnrDb, thresholdDb);
  const bool fails = point.at("fails").get<bool>();
  if (fails == failure.empty())
    throw UsageError(where + ": \"fails\" is " + (fails ? "true" : "false") + ", but its numbers say " +
                     (failure.empty() ? std::string("it passes") : "it fails (" + failure + ")"));
  if (point.at("failure") != failure)
    throw UsageError(where + ": \"failure\" is " + quoted(point.at("failure")) + ", but its numbers say " +
                     json(failure).dump());
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
    // Its shard_values are its shard's values of the range, and its points exactly those
    // values times the sides: none lost, none extra.
    const std::vector<double> values = shardRangeValues(path, shard);
    const std::vector<size_t> own = shardValueIndexes(spec, values.size());
    if (shard.at("shard_values") != json(own))
      throw UsageError(path + ": \"shard_values\" is " + quoted(shard.at("shard_values")) + ", not " + quoted(json(own)) +
                       ", the values of shard " + shard.at("shard").get<std::string>() + " of its range's " +
                       std::to_string(values.size()));
    const std::vector<std::string> order = sweepSides(merged);
    std::set<std::pair<size_t, std::string>> expected, found;
    for (size_t v : own)
      for (const std::string& side : order) expected.insert({v, side});
    for (size_t n = 0; n < shard.at("points").size(); ++n) {
      const json& p = shard.at("points")[n];
      const std::string where = path + ": point " + std::to_string(n);
      checkPointFields(where, p);
      checkPointValues(where + " (" + p.at("method").get<std::string>() + ")", p, values,
                       shard.at("threshold_db").get<double>());
      if (!found.insert({p.at("value_index").get<size_t>(), p.at("method").get<std::string>()}).second)
        throw UsageError(path + ": holds value " + p.at("value").dump() + " of " + p.at("method").get<std::string>() + " twice");
      merged["points"].push_back(p);
    }
    if (found != expected)
      throw UsageError(path + ": its points are not its shard_values times the sides " +
                       "(an interrupted or edited shard; run that shard again)");
  }
  std::string missing;
  for (int k = 1; k <= count; ++k)
    if (!seen.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(count);
  if (!missing.empty()) throw UsageError("shards missing: " + missing);

  // The unsharded order: value by value, each value's sides in the run's order. Each point
  // is there once: each shard holds exactly its own values' points, and each shard is there
  // once, with the same range.
  const std::vector<std::string> order = sweepSides(merged);
  auto rank = [&](const json& p) {
    const auto at = std::find(order.begin(), order.end(), p.at("method").get<std::string>());
    return std::make_pair(p.at("value_index").get<size_t>(), size_t(at - order.begin()));
  };
  std::vector<json> points = merged.at("points").get<std::vector<json>>();
  std::stable_sort(points.begin(), points.end(), [&](const json& a, const json& b) { return rank(a) < rank(b); });
  merged["points"] = points;
  checkOutputFolder("--out", args.out, sweepFiles(/*shard=*/false));
  checkChartTools(kSweepChartScript);
  writeSweep(std::move(merged), args.out);
  return 0;
}

}  // namespace cli
