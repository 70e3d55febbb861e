// The stage views (raster/view_recorder.h, tile/inspect_tile.h, apps/views/stage_views.h): recording a
// view leaves every target's bytes as they are, its counts are GL's in-order counts (those
// of the scalar path with visibility first off), they do not depend on the thread count, the
// wireframe's corners are the triangles' own, and the command writes a PNG with a sidecar
// whose totals agree with the pipeline counters.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "io/image_io.h"
#include "io/target_dump.h"
#include "raster/geometry/setup.h"
#include "raster/view_recorder.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/geometry/geometry_test_helpers.h"
#include "tests/scene_test_helpers.h"

namespace {

using raster::ViewRecorder;
using Record = ViewRecorder::Record;

constexpr int kWidth = 97, kHeight = 61;   // odd: quads and tiles hang over the edges

struct Recorded {
  std::vector<scenes::Target> targets;
  std::unique_ptr<ViewRecorder> recorder;
};

Recorded renderRecorded(const std::string& scene, Record what, int threads) {
  Recorded r;
  r.recorder = std::make_unique<ViewRecorder>(what);
  auto backend = scenes::makeRasterBackend(threads);
  scenes::setViewRecorder(*backend, r.recorder.get());
  r.targets = testing_support::renderScene(*backend, scene, 1.0f, kWidth, kHeight);
  scenes::setViewRecorder(*backend, nullptr);
  return r;
}

double statistic(const scenes::Backend& backend, const std::string& name) {
  for (const auto& [key, value] : backend.statistics())
    if (key == name) return value;
  FAIL("no statistic " << name);
  return 0;
}

uint64_t sum(const std::vector<uint32_t>& values) {
  uint64_t total = 0;
  for (uint32_t v : values) total += v;
  return total;
}

}  // namespace

