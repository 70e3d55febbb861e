// Scene parameters (`raster params`, --set), `raster sweep` and `raster sweep-merge`.
//
// What a user depends on: a --set reaches the scene (and an unset one leaves the seed's
// bytes), every bad parameter, range or shard is refused before anything is written, a
// sweep's JSON holds the fields with flags that agree with its numbers, and shards
// merged in any order give the unsharded run's sweep.json byte for byte.
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "scenes/registry.h"
#include "tests/apps/cli_test_helpers.h"

namespace {

using namespace cli_test;
using nlohmann::json;

}  // namespace

TEST_SUITE("sweep") {
  // Every row of the registry; world_offset too, which every scene offers so that its sweep
  // reaches coordinates far from the origin (STABILITY.md).
  TEST_CASE("params: every scene lists time and size; --json holds the same names") {
    TempFolder temp;
    for (const std::string& scene : scenes::sceneNames()) {
      const RunResult text = runCli(temp.path, std::string("params ") + scene);
      REQUIRE(text.status == 0);
      const RunResult asJson = runCli(temp.path, std::string("params ") + scene + " --json");
      REQUIRE(asJson.status == 0);
      std::set<std::string> names;
      for (const json& p : json::parse(asJson.out)) {
        names.insert(p["name"].get<std::string>());
        CHECK(text.out.find(p["name"].get<std::string>()) != std::string::npos);
        CHECK(p["min"].get<double>() <= p["max"].get<double>());
      }
      CHECK(names.count("time") == 1);
      CHECK(names.count("size") == 1);
      CHECK(names.count("world_offset") == 1);
    }
    expectRefused("params no_such_scene", "known scenes");
  }

  TEST_CASE("--set reaches the scene; unset parameters keep the seed's bytes; size=WxH is --size") {
    TempFolder temp;
    REQUIRE(runCli(temp.path, "render shadow --size 80x60 --out plain.png").status == 0);
    REQUIRE(runCli(temp.path, "render shadow --set size=80x60 --out set.png").status == 0);
    REQUIRE(runCli(temp.path, "render shadow --size 80x60 --set light_elevation=10 --out low.png").status == 0);
    REQUIRE(runCli(temp.path, "render shadow --size 80x60 --set offset_scale=1 --out same.png").status == 0);
    REQUIRE(runCli(temp.path, "render hdr --size 80x60 --out hdr.png").status == 0);
    REQUIRE(runCli(temp.path, "render hdr --size 80x60 --set intensity=50 --out bright.png").status == 0);
    CHECK(readText(temp.path / "plain.png") == readText(temp.path / "set.png"));
    CHECK(readText(temp.path / "plain.png") != readText(temp.path / "low.png"));
    // offset_scale=1 multiplies the seed's offsets by one: the same frame.
    CHECK(readText(temp.path / "plain.png") == readText(temp.path / "same.png"));
    CHECK(readText(temp.path / "hdr.png") != readText(temp.path / "bright.png"));
  }

  TEST_CASE("bad --set values are refused, naming the scene's parameters or the range") {
    expectRefused("render shadow --set no_such=1", "light_elevation");
    expectRefused("render hdr --set light_elevation=10", "intensity");   // not an hdr parameter
    expectRefused("render shadow --set near=0", "out of range");
    expectRefused("render shadow --set near", "NAME=VALUE");
    expectRefused("render hdr --set instances=2.5", "whole number");
    expectRefused("render shadow --set size=0x5", "size");
    expectRefused("render shadow --set time=nan", "finite");
    expectRefused("render shadow --set near=0.1 --set near=0.2", "near is given twice");
    expectRefused("render shadow --method shading=2x2,shading=1x1", "shading is given twice");
  }

  TEST_CASE("sweep: bad ranges, method lists and shards are refused before anything is written") {
    expectRefused("sweep shadow --param no_such=1:2:3 --out s", "offset_scale");
    expectRefused("sweep shadow --param near=1:2 --out s", "NAME=FROM:TO:STEPS");
    expectRefused("sweep shadow --param near=0.1:0.01:0 --out s", "STEPS");
    expectRefused("sweep shadow --param near=0.1:0.01:3:cubic --out s", "log");
    expectRefused("sweep shadow --param world_offset=-1:10:3:log --out s", "log range");
    expectRefused("sweep shadow --param near=0.1:20:3 --out s", "out of range");
    expectRefused("sweep shadow --param near=0.1:0.01:3 --shard 0/2 --out s", "K = 0");
    expectRefused("sweep shadow --param near=0.1:0.01:3 --shard 3/2 --out s", "outside 1..2");
    expectRefused("sweep shadow --param near=0.1:0.01:3 --shard 1 --out s", "K/N");
    // Plain digits, as every other number: strtol had taken ' 1/+2' as 1/2 and '+3' steps.
    expectRefused("sweep shadow --param near=0.1:0.01:3 --shard '1/+2' --out s", "K/N");
    expectRefused("sweep shadow --param near=0.1:0.01:3 --shard ' 1/2' --out s", "K/N");
    expectRefused("sweep shadow --param near=0.1:0.01:+3 --out s", "STEPS '+3'");
    expectRefused("sweep shadow --param near=0.1:0.01:3 --methods gl,nope --out s", "nope");
    expectRefused("sweep shadow --param near=0.1:0.01:3 --methods gl,llvmpipe --out s", "driver");
    expectRefused("sweep shadow --param near=0.1:0.01:3 --set near=1 --out s", "swept");
    expectRefused("sweep shadow --param near=0.1:0.01:3 --out /nonexistent/dir/s", "--out");
    expectRefused("sweep-merge missing_a missing_b --out m", "missing_a");
  }

  TEST_CASE("sweep: the JSON's fields, flags that agree with the numbers, and the failure threshold") {
    TempFolder temp;
    // A threshold no image can reach: every side not identical to llvmpipe fails.
    const RunResult run = runCli(temp.path, "sweep hdr --param intensity=1:1e6:3:log --size 64x48 --methods gl,half=rne "
                                            "--threshold 1000 --out s --quiet");
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    for (const char* file : {"sweep.json", "sweep.md", "sweep.png", "sweep.svg"}) CHECK(fs::file_size(temp.path / "s" / file) > 100);
    const json sweep = json::parse(readText(temp.path / "s" / "sweep.json"));
    CHECK(sweep["scene"] == "hdr");
    CHECK(sweep["param"] == "intensity");
    CHECK(sweep["size"] == json::array({64, 48}));
    CHECK(sweep["methods"] == json::array({"gl", "half=rne"}));
    REQUIRE(sweep["points"].size() == 3 * 4);   // llvmpipe, gl, half=rne, softpipe at each value
    std::set<double> values;
    for (const json& p : sweep["points"]) {
      values.insert(p["value"].get<double>());
      CHECK(p["identical_to_llvmpipe"].get<bool>() == p["psnr_vs_llvmpipe_db"].is_null());
      // The final image's FLIP beside its PSNR (hdr's final target is RGBA8): 0 when identical.
      REQUIRE(p["flip_vs_llvmpipe"].is_number());
      if (p["identical_to_llvmpipe"].get<bool>()) CHECK(p["flip_vs_llvmpipe"].get<double>() == 0.0);
      CHECK(p["flip_vs_llvmpipe"].get<double>() <= 1.0);
      const bool fails = p["fails"].get<bool>();
      CHECK(fails == !p["failure"].get<std::string>().empty());
      if (p["method"] == "llvmpipe" || p["method"] == "gl") CHECK(p["identical_to_llvmpipe"].get<bool>());
      if (!p["identical_to_llvmpipe"].get<bool>()) CHECK(fails);   // below 1000 dB
      if (p["nonfinite_pixels"].get<uint64_t>() > 0) CHECK(fails);
    }
    CHECK(values == std::set<double>{1, 1000, 1e6});
    // At 1e6 the scene's colours pass the largest half (65504). llvmpipe converts to half
    // toward zero, which saturates there; round-to-nearest-even overflows to infinity.
    uint64_t llvmpipeNonFinite = 1, rneNonFinite = 0;
    for (const json& p : sweep["points"]) {
      if (p["value"] != 1e6) continue;
      if (p["method"] == "llvmpipe") llvmpipeNonFinite = p["nonfinite_pixels"].get<uint64_t>();
      if (p["method"] == "half=rne") rneNonFinite = p["nonfinite_pixels"].get<uint64_t>();
    }
    CHECK(llvmpipeNonFinite == 0);
    CHECK(rneNonFinite > 0);
    CHECK(sweep["first_failure"]["llvmpipe"].is_null());
    CHECK(sweep["first_failure"]["gl"].is_null());
    CHECK(readText(temp.path / "s" / "sweep.svg").find("<svg") != std::string::npos);
    CHECK(readText(temp.path / "s" / "sweep.md").find("| FLIP |") != std::string::npos);
    // The chart's Python as apps/common/charts.cpp picks it: $RASTER_PYTHON, else /usr/bin/python3.
    const std::string python = "${RASTER_PYTHON:-$(test -x /usr/bin/python3 && echo /usr/bin/python3 || echo python3)} ";
    const std::string script = shellQuote(std::string(RASTER_SOURCE_DIR) + "/bench/sweep_chart.py");
    const RunResult chart = runShell(temp.path, python + script + " s/sweep.json --out flipchart --metric flip");
    CAPTURE(chart.err);
    CHECK(chart.status == 0);
    CHECK(readText(temp.path / "flipchart.svg").find("mean FLIP") != std::string::npos);
  }

  TEST_CASE("sweep.md's header names the base size and time only where the sweep does not move them, and every --set") {
    TempFolder temp;
    const std::string common = " --methods gl --no-softpipe --threads 1 --quiet";
    // (--size or --time beside a sweep of it is refused: hostile_cli_test.cpp.)
    REQUIRE(runCli(temp.path, "sweep shadow --param size=4:8:2 --time 2" + common + " --out size").status == 0);
    REQUIRE(runCli(temp.path, "sweep shadow --param time=0:1:2 --size 8x6" + common + " --out time").status == 0);
    REQUIRE(runCli(temp.path, "sweep shadow --param near=0.1:0.2:2 --size 8x6 --time 2 --set light_elevation=20 "
                              "--set offset_scale=2" + common + " --out near").status == 0);
    const std::string size = readText(temp.path / "size" / "sweep.md");
    const std::string time = readText(temp.path / "time" / "sweep.md");
    const std::string near = readText(temp.path / "near" / "sweep.md");
    CHECK(size.find("in 2 steps, each width at 4:3, t=2. ") != std::string::npos);
    CHECK(size.find("640x480") == std::string::npos);   // the default --size, not rendered at
    CHECK(time.find("in 2 steps, 8x6, each value's time. ") != std::string::npos);
    CHECK(near.find("in 2 steps, 8x6, t=2, with `--set light_elevation=20 --set offset_scale=2`. ") != std::string::npos);
    CHECK(size.find("--set") == std::string::npos);   // none given
  }

  TEST_CASE("sweep-merge: shards in any order equal the unsharded sweep.json; missing, doubled or foreign shards refused") {
    TempFolder temp;
    const std::string sweep = "sweep shadow --param light_elevation=10:70:5 --size 48x36 --methods gl --no-softpipe --quiet";
    REQUIRE(runCli(temp.path, sweep + " --out whole").status == 0);
    for (int k = 1; k <= 3; ++k)
      REQUIRE(runCli(temp.path, sweep + " --shard " + std::to_string(k) + "/3 --out part" + std::to_string(k)).status == 0);
    // A shard holds only its own values, and no chart or first_failure.
    const json part2 = json::parse(readText(temp.path / "part2" / "sweep.json"));
    CHECK(part2["shard"] == "2/3");
    CHECK(part2["shard_values"] == json::array({1, 4}));
    CHECK(!part2.contains("first_failure"));
    CHECK(!fs::exists(temp.path / "part2" / "sweep.png"));

    const RunResult merged = runCli(temp.path, "sweep-merge part3 part1 part2 --out merged");
    CAPTURE(merged.err);
    REQUIRE(merged.status == 0);
    CHECK(readText(temp.path / "merged" / "sweep.json") == readText(temp.path / "whole" / "sweep.json"));

    RunResult refused = runCli(temp.path, "sweep-merge part1 part2 --out m2");
    CHECK(refused.status == 2);
    CHECK(refused.err.find("3/3") != std::string::npos);
    refused = runCli(temp.path, "sweep-merge part1 part1 part2 part3 --out m2");
    CHECK(refused.status == 2);
    CHECK(refused.err.find("also in") != std::string::npos);
    // Merged into a shard's own folder, the shard's sweep.json would be lost.
    const std::string part2Before = readText(temp.path / "part2" / "sweep.json");
    refused = runCli(temp.path, "sweep-merge part1 part2 part3 --out ./part2/");
    CHECK(refused.status == 2);
    CHECK(refused.err.find("is the shard folder part2") != std::string::npos);
    CHECK(readText(temp.path / "part2" / "sweep.json") == part2Before);
    REQUIRE(runCli(temp.path, "sweep shadow --param light_elevation=10:70:5 --size 48x36 --methods gl,fast --no-softpipe "
                              "--quiet --shard 3/3 --out other").status == 0);
    refused = runCli(temp.path, "sweep-merge part1 part2 other --out m2");
    CHECK(refused.status == 2);
    CHECK(refused.err.find("\"methods\"") != std::string::npos);
    {   // a later shard with a header field the first lacks (the check is not one-sided)
      json extra = json::parse(readText(temp.path / "part2" / "sweep.json"));
      extra["note"] = "from another build";
      fs::create_directories(temp.path / "extra");
      std::ofstream(temp.path / "extra" / "sweep.json") << extra.dump(2);
      refused = runCli(temp.path, "sweep-merge part1 extra part3 --out m2");
      CHECK(refused.status == 2);
      CHECK(refused.err.find("extra/sweep.json: a shard of a different sweep (other fields)") != std::string::npos);
    }
    // A shard that lost a point (an interrupted or edited file) is named, not merged.
    json cut = json::parse(readText(temp.path / "part1" / "sweep.json"));
    cut["points"].erase(cut["points"].size() - 1);
    {
      std::ofstream out(temp.path / "part1" / "sweep.json");
      out << cut.dump(2);
    }
    refused = runCli(temp.path, "sweep-merge part1 part2 part3 --out m2");
    CHECK(refused.status == 2);
    CHECK(refused.err.find("part1") != std::string::npos);
    CHECK(!fs::exists(temp.path / "m2"));
  }

  // Its --out folder is made with its first file: a run that fails before writing leaves none.
  TEST_CASE("sweep: a run that fails as it renders leaves no --out folder") {
    // 1 MiB passes the checks (16x12 frames) but not the scene's 1024x1024 shadow map (4 MiB).
    expectRefused("sweep shadow --param time=1:2:2 --size 16x12 --methods gl --no-softpipe --max-memory 1M --quiet --out s",
                  "memory:");
  }

  // Everything a run would refuse before its first render, --check refuses too: it renders
  // nothing, so a cluster runner trusts its exit status before sending the run out.
  TEST_CASE("sweep --check refuses a value the scene refuses, a missing asset and a cap below the frames") {
    const std::string small = " --size 16x12 --methods gl --no-softpipe --check --out s";
    // pbr's cascade splits must rise: 5:20:3 reaches 12.5, above cascade_split2's 10.
    expectRefused("sweep pbr --param cascade_split1=5:20:3" + small, "cascade_split1=12.5");
    expectRefused("sweep pbr --param cascade_split2=20:1:3" + small, "cascade_split2=1:");
    TempFolder temp;
    fs::create_directory(temp.path / "noassets");
    expectRefused("sweep deferred --param time=1:2:2 --assets " + shellQuote((temp.path / "noassets").string()) + small,
                  "concrete_cat_statue.obj: no such file (the folder");   // the loader's own words
    expectRefused("sweep shadow --param time=1:2:2 --max-memory 1K" + small, "--max-memory");
    const RunResult valid = runCli(temp.path, "sweep pbr --param cascade_split1=0.5:9:3" + small);
    CAPTURE(valid.err);
    CHECK(valid.status == 0);
    CHECK(!fs::exists(temp.path / "s"));
  }

  // A shard's sweep.json is read back from disk, where anyone may have edited it: each field
  // the merge and sweep.md read is checked against what `raster sweep` writes, and a wrong
  // one is refused naming the file and the field, never merged or thrown from the JSON
  // library.
  TEST_CASE("sweep-merge: a shard's wrong types, values outside its range and flags its numbers contradict are refused") {
    TempFolder temp;
    REQUIRE(runCli(temp.path, "sweep shadow --param light_elevation=10:70:3 --size 16x12 --methods gl --no-softpipe "
                              "--set near=0.2 --quiet --shard 1/1 --out shard").status == 0);
    const json shard = json::parse(readText(temp.path / "shard" / "sweep.json"));
    REQUIRE(shard["points"].size() == 3 * 2);
    CHECK(shard["points"][3]["value"] == 40.0);   // the second value's llvmpipe row

    const RunResult merged = runCli(temp.path, "sweep-merge shard --out merged");
    CAPTURE(merged.err);
    REQUIRE(merged.status == 0);

    const auto expectEditRefused = [&](const std::function<void(json&)>& edit, const std::string& mentions) {
      json edited = shard;
      edit(edited);
      fs::create_directories(temp.path / "edited");
      {
        std::ofstream out(temp.path / "edited" / "sweep.json");
        out << edited.dump(2);
      }
      const RunResult refused = runCli(temp.path, "sweep-merge edited --out m");
      INFO("mentions " << mentions << "\nstderr: " << refused.err);
      CHECK(refused.status == 2);
      CHECK(refused.err.rfind("raster: edited/sweep.json: ", 0) == 0);
      CHECK(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
      CHECK(refused.err.find(mentions) != std::string::npos);
      CHECK(!fs::exists(temp.path / "m"));
    };
    // Types.
    expectEditRefused([](json& s) { s["points"] = "x"; }, "\"points\"");
    expectEditRefused([](json& s) { s["points"][0]["value_index"] = "a"; }, "\"value_index\"");
    expectEditRefused([](json& s) { s["points"][1]["psnr_vs_llvmpipe_db"] = "abc"; }, "\"psnr_vs_llvmpipe_db\"");
    expectEditRefused([](json& s) { s["points"][0]["fails"] = "yes"; }, "\"fails\"");
    expectEditRefused([](json& s) { s["points"][0] = json::object(); }, "point 0");
    expectEditRefused([](json& s) { s["range"]["steps"] = -3; }, "\"steps\"");
    expectEditRefused([](json& s) { s["softpipe"] = "no"; }, "\"softpipe\"");
    expectEditRefused([](json& s) { s["points"][1]["nonfinite_pixels"] = -1; }, "\"nonfinite_pixels\"");   // a count
    // Values against the shard's own header.
    expectEditRefused([](json& s) { s["points"][3]["value"] = 1000; }, "\"value\"");
    expectEditRefused([](json& s) {
      s["points"][2]["value_index"] = 7;
      s["points"][3]["value_index"] = 7;
    }, "\"value_index\"");
    expectEditRefused([](json& s) {
      s["points"][1]["identical_to_llvmpipe"] = false;
      s["points"][1]["psnr_vs_llvmpipe_db"] = -5;
    }, "\"fails\"");
    expectEditRefused([](json& s) { s["shard_values"] = json::array({0, 1, 2, 3}); }, "\"shard_values\"");
    expectEditRefused([](json& s) { s["points"][1]["max_diff_vs_llvmpipe"] = -0.5; }, "\"max_diff_vs_llvmpipe\" is -0.5, below 0");
    expectEditRefused([](json& s) { s["points"][1]["share_over1_vs_llvmpipe"] = -0.25; }, "\"share_over1_vs_llvmpipe\" is -0.25, below 0");

    // Points that fail, by PSNR and by non-finite pixels, agree with their flags: the shards
    // of a failing sweep merge (that shards merge byte for byte into the unsharded sweep.json
    // is the merge case above).
    const std::string failing = "sweep hdr --param intensity=1:1e6:3:log --size 16x12 --methods gl,half=rne --no-softpipe "
                                "--threshold 65 --quiet";
    REQUIRE(runCli(temp.path, failing + " --shard 1/2 --out half1").status == 0);
    REQUIRE(runCli(temp.path, failing + " --shard 2/2 --out half2").status == 0);
    const RunResult failingMerged = runCli(temp.path, "sweep-merge half2 half1 --out failing");
    CAPTURE(failingMerged.err);
    REQUIRE(failingMerged.status == 0);
    const std::string failed = readText(temp.path / "failing" / "sweep.json");
    CHECK(failed.find(" dB < 65 dB") != std::string::npos);
    CHECK(failed.find("non-finite pixels") != std::string::npos);

    // A folder where the shard's sweep.json should be.
    fs::remove(temp.path / "edited" / "sweep.json");
    fs::create_directory(temp.path / "edited" / "sweep.json");
    const RunResult folder = runCli(temp.path, "sweep-merge edited --out m");
    CAPTURE(folder.err);
    CHECK(folder.status == 2);
    CHECK(folder.err.find("edited/sweep.json") != std::string::npos);
    CHECK(!fs::exists(temp.path / "m"));
  }
}
