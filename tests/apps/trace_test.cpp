// Pixel history: `raster trace` and the pipeline's records behind it (raster/pixel_history.h).
//
// What a user depends on: the value each traced pass stores is the pixel of the frame's
// target (its dump), the fragments of a pass tell one consistent story (each starts from
// the value the last one left, the last leaves the stored value), each lookup's footprint
// explains its result, tracing changes no byte of any target and no thread count changes
// the trace, and a pixel outside the image is bad input.
#include <doctest/doctest.h>

#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "backends/backends.h"
#include "raster/methods.h"
#include "raster/pixel_history.h"
#include "scenes/registry.h"
#include "tests/apps/cli_test_helpers.h"
#include "tests/scene_test_helpers.h"

namespace {

using namespace cli_test;
using nlohmann::json;

json traceJson(const TempFolder& temp, const std::string& scene, const std::string& pixel, const std::string& extra = "") {
  const RunResult run = runCli(temp.path, "trace " + scene + " --size 160x120 --pixel " + pixel + " --quiet --json t.json " + extra);
  INFO(run.err);
  REQUIRE(run.status == 0);
  return json::parse(readText(temp.path / "t.json"));
}

// Values equal, NaN equal to NaN (JSON writes it as null on both sides).
bool same(const json& a, const json& b) { return a.dump() == b.dump(); }

// The story of one pass must hold together.
void checkPass(const json& pass) {
  INFO("pass " << pass["pass"].get<int>() << " " << pass["label"].get<std::string>());
  const json& fragments = pass["fragments"];
  json value = pass["start"];
  for (const json& f : fragments) {
    CHECK(same(f["before"], value));
    value = f["after"];
    if (f["written"].get<bool>()) {
      CHECK(f["covered"].get<bool>());
      CHECK(f["depth_test"] != "failed");
      CHECK(f["shaded"].get<bool>());
    }
    if (f["helper"].get<bool>()) CHECK_FALSE(f["written"].get<bool>());
    if (!f["written"].get<bool>() && !f["region_fill"].get<bool>()) {   // nothing of it may land
      for (auto it = f["before"].begin(); it != f["before"].end(); ++it)
        if (!it.value().is_object()) CHECK(same(it.value(), f["after"][it.key()]));
    }
    for (const json& s : f.value("samples", json::array())) {
      CHECK(same(s["result"], s["explained"]));   // the footprint explains the lookup
      double weights = 0;
      for (const json& t : s["texels"]) weights += t["weight"].get<double>();
      CHECK(weights == doctest::Approx(1.0).epsilon(1e-5));
    }
  }
  if (!fragments.empty()) CHECK(same(value, pass["stored"]));
  for (auto it = pass["matches_dump"].begin(); it != pass["matches_dump"].end(); ++it) {
    INFO(it.key());
    CHECK(it.value().get<bool>());
  }
}

struct Traced {
  int passes = 0, fragments = 0, lookups = 0, failedCompares = 0, helpers = 0;
  std::map<std::string, int> fragmentsOfPass;
};

Traced checkTrace(const json& trace, int x, int y) {
  CHECK(trace["stored_matches_dumps"].get<bool>());
  const json& last = trace["passes"].back();
  CHECK(last["label"] == "final");
  CHECK(last["pixel"] == json::array({x, y}));
  for (const json& d : last["difference"]["final"]) CHECK(d.get<double>() == 0.0);   // gl is llvmpipe's bytes
  Traced traced;
  for (const json& pass : trace["passes"]) {
    checkPass(pass);
    ++traced.passes;
    traced.fragmentsOfPass[pass["label"]] = int(pass["fragments"].size());
    for (const json& f : pass["fragments"]) {
      ++traced.fragments;
      traced.helpers += f["helper"].get<bool>();
      for (const json& s : f.value("samples", json::array())) {
        ++traced.lookups;
        for (const json& t : s["texels"]) traced.failedCompares += t.contains("compare") && !t["compare"].get<bool>();
      }
    }
  }
  return traced;
}

}  // namespace

