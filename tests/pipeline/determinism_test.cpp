// Same inputs, same bytes: the output does not depend on the thread count, nor on whether
// the SIMD fast paths are on. Each tile is rasterized by one task in API order, and the
// SIMD lane type computes exactly what the plain C++ one does.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "backends/backends.h"
#include "raster/methods.h"
#include "raster/util/parallel.h"
#include "scenes/soup/soup_check.h"
#include "tests/method_sets.h"
#include "tests/scene_test_helpers.h"

using testing_support::checkSameBytes;

TEST_SUITE("determinism") {
  // The tests below that run more threads than this machine has cores test something only if
  // those threads run at once: a pool of N must have N items in flight together (oneTBB
  // admits only as many workers as there are cores unless it is told otherwise). Each item
  // waits, at most 5 s in all, until as many are in flight as the pool has threads.
  TEST_CASE("a pool of more threads than cores runs that many items at once") {
    for (int threads : {3, 16}) {
      raster::ThreadPool pool(threads);
      std::atomic<int> inFlight{0};
      std::atomic<int> mostAtOnce{0};
      std::atomic<bool> gaveUp{false};
      const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(5);
      pool.parallelFor(threads, [&](int) {
        const int now = ++inFlight;
        int most = mostAtOnce.load();
        while (now > most && !mostAtOnce.compare_exchange_weak(most, now)) {
        }
        while (mostAtOnce.load() < threads && !gaveUp.load()) {
          if (std::chrono::steady_clock::now() > giveUp) gaveUp = true;
          std::this_thread::yield();
        }
        --inFlight;
      });
      CHECK_MESSAGE(mostAtOnce.load() == threads, "pool of ", threads, " threads");
    }
  }

  TEST_CASE("threads 1, 2 and 7 and the scalar path give identical bytes") {
    for (const auto& [w, h] : {std::pair{640, 480}, std::pair{333, 217}}) {
      auto one = scenes::makeRasterBackend(1);
      const auto reference = testing_support::renderScene(*one, "shadow", 1.3f, w, h);
      for (int threads : {2, 7}) {
        auto backend = scenes::makeRasterBackend(threads);
        INFO("threads " << threads << " at " << w << "x" << h);
        checkSameBytes(reference, testing_support::renderScene(*backend, "shadow", 1.3f, w, h));
      }
      auto scalar = scenes::makeRasterBackend(3, /*scalarOnly=*/true);
      INFO("scalar lanes at " << w << "x" << h);
      checkSameBytes(reference, testing_support::renderScene(*scalar, "shadow", 1.3f, w, h));
    }
  }

  // Every scene, every thread count the issue names, with the SIMD lanes and with the plain
  // ones (--scalar): the bytes of one SIMD thread. The scene suites hold one thread to
  // llvmpipe, so all of them match llvmpipe too. Two cases, so that the sanitizer
  // configurations can leave the plain lanes out (which lane type runs changes no thread's
  // share of the work, and the plain lanes are the slowest under them: tests/configs/tsan.sh
  // and asan-ubsan.sh say what covers them there).
  TEST_CASE("every scene: threads 1, 2 and 5 give identical bytes") {
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      for (const auto& [w, h] : {std::pair{97, 61}, std::pair{640, 480}}) {
        auto one = scenes::makeRasterBackend(1);
        const auto reference = testing_support::renderScene(*one, scene, 1.0f, w, h);
        for (int threads : {2, 5}) {
          INFO(scene << " at " << w << "x" << h << ", " << threads << " threads");
          auto backend = scenes::makeRasterBackend(threads);
          checkSameBytes(reference, testing_support::renderScene(*backend, scene, 1.0f, w, h));
        }
      }
    }
  }

  // The plain lanes run at every thread count on the small frame and on five threads on the
  // large one: under the sanitizers a plain-lane frame costs ten times a SIMD one, and what the
  // large frame adds (full tiles, many tiles per thread) does not depend on the lane type.
  TEST_CASE("every scene: scalar lanes give the bytes of SIMD lanes") {
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      for (const auto& [w, h] : {std::pair{97, 61}, std::pair{640, 480}}) {
        auto one = scenes::makeRasterBackend(1);
        const auto reference = testing_support::renderScene(*one, scene, 1.0f, w, h);
        for (int threads : {1, 2, 5}) {
          if (w == 640 && threads != 5) continue;
          INFO(scene << " at " << w << "x" << h << ", " << threads << " threads, scalar lanes");
          auto backend = scenes::makeRasterBackend(threads, /*scalarOnly=*/true);
          checkSameBytes(reference, testing_support::renderScene(*backend, scene, 1.0f, w, h));
        }
      }
    }
  }

  TEST_CASE("a backend that already rendered other frames gives the same bytes again") {
    auto backend = scenes::makeRasterBackend(0);
    const auto first = testing_support::renderScene(*backend, "shadow", 0.7f, 640, 480);
    testing_support::renderScene(*backend, "shadow", 5.0f, 320, 200);   // leaves other state behind
    checkSameBytes(first, testing_support::renderScene(*backend, "shadow", 0.7f, 640, 480));
  }
}

