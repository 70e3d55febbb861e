// ꟻLIP (compare/flip.h) against the reference implementation's values, and what a caller of
// `raster compare` relies on: no difference reads 0, the metric does not care which image is
// the reference, the extreme reads 1, and bad input is refused with a message.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "compare/flip.h"
#include "compare/metrics.h"
#include "io/image_io.h"

namespace {

std::string fixture(const std::string& name) {
  return std::string(RASTER_SOURCE_DIR) + "/tests/compare/fixtures/flip/" + name;
}

scenes::ImageData solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  scenes::ImageData image;
  image.width = w;
  image.height = h;
  image.format = scenes::TexelFormat::RGBA8;
  for (int i = 0; i < w * h; ++i) image.rgba8.insert(image.rgba8.end(), {r, g, b, 255});
  return image;
}

}  // namespace

TEST_SUITE("flip") {

TEST_CASE("the default observer is the reference's: 0.7 m from a 0.7 m wide 3840-pixel monitor") {
  CHECK(compare::flipDefaultPpd() == doctest::Approx(67.0206).epsilon(1e-5));
  CHECK(compare::flipPpd(0.7f, 3840.0f, 0.7f) == compare::flipDefaultPpd());
}

TEST_CASE("the reference implementation's map and mean on a pair cut from its reference image") {
  // Values from NVlabs/flip's src/cpp/FLIP.h at 1eb247c (fixtures/flip/README.md says how).
  const scenes::ImageData reference = compare::readPng(fixture("reference.png"));
  const scenes::ImageData test = compare::readPng(fixture("test.png"));
  const scenes::ImageData expected = compare::readPng(fixture("expected_map.png"));
  REQUIRE(reference.width == 128);
  REQUIRE(expected.width == reference.width);
  REQUIRE(expected.height == reference.height);

  const std::vector<float> map = compare::flipErrorMap(reference, test);
  REQUIRE(map.size() == size_t(128 * 96));
  // The reference tool saves maps as uint8(255 * e + 0.5); every pixel must land on its byte.
  int differing = 0;
  for (size_t i = 0; i < map.size(); ++i) {
    CHECK(map[i] >= 0.0f);
    CHECK(map[i] <= 1.0f);
    differing += uint8_t(255.0f * map[i] + 0.5f) != expected.rgba8[4 * i];
  }
  CHECK(differing == 0);
  // The reference prints the mean with six decimals: 0.087220.
  CHECK(std::fabs(compare::flipMean(map) - 0.087220) < 5e-7);
}

TEST_CASE("the map is the same bytes at any thread count") {
  const scenes::ImageData reference = compare::readPng(fixture("reference.png"));
  const scenes::ImageData test = compare::readPng(fixture("test.png"));
  const std::vector<float> one = compare::flipErrorMap(reference, test, compare::flipDefaultPpd(), 1);
  CHECK(compare::flipErrorMap(reference, test, compare::flipDefaultPpd(), 3) == one);
  CHECK(compare::flipErrorMap(reference, test, compare::flipDefaultPpd(), 7) == one);
}

TEST_CASE("identical images read 0 everywhere") {
  const scenes::ImageData reference = compare::readPng(fixture("reference.png"));
  const std::vector<float> map = compare::flipErrorMap(reference, reference);
  for (float e : map) CHECK(e == 0.0f);
  CHECK(compare::flipMean(reference, reference) == 0.0);
}

TEST_CASE("alpha is ignored: LDR-FLIP reads colour only") {
  const scenes::ImageData reference = compare::readPng(fixture("reference.png"));
  scenes::ImageData translucent = reference;
  for (size_t i = 3; i < translucent.rgba8.size(); i += 4) translucent.rgba8[i] = uint8_t(i * 7);
  CHECK(compare::flipMean(reference, translucent) == 0.0);
}

TEST_CASE("swapping reference and test gives the same map (every step of FLIP is symmetric)") {
  const scenes::ImageData reference = compare::readPng(fixture("reference.png"));
  const scenes::ImageData test = compare::readPng(fixture("test.png"));
  CHECK(compare::flipErrorMap(reference, test) == compare::flipErrorMap(test, reference));
}

TEST_CASE("the largest colour difference, green against blue, reads 1 (the paper's cmax)") {
  // Uniform images have no edges or points, so the error is the colour difference alone.
  const std::vector<float> map = compare::flipErrorMap(solid(16, 8, 0, 255, 0), solid(16, 8, 0, 0, 255));
  for (float e : map) CHECK(e == doctest::Approx(1.0).epsilon(1e-5));
  // A small difference reads small, and a larger one larger.
  const double slight = compare::flipMean(solid(16, 8, 128, 128, 128), solid(16, 8, 130, 128, 128));
  const double more = compare::flipMean(solid(16, 8, 128, 128, 128), solid(16, 8, 160, 128, 128));
  CHECK(slight > 0.0);
  CHECK(slight < more);
  CHECK(more < 1.0);
}

TEST_CASE("compare's stats line gains the FLIP mean for colour targets, '-' for the others") {
  const scenes::ImageData reference = compare::readPng(fixture("reference.png"));
  const scenes::ImageData test = compare::readPng(fixture("test.png"));
  compare::TargetStats stats = compare::compareImages("final", test, reference);
  const std::string before = compare::formatStatsLine(stats);
  CHECK(before.find("flip") == std::string::npos);   // not asked for: the line as it was
  compare::measureFlip(stats, test, reference);
  REQUIRE(stats.flipMean);
  CHECK(*stats.flipMean == compare::flipMean(reference, test));
  // Every column as before, the mean with the reference's six decimals after them.
  CHECK(compare::formatStatsLine(stats) == before + "  flip 0.087220");

  compare::TargetStats same = compare::compareImages("final", reference, reference);
  compare::measureFlip(same, reference, reference);
  CHECK(same.flipMean == 0.0);

  scenes::ImageData depth;
  depth.width = 2;
  depth.height = 1;
  depth.format = scenes::TexelFormat::Depth24;
  depth.depthBits = 24;
  depth.depth = {1000, 2000};
  scenes::ImageData otherDepth = depth;
  otherDepth.depth[1] = 2003;
  compare::TargetStats depthStats = compare::compareImages("depth", depth, otherDepth);
  compare::measureFlip(depthStats, depth, otherDepth);
  CHECK(!depthStats.flipMean);
  const std::string line = compare::formatStatsLine(depthStats);
  CHECK(line.substr(line.size() - 8) == "  flip -");
}

TEST_CASE("bad input is refused with a message") {
  const scenes::ImageData a = solid(4, 4, 10, 20, 30);
  SUBCASE("different sizes") {
    CHECK_THROWS_WITH_AS(compare::flipErrorMap(a, solid(4, 3, 10, 20, 30)), doctest::Contains("differ in size"),
                         std::invalid_argument);
  }
  SUBCASE("a depth image") {
    scenes::ImageData depth;
    depth.width = 4;
    depth.height = 4;
    depth.format = scenes::TexelFormat::Depth24;
    depth.depth.assign(16, 0);
    depth.depthBits = 24;
    CHECK_THROWS_WITH_AS(compare::flipErrorMap(a, depth), doctest::Contains("not RGBA8"), std::invalid_argument);
  }
  SUBCASE("a float image") {
    scenes::ImageData floats;
    floats.width = 4;
    floats.height = 4;
    floats.format = scenes::TexelFormat::RGBA32F;
    floats.floats.assign(64, 0.5f);
    CHECK_THROWS_WITH_AS(compare::flipErrorMap(floats, a), doctest::Contains("not RGBA8"), std::invalid_argument);
  }
  SUBCASE("a buffer of the wrong length") {
    CHECK_THROWS_WITH_AS(compare::flipErrorMap(a.rgba8, std::vector<uint8_t>(63), 4, 4),
                         doctest::Contains("64 bytes"), std::invalid_argument);
  }
  SUBCASE("an empty size") {
    CHECK_THROWS_AS(compare::flipErrorMap(std::vector<uint8_t>{}, std::vector<uint8_t>{}, 0, 0),
                    std::invalid_argument);
  }
  SUBCASE("pixels per degree not positive") {
    CHECK_THROWS_WITH_AS(compare::flipErrorMap(a, a, 0.0f), doctest::Contains("pixels per degree"),
                         std::invalid_argument);
    CHECK_THROWS_AS(compare::flipErrorMap(a, a, NAN), std::invalid_argument);
  }
}

}  // TEST_SUITE
