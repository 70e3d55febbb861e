// The test binary's entry point (doctest). ctest runs it once per test suite.
//
// $RASTER_TEST_SCENE_ALIAS=NEW=EXISTING registers one more scene row first: EXISTING's
// under the name NEW. The registry suite runs the generic suites that way
// (tests/registry/registry_test.cpp), to see that a new row is all they need.
//
// $RASTER_TEST_CASE_EXCLUDE leaves out the test cases whose names match it (doctest's
// --test-case-exclude: wildcards, commas between patterns), for a CI configuration that
// runs a suite through ctest but has no use for some of its cases (tests/configs/tsan.sh).
//
// Decoded images are kept for the whole run (scenes::ScopedImageCache): the suites set the
// same scenes up hundreds of times, and decoding their JPEGs was a quarter of the suite's
// CPU time; every check of a file still runs on each load.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "io/assets.h"
#include "scenes/registry.h"

int main(int argc, char** argv) {
  if (const char* alias = std::getenv("RASTER_TEST_SCENE_ALIAS"); alias && *alias) {
    const std::string text = alias;
    const size_t equals = text.find('=');
    if (equals == std::string::npos) {
      std::cerr << "RASTER_TEST_SCENE_ALIAS: '" << text << "' is not NEW=EXISTING\n";
      return 2;
    }
    try {
      scenes::SceneEntry row = scenes::sceneEntry(text.substr(equals + 1));
      row.name = text.substr(0, equals);
      scenes::registerScene(std::move(row));
    } catch (const scenes::SceneError& e) {
      std::cerr << "RASTER_TEST_SCENE_ALIAS: " << e.what() << "\n";
      return 2;
    }
  }
  const scenes::ScopedImageCache decodedOnce;
  doctest::Context context(argc, argv);
  if (const char* exclude = std::getenv("RASTER_TEST_CASE_EXCLUDE"); exclude && *exclude)
    context.addFilter("test-case-exclude", exclude);
  return context.run();
}
