// The registry of stage views (apps/views/stage_views.h) is the only list of them: every
// record is complete, and `raster views`, `render --view`, its error for a name it does not
// know and `raster report` all follow the table (tests/pipeline/views_test.cpp checks what
// the views count and draw).
#include <doctest/doctest.h>

#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/views/stage_views.h"
#include "io/image_io.h"
#include "tests/apps/cli_test_helpers.h"

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
}