TEST_SUITE("trace") {
  TEST_CASE("shadow: floor, shadowed, cube and background pixels, and the image's corners") {
    TempFolder temp;
    const Traced shadowed = checkTrace(traceJson(temp, "shadow", "90,70"), 90, 70);
    CHECK(shadowed.failedCompares > 0);              // the cube's shadow: some PCF texels fail
    CHECK(shadowed.fragmentsOfPass.count("shadow_map") == 1);
    const Traced background = checkTrace(traceJson(temp, "shadow", "120,30"), 120, 30);
    CHECK(background.fragmentsOfPass.at("final") == 0);   // only the clear reaches it
    CHECK(background.passes == 1);                        // and it reads no shadow map
    const Traced cube = checkTrace(traceJson(temp, "shadow", "80,60"), 80, 60);
    CHECK(cube.fragmentsOfPass.at("final") >= 2);          // overdraw: floor, then cube faces
    checkTrace(traceJson(temp, "shadow", "0,0"), 0, 0);
    checkTrace(traceJson(temp, "shadow", "159,119"), 159, 119);
  }

  TEST_CASE("deferred: the G-buffer, SSAO and shadow map behind a lit pixel; a sky pixel") {
    TempFolder temp;
    const json lit = traceJson(temp, "deferred", "75,65");
    const Traced traced = checkTrace(lit, 75, 65);
    for (const char* pass : {"shadow_map", "gbuffer", "ssao", "final"}) CHECK(traced.fragmentsOfPass.count(pass) == 1);
    CHECK(traced.lookups > 30);   // SSAO's kernel, the PCF taps, the G-buffer reads
    // Denormals are kept from the G-buffer's half-float draw on, as llvmpipe's threads keep
    // them (raster/simd/gl_math.h); the text says so under those passes.
    for (const json& pass : lit["passes"])
      if (pass["label"] != "shadow_map") CHECK(pass["denormals"] == "kept");
    // The G-buffer pass's value is what the lighting pass read there.
    const Traced sky = checkTrace(traceJson(temp, "deferred", "80,2"), 80, 2);
    CHECK(sky.fragmentsOfPass.count("gbuffer") == 1);
    checkTrace(traceJson(temp, "deferred", "159,0"), 159, 0);
  }

  TEST_CASE("hdr: the bloom chain behind a pixel, every mip down and up") {
    TempFolder temp;
    const Traced traced = checkTrace(traceJson(temp, "hdr", "50,37"), 50, 37);
    for (int i = 0; i < 5; ++i) CHECK(traced.fragmentsOfPass.count("bloom_down_" + std::to_string(i)) == 1);
    for (int i = 0; i < 4; ++i) CHECK(traced.fragmentsOfPass.count("bloom_up_" + std::to_string(i)) == 1);
    CHECK(traced.fragmentsOfPass.count("hdr_scene") == 1);
    checkTrace(traceJson(temp, "hdr", "0,119"), 0, 119);
  }

  TEST_CASE("the trace does not depend on the thread count, and the text says what the JSON says") {
    TempFolder temp;
    const json one = traceJson(temp, "deferred", "60,70", "--threads 1 --no-reference");
    const json two = traceJson(temp, "deferred", "60,70", "--threads 2 --no-reference");
    CHECK(one.dump() == two.dump());
    const RunResult text = runCli(temp.path, "trace deferred --size 160x120 --pixel 60,70 --quiet --no-reference");
    REQUIRE(text.status == 0);
    for (const json& pass : one["passes"]) {
      std::string quoted = pass["label"].get<std::string>();
      quoted.insert(quoted.begin(), '"');
      quoted.push_back('"');
      CHECK(text.out.find(quoted) != std::string::npos);
    }
    CHECK(text.out.find("equals the frame's dump") != std::string::npos);
    CHECK(text.out.find("denormals kept") != std::string::npos);
  }

  TEST_CASE("a coarse-shaded pass: the invocation behind the pixel, its coarse pixel, and where its outputs went") {
    TempFolder temp;
    for (const char* rate : {"2x2", "4x4", "2x2-all"}) {
      INFO(rate);
      const int side = rate[0] - '0';
      const json trace = traceJson(temp, "deferred", "75,65", std::string("--no-reference --method shading=") + rate);
      CHECK(trace["stored_matches_dumps"].get<bool>());
      std::map<std::string, int> coarsePasses;
      for (const json& pass : trace["passes"]) {
        checkPass(pass);   // the story holds, and the stored value is the frame's
        const std::string label = pass["label"];
        const bool post = label == "ssao" || label == "final";   // deferred's passes without a depth test
        const bool coarse = post || (std::string(rate) == "2x2-all" && label == "gbuffer");
        const int x = pass["texel"][0], y = pass["texel"][1];
        std::set<std::string> broadcast;   // the texels the pass's invocations wrote
        for (const json& f : pass["fragments"]) {
          INFO(label);
          if (!coarse || !f.contains("coarse")) {   // the 1x1 passes keep the 1x1 record
            CHECK_FALSE(f.contains("coarse"));
            continue;
          }
          coarsePasses[label] = 1;
          const json& c = f["coarse"];
          CHECK(c["size"] == json::array({side, side}));
          // The coarse pixel holding the texel, aligned to the memory origin.
          CHECK(c["texel"] == json::array({x - x % side, y - y % side}));
          if (!f["shaded"].get<bool>()) continue;
          // One invocation at the coarse pixel's centre, its outputs on the pixels that passed.
          const double centreX = c["texel"][0].get<int>() + side / 2.0;
          CHECK(c["sample_position"][0].get<double>() == centreX);
          bool here = false;
          for (const json& p : c["broadcast_to"]) here |= p == json::array({x, y});
          CHECK(here == f["written"].get<bool>());
          if (!f["written"].get<bool>()) CHECK(f["helper"].get<bool>());
          CHECK(c["broadcast_to"].size() <= size_t(side * side));
          for (const json& p : c["broadcast_to"])   // a post pass has one layer: one writer per pixel
            if (!broadcast.insert(p.dump()).second) CHECK_FALSE(post);
        }
        // A fullscreen pass writes the whole coarse pixel, from one invocation or, where the
        // clipped triangle's seam crosses it, one per piece (coarse fragments are per primitive).
        if (post) CHECK(broadcast.size() == size_t(side * side));
      }
      CHECK(coarsePasses["ssao"] == 1);
      CHECK(coarsePasses["final"] == 1);
      if (std::string(rate) == "2x2-all") CHECK(coarsePasses["gbuffer"] >= 1);
    }
    // The text says it too.
    const RunResult text = runCli(temp.path, "trace deferred --size 160x120 --pixel 75,65 --quiet --no-reference --method shading=2x2");
    REQUIRE(text.status == 0);
    CHECK(text.out.find("coarse pixel 2x2 from texel [74,") != std::string::npos);
    CHECK(text.out.find("outputs broadcast to 4 of its 4 pixels") != std::string::npos);
  }

  TEST_CASE("bad pixels are refused before rendering") {
    expectRefused("trace shadow --size 160x120 --pixel 160,0", "outside the 160x120 image");
    expectRefused("trace shadow --size 160x120 --pixel 0,120", "outside");
    expectRefused("trace shadow --pixel -1,5", "--pixel");
    expectRefused("trace shadow --pixel 5", "--pixel");
    expectRefused("trace shadow --pixel 5,5 --json /no/such/folder/t.json", "--json");
  }

  TEST_CASE("tracing changes no byte of any target, at any probe, at the GL rate and coarse rates") {
    for (const char* rate : {"1x1", "2x2", "2x2-all"})
    for (const std::string& name : testing_support::scenesUnderTest()) {
      INFO(name << " at shading=" << rate);
      raster::MethodSet methods;
      raster::setMethod(methods, "shading", rate);
      const raster::ScopedMethods scoped(methods);
      scenes::SceneOptions options;
      options.width = 96;
      options.height = 72;
      auto render = [&](bool traced) {
        auto scene = scenes::makeScene(name, options);
        auto backend = scenes::makeRasterBackend(2);
        backend->resizeDefaultFramebuffer(options.width, options.height);
        scene->setup(*backend);
        raster::PixelHistory history;
        for (int pass = 0; pass < 16; ++pass) history.probes[pass] = {(pass * 37) % 96, (pass * 23) % 72};
        if (traced) scenes::setPixelHistory(*backend, &history);
        scene->renderFrame(*backend, options.time);
        scenes::setPixelHistory(*backend, nullptr);
        if (traced) CHECK(!history.passes.empty());
        return scene->readTargets(*backend);
      };
      const std::vector<scenes::Target> plain = render(false), traced = render(true);
      REQUIRE(plain.size() == traced.size());
      for (size_t i = 0; i < plain.size(); ++i) {
        INFO(plain[i].name);
        CHECK(plain[i].image.rgba8 == traced[i].image.rgba8);
        CHECK(plain[i].image.depth == traced[i].image.depth);
        REQUIRE(plain[i].image.floats.size() == traced[i].image.floats.size());
        if (!plain[i].image.floats.empty())   // bit for bit: a NaN pixel equals itself
          CHECK(std::memcmp(plain[i].image.floats.data(), traced[i].image.floats.data(), plain[i].image.floats.size() * 4) == 0);
      }
    }
  }
}