// The code paths a frame can take besides the plain one (every method of every step, draws
// split over threads, visible-first shading) against the plain one's bytes. A suite of its
// own so ctest runs it beside the one above (these two are the longest under the sanitizers).
TEST_SUITE("determinism_paths") {
  // The same under every method of every step (tests/method_sets.h), so each method's SIMD
  // code is held to its scalar reference and to one thread, not only gl's. Every scene at a
  // small size (the methods' code paths, not the frame's, are what is new here), set up
  // once per backend (deferred's assets take longer to load than a frame of it to render)
  // and drawn under each set in turn: the backends see the same frames in the same order.
  // Scalar lanes run on one thread here: on several they are held to one thread's bytes by
  // the suite above ("every scene: scalar lanes", 1, 2 and 5 threads).
  TEST_CASE("every method of every step, every scene: SIMD lanes on threads 1 and 3, scalar lanes, give identical bytes") {
    scenes::SceneOptions options;
    options.width = 97;
    options.height = 61;
    for (const std::string& sceneName : testing_support::scenesUnderTest()) {
      // The first, SIMD lanes on one thread, is the reference.
      auto runs = testing_support::prepareScene(sceneName, options, {{1, false}, {3, false}, {1, true}});
      for (const raster::MethodSet& set : testing_support::everyMethodSet()) {
        const raster::ScopedMethods scoped(set);
        std::vector<std::vector<scenes::Target>> targets;
        for (testing_support::PreparedScene& run : runs) targets.push_back(run.render(options.time));
        for (size_t i = 1; i < runs.size(); ++i) {
          INFO("methods " << raster::methodLabel(set) << ": " << sceneName << " at " << options.width << "x" << options.height
                          << ", " << runs[i].name);
          checkSameBytes(targets[0], targets[i]);
        }
      }
    }
  }

  // Draws of thousands of triangles (the hdr scene's instanced cubes, deferred's statue) are
  // set up in chunks and binned in parts of the triangle list in parallel when there are
  // threads to share them, and deferred's single-instance statue has its vertices shaded in
  // ranges (renderer.cpp, geometry/bin.h): the triangles must reach every tile in API order,
  // with their own varyings, whatever the chunks. 16 and 32 threads (more than the machine
  // has, as a machine with more cores would run them) cut the draws and the frame's tiles
  // finest: more threads than this frame has tiles.
  TEST_CASE("large draws shaded, set up and binned in parallel give the bytes of one thread") {
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      auto one = scenes::makeRasterBackend(1);
      const auto reference = testing_support::renderScene(*one, scene, 0.9f, 333, 217);
      for (int threads : {2, 7, 16, 32}) {
        INFO(scene << " with " << threads << " threads");
        auto backend = scenes::makeRasterBackend(threads);
        checkSameBytes(reference, testing_support::renderScene(*backend, scene, 0.9f, 333, 217));
      }
    }
  }

  // A chunk of a large draw is set up into a window of the pass's lists with a slot per
  // primitive (renderer.cpp, geometry/setup.h); what clipping makes beyond those slots
  // spills into a list appended after the draw and binned right after its chunk. Here every
  // triangle reaches far past the viewport's guard band, so each is clipped into two and
  // every chunk spills; all lie at one depth, so under the LESS test each pixel keeps the
  // first triangle to reach it, and any triangle out of API order shows. The bytes must be
  // one thread's (which sets up in one piece), and llvmpipe's.
  TEST_CASE("a large draw whose clipping makes more triangles than it has primitives gives the bytes of one thread") {
    scenes::soup::Soup soup;
    soup.width = 160;
    soup.height = 120;
    for (int i = 0; i < 4096; ++i) {
      // A sliver from a point in the frame to an apex 10^4 viewport widths to the left or
      // right, crossing the slivers started before it.
      const float x = float(i % 64) / 32.0f - 1.0f, y = float(i / 64) / 32.0f - 1.0f;
      const float apex = i % 2 ? 1e4f : -1e4f;
      soup.triangles.push_back({scenes::soup::Kind::FarOut,
                                {glm::vec4(x, y, 0.5f, 1.0f), glm::vec4(x + 0.02f, y + 0.06f, 0.5f, 1.0f),
                                 glm::vec4(apex, y + 0.03f * float(i % 5), 0.5f, 1.0f)}});
    }
    auto reference = scenes::makeRasterBackend(1);
    const scenes::soup::Rendering one = scenes::soup::SoupRenderer(*reference, soup.width, soup.height).render(soup);
    auto gl = scenes::makeGlBackend();
    const scenes::soup::Verdict againstGl =
        scenes::soup::compare(soup, one, scenes::soup::SoupRenderer(*gl, soup.width, soup.height).render(soup));
    CHECK(againstGl.covered > soup.width * soup.height / 2);
    CHECK(againstGl.identical());
    for (int threads : {2, 7, 16}) {
      INFO(threads << " threads");
      auto backend = scenes::makeRasterBackend(threads);
      const scenes::soup::Rendering many = scenes::soup::SoupRenderer(*backend, soup.width, soup.height).render(soup);
      CHECK(scenes::soup::compare(soup, many, one).identical());
    }
  }

  // Passes whose colour draws do not blend shade only each pixel's visible fragment
  // (tile/visible_first.h): the hdr scene's cubes and deferred's G-buffer
  // (many triangles per tile, overlapping) take that path. It must leave the bytes of
  // shading every fragment in order, with SIMD lanes and with plain ones (the plain ones on
  // the smaller frame, as above).
  TEST_CASE("shading only visible fragments gives the bytes of shading every fragment in order") {
    for (const std::string& scene : testing_support::scenesUnderTest()) {
      for (const auto& [w, h] : {std::pair{640, 480}, std::pair{333, 217}}) {
        INFO(scene << " at " << w << "x" << h);
        auto inOrder = scenes::makeRasterBackend(2, /*scalarOnly=*/false, /*visibilityFirst=*/false);
        const auto reference = testing_support::renderScene(*inOrder, scene, 1.3f, w, h);
        auto visible = scenes::makeRasterBackend(2);
        checkSameBytes(reference, testing_support::renderScene(*visible, scene, 1.3f, w, h));
        if (w == 640) continue;
        auto scalar = scenes::makeRasterBackend(2, /*scalarOnly=*/true);
        checkSameBytes(reference, testing_support::renderScene(*scalar, scene, 1.3f, w, h));
      }
    }
  }
}
