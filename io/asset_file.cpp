#include "io/asset_file.h"

#include "io/asset_manifest.h"
#include "scenes/scene.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace scenes {

namespace fs = std::filesystem;

void failAsset(const std::string& path, const std::string& what) { throw SceneError("asset " + path + ": " + what); }

void checkAssetFileExists(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) {
    std::error_code ec2;
    if (fs::is_symlink(fs::symlink_status(path, ec2))) failAsset(path, "no such file (a symbolic link to a missing file)");
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::exists(parent, ec2) && !ec2)
      failAsset(path, "no such file (the folder " + parent.string() + " does not exist)");
    failAsset(path, "no such file");
  }
  if (ec) {
    if (ec == std::errc::permission_denied) failAsset(path, "permission denied (cannot look into its folder)");
    failAsset(path, "cannot be examined (" + ec.message() + ")");
  }
  if (fs::is_directory(st)) failAsset(path, "is a directory, not a file");
  if (!fs::is_regular_file(st)) failAsset(path, "is not a regular file");
}

// The whole file, after checking that it is there, is a file, can be read and is not empty.
std::string readAssetFile(const std::string& path) {
  checkAssetFileExists(path);
  std::error_code ec;
  errno = 0;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    const int e = errno;
    if (e == EACCES || e == EPERM) failAsset(path, "permission denied");
    failAsset(path, std::string("cannot be opened (") + std::strerror(e) + ")");
  }
  std::string data;
  const uintmax_t expected = fs::file_size(path, ec);
  if (!ec) data.reserve(static_cast<size_t>(expected));
  char buf[1 << 16];
  size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) data.append(buf, got);
  const bool readError = std::ferror(f) != 0;
  const int e = errno;
  std::fclose(f);
  if (readError) failAsset(path, std::string("read error (") + std::strerror(e) + ")");
  if (data.empty()) failAsset(path, "empty file (0 bytes)");
  checkAssetAgainstManifest(path, data);   // a checked asset folder: the listed bytes or an error
  return data;
}

}  // namespace scenes
