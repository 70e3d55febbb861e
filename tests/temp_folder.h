// A fresh temporary folder for one test, removed with its content afterwards: the CLI tests'
// working folders, the image and asset tests' bad files; and the whole bytes of a file, read
// and written.
#pragma once

#include <doctest/doctest.h>

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

namespace testing_support {

struct TempFolder {
  std::filesystem::path path;

  // `prefix` names the folder's test in /tmp ("raster-cli-test" -> raster-cli-test-XXXXXX),
  // so that a folder left by a crashed run says whose it is.
  explicit TempFolder(const std::string& prefix = "raster-test") {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
    REQUIRE(mkdtemp(pattern.data()) != nullptr);
    path = pattern;
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  // Owner permissions back on the folder first, so that a test which takes them away (to
  // check the error for an unreadable path) cannot leave it behind.
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::permissions(path, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ignored);
    std::filesystem::remove_all(path, ignored);
  }

  std::string file(const std::string& name) const { return (path / name).string(); }
};

inline std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  REQUIRE(out.good());
}

}  // namespace testing_support
