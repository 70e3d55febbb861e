// Bad input to every scene of the registry, from its row alone, so a scene added later gets
// these checks with no line naming it:
//   - each asset the row lists, missing, or cut to half its size (refused by the folder's
//     SHA256SUMS, and without one, by the loader reading it);
//   - each parameter the row declares, set just outside its range.
// Each must stop the command before anything is rendered: exit status 2, the file or the
// parameter named on stderr in one "raster: ..." line, no image written.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>

#include "io/assets.h"
#include "scenes/registry.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/scene_test_helpers.h"

namespace {

using namespace cli_test;

// Renders `scene` from the asset folder `assets` in `cwd`, which must stay empty.
void expectAssetRefused(const fs::path& cwd, const std::string& scene, const fs::path& assets, const std::string& asset,
                        const std::string& how, const std::string& mentions) {
  const RunResult r = runCli(cwd, "render " + scene + " --size 16x12 --threads 1 --quiet --assets " +
                                      shellQuote(assets.string()) + " --out out.png");
  INFO(scene << ", " << asset << " " << how << "\nstderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.err.rfind("raster: ", 0) == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find(fs::path(asset).filename().string()) != std::string::npos);
  CHECK(r.err.find(mentions) != std::string::npos);
  CHECK(fs::is_empty(cwd));
}

std::string number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

}  // namespace

TEST_SUITE("hostile") {
  TEST_CASE("assets: each file of every scene's row, missing or cut short, is refused naming it, exit 2, no image") {
    TempFolder temp;
    // Files set aside go to a folder of their own: a manifest in the asset folder's parent
    // would be found and read (io/asset_manifest.h).
    const fs::path assets = temp.path / "data" / "assets", cwd = temp.path / "cwd", aside = temp.path / "aside";
    fs::create_directories(assets.parent_path());
    fs::create_directory(cwd);
    fs::create_directory(aside);
    fs::copy(scenes::assetDirectory({}), assets, fs::copy_options::recursive);
    REQUIRE(fs::exists(assets / "SHA256SUMS"));
    int files = 0;
    std::set<std::string> loadersRun;   // scene + extension
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      for (const std::string& asset : scenes::sceneEntry(scene).assets) {
        ++files;
        const fs::path file = assets / asset, away = aside / "away";
        REQUIRE(fs::exists(file));
        fs::rename(file, away);
        expectAssetRefused(cwd, scene, assets, asset, "missing", "");
        fs::rename(away, file);
        // Cut to half: the manifest's hash refuses it first; without a manifest (a user's own
        // folder), the loader must find the cut itself: once per scene and kind of file (a
        // run without the manifest decodes the scene's other images before it stops, the
        // suite's longest step, so each loader is run once a scene, not once a file).
        fs::copy_file(file, away);
        fs::resize_file(file, fs::file_size(file) / 2);
        expectAssetRefused(cwd, scene, assets, asset, "cut to half", "changed or truncated");
        if (loadersRun.insert(scene + fs::path(asset).extension().string()).second) {
          fs::rename(assets / "SHA256SUMS", aside / "SHA256SUMS");
          expectAssetRefused(cwd, scene, assets, asset, "cut to half, no manifest", "");
          fs::rename(aside / "SHA256SUMS", assets / "SHA256SUMS");
        }
        fs::rename(away, file);
      }
    }
    MESSAGE(files << " asset files of " << testing_support::scenesUnderTest().size() << " scenes checked");
  }

  TEST_CASE("parameters: every declared parameter of every scene, just outside its range, is refused naming it") {
    int checked = 0;
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      for (const scenes::ParamSpec& p : scenes::sceneEntry(scene).params) {
        if (p.name == "size") continue;   // not a number (WxH): the cli and sweep suites refuse its bad forms
        const double step = p.integer ? 1.0 : std::max(std::abs(p.max), std::abs(p.min)) * 1e-3 + 1e-6;
        for (const double value : {p.min - step, p.max + step}) {
          if (!std::isfinite(value) || std::isinf(float(value))) continue;   // a range to the float's end
          expectRefused("render " + scene + " --size 16x12 --set " + p.name + "=" + number(value), p.name);
          ++checked;
        }
      }
    }
    MESSAGE(checked << " out-of-range values refused");
    CHECK(checked > 0);
  }
}
