// `raster report` on the command line: what it writes, how it replaces an earlier report,
// and the bad input it refuses before rendering (the browser test is report_chromium_test.py).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/views/stage_views.h"
#include "io/image_io.h"
#include "tests/apps/cli_test_helpers.h"

namespace {

using namespace cli_test;

// The names in `folder` that start with a dot: a temporary folder left behind.
int hiddenEntries(const fs::path& folder) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(folder)) n += entry.path().filename().string()[0] == '.';
  return n;
}

}  // namespace

TEST_SUITE("report") {

TEST_CASE("report: bad input exits 2 with one line before anything renders") {
  expectRefused("report nosuch --out r", "unknown scene 'nosuch'");
  expectRefused("report shadow all nosuch --out r", "nosuch");
  expectRefused("report shadow --pixels 17 --out r", "--pixels");
  expectRefused("report shadow --include no_such_folder --out r", "no_such_folder");
  expectRefused("report shadow --size 0x5 --out r", "--size");
  expectRefused("report shadow --out no/such/folder", "no/such");
  expectRefused("report shadow --out .", "--out");

  TempFolder temp;
  fs::create_directory(temp.path / "mine");
  { std::ofstream(temp.path / "mine" / "notes.txt") << "keep me"; }
  fs::create_directory(temp.path / "real");
  fs::create_directory_symlink(temp.path / "real", temp.path / "link");
  { std::ofstream(temp.path / "file") << "x"; }
  // Another tool's report.json (a common name), even beside an index.html, is no earlier
  // report of this command: the folder is not replaced.
  for (const char* other : {"", "{}", "{\"made_by\": \"pytest-json-report\"}"}) {
    fs::create_directory(temp.path / "theirs");
    { std::ofstream(temp.path / "theirs" / "report.json") << other; }
    { std::ofstream(temp.path / "theirs" / "index.html") << "<p>theirs</p>"; }
    { std::ofstream(temp.path / "theirs" / "notes.txt") << "keep me"; }
    const RunResult result = runCli(temp.path, "report shadow --size 16x12 --quiet --out theirs");
    INFO("report.json holding '" << other << "': " << result.err);
    CHECK(result.status == 2);
    CHECK(result.err.find("holds no earlier report") != std::string::npos);
    CHECK(readText(temp.path / "theirs" / "notes.txt") == "keep me");
    fs::remove_all(temp.path / "theirs");
  }
  for (const char* out : {"mine", "link", "file"}) {
    const RunResult result = runCli(temp.path, std::string("report shadow --size 16x12 --quiet --out ") + out);
    INFO("--out " << out << ": " << result.err);
    CHECK(result.status == 2);
    CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
  }
  CHECK(readText(temp.path / "mine" / "notes.txt") == "keep me");
  CHECK(fs::is_empty(temp.path / "real"));
  CHECK(readText(temp.path / "file") == "x");
  CHECK(hiddenEntries(temp.path) == 0);

  // A result under --include that is not one: refused naming its file, before the scenes
  // render (a 1920x1080 report of every scene would take minutes before reaching it).
  const std::pair<const char*, const char*> bad[] = {{"tradeoff.json", "{\"points\": ["},
                                                     {"sweep.json", "[1, 2]"},
                                                     {"tradeoff.json", "{\"scene\": \"shadow\"}"}};
  for (const auto& [name, text] : bad) {
    TempFolder results;
    fs::create_directories(results.path / "inc" / "one");
    { std::ofstream(results.path / "inc" / "one" / name) << text; }
    const RunResult result =
        runCli(results.path, "report all --size 1920x1080 --include inc --no-default-include --quiet --out r");
    INFO(name << " holding " << text << ": " << result.err);
    CHECK(result.status == 2);
    CHECK(result.err.find("--include: inc/one/" + std::string(name)) != std::string::npos);
    CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
    CHECK(!fs::exists(results.path / "r"));
    CHECK(hiddenEntries(results.path) == 0);
  }
}

// What --include's search cannot read holds no result: passed over, as a folder it may not
// enter is. (A link that loops had made the status call throw: exit 1 with a bare
// "filesystem error".)
TEST_CASE("report: an entry under --include whose status cannot be read is passed over") {
  TempFolder temp;
  fs::create_directories(temp.path / "inc" / "one");
  fs::create_symlink("sweep.json", temp.path / "inc" / "one" / "sweep.json");   // loops
  const RunResult result =
      runCli(temp.path, "report shadow --size 16x12 --pixels 0 --include inc --no-default-include --quiet --out r");
  REQUIRE_MESSAGE(result.status == 0, result.err);
  CHECK(readText(temp.path / "r" / "index.html").find("No tradeoff.json or sweep.json") != std::string::npos);
}

TEST_CASE("report: every target's images and metrics; a second run replaces the first whole") {
  TempFolder temp;
  const std::string command = "report shadow --size 32x24 --pixels 1 --threads 2 --no-default-include --quiet --out r";
  RunResult result = runCli(temp.path, command);
  REQUIRE_MESSAGE(result.status == 0, result.err);
  const fs::path out = temp.path / "r";
  std::ifstream in(out / "report.json");
  const nlohmann::json record = nlohmann::json::parse(in);
  REQUIRE(record.at("scenes").size() == 1);
  const std::string page = readText(out / "index.html");
  for (const auto& target : record.at("scenes")[0].at("targets")) {
    const std::string name = target.at("name");
    for (const char* side : {"_ours.png", "_gl.png", "_diff.png"}) CHECK(fs::is_regular_file(out / "shadow" / (name + side)));
    if (target.at("kind") != "rgba8") CHECK(fs::is_regular_file(out / "shadow" / (name + "_ours.exr")));
    CHECK(page.find("id=\"metrics-shadow-" + name + "\"") != std::string::npos);
  }
  // Every stage view of the registry, in its order, with its image.
  const nlohmann::json& views = record.at("scenes")[0].at("views");
  REQUIRE(views.size() == cli::stageViews().size());
  for (size_t i = 0; i < views.size(); ++i) {
    CHECK(views[i].at("view") == cli::stageViews()[i].name);
    CHECK(fs::is_regular_file(out / views[i].at("image").get<std::string>()));
    CHECK(page.find("<h4>" + std::string(cli::stageViews()[i].name) + "</h4>") != std::string::npos);
  }
  // Traces: either shown, or a note says why not.
  CHECK((page.find("this build has no `raster trace`") != std::string::npos || page.find("class=\"trace\"") != std::string::npos));
  CHECK(page.find("No tradeoff.json or sweep.json") != std::string::npos);

  { std::ofstream(out / "stale.txt") << "from the first run"; }
  result = runCli(temp.path, command);
  REQUIRE_MESSAGE(result.status == 0, result.err);
  CHECK(fs::is_regular_file(out / "index.html"));
  CHECK(!fs::exists(out / "stale.txt"));
  CHECK(hiddenEntries(temp.path) == 0);
  CHECK(hiddenEntries(out) == 0);
}

TEST_CASE("report: RGBA8 previews are opaque, and each has its alpha beside it as grey") {
  TempFolder temp;
  RunResult result = runCli(temp.path, "report deferred --size 32x24 --pixels 0 --threads 2 --no-default-include --quiet --out r");
  REQUIRE_MESSAGE(result.status == 0, result.err);
  // The same frame's targets as stored (an RGBA8 dump is the target's bytes, alpha included).
  result = runCli(temp.path, "render deferred --size 32x24 --threads 2 --quiet --out final.png --dump stored");
  REQUIRE_MESSAGE(result.status == 0, result.err);
  const fs::path out = temp.path / "r" / "deferred";
  std::ifstream in(temp.path / "r" / "report.json");
  const nlohmann::json record = nlohmann::json::parse(in);
  const std::string page = readText(temp.path / "r" / "index.html");
  int rgba8Targets = 0;
  bool alphaIsData = false;   // some stored alpha is not 255 (the G-buffer's specular intensity)
  for (const auto& target : record.at("scenes")[0].at("targets")) {
    const std::string name = target.at("name");
    INFO(name);
    if (target.at("kind") != "rgba8") {
      CHECK(!fs::exists(out / (name + "_ours_alpha.png")));
      continue;
    }
    ++rgba8Targets;
    const scenes::ImageData stored = compare::readPng((temp.path / "stored" / (name + ".png")).string());
    for (const char* side : {"ours", "gl"}) {
      INFO(side);
      const scenes::ImageData colour = compare::readPng((out / (name + "_" + side + ".png")).string());
      const scenes::ImageData alpha = compare::readPng((out / (name + "_" + side + "_alpha.png")).string());
      REQUIRE(colour.rgba8.size() == stored.rgba8.size());
      REQUIRE(alpha.rgba8.size() == stored.rgba8.size());
      size_t seeThrough = 0, colourChanged = 0, alphaWrong = 0;
      for (size_t i = 0; i < stored.rgba8.size(); i += 4) {
        seeThrough += colour.rgba8[i + 3] != 255 || alpha.rgba8[i + 3] != 255;
        if (std::string(side) == "ours") {   // GL's side may differ from ours; its own bytes are not dumped here
          for (size_t c = 0; c < 3; ++c) colourChanged += colour.rgba8[i + c] != stored.rgba8[i + c];
          for (size_t c = 0; c < 3; ++c) alphaWrong += alpha.rgba8[i + c] != stored.rgba8[i + 3];
        }
        alphaIsData |= stored.rgba8[i + 3] != 255;
      }
      CHECK(seeThrough == 0);
      CHECK(colourChanged == 0);
      CHECK(alphaWrong == 0);
      CHECK(page.find("deferred/" + name + "_" + side + "_alpha.png") != std::string::npos);
    }
  }
  CHECK(rgba8Targets >= 2);
  CHECK(alphaIsData);
}

}  // TEST_SUITE
