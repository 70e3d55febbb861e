// Hostile environment and values: a Gallium driver or thread count Mesa cannot use, numbers
// that are not decimal or out of range, empty values, a parameter given twice, output paths
// that are taken or loop, a child process that refuses, images with NaN and infinite pixels
// in a comparison.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "compare/metrics.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/compare/test_images.h"

namespace {

using namespace cli_test;
using test_images::halfImage;

void expectBadInput(const std::string& script, const std::string& needle) {
  TempFolder temp;
  const fs::path cwd = temp.path / "cwd";
  fs::create_directory(cwd);
  const RunResult r = runShell(cwd, script);
  INFO(script << "\nstderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.err.rfind("raster: ", 0) == 0);
  CHECK(r.err.find(needle) != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(fs::is_empty(cwd));
}

}  // namespace

TEST_SUITE("hostile") {
  // An unknown GALLIUM_DRIVER crashed inside Mesa (SIGSEGV, no message).
  TEST_CASE("environment: GALLIUM_DRIVER and LP_NUM_THREADS are checked before Mesa starts") {
    expectBadInput("GALLIUM_DRIVER=nosuchdriver exec \"$RASTER\" render shadow --backend gl --size 32x32 --out x.png",
                   "GALLIUM_DRIVER='nosuchdriver'");
    expectBadInput("LP_NUM_THREADS=many exec \"$RASTER\" render shadow --backend gl --size 32x32 --out x.png",
                   "LP_NUM_THREADS='many'");
    expectBadInput("LP_NUM_THREADS=-3 exec \"$RASTER\" compare shadow --size 32x32 --out cmp",
                   "LP_NUM_THREADS='-3'");
  }

  // --time was read by strtod: "0x10" was 16, " 1" was 1, and 1e31 passed though --set time=
  // (and `raster params`) stop at 1e30. Both now read a decimal number in the parameter's range.
  TEST_CASE("values: --time takes what --set time= takes, and nothing else") {
    for (const char* time : {"1e39", "1e31", "-1"}) {
      expectBadInput(std::string("exec \"$RASTER\" render shadow --time ") + time, "--time: " + std::string(time) + " is out of range (0..1e+30)");
      expectBadInput(std::string("exec \"$RASTER\" render shadow --set time=") + time, "time: " + std::string(time) + " is out of range");
    }
    for (const char* time : {"0x10", "' 1'", "'1 '", "+1", "inf", "nan", "1e"}) {
      expectBadInput(std::string("exec \"$RASTER\" render shadow --time ") + time, "is not a finite number");
      expectBadInput(std::string("exec \"$RASTER\" render shadow --set time=") + time, "is not a finite number");
    }
    expectBadInput("exec \"$RASTER\" compare shadow --max-rmse 0x1 --out cmp", "--max-rmse: '0x1' is not a finite number");
    // The range's top, as a child process gets it back (the float of 1e30 is 1.00000002e+30).
    TempFolder temp;
    const RunResult top = runCli(temp.path, "compare shadow --size 16x12 --time 1e30 --reference softpipe --max-rmse 1000 --quiet --out cmp");
    INFO(top.err);
    CHECK(top.status == 0);
  }

  // An empty value was taken as the option left out: `--max-rmse ""` turned a CI gate off,
  // `--out ""` wrote shadow.png into the working folder.
  TEST_CASE("values: an option given an empty value is refused, not taken as left out") {
    expectBadInput("exec \"$RASTER\" compare shadow --size 16x12 --max-rmse '' --out cmp", "--max-rmse: an empty value");
    expectBadInput("exec \"$RASTER\" render shadow --size 16x12 --out ''", "--out: an empty value");
    expectBadInput("exec \"$RASTER\" render shadow --size 16x12 --threads '' --out x.png", "--threads: an empty value");
    expectBadInput("exec \"$RASTER\" sweep shadow --param near=0.01:0.1:2 --shard '' --out s", "--shard: an empty value");
  }

  // A 5000-character value was echoed whole: a 5000-character error line. A long word keeps
  // its head and tail, and a cut never splits a UTF-8 character (the path's cut neither).
  TEST_CASE("values: a very long value is shown by its head and tail in the error line") {
    expectBadInput("exec \"$RASTER\" render shadow --set near=$(printf '1%.0s' $(seq 5000))x --out x.png",
                   "...[4823 bytes not shown]...111");
    TempFolder temp;
    std::string command = "render shadow --set near=";   // appended piece by piece: GCC 12 reads a
    command.append(1000, '7');                           // chain of operator+ here as a copy past
    command += "x --out x.png";                          // a string's end (-Warray-bounds)
    const RunResult r = runCli(temp.path, command);
    CHECK(r.status == 2);
    CHECK(r.err.size() < 400);
    CHECK(r.err.find("7x'") != std::string::npos);   // the tail, where the wrong character is
    std::string accents;
    for (int i = 0; i < 200; ++i) accents += "\xc3\xa9";   // é, two bytes each
    const RunResult path = runCli(temp.path, "render shadow --size 8x6 --out " + accents.append("/x.png"));
    CHECK(path.status == 2);
    for (size_t at = path.err.find("\xc3"); at != std::string::npos; at = path.err.find('\xc3', at + 2))
      CHECK(static_cast<unsigned char>(path.err[at + 1]) == 0xa9);   // every é whole
    CHECK(path.err.find("\xc3...") == std::string::npos);
    // Where the cut starts: a word of 301 bytes ('111...1x' in quotes) is cut, one of 300 is shown whole.
    expectBadInput("exec \"$RASTER\" render shadow --set near=$(printf '1%.0s' $(seq 298))x --out x.png", "'" + std::string(120 - 1, '1') + "...[121 bytes not shown]...");
    const RunResult whole = runShell(temp.path, "exec \"$RASTER\" render shadow --set near=$(printf '1%.0s' $(seq 297))x --out x.png");
    CHECK(whole.err.find("'" + std::string(297, '1') + "x'") != std::string::npos);
  }

  // `--set size=64x48 --size 32x24` rendered 64x48: a parameter given two ways is ambiguous.
  TEST_CASE("values: a parameter given by --set (or a sweep's --param) and by its own option is refused") {
    expectBadInput("exec \"$RASTER\" render shadow --set size=64x48 --size 32x24 --out x.png", "--set size=64x48 and --size both give the size");
    expectBadInput("exec \"$RASTER\" render hdr --size 16x12 --instances 5 --set instances=7 --out x.png", "both give the instances");
    expectBadInput("exec \"$RASTER\" sweep shadow --param time=0:2:3 --time 3 --out s", "--param time=0:2:3 and --time both give the time");
    // A name that is no scene parameter is that, not "given twice" (--threads is no frame option).
    expectBadInput("exec \"$RASTER\" render hdr --size 16x12 --set threads=2 --threads 2 --out x.png", "unknown parameter 'threads'");
    // Given once, by --set, it reaches a child process (softpipe's render) as its option only.
    TempFolder temp;
    const RunResult child = runCli(temp.path, "compare shadow --set size=20x14 --set time=2 --reference softpipe --max-rmse 1000 --quiet --out cmp");
    INFO(child.err);
    CHECK(child.status == 0);
    CHECK(child.out.find("scene: shadow at 20x14, t=2.000") != std::string::npos);
  }

  // A folder name past NAME_MAX was "filesystem error: cannot create directory" (exit 1) at
  // the end of the run, after render had written its PNG.
  TEST_CASE("output: an output folder's name too long is refused before the run") {
    const std::string longName(300, 'y');
    expectBadInput("exec \"$RASTER\" render shadow --size 16x12 --out a.png --dump " + longName, "--dump: cannot write");
    expectBadInput("exec \"$RASTER\" compare shadow --size 16x12 --out " + longName, "is longer than 255 bytes");
  }

  // A link that loops, or points at nothing, where a folder is asked for: found by the status
  // call that the checks made without an error code (exit 1, a bare "filesystem error"), and
  // for sweep and tradeoff only at the end, when the folder was made after the work.
  TEST_CASE("paths: a link that loops or points at nothing, given as a folder, is refused before the run") {
    const std::string loop = "ln -s loop ../loop && ln -s nothing-here ../dangling && exec \"$RASTER\" ";
    expectBadInput(loop + "render shadow --size 16x12 --out ../a.png --dump ../loop", "--dump: ../loop: Too many levels");
    expectBadInput(loop + "compare shadow --size 16x12 --out ../loop", "--out: ../loop: Too many levels");
    expectBadInput(loop + "sweep shadow --param time=1:2:2 --size 16x12 --out ../loop", "--out: ../loop: Too many levels");
    expectBadInput(loop + "tradeoff shadow --size 16x12 --out ../loop", "--out: ../loop: Too many levels");
    expectBadInput(loop + "render shadow --size 16x12 --out ../a.png --assets ../loop", "--assets: ../loop: Too many levels");
    expectBadInput(loop + "report shadow --size 16x12 --include ../loop --out ../r", "--include: ../loop: Too many levels");
    expectBadInput(loop + "compare shadow --size 16x12 --out ../dangling", "--out: ../dangling is a symbolic link to nothing");
    expectBadInput(loop + "render shadow --size 16x12 --out ../a.png --assets ../dangling", "--assets: no such folder: ../dangling");
  }

  // A name in an existing --out folder that a folder or link took is found before the work
  // (a race, a sweep), not after it with half the files written.
  TEST_CASE("output: a file name taken in the --out folder is refused before the work, nothing written") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    for (const char* taken : {"t/tradeoff.svg", "s/sweep.png", "d/hdr_depth.exr"}) fs::create_directories(cwd / taken);
    fs::create_directory(cwd / "s2");
    fs::create_directory_symlink("/tmp", cwd / "s2" / "sweep.md");
    const auto expectRefused = [&](const std::string& args, const std::string& says) {
      const RunResult result = runCli(cwd, args);
      INFO("raster " << args << "\nstderr: " << result.err);
      CHECK(result.status == 2);
      CHECK(result.err.rfind("raster: " + says, 0) == 0);
    };
    expectRefused("tradeoff shadow --size 32x24 --out t", "--out: cannot write t/tradeoff.svg: it is a folder");
    expectRefused("sweep shadow --param offset_scale=0:2:2 --size 32x24 --out s", "--out: cannot write s/sweep.png");
    expectRefused("sweep shadow --param offset_scale=0:2:2 --size 32x24 --out s2", "--out: cannot write s2/sweep.md");
    // A shard draws no chart: its sweep.png may stay a folder.
    CHECK(runCli(cwd, "sweep shadow --param offset_scale=0:2:2 --size 32x24 --shard 1/2 --out s --check").status == 0);
    // The dump's names are the scene's targets: checked once rendered, before --out's PNG.
    expectRefused("render hdr --size 32x24 --dump d --out d/x.png --quiet", "--dump: cannot write d/hdr_depth.exr");
    CHECK_FALSE(fs::exists(cwd / "d" / "x.png"));
    CHECK_FALSE(fs::exists(cwd / "d" / "hdr_scene.png"));
  }

  // The softpipe side renders in a child process of this program; when the child refuses
  // (here: the memory cap it is handed, half of what is left of ours), the user gets one
  // error line, ours, carrying the child's reason, and the child's progress as it came.
  TEST_CASE("child: a child process's refusal ends the run in one line that gives the child's reason") {
    TempFolder temp;
    for (const bool quiet : {true, false}) {
      const RunResult run =
          runCli(temp.path, std::string("compare shadow --test softpipe --size 32x24 --max-memory 10M") + (quiet ? " --quiet" : ""));
      CAPTURE(run.err);
      CHECK(run.status == 2);
      const size_t error = run.err.find("raster: ");
      REQUIRE(error != std::string::npos);
      CHECK(run.err.substr(error).rfind("raster: the softpipe render (child process) failed with exit status 2: memory: "
                                        "reading back a 1024x1024 depth target from GL needs 4.0 MiB",
                                        0) == 0);
      CHECK(run.err.find("raster: ", error + 1) == std::string::npos);
      CHECK(run.err.back() == '\n');
      CHECK(std::count(run.err.begin() + long(error), run.err.end(), '\n') == 1);
      CHECK((run.err.find("rendering shadow with softpipe") != std::string::npos) == !quiet);
      CHECK_FALSE(fs::exists(temp.path / "compare-shadow"));
    }
  }

  // With an interpreter that exits 0 and draws nothing, tradeoff said it wrote its chart.
  TEST_CASE("output: a chart script that writes no chart is a failure") {
    TempFolder temp;
    const RunResult r = runShell(temp.path, "RASTER_PYTHON=/bin/true exec \"$RASTER\" tradeoff shadow --size 16x12 --frames 1 "
                                            "--warmup 0 --no-softpipe --quiet --threads 1 --out o");
    INFO(r.err);
    CHECK(r.status == 1);
    CHECK(r.err.find("the chart script wrote no o/tradeoff.png") != std::string::npos);
  }

  // `raster methods --json > /dev/full` exited 0: the listing was lost without a word.
  TEST_CASE("output: a listing that cannot be written is a failure, not a success") {
    TempFolder temp;
    for (const char* command : {"scenes", "scenes --json", "methods --json", "views", "params shadow"}) {
      const RunResult r = runShell(temp.path, std::string("exec \"$RASTER\" ") + command + " > /dev/full");
      INFO(command << ": " << r.err);
      CHECK(r.status == 1);
      CHECK(r.err == "raster: cannot write the standard output\n");
    }
  }

  // Identical NaN pixels made RMSE and PSNR NaN ("psnr nan").
  TEST_CASE("compare: non-finite pixels are counted apart, and no metric is ever NaN") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const auto a = halfImage({nan, 0.5f, 0.25f, 1.0f, 0.5f, 0.5f, 0.5f, 1.0f, inf, 0, 0, 1});
    compare::TargetStats same = compare::compareImages("hdr", a, a);
    CHECK(same.nonFinitePixels == 2);
    CHECK(same.rmse == 0.0);
    CHECK(std::isinf(same.psnr));
    CHECK(same.shareBitIdentical == 1.0);
    const std::string line = compare::formatStatsLine(same);
    INFO(line);
    CHECK(line.find("nan") == std::string::npos);
    CHECK(line.find("nonfinite 2") != std::string::npos);

    // NaN against a number: a differing pixel, but RMSE only over the finite samples.
    const auto b = halfImage({0.0f, 0.5f, 0.25f, 1.0f, 0.5f, 0.5f, 0.75f, 1.0f, inf, 0, 0, 1});
    const compare::TargetStats differ = compare::compareImages("hdr", a, b);
    CHECK(differ.nonFinitePixels == 2);
    CHECK(std::isfinite(differ.rmse));
    CHECK(differ.rmse > 0.0);
    CHECK(std::isfinite(differ.psnr));
    CHECK(differ.shareDiffering == doctest::Approx(2.0 / 3.0));
    CHECK(compare::formatStatsLine(differ).find("nan") == std::string::npos);
  }
}