TEST_SUITE("views") {
  TEST_CASE("recording any view leaves every target's bytes unchanged") {
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      auto plain = scenes::makeRasterBackend(2);
      const auto expected = testing_support::renderScene(*plain, scene, 1.0f, kWidth, kHeight);
      for (Record what : {Record::Fragments, Record::TileTimes, Record::Triangles}) {
        INFO(scene << ", record " << int(what));
        const Recorded r = renderRecorded(scene, what, 2);
        REQUIRE(r.targets.size() == expected.size());
        for (size_t i = 0; i < expected.size(); ++i) {
          INFO("target " << expected[i].name);
          CHECK(r.targets[i].image.rgba8 == expected[i].image.rgba8);
          CHECK(r.targets[i].image.depth == expected[i].image.depth);
          CHECK(r.targets[i].image.floats == expected[i].image.floats);
        }
        CHECK(r.recorder->passes().size() >= 2);
      }
    }
  }

  TEST_CASE("fragment counts are GL's in-order counts: those of the scalar path without visibility first") {
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      INFO(scene);
      auto inOrder = scenes::makeRasterBackend(2, /*scalarOnly=*/true, /*visibilityFirst=*/false);
      testing_support::renderScene(*inOrder, scene, 1.0f, kWidth, kHeight);
      const Recorded r = renderRecorded(scene, Record::Fragments, 2);
      uint64_t shaded = 0, lanesCovered = 0, lanesShaded = 0, helpers = 0, kills = 0;
      for (const raster::ViewPass& pass : r.recorder->passes()) {
        INFO("pass " << pass.index);
        // Per pass, the pixels' fragments are the pass's covered lanes.
        CHECK(sum(pass.counts.shaded) == pass.counters.lanesCovered);
        // Helpers counted per pixel are at most the helper lanes (some fall off the edge).
        const uint64_t passHelpers = sum(pass.counts.helpersUncovered) + sum(pass.counts.helpersKilled);
        CHECK(passHelpers <= pass.counters.lanesShaded - pass.counters.lanesCovered);
        if (pass.colorTargets == 0) CHECK(sum(pass.counts.shaded) == 0);
        shaded += sum(pass.counts.shaded);
        lanesCovered += pass.counters.lanesCovered;
        lanesShaded += pass.counters.lanesShaded;
        helpers += passHelpers;
        kills += sum(pass.counts.depthKills);
      }
      CHECK(shaded == uint64_t(statistic(*inOrder, "lanes_covered")));
      CHECK(lanesCovered == uint64_t(statistic(*inOrder, "lanes_covered")));
      CHECK(lanesShaded == uint64_t(statistic(*inOrder, "lanes_shaded")));
      CHECK(helpers > 0);
      if (std::string(scene) != "hdr") CHECK(kills > 0);   // geometry in front of geometry
    }
    // The shadow scene's shadow map pass is depth only: fragments pass, none is shaded.
    const Recorded r = renderRecorded("shadow", Record::Fragments, 1);
    CHECK(r.recorder->passes().front().colorTargets == 0);
    CHECK(sum(r.recorder->passes().front().counts.depthOnly) > 0);
  }

  TEST_CASE("counts and wireframes do not depend on the thread count") {
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      INFO(scene);
      const Recorded one = renderRecorded(scene, Record::Fragments, 1), two = renderRecorded(scene, Record::Fragments, 2);
      REQUIRE(one.recorder->passes().size() == two.recorder->passes().size());
      for (size_t p = 0; p < one.recorder->passes().size(); ++p) {
        const raster::FragmentCounts &a = one.recorder->passes()[p].counts, &b = two.recorder->passes()[p].counts;
        CHECK(a.shaded == b.shaded);
        CHECK(a.depthOnly == b.depthOnly);
        CHECK(a.depthKills == b.depthKills);
        CHECK(a.helpersUncovered == b.helpersUncovered);
        CHECK(a.helpersKilled == b.helpersKilled);
      }
      const Recorded t1 = renderRecorded(scene, Record::Triangles, 1), t2 = renderRecorded(scene, Record::Triangles, 2);
      REQUIRE(t1.recorder->passes().size() == t2.recorder->passes().size());
      for (size_t p = 0; p < t1.recorder->passes().size(); ++p) {
        const auto &a = t1.recorder->passes()[p], &b = t2.recorder->passes()[p];
        CHECK(a.triangleList.size() == a.triangles);   // every set-up triangle has its corners
        REQUIRE(a.triangleList.size() == b.triangleList.size());
        for (size_t i = 0; i < a.triangleList.size(); ++i)
          for (int c = 0; c < 3; ++c) {
            CHECK(a.triangleList[i].x[c] == b.triangleList[i].x[c]);
            CHECK(a.triangleList[i].y[c] == b.triangleList[i].y[c]);
          }
      }
    }
  }

  TEST_CASE("a wireframe's corners are the triangle's window positions, recovered from its edges") {
    raster::TriangleList triangles;
    raster::PlaneList planes;
    raster::SetupState state;
    state.framebufferWidth = 200;
    state.framebufferHeight = 100;
    const float corners[3][2] = {{10.25f, 5.5f}, {150.75f, 20.125f}, {40.0f, 90.5f}};
    const auto v0 = geometry_test::windowVertex(corners[0][0], corners[0][1]);
    const auto v1 = geometry_test::windowVertex(corners[1][0], corners[1][1]);
    const auto v2 = geometry_test::windowVertex(corners[2][0], corners[2][1]);
    REQUIRE(raster::setupTriangle(state, v0.data(), v1.data(), v2.data(), {triangles, planes}));
    raster::Framebuffer fb;
    fb.width = 200;
    fb.height = 100;
    raster::TileJob job;
    job.framebuffer = &fb;
    job.triangles = triangles;
    std::vector<raster::DrawRecord> draws(1);
    job.draws = draws;
    ViewRecorder recorder(Record::Triangles);
    const raster::ViewPass& pass = recorder.beginPass(job, 4, 2);
    REQUIRE(pass.triangleList.size() == 1);
    const raster::ViewTriangle& t = pass.triangleList[0];
    // Each recovered corner is one of the vertices, within the snapping (1/256 pixel) and
    // the fill rule's bias; all three are found.
    for (const auto& corner : corners) {
      double nearest = 1e9;
      for (int c = 0; c < 3; ++c) nearest = std::min(nearest, std::hypot(double(t.x[c]) - corner[0], double(t.y[c]) - corner[1]));
      INFO("corner " << corner[0] << ", " << corner[1]);
      CHECK(nearest < 1.0 / 64.0);
    }
  }

  TEST_CASE("raster render --view: the image's bytes stay, the sidecar's totals are the counters'") {
    using namespace cli_test;
    TempFolder temp;
    // Every view of the first scene, and one view of each other scene, a different one each
    // (a run of the program per view and scene: 24 runs took 29 of this suite's 66 seconds
    // under ASan + UBSan). That every view leaves every scene's bytes unchanged is checked
    // in-process above; what this adds is the program's files.
    const std::vector<std::string> views = {"overdraw", "depth-kills", "helpers", "tile-cost", "triangles"};
    const std::vector<std::string> scenesTested = testing_support::scenesUnderTest();
    for (size_t s = 0; s < scenesTested.size(); ++s) {
      const std::string& scene = scenesTested[s];
      const std::string plain = std::string(scene) + "-plain.png";
      const RunResult base = runCli(temp.path, std::string("render ") + scene + " --size 64x48 --threads 2 --quiet --out " + plain);
      REQUIRE(base.status == 0);
      std::vector<std::string> viewsHere = views;
      if (s > 0) viewsHere = {views[s % views.size()]};
      for (const std::string& view : viewsHere) {
        INFO(scene << " --view " << view);
        const std::string out = std::string(scene) + "-" + view + ".png", dump = std::string(scene) + "-" + view;
        const RunResult r = runCli(temp.path, std::string("render ") + scene + " --size 64x48 --threads 2 --quiet --view " + view +
                                                  " --out " + out + " --dump " + dump);
        INFO(r.err);
        REQUIRE(r.status == 0);
        // The dump's final image (the last target) is the plain render's, byte for byte.
        const std::vector<scenes::Target> dumped = compare::loadTargetDump((temp.path / dump).string());
        REQUIRE(!dumped.empty());
        CHECK(dumped.back().image.rgba8 == compare::readPng((temp.path / plain).string()).rgba8);
        // The PNG is there, and the sidecar agrees with itself and the pipeline's counters.
        const scenes::ImageData png = compare::readPng((temp.path / out).string());
        CHECK(png.width >= 64);
        const nlohmann::json json = nlohmann::json::parse(readText(temp.path / (std::string(scene) + "-" + view + ".json")));
        CHECK(json["view"] == view);
        uint64_t covered = 0;
        for (const auto& pass : json["passes"]) covered += pass["pipeline_counters"]["lanes_covered"].get<uint64_t>();
        CHECK(json["totals"]["lanes_covered"].get<uint64_t>() == covered);
        CHECK(json["legend"].is_object());
        if (view == "overdraw") CHECK(json["totals"]["fragments_shaded"].get<uint64_t>() == covered);
        if (view == "depth-kills") CHECK(json["totals"]["late"] == 0);
        if (view == "helpers")
          CHECK(json["totals"]["helpers"]["total"].get<uint64_t>() ==
                json["totals"]["lanes_shaded"].get<uint64_t>() - covered);
        if (view == "triangles") {
          uint64_t triangles = 0;
          for (const auto& pass : json["passes"]) triangles += pass["triangles_drawn"].get<uint64_t>();
          CHECK(triangles == json["totals"]["triangles"].get<uint64_t>());
        }
        if (view == "tile-cost") CHECK(json["totals"]["tile_cycles"].get<uint64_t>() > 0);
      }
    }
    // One pass alone, at its own size.
    const RunResult one = runCli(temp.path, "render shadow --size 64x48 --quiet --view overdraw --pass 1 --out one.png");
    REQUIRE(one.status == 0);
    CHECK(nlohmann::json::parse(readText(temp.path / "one.json"))["passes_shown"] == nlohmann::json::array({1}));
  }

  TEST_CASE("bad views and passes are refused, naming the valid ones") {
    cli_test::expectRefused("render shadow --size 32x32 --view nope --out v.png", "overdraw, depth-kills, helpers, tile-cost, triangles");
    cli_test::expectRefused("render shadow --size 32x32 --view help --out v.png", "overdraw, depth-kills, helpers, tile-cost, triangles");
    cli_test::expectRefused("render shadow --size 32x32 --view overdraw --pass 99 --quiet --out v.png", "passes 0..1");
    cli_test::expectRefused("render shadow --size 32x32 --view overdraw --pass x --out v.png", "--pass");
    cli_test::expectRefused("render shadow --size 32x32 --view overdraw --backend gl --out v.png", "--backend raster");
    cli_test::expectRefused("render shadow --size 32x32 --pass 1 --out v.png", "--view");
  }
}
