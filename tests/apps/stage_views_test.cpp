// The registry of stage views (apps/views/stage_views.h) is the only list of them: every
// record is complete, and `raster views`, `render --view`, its error for a name it does not
// know and `raster report` all follow the table (tests/pipeline/views_test.cpp checks what
// the views count and draw).
#include <doctest/doctest.h>

#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/views/stage_views.h"
#include "apps/views/view_sheet.h"
#include "backends/backends.h"
#include "raster/methods.h"
#include "raster/view_recorder.h"
#include "scenes/registry.h"
#include "io/image_io.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/scene_test_helpers.h"

using namespace cli_test;

TEST_SUITE("views") {
  TEST_CASE("registry: every view's record is complete, and names are unique") {
    REQUIRE(!cli::stageViews().empty());
    std::set<std::string> names;
    for (const cli::StageView& view : cli::stageViews()) {
      INFO(view.name);
      CHECK(names.insert(view.name).second);
      CHECK(cli::findStageView(view.name) == &view);
      CHECK(std::string(view.shows).size() > 0);
      CHECK(std::string(view.about).size() > 0);
      CHECK((view.figures != nullptr));
      CHECK((view.totals != nullptr));
      REQUIRE((view.painter != nullptr));
      // A heat map needs its field, the top of its scale and its tick labels.
      if (view.painter == cli::heatMapPainter) {
        CHECK((view.heatMap.field != nullptr));
        CHECK((view.heatMap.top != nullptr));
        CHECK((view.heatMap.tickText != nullptr));
        CHECK(std::string(view.heatMap.quantity).size() > 0);
        CHECK(((view.heatMap.noData == nullptr) == (view.heatMap.noDataNote == nullptr)));
      }
    }
    CHECK(cli::findStageView("help") == nullptr);
  }

  TEST_CASE("registry: `raster views` lists it, and --view refuses other names with its list") {
    TempFolder temp;
    const RunResult list = runCli(temp.path, "views");
    REQUIRE(list.status == 0);
    std::string expected;
    for (const cli::StageView& view : cli::stageViews()) {
      std::string name = view.name;
      name.resize(std::max<size_t>(name.size(), 12), ' ');
      expected += name + " " + view.shows + "\n";
    }
    CHECK(list.out == expected);
    expectRefused("render shadow --size 16x16 --view help --out v.png", "(views: " + cli::stageViewList() + ")");
  }

  TEST_CASE("registry: every view in it renders through render --view, with a sidecar of its own") {
    TempFolder temp;
    for (const cli::StageView& view : cli::stageViews()) {
      INFO(view.name);
      const std::string out = std::string(view.name) + ".png";
      const RunResult r = runCli(temp.path, std::string("render shadow --size 40x30 --threads 1 --quiet --view ") + view.name +
                                                " --out " + out);
      INFO(r.err);
      REQUIRE(r.status == 0);
      CHECK(compare::readPng((temp.path / out).string()).width > 0);
      const nlohmann::json sidecar = nlohmann::json::parse(readText(temp.path / (std::string(view.name) + ".json")));
      CHECK(sidecar["view"] == view.name);
      CHECK(sidecar["about"] == view.about);
      CHECK(sidecar["legend"].is_object());
      CHECK(sidecar["passes"].size() == sidecar["totals"]["passes"]);
    }
  }

  // A 1x1024 frame's sheet was 464x225504 (its cells kept the frame's aspect at 220 px wide;
  // at 1x16384 a render took 22 GB): a cell is now at most twice as tall as wide. The layout
  // every view shares, at 1x16384, then one view drawn end to end.
  TEST_CASE("registry: a tall, thin frame's sheet stays a sheet") {
    cli::Frame frame;
    frame.width = 1;
    frame.height = 16384;
    raster::ViewPass pass;
    pass.width = 1;
    pass.height = 16384;
    const cli::SheetLayout layout = cli::layoutSheet(frame, {&pass, &pass, &pass});
    CHECK(layout.cellHeight <= 2 * layout.cellWidth);

    TempFolder temp;
    const RunResult r = runCli(temp.path, "render shadow --size 1x1024 --threads 1 --quiet --view overdraw --out v.png");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const scenes::ImageData sheet = compare::readPng((temp.path / "v.png").string());
    CHECK(sheet.height < 4 * sheet.width);
  }

  TEST_CASE("invocations: one per fragment at the GL rate, a quarter per pixel of a 2x2 post pass") {
    TempFolder temp;
    for (const char* rate : {"1x1", "2x2", "4x4"}) {
      INFO(rate);
      const int side = rate[0] - '0';
      const RunResult r = runCli(temp.path, std::string("render deferred --size 160x120 --threads 2 --quiet --view invocations "
                                                        "--out v.png --method shading=") + rate);
      INFO(r.err);
      REQUIRE(r.status == 0);
      const nlohmann::json sidecar = nlohmann::json::parse(readText(temp.path / "v.json"));
      std::set<std::string> seen;
      for (const nlohmann::json& pass : sidecar["passes"]) {
        const std::string label = pass["label"];
        INFO(label);
        seen.insert(label);
        const double invocations = pass["invocations"]["total"], fragments = pass["fragments_shaded"];
        if (label == "ssao" || label == "final") {   // fullscreen post passes: every pixel written once
          CHECK(fragments == 160.0 * 120.0);
          // One invocation per coarse pixel, each shared by its side * side pixels; the
          // fullscreen triangle is clipped into two, and a coarse pixel on their seam is
          // shaded once by each (coarse fragments are per primitive), hence "about".
          CHECK(pass["invocations"]["min"].get<double>() == 1.0 / (side * side));
          CHECK(invocations >= fragments / (side * side));
          CHECK(invocations <= fragments / (side * side) * (side == 1 ? 1.0 : 1.1));
        } else {   // the G-buffer and shadow map keep one invocation per fragment
          CHECK(invocations == doctest::Approx(fragments));
        }
      }
      CHECK(seen.count("ssao") == 1);
      CHECK(sidecar["totals"]["invocations"].get<double>() <= sidecar["totals"]["fragments_shaded"].get<double>());
    }
  }

  TEST_CASE("recording fragment counts of coarse-shaded passes leaves every target's bytes unchanged") {
    for (const char* rate : {"2x2", "2x2-all", "4x4"})
      for (const std::string& scene : testing_support::scenesUnderTest()) {
        INFO(scene << " at shading=" << rate);
        raster::MethodSet methods;
        raster::setMethod(methods, "shading", rate);
        const raster::ScopedMethods scoped(methods);
        auto plain = scenes::makeRasterBackend(2);
        const auto expected = testing_support::renderScene(*plain, scene, 1.0f, 97, 61);
        raster::ViewRecorder recorder(raster::ViewRecorder::Record::Fragments);
        auto backend = scenes::makeRasterBackend(2);
        scenes::setViewRecorder(*backend, &recorder);
        const auto recorded = testing_support::renderScene(*backend, scene, 1.0f, 97, 61);
        scenes::setViewRecorder(*backend, nullptr);
        REQUIRE(recorded.size() == expected.size());
        for (size_t i = 0; i < expected.size(); ++i) {
          INFO("target " << expected[i].name);
          CHECK(recorded[i].image.rgba8 == expected[i].image.rgba8);
          CHECK(recorded[i].image.depth == expected[i].image.depth);
          CHECK(recorded[i].image.floats == expected[i].image.floats);
        }
        // Each pass's shares add up to the invocations that wrote: at most one per fragment.
        for (const raster::ViewPass& pass : recorder.passes()) {
          double invocations = 0;
          uint64_t fragments = 0;
          for (float v : pass.counts.invocations) invocations += v;
          for (uint32_t v : pass.counts.shaded) fragments += v;
          CHECK(invocations <= double(fragments) + 1e-3);
        }
      }
  }
}
