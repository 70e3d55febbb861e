// Bounded memory: every image, texture, target and read-back is reserved against
// --max-memory from its size before it is allocated (io/memory_budget.h); past the cap
// the program exits 2 naming what it was allocating, having allocated at most the cap.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "scenes/scene.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/sanitizer_build.h"
#include "tests/scene_test_helpers.h"

namespace {

using namespace cli_test;

// `render` (which writes final.png) succeeds under its --max-memory cap; the same command
// with `more` asks for more than the cap and is refused: exit 2, the message naming what
// it was allocating, and nothing written, not even the final image.
void checkRefusedOnlyWithMore(const std::string& render, const std::string& more, const std::string& message) {
  TempFolder temp;
  const fs::path cwd = temp.path / "cwd";
  fs::create_directory(cwd);
  const RunResult plain = runCli(cwd, render);
  INFO(plain.err);
  CHECK(plain.status == 0);
  CHECK(fs::is_regular_file(cwd / "final.png"));
  fs::remove(cwd / "final.png");
  const RunResult refused = runCli(cwd, render + " " + more);
  INFO(refused.err);
  CHECK(refused.status == 2);
  CHECK(refused.err.find(message) != std::string::npos);
  CHECK(fs::is_empty(cwd));
}

// The peak resident memory of one run of `raster ARGS...` (its own, from wait4), in KiB;
// -1 when it did not exit 0. Output goes nowhere: ARGS name their own --out.
long peakResidentKiB(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {RASTER_CLI_PATH};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> pointers;
  for (std::string& a : argv) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1), dup2(null, 2);
    execv(pointers[0], pointers.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return usage.ru_maxrss;   // KiB on Linux
}

}  // namespace

