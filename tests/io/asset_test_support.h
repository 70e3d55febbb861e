// What the asset tests share (assets_test.cpp, image_structure_test.cpp): a temporary folder
// for bad files, the real assets, and the check that an error is one "asset PATH: ..." line.
#pragma once

#include <doctest/doctest.h>

#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "io/assets.h"
#include "scenes/scene.h"
#include "tests/temp_folder.h"

namespace asset_test {

namespace fs = std::filesystem;

struct TempFolder : testing_support::TempFolder {
  TempFolder() : testing_support::TempFolder("raster-assets-test") {}
};

inline std::string realAsset(const std::string& relative) {
  const std::string p = scenes::assetPath(scenes::SceneOptions{}, relative);
  INFO("asset folder: " << scenes::assetDirectory(scenes::SceneOptions{}));
  REQUIRE_MESSAGE(fs::exists(p), "missing real asset " << p);
  return p;
}

using testing_support::readBytes;
using testing_support::writeBytes;

// The SceneError message of f(); fails the test if f does not throw one.
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const scenes::SceneError& e) {
    MESSAGE(std::string(e.what()));
    return e.what();
  } catch (const std::exception& e) {
    FAIL("threw something other than SceneError: " << e.what());
  }
  FAIL("did not throw");
  return "";
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// "asset PATH: ..." or, for a problem on one line of a text file, "asset PATH:LINE: ...".
inline void checkOneLine(const std::string& message, const std::string& path) {
  const std::string prefix = "asset " + path + ":";
  REQUIRE(message.rfind(prefix, 0) == 0);
  size_t at = prefix.size();
  if (at < message.size() && std::isdigit(static_cast<unsigned char>(message[at]))) {
    while (at < message.size() && std::isdigit(static_cast<unsigned char>(message[at]))) ++at;
    CHECK(message.compare(at, 1, ":") == 0);
    ++at;
  }
  CHECK(message.compare(at, 1, " ") == 0);
  CHECK(message.find('\n') == std::string::npos);
}

inline constexpr const char* kCatObj = "cat/concrete_cat_statue.obj";
inline const std::vector<std::string> kJpegs = {
    "cat/textures/concrete_cat_statue_diff_2k.jpg",   "cat/textures/concrete_cat_statue_nor_gl_1k.jpg",
    "cat/textures/concrete_cat_statue_arm_2k.jpg",    "brick/Bricks031_1K-JPG_Color.jpg",
    "brick/Bricks031_1K-JPG_NormalGL.jpg",            "brick/Bricks031_1K-JPG_AmbientOcclusion.jpg",
    "brick/Bricks031_1K-JPG_Roughness.jpg"};
inline constexpr const char* kHdr = "hdri/cannon_1k.hdr";

}  // namespace asset_test
