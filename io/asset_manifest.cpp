// Asset manifests (asset_manifest.h).
#include "io/asset_manifest.h"

#include <openssl/evp.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "scenes/scene.h"

namespace scenes {
namespace {

namespace fs = std::filesystem;

constexpr const char* kManifestName = "SHA256SUMS";
constexpr int kLevelsUp = 3;

// path -> hash of one manifest; SceneError naming the manifest and line when malformed.
std::map<std::string, std::string> readManifest(const fs::path& manifest) {
  std::ifstream in(manifest);
  if (!in) throw SceneError("asset manifest " + manifest.string() + ": cannot be read");
  std::map<std::string, std::string> hashes;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    // "<hash>  <path>" ("<hash> *<path>" in binary mode): 64 hex digits, a space, a mode
    // character, the path.
    const bool wellFormed = line.size() > 66 && line[64] == ' ' && (line[65] == ' ' || line[65] == '*') &&
                            line.find_first_not_of("0123456789abcdef") >= 64;
    if (!wellFormed)
      throw SceneError("asset manifest " + manifest.string() + ":" + std::to_string(number) +
                       ": not '<64 lowercase hex digits>  <path>'");
    hashes[line.substr(66)] = line.substr(0, 64);
  }
  return hashes;
}

}  // namespace

std::string sha256Hex(std::string_view data) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(data.data(), data.size(), digest, &length, EVP_sha256(), nullptr) != 1 || length != 32)
    throw std::runtime_error("SHA-256 failed (OpenSSL EVP_Digest)");
  static const char* kHex = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) hex.append({kHex[digest[i] >> 4], kHex[digest[i] & 15]});
  return hex;
}

void checkAssetAgainstManifest(const std::string& path, std::string_view data) {
  const fs::path file = fs::absolute(fs::path(path)).lexically_normal();
  fs::path folder = file.parent_path();
  for (int level = 0; level < kLevelsUp && !folder.empty(); ++level, folder = folder.parent_path()) {
    const fs::path manifest = folder / kManifestName;
    std::error_code error;
    if (!fs::is_regular_file(manifest, error)) {
      if (folder == folder.root_path()) return;
      continue;
    }
    const std::string relative = file.lexically_relative(folder).generic_string();
    const std::map<std::string, std::string> hashes = readManifest(manifest);
    const auto listed = hashes.find(relative);
    if (listed == hashes.end())
      throw SceneError("asset " + path + ": not listed in " + manifest.string() +
                       " (every file of a checked asset folder must be; add its line with sha256sum)");
    const std::string actual = sha256Hex(data);
    if (actual != listed->second)
      throw SceneError("asset " + path + ": changed or truncated: its SHA-256 is " + actual + ", " +
                       manifest.string() + " lists " + listed->second);
    return;
  }
}

}  // namespace scenes