TEST_SUITE("memory") {
  // A 16384x16384 window alone is 2 GiB of colour and depth: refused before it is made.
  TEST_CASE("memory: a render over the cap is refused before its buffers are allocated") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult r = runCli(cwd, "render shadow --size 16384x16384 --max-memory 1G --out big.png");
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("raster: memory: the 16384x16384 window") != std::string::npos);
    CHECK(r.err.find("over the cap of 1.00 GiB (--max-memory)") != std::string::npos);
    CHECK(fs::is_empty(cwd));
    CHECK(runCli(cwd, "render shadow --max-memory 12X").status == 2);
    CHECK(runCli(cwd, "render shadow --max-memory 0").status == 2);
  }

  // The backends made a 640x480 window before the scene sized it, so an 8x8 render under a
  // 2 MiB cap was refused for "the 640x480 window": the error names what the run needs.
  TEST_CASE("memory: the cap is met or missed at the size asked for, not at a default") {
    TempFolder temp;
    for (const char* backend : {"raster", "gl"}) {
      const RunResult r = runCli(temp.path, std::string("render shadow --size 8x8 --max-memory 2M --quiet --out x.png --backend ") + backend);
      INFO(backend << ": " << r.err);
      CHECK(r.status == 2);
      CHECK(r.err.find("640x480") == std::string::npos);
      CHECK(r.err.find("over the cap of 2.0 MiB") != std::string::npos);
    }
  }

  // render used to read back every target even without --dump (a 16384x16384 deferred render
  // died with bad_alloc at 21 GB). At 2048x2048 the frame needs under 250 MiB (the material
  // maps kept in strips, footprint_strips.h, 4/3 of their rows, and each decoded image freed
  // once uploaded), and reading back every target for --dump passes 400 MiB: under a 380 MiB
  // cap the plain render succeeds, and the same render with --dump is refused. (This ran at 4096x4096
  // under a 900 MiB cap until the sanitizer and SIMD-off builds took a minute or two on that
  // frame alone.)
  TEST_CASE("memory: render reads back only the final image unless it dumps every target") {
    checkRefusedOnlyWithMore("render deferred --size 2048x2048 --threads 2 --max-memory 380M --out final.png",
                             "--dump targets", "memory: reading back a 2048x2048 target");
  }

  // A stage view keeps six counters per pixel of every pass it records (24 bytes a pixel):
  // at 2048x1536 the shadow frame's window pass alone needs 72 MiB of records beside its
  // ~48 MiB of targets and read-backs. Under an 80 MiB cap the plain render succeeds; the
  // overdraw view is refused when its record would pass the cap, and writes nothing.
  TEST_CASE("memory: a stage view's per-pixel records count against the cap") {
    checkRefusedOnlyWithMore("render shadow --size 2048x1536 --max-memory 80M --quiet --out final.png", "--view overdraw",
                             "memory: the view's record of pass 1 (2048x1536) needs 72.0 MiB");   // six 4-byte counts a pixel
  }

  // Issue 26 asks that this pipeline's peak memory at 1920x1080 stay at or below llvmpipe's.
  // It had not for deferred, whose material maps were kept twice (rows and strips: 350
  // against 299 MiB): they are kept in strips alone now (footprint_strips.h), and a run that
  // makes no GL backend never loads Mesa (backends/gl_entry_points.h). Each scene is rendered
  // once with each backend, each a process of its own. Sanitizer builds are left out: their
  // allocators' redzones and shadow memory weigh on the two sides unevenly.
  TEST_CASE("memory: at 1920x1080 no scene's render needs more memory than llvmpipe's" *
            doctest::skip(testing_support::kUnderSanitizer)) {
    TempFolder temp;
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      long peak[2] = {};
      for (int k = 0; k < 2; ++k)
        peak[k] = peakResidentKiB({"render", scene, "--size", "1920x1080", "--threads", "2", "--backend", k == 0 ? "raster" : "gl",
                                   "--quiet", "--out", (temp.path / (scene + ".png")).string()});
      MESSAGE(scene << ": this pipeline " << peak[0] / 1024 << " MiB, llvmpipe " << peak[1] / 1024 << " MiB");
      REQUIRE(peak[0] > 0);
      REQUIRE(peak[1] > 0);
      CHECK(peak[0] <= peak[1]);
    }
  }

  // Seven 16384x16384 JPEGs in the asset folder took 17 GB before anything failed. An image
  // is now refused from its header, before it is decoded: here a PNG whose header claims
  // 16384x16384 (1 GiB decoded) among the deferred scene's real assets.
  TEST_CASE("memory: an asset image over the cap is refused from its header, before decoding") {
    TempFolder temp;
    const fs::path assets = temp.path / "assets", cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    fs::copy(scenes::assetDirectory({}), assets, fs::copy_options::recursive);
    // A user's own asset folder, without a manifest, so that the cap is what refuses it
    // (with the manifest, the changed file would be refused by its hash first).
    fs::remove(assets / "SHA256SUMS");
    const fs::path victim = assets / "brick" / "Bricks031_1K-JPG_Color.jpg";
    REQUIRE(fs::exists(victim));
    scenes::ImageData small;
    small.width = small.height = 4;
    small.format = scenes::TexelFormat::RGBA8;
    small.rgba8.assign(64, 7);
    const fs::path png = temp.path / "small.png";
    compare::writePng(png.string(), small);
    std::string bytes = readText(png);
    for (int k = 0; k < 2; ++k) {   // IHDR width and height, big-endian, at bytes 16 and 20
      bytes[size_t(16 + 4 * k)] = 0;
      bytes[size_t(17 + 4 * k)] = 0;
      bytes[size_t(18 + 4 * k)] = char(0x40);
      bytes[size_t(19 + 4 * k)] = 0;
    }
    fs::remove(victim);
    std::ofstream(victim, std::ios::binary) << bytes;
    const RunResult r = runCli(cwd, "render deferred --size 64x48 --max-memory 600M --assets " + shellQuote(assets.string()));
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("memory: decoding " + victim.string() + " (16384x16384) needs 1.00 GiB") != std::string::npos);
  }
}
