// The scene registry (scenes/registry.h): every row is whole and true of the files it
// names; a bad row is refused with a clear error; and a new row is all it takes for
// `raster scenes`, the commands, the bench/ runners and the suites that cover every scene
// to take a scene (tests/registry/extra_scene_main.cpp adds `shadow-again`, the shadow
// scene under a second name, to the command line).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "backends/backend.h"
#include "scenes/program_registry.h"
#include "scenes/registry.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/scene_test_helpers.h"

namespace {

namespace fs = std::filesystem;
using cli_test::RunResult;
using cli_test::shellQuote;

const char* const kExtra = "shadow-again";

fs::path sourceRoot() {
  const char* root = std::getenv("RASTER_SOURCE_DIR");
  return root && *root ? fs::path(root) : fs::path(RASTER_SOURCE_DIR);
}

// Runs a shell command line in a temporary folder; $EXTRA is the command line with the
// extra row, $ROOT the source tree.
RunResult runWithExtraScene(const fs::path& cwd, const std::string& script) {
  return cli_test::runShell(cwd, "EXTRA=" + shellQuote(RASTER_EXTRA_SCENE_CLI_PATH) + "; ROOT=" +
                                     shellQuote(sourceRoot().string()) + "; " + script);
}

bool hasParam(const scenes::SceneEntry& row, const std::string& name) {
  return std::any_of(row.params.begin(), row.params.end(), [&](const scenes::ParamSpec& p) { return p.name == name; });
}

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// doctest's closing line: "[doctest] assertions: N | N passed | 0 failed |".
long assertionsRun(const std::string& output) {
  std::smatch m;
  const std::regex line(R"(assertions:\s*(\d+) \|)");
  return std::regex_search(output, m, line) ? std::stol(m[1]) : -1;
}

}  // namespace

