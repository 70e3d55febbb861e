// The `raster` program's command line and the comparison machinery behind it.
//
// Bad input must fail fast and cleanly: exit status 2, one "raster: ..." line on stderr, and
// no file written. These run the built executable (RASTER_CLI_PATH) in an empty temporary
// folder and look at what it leaves. The units the comparison reports (8-bit steps, depth
// LSBs, half and float ULPs) are pinned by tests/compare/metrics_test.cpp.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "io/image_io.h"
#include "io/target_dump.h"
#include "compare/metrics.h"
#include "raster/methods.h"
#include "scenes/registry.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/compare/test_images.h"
#include "tests/scene_test_helpers.h"

namespace {

using namespace cli_test;
using scenes::ImageData;
using test_images::rgba8Image;

std::string aScene() { return scenes::sceneNames().front(); }

}  // namespace

TEST_SUITE("cli") {
  TEST_CASE("--help at every level exits 0 and names the commands") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult top = runCli(cwd, "--help");
    CHECK(top.status == 0);
    CHECK(top.out.find("render") != std::string::npos);
    CHECK(top.out.find("compare") != std::string::npos);
    CHECK(runCli(cwd, "render --help").status == 0);
    CHECK(runCli(cwd, "compare --help").status == 0);
    CHECK(runCli(cwd, "bench --help").status == 0);
    // One line per registry row, in its order: a new scene's row needs no edit here.
    std::string listed;
    for (const std::string& name : scenes::sceneNames()) listed += name + "\n";
    CHECK(runCli(cwd, "scenes").out == listed);
    CHECK(listed.rfind("shadow\ndeferred\nhdr\n", 0) == 0);   // the first three, as shipped
    CHECK(fs::is_empty(cwd));
  }

  TEST_CASE("the commands are the table's: the help lists each with its line, each has its own help") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult top = runCli(cwd, "--help");
    REQUIRE(top.status == 0);
    std::string names;
    for (const cli::Command& command : cli::commands()) {
      INFO(command.name);
      CHECK(top.out.find(std::string(command.name) + " ") != std::string::npos);
      CHECK(top.out.find(command.help) != std::string::npos);
      const RunResult own = runCli(cwd, std::string(command.name) + " --help");
      CHECK(own.status == 0);
      CHECK(own.out.rfind(command.help, 0) == 0);   // CLI11 starts a subcommand's help with its line
      names += (names.empty() ? "" : ", ") + std::string(command.name);
    }
    CHECK(top.out.find("(" + names + ")") != std::string::npos);   // the footer
    // An unknown command is bad input that names the commands.
    expectRefused("nosuch", "'nosuch' is not a command (commands: " + names + ")");
    expectRefused("rendr shadow", "commands: render, ");
    CHECK(fs::is_empty(cwd));
  }

  TEST_CASE("an unknown scene is refused, naming the known ones") {
    expectRefused("render no_such_scene");
    expectRefused("compare no_such_scene");
  }

  TEST_CASE("bad sizes, times, threads and backends are refused") {
    for (const char* size : {"0x0", "100000x100000", "640", "16385x10", "ax480", "640x-1"})
      expectRefused("render " + aScene() + " --size=" + size);
    expectRefused("render " + aScene() + " --size=10x16385", "10x16385 is out of range (each side 1..16384)");   // the height too
    {   // and the ends of the ranges are in them: --threads 1024, as the help says
      TempFolder edge;
      const RunResult r = runCli(edge.path, "render shadow --size 16x12 --threads 1024 --quiet --out t.png");
      INFO(r.err);
      CHECK(r.status == 0);
    }
    for (const char* time : {"nan", "inf", "-1", "abc"})
      expectRefused("render " + aScene() + " --time=" + time);
    for (const char* threads : {"-1", "1025", "two"})
      expectRefused("render " + aScene() + " --threads=" + threads);
    expectRefused("render " + aScene() + " --backend foo");
    expectRefused("compare " + aScene() + " --reference foo");
    expectRefused("compare " + aScene() + " --test foo");
    expectRefused("compare " + aScene() + " --max-rmse nan");
    for (const char* instances : {"0", "-5", "200001", "many"})
      expectRefused("render hdr --instances=" + std::string(instances));
    expectRefused("bench " + aScene() + " --frames 0");
    expectRefused("bench " + aScene() + " --gl-driver nouveau");
    expectRefused("bench " + aScene() + " --size 0x0");
    expectRefused("bench " + aScene() + " --json /nonexistent/dir/results.json");
  }

  TEST_CASE("bench --passes times every pass of both backends, on screen and in the JSON") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult run = runCli(cwd, "bench hdr --size 64x48 --frames 2 --warmup 0 --passes --json passes.json");
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    CHECK(run.out.find("per pass") != std::string::npos);
    for (const char* program : {"hdr/scene", "hdr/post+bright", "hdr/post+down", "hdr/post+up", "hdr/post+composite"})
      CHECK(run.out.find(program) != std::string::npos);
    const nlohmann::json json = nlohmann::json::parse(readText(cwd / "passes.json"));
    REQUIRE(json["passes"].size() >= 5);
    CHECK(json["passes"][0]["program"] == "hdr/scene");
    for (const nlohmann::json& pass : json["passes"]) {
      CHECK(pass["raster_ms"].get<double>() >= 0);
      CHECK(pass["llvmpipe_ms"].get<double>() >= 0);
    }
    CHECK(json["backends"][0]["frames_ms"].size() == 2);
    CHECK(json["ratio"].get<double>() > 0);
  }

  TEST_CASE("methods: listed one a line; unknown presets, steps and methods refused with the valid names") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult list = runCli(cwd, "methods");
    REQUIRE(list.status == 0);
    for (const char* line : {"math=llvmpipe (default)", "math=libm", "math=fast", "math=fast-fragment", "filter=8bit (default)", "filter=float",
                             "half=rtz (default)", "half=rne", "div=exact (default)", "div=approx",
                             "interp=perspective (default)", "interp=affine", "compare=bilinear (default)", "compare=nearest",
                             "shading=1x1 (default)", "shading=2x2", "shading=2x2-all",
                             "shading=2x2-local", "shading=2x2-offscreen", "shading=2x2-smooth", "lookup=linear (default)", "lookup=nearest",
                             "  gl  math=llvmpipe", "  precise ", "  fast ", "  draft ", "    promise: llvmpipe's bytes"})
      CHECK(list.out.find(line) != std::string::npos);
    // --json: the same registry as one object (bench/goal_runs.py takes its presets from it).
    const RunResult listed = runCli(cwd, "methods --json");
    REQUIRE(listed.status == 0);
    const nlohmann::json methods = nlohmann::json::parse(listed.out);
    REQUIRE(methods["steps"].size() == raster::methodCatalog().size());
    for (size_t i = 0; i < raster::methodCatalog().size(); ++i) {
      const raster::StepInfo& step = raster::methodCatalog()[i];
      CHECK(methods["steps"][i]["name"] == step.name);
      REQUIRE(methods["steps"][i]["methods"].size() == step.methods.size());
      CHECK(methods["steps"][i]["methods"][0]["default"] == true);
      CHECK(methods["steps"][i]["methods"].back()["name"] == step.methods.back().name);
    }
    REQUIRE(methods["presets"].size() == raster::presetNames().size());
    for (size_t i = 0; i < raster::presetNames().size(); ++i) {
      const std::string& preset = raster::presetNames()[i];
      CHECK(methods["presets"][i]["name"] == preset);
      CHECK(methods["presets"][i]["promise"] == raster::presetPromise(preset));
      for (const auto& [step, method] : raster::methodNames(raster::presetMethods(preset)))
        CHECK(methods["presets"][i]["methods"][step] == method);
    }
    for (const char* command : {"render", "compare", "bench"}) {
      expectRefused(std::string(command) + " " + aScene() + " --preset turbo");
      expectRefused(std::string(command) + " " + aScene() + " --method math=slow");
      expectRefused(std::string(command) + " " + aScene() + " --method blend=fast");
      expectRefused(std::string(command) + " " + aScene() + " --method math");
    }
    // A shading rate that is not one: refused with the rates.
    expectRefused("render " + aScene() + " --method shading=3x3",
                  "(methods: 1x1, 2x1, 1x2, 2x2, 4x4, 2x2-all, 2x2-local, 2x2-offscreen, 4x4-offscreen, 2x2-smooth)");
    // A lookup that is not one, and a preset that is not one: refused with the names.
    expectRefused("render " + aScene() + " --method lookup=cubic", "(methods: linear, nearest)");
    expectRefused("bench " + aScene() + " --preset drafty", "(presets: gl, precise, fast, draft)");
    const RunResult bad = runCli(cwd, "render " + aScene() + " --method math=slow");
    CHECK(bad.err.find("llvmpipe, libm, fast") != std::string::npos);
    // GL has its own numerics: asking it for ours is refused rather than ignored.
    expectRefused("render " + aScene() + " --backend gl --preset fast");
    expectRefused("compare " + aScene() + " --test softpipe --method math=fast");
    // Nor does GL have our SIMD paths to turn off.
    expectRefused("render " + aScene() + " --backend gl --scalar", "--scalar");
    expectRefused("compare " + aScene() + " --test softpipe --scalar", "--scalar");
  }

  TEST_CASE("render --preset and --method change this pipeline's image; gl is the default's bytes") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    REQUIRE(runCli(cwd, "render deferred --size 96x64 --out default.png").status == 0);
    REQUIRE(runCli(cwd, "render deferred --size 96x64 --preset gl --out gl.png").status == 0);
    REQUIRE(runCli(cwd, "render deferred --size 96x64 --method math=libm --out libm.png").status == 0);
    CHECK(readText(cwd / "default.png") == readText(cwd / "gl.png"));
    CHECK(readText(cwd / "default.png") != readText(cwd / "libm.png"));
  }

  // Scripts read compare.json, not the lines (bench/random_frames.py among them): it must say
  // what the lines and the exit status say, target by target. `draft` leaves the shadow
  // scene's final image off llvmpipe's, so a threshold fails and the run exits 1.
  TEST_CASE("compare writes compare.json: each printed target's numbers, the thresholds exceeded, the pixel to trace") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult run =
        runCli(cwd, "compare shadow --size 64x48 --preset draft --max-rmse 0 --max-depth-lsb 0 --exact --quiet --out cmp");
    REQUIRE(run.status == 1);
    const nlohmann::json json = nlohmann::json::parse(readText(cwd / "cmp" / "compare.json"));
    CHECK(json.at("scene") == "shadow");
    CHECK(json.at("size") == nlohmann::json::array({64, 48}));
    CHECK(json.at("methods") == "draft");
    CHECK(json.at("test") == "raster");
    CHECK(json.at("reference") == "llvmpipe");
    // One entry a target's line, in order, with the line's name, kind and "max".
    std::vector<std::string> lines;
    for (size_t start = 0, end; (end = run.out.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string line = run.out.substr(start, end - start);
      if (line.rfind("test:", 0) != 0 && line.rfind("images:", 0) != 0 && line.find(" differs most at (") == std::string::npos)
        lines.push_back(line);
    }
    const nlohmann::json& targets = json.at("targets");
    REQUIRE(targets.size() == lines.size());
    REQUIRE(targets.size() == 3);   // the map, the window's depth, the final image
    bool finalDiffers = false;
    for (size_t i = 0; i < targets.size(); ++i) {
      const nlohmann::json& t = targets[i];
      CAPTURE(lines[i]);
      CHECK(lines[i].rfind(t.at("name").get<std::string>() + " ", 0) == 0);
      CHECK(lines[i].find(" " + t.at("kind").get<std::string>() + " ") != std::string::npos);
      std::ostringstream max;
      max << " max " << t.at("max_in_unit").get<uint64_t>() << (t.at("kind") == "depth" ? " lsb" : " ");
      CHECK(lines[i].find(max.str()) != std::string::npos);
      if (t.at("name") == "final") finalDiffers = t.at("max_in_unit").get<uint64_t>() > 0;
    }
    CHECK(finalDiffers);
    // The failures are the lines on stderr, without the program's prefix.
    std::string failures;
    for (const nlohmann::json& failure : json.at("failures")) failures += "raster: " + failure.get<std::string>() + "\n";
    CHECK(failures == run.err);
    // --max-rmse and --exact fail on the final image; the two depth targets match.
    CHECK(json.at("failures").size() == 2);
    CHECK(run.err.find("raster: final: rmse ") != std::string::npos);
    CHECK(run.err.find("% of its pixels differ (by up to " + std::to_string(targets.back().at("max_in_unit").get<uint64_t>()) +
                       " 8-bit steps), under --exact\n") != std::string::npos);

    // The final image's worst pixel, and a `raster trace` of it that runs: its history.
    const nlohmann::json& worst = json.at("worst_pixel");
    REQUIRE(worst.is_object());
    CHECK(worst.at("target") == "final");
    CHECK(worst.at("difference").get<uint64_t>() == targets.back().at("max_in_unit").get<uint64_t>());
    const std::string at = std::to_string(worst.at("x").get<int>()) + "," + std::to_string(worst.at("y").get<int>());
    CHECK(run.out.find("final differs most at (" + at + ")") != std::string::npos);
    std::string trace;
    for (const nlohmann::json& word : worst.at("trace")) trace += (trace.empty() ? "" : " ") + word.get<std::string>();
    CHECK(run.out.find("its history: " + trace + "\n") != std::string::npos);
    REQUIRE(trace.rfind("raster trace shadow --pixel " + at + " ", 0) == 0);
    const RunResult traced = runCli(cwd, trace.substr(std::string("raster ").size()) + " --no-reference --quiet");
    CHECK(traced.status == 0);
    CHECK(traced.out.find("pixel (" + std::to_string(worst.at("x").get<int>()) + ", ") != std::string::npos);
    CHECK(traced.out.find("math=fast-fragment") != std::string::npos);   // draft's methods, as compared

    // A compare.json that could not be written is refused before the renders, not after them.
    fs::create_directories(cwd / "taken" / "compare.json");
    const RunResult taken = runCli(cwd, "compare shadow --size 32x24 --quiet --out taken");
    CHECK(taken.status == 2);
    CHECK(taken.err == "raster: --out: cannot write taken/compare.json: it is a folder, not a regular file\n");
    CHECK(!fs::exists(cwd / "taken" / "final_ours.png"));
    // A target's image name taken: known only once the targets are, and still refused before
    // any file is written, so the folder holds what it held.
    fs::create_directories(cwd / "taken2" / "final_gl.png");
    const RunResult taken2 = runCli(cwd, "compare shadow --size 32x24 --quiet --out taken2");
    CHECK(taken2.status == 2);
    CHECK(taken2.err == "raster: --out: cannot write taken2/final_gl.png: it is a folder, not a regular file\n");
    CHECK(std::distance(fs::directory_iterator(cwd / "taken2"), fs::directory_iterator()) == 1);

    // A frame that matches names no pixel, and passes --exact.
    const RunResult same = runCli(cwd, "compare shadow --size 32x24 --exact --quiet --out same");
    REQUIRE(same.status == 0);
    CHECK(nlohmann::json::parse(readText(cwd / "same" / "compare.json")).at("worst_pixel").is_null());
    CHECK(same.out.find("differs most") == std::string::npos);
  }

  // The program as built, every target of every scene against llvmpipe. The pipeline's own
  // suites (scene_*, determinism) check the same bytes inside raster_tests, whose sources
  // compile at -O1 in an optimized build (CMakeLists.txt): a header's inline function that a
  // test source instantiates too may be linked from that copy there. This case runs the
  // `raster` of the build, every function at the build's level, as ./demo.sh does.
  // 97x61: odd sizes, partial tiles at the right and bottom; two threads.
  TEST_CASE("compare --exact: the built program renders every target of every scene as llvmpipe does") {
    TempFolder temp;
    for (const std::string& scene : scenes::sceneNames()) {
      CAPTURE(scene);
      const RunResult run = runCli(temp.path, "compare " + scene + " --size 97x61 --threads 2 --exact --quiet --out " + scene);
      CHECK(run.status == 0);
      const nlohmann::json json = nlohmann::json::parse(readText(temp.path / scene / "compare.json"));
      CHECK(json.at("failures").empty());
      CHECK(json.at("targets").size() >= 2);
      for (const nlohmann::json& target : json.at("targets")) {
        CAPTURE(target.at("name"));
        CHECK(target.at("max_in_unit") == 0);
        CHECK(target.at("share_differing") == 0.0);
      }
    }
  }

  TEST_CASE("tradeoff: refused before rendering without --out or with an unwritable one; else every file, complete") {
    expectRefused("tradeoff " + aScene());
    expectRefused("tradeoff " + aScene() + " --out /nonexistent/dir/t");
    expectRefused("tradeoff no_such_scene --out t");
    expectRefused("tradeoff " + aScene() + " --out t --frames 0");
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult run = runCli(cwd, "tradeoff hdr --size 64x48 --set time=2 --frames 2 --warmup 0 --softpipe-frames 1 --quiet --out t");
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    CHECK(run.err.empty());   // --quiet: the softpipe child's progress too
    // tradeoff.md says how to make it again, the --set time among the options.
    CHECK(readText(cwd / "t" / "tradeoff.md").find("Made by `raster tradeoff hdr --size 64x48 --time 2 --instances 1000 --threads ") !=
          std::string::npos);
    CHECK(readText(cwd / "t" / "tradeoff.md").find("--frames 2 --warmup 0 --softpipe-frames 1`") != std::string::npos);
    for (const char* file : {"tradeoff.json", "tradeoff.md", "tradeoff.png", "tradeoff.svg"})
      CHECK(fs::file_size(cwd / "t" / file) > 100);
    const nlohmann::json result = nlohmann::json::parse(readText(cwd / "t" / "tradeoff.json"));
    CHECK(result["scene"] == "hdr");
    CHECK(result["size"] == nlohmann::json::array({64, 48}));
    CHECK(result["time"] == 2.0);
    CHECK(result["sets"] == nlohmann::json::array({"time=2"}));
    std::set<std::string> names;
    for (const nlohmann::json& p : result["points"]) {
      names.insert(p["name"].get<std::string>());
      CHECK(p["median_ms"].get<double>() > 0);
      // The identical flag and the PSNR agree: null exactly when identical.
      CHECK(p["identical_to_llvmpipe"].get<bool>() == p["psnr_vs_llvmpipe_db"].is_null());
      // FLIP beside the PSNR: 0 exactly when identical, else a visible-difference error in (0, 1].
      REQUIRE(p["flip_vs_llvmpipe"].is_number());
      if (p["identical_to_llvmpipe"].get<bool>()) CHECK(p["flip_vs_llvmpipe"].get<double>() == 0.0);
      else CHECK((p["flip_vs_llvmpipe"].get<double>() > 0.0 && p["flip_vs_llvmpipe"].get<double>() <= 1.0));
      CHECK(p["flip_vs_precise"].is_number());
      if (p["kind"] == "driver") CHECK(p["methods"].is_null());
      else CHECK(p["methods"].size() == raster::methodCatalog().size());
    }
    for (const char* name : {"gl", "precise", "fast", "math=libm", "math=fast", "math=fast-fragment", "filter=float", "half=rne", "div=approx",
                             "interp=affine", "compare=nearest", "llvmpipe", "softpipe"})
      CHECK(names.count(name) == 1);
    for (const nlohmann::json& p : result["points"]) {
      if (p["name"] == "gl") CHECK(p["identical_to_llvmpipe"].get<bool>());
      if (p["name"] == "llvmpipe") CHECK(p["speedup_vs_llvmpipe"].get<double>() == 1.0);
    }
    CHECK(readText(cwd / "t" / "tradeoff.md").find("| gl | preset |") != std::string::npos);
    CHECK(readText(cwd / "t" / "tradeoff.md").find("FLIP vs llvmpipe") != std::string::npos);
    CHECK(readText(cwd / "t" / "tradeoff.svg").find("<svg") != std::string::npos);
    // The chart plots FLIP on the accuracy axis when asked.
    // The chart's Python as apps/common/charts.cpp picks it: $RASTER_PYTHON, else /usr/bin/python3.
    const std::string python = "${RASTER_PYTHON:-$(test -x /usr/bin/python3 && echo /usr/bin/python3 || echo python3)} ";
    const std::string script = shellQuote(std::string(RASTER_SOURCE_DIR) + "/bench/tradeoff_chart.py");
    const RunResult chart = runShell(cwd, python + script + " t/tradeoff.json --out flipchart --metric flip");
    CAPTURE(chart.err);
    CHECK(chart.status == 0);
    CHECK(readText(cwd / "flipchart.svg").find("mean FLIP") != std::string::npos);
  }

  TEST_CASE("an --out that cannot be written is refused before rendering") {
    expectRefused("render " + aScene() + " --out /nonexistent/dir/x.png");
    CHECK_FALSE(fs::exists("/nonexistent/dir/x.png"));
    expectRefused("render " + aScene() + " --dump /nonexistent/dir/dump");
    expectRefused("compare " + aScene() + " --out /nonexistent/dir/cmp");
  }

  // To root, access(W_OK) says yes of /proc, which takes no new files: the check tries a
  // file there, so the run is refused before its work, not failed after it with exit 1.
  TEST_CASE("a folder that takes no files, even from root, is refused before the work") {
    expectRefused("render " + aScene() + " --out /proc/x.png", "--out");
    expectRefused("render " + aScene() + " --dump /proc/dump", "--dump");
    expectRefused("compare " + aScene() + " --out /proc/cmp", "--out");
    expectRefused("bench " + aScene() + " --frames 1 --json /proc/b.json", "--json");
    expectRefused("render " + aScene() + " --out /proc/self/x.png", "--out");
    // A file where a folder is asked for says so.
    expectRefused("render " + aScene() + " --dump /etc/passwd", "/etc/passwd is a file, not a folder");
    expectRefused("compare " + aScene() + " --out /etc/passwd", "/etc/passwd is a file, not a folder");
  }

  TEST_CASE("render writes PNG only under a .png name") {
    expectRefused("render " + aScene() + " --out x.jpg", "ending in .png");
    expectRefused("render " + aScene() + " --out x", "ending in .png");
    expectRefused("render " + aScene() + " --view overdraw --out x.jpeg", "ending in .png");
    TempFolder temp;
    REQUIRE(runCli(temp.path, "render " + aScene() + " --size 8x6 --quiet --out X.PNG").status == 0);
    CHECK(fs::file_size(temp.path / "X.PNG") > 0);
  }

  TEST_CASE("render --dump: a PNG per target, and OpenEXR files for depth and float ones that exrheader reads") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult result = runCli(cwd, "render hdr --size 48x32 --dump dump --out final.png");
    INFO("stderr: " << result.err);
    REQUIRE(result.status == 0);
    // hdr: the RGBA16F scene and bloom targets, a 16-bit depth buffer, the RGBA8 window.
    const std::string manifest = readText(cwd / "dump" / "targets.txt");
    CHECK(manifest.find("hdr_scene half\n") != std::string::npos);
    CHECK(manifest.find("hdr_depth depth16\n") != std::string::npos);
    CHECK(manifest.find("final rgba8\n") != std::string::npos);
    CHECK(fs::exists(cwd / "dump" / "final.png"));
    CHECK_FALSE(fs::exists(cwd / "dump" / "final.exr"));
    for (const char* name : {"hdr_scene", "hdr_depth", "bloom_up_0"}) {
      CHECK(fs::exists(cwd / "dump" / (std::string(name) + ".png")));
      CHECK(result.out.find("wrote dump/" + std::string(name) + ".exr\n") != std::string::npos);
    }

    if (std::system("command -v exrheader > /dev/null 2>&1") != 0) {
      MESSAGE("exrheader is not installed (Debian package openexr, in setup.sh): its checks are skipped");
      return;
    }
    const auto header = [&](const std::string& name) {
      const RunResult r = runShell(cwd, "exrheader dump/" + name + ".exr");
      INFO("exrheader " << name << ": " << r.err);
      CHECK(r.status == 0);
      return r.out;
    };
    const std::string half = header("hdr_scene");
    CHECK(half.find("zip, multi-scanline blocks") != std::string::npos);
    for (const char* channel : {"R", "G", "B", "A"})
      CHECK(half.find(std::string(channel) + ", 16-bit floating-point") != std::string::npos);
    const std::string depth = header("hdr_depth");
    CHECK(depth.find("Z, 32-bit floating-point") != std::string::npos);
    CHECK(depth.find("depthBits (type int): 16") != std::string::npos);
    CHECK(depth.find("dataWindow (type box2i): (0 0) - (47 31)") != std::string::npos);
  }

  TEST_CASE("a dump made by another process loads back as the frame rendered here, bit for bit") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    // shadow: a 24-bit shadow map and window depth; hdr: half targets and 16-bit depth.
    for (const char* scene : {"shadow", "hdr"}) {
      const std::string dump = std::string("dump_") + scene;
      const RunResult result = runCli(cwd, std::string("render ") + scene + " --size 40x24 --time 0.5 --dump " + dump +
                                               " --out " + dump + ".png");
      INFO(scene << " stderr: " << result.err);
      REQUIRE(result.status == 0);
      const std::vector<scenes::Target> loaded = compare::loadTargetDump((cwd / dump).string());
      auto backend = scenes::makeRasterBackend(0);
      const std::vector<scenes::Target> here = testing_support::renderScene(*backend, scene, 0.5f, 40, 24);
      REQUIRE(loaded.size() == here.size());
      for (size_t i = 0; i < here.size(); ++i) {
        INFO(here[i].name);
        const ImageData& a = loaded[i].image;
        const ImageData& b = here[i].image;
        CHECK(loaded[i].name == here[i].name);
        CHECK((a.format == b.format && a.channels == b.channels && a.depthBits == b.depthBits));
        CHECK(a.rgba8 == b.rgba8);
        CHECK(a.depth == b.depth);
        REQUIRE(a.floats.size() == b.floats.size());
        CHECK((a.floats.empty() || std::memcmp(a.floats.data(), b.floats.data(), a.floats.size() * sizeof(float)) == 0));
      }
    }
  }

  TEST_CASE("writes leave no temporary file, and fail with the path named") {
    TempFolder temp;
    const std::string path = (temp.path / "x.png").string();
    compare::writePng(path, rgba8Image(2, 2, 9));
    CHECK(compare::readPng(path).rgba8 == rgba8Image(2, 2, 9).rgba8);
    CHECK(std::distance(fs::directory_iterator(temp.path), fs::directory_iterator()) == 1);
    CHECK_THROWS_WITH_AS(compare::writePng("/nonexistent/dir/x.png", rgba8Image(1, 1, 0)),
                         doctest::Contains("cannot write /nonexistent/dir/x.png: "),
                         std::runtime_error);
  }
}