TEST_SUITE("registry") {
  TEST_CASE("every row is whole: parameters, programs with their GLSL, assets, sweeps of its own parameters") {
    REQUIRE(!scenes::sceneRegistry().empty());
    for (const scenes::SceneEntry& row : scenes::sceneRegistry()) {
      INFO("scene " << row.name);
      CHECK(!row.description.empty());
      CHECK(fs::exists(sourceRoot() / ".." / "shared" / "seeds" / row.seed) == fs::exists(sourceRoot() / ".." / "shared"));
      CHECK(hasParam(row, "time"));
      CHECK(hasParam(row, "size"));
      REQUIRE(!row.programs.empty());
      for (const scenes::ProgramEntry& program : row.programs) {
        INFO("program " << program.name);
        const scenes::ProgramFiles files = scenes::programFiles(program.name);
        CHECK(fs::exists(files.vertex));
        CHECK(fs::exists(files.fragment));
        CHECK(!program.uniforms.empty());
        CHECK(scenes::makeBoundProgram(program.name) != nullptr);
      }
      for (const std::string& asset : row.assets) CHECK(fs::exists(sourceRoot() / "assets" / asset));
      for (const auto* sweeps : {&row.sweeps, &row.coarseSweeps})
        for (const std::string& sweep : *sweeps) {
          INFO("sweep " << sweep);
          CHECK(hasParam(row, sweep.substr(0, sweep.find('='))));
        }
      for (const std::string& sweep : row.coarseSweeps) CHECK(sweep.find(" --methods ") != std::string::npos);
      CHECK(scenes::makeScene(row.name, {}) != nullptr);
    }
  }

  TEST_CASE("a bad row or an unknown name is refused with the names it could have been") {
    CHECK(errorOf([] { scenes::sceneEntry("nope"); }).find("unknown scene 'nope' (known scenes: ") == 0);
    scenes::SceneEntry copy = scenes::sceneRegistry().front();
    CHECK(errorOf([&] { scenes::registerScene(copy); }).find("is registered already") != std::string::npos);
    copy.name = "Bad Name";
    CHECK(errorOf([&] { scenes::registerScene(copy); }).find("is not lower-case letters") != std::string::npos);
    copy.name = "no-time";
    copy.params.erase(copy.params.begin());
    CHECK(errorOf([&] { scenes::registerScene(copy); }).find("time and size") != std::string::npos);
    copy.make = nullptr;
    CHECK(errorOf([&] { scenes::registerScene(copy); }).find("has no factory") != std::string::npos);
    CHECK(errorOf([] { scenes::makeBoundProgram("nope/nope"); }) == "no C++ port of shader program nope/nope");
  }

  TEST_CASE("raster scenes lists the registry; --json has every row's columns") {
    cli_test::TempFolder temp;
    const RunResult plain = runWithExtraScene(temp.path, "$EXTRA scenes");
    REQUIRE(plain.status == 0);
    std::string expected;
    for (const std::string& name : scenes::sceneNames()) expected += name + "\n";
    CHECK(plain.out == expected + kExtra + "\n");
    const RunResult json = runWithExtraScene(temp.path, "$EXTRA scenes --json");
    REQUIRE(json.status == 0);
    const nlohmann::json rows = nlohmann::json::parse(json.out);
    REQUIRE(rows.size() == scenes::sceneRegistry().size() + 1);
    for (const auto& row : rows)
      for (const char* column : {"name", "description", "seed", "params", "programs", "assets", "sweeps", "coarse_sweeps"})
        CHECK(row.contains(column));
    CHECK(rows.back()["name"] == kExtra);
    CHECK(rows.back()["programs"] == rows.front()["programs"]);
  }

  TEST_CASE("a new row renders, compares bit-identical to llvmpipe, and takes its parameters") {
    cli_test::TempFolder temp;
    const RunResult compare = runWithExtraScene(temp.path, std::string("$EXTRA compare ") + kExtra + " --size 40x30 --out c");
    INFO(compare.out << compare.err);
    REQUIRE(compare.status == 0);
    const std::regex target(R"(\n(\S+)\s+\S+\s+\d+x\d+\s+max (\d+))");
    int targets = 0;
    for (auto it = std::sregex_iterator(compare.out.begin(), compare.out.end(), target); it != std::sregex_iterator(); ++it) {
      CHECK((*it)[2] == "0");
      ++targets;
    }
    CHECK(targets >= 2);
    CHECK(runWithExtraScene(temp.path, std::string("$EXTRA params ") + kExtra).status == 0);
    CHECK(runWithExtraScene(temp.path, std::string("$EXTRA render ") + kExtra + " --size 16x12 --set near=0.5 --out r.png").status == 0);
    CHECK(runWithExtraScene(temp.path, std::string("$EXTRA render ") + kExtra + " --set nope=1 --out r.png").status == 2);
  }

  TEST_CASE("the bench runners and the stability sweeps take every row") {
    cli_test::TempFolder temp;
    const RunResult goals = runWithExtraScene(temp.path, "/usr/bin/python3 $ROOT/bench/goal_runs.py --raster $EXTRA --dry-run");
    INFO(goals.out << goals.err);
    CHECK(goals.status == 0);
    CHECK(goals.out.find(std::string("bench ") + kExtra + " ") != std::string::npos);
    const RunResult bench = runWithExtraScene(temp.path, "/usr/bin/python3 $ROOT/bench/run_benchmarks.py --raster $EXTRA --dry-run");
    INFO(bench.out << bench.err);
    CHECK(bench.status == 0);
    CHECK(bench.out.find(std::string("bench ") + kExtra + " ") != std::string::npos);
    // paper_bounds.py runs it too (and lists it as having no bound until its passes are counted).
    const RunResult bounds = runWithExtraScene(temp.path, "/usr/bin/python3 $ROOT/bench/paper_bounds.py --raster $EXTRA --dry-run");
    INFO(bounds.out << bounds.err);
    CHECK(bounds.status == 0);
    CHECK(bounds.out.find(std::string("bench ") + kExtra + " ") != std::string::npos);
    const RunResult sweeps = runWithExtraScene(temp.path, "bash $ROOT/bench/stability_sweeps.sh --dry-run $EXTRA");
    INFO(sweeps.out << sweeps.err);
    CHECK(sweeps.status == 0);
    CHECK(sweeps.out.find(std::string("sweep ") + kExtra + " ") != std::string::npos);
  }

  // The suites that cover every scene, run on the new row alone: they pass, and they ran
  // assertions for it; without the row, the same run fails on the unknown name.
  TEST_CASE("the suites that cover every scene take a new row") {
    cli_test::TempFolder temp;
    const std::string suites =
        " --test-suite=determinism,determinism_paths,views,trace --test-case='every scene*,tracing changes no byte*,*every scene*' --no-intro";
    const std::string self = shellQuote(fs::read_symlink("/proc/self/exe").string());
    const RunResult with = cli_test::runShell(temp.path, std::string("RASTER_TEST_SCENE_ALIAS=") + kExtra + "=shadow RASTER_TEST_SCENES=" +
                                                             kExtra + " " + self + suites);
    INFO(with.out << with.err);
    CHECK(with.status == 0);
    CHECK(assertionsRun(with.out) > 0);
    const RunResult without = cli_test::runShell(temp.path, std::string("RASTER_TEST_SCENES=") + kExtra + " " + self + suites);
    CHECK(without.status != 0);
    CHECK(without.out.find("unknown scene '" + std::string(kExtra) + "'") != std::string::npos);
  }
}
