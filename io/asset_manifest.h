// The SHA-256 manifest of an asset folder: a file `SHA256SUMS` (the format `sha256sum`
// writes and `sha256sum -c` checks: "<64 hex digits>  <path relative to the folder>" a line).
//
// A folder with a manifest is a checked asset root: every asset read from below it must be
// listed and have the listed hash, so a changed or truncated file is an error naming the file
// and both hashes, before any decoder sees it. The repository's assets/ has one; a folder
// given with --assets or RASTER_ASSETS is checked when it has one too, and read as it is when
// it has none (a user's own assets, or the hostile files of the tests).
#pragma once

#include <string>
#include <string_view>

namespace scenes {

// The SHA-256 of `data`, as 64 lowercase hex digits.
std::string sha256Hex(std::string_view data);

// Checks `data`, the bytes of the asset file at `path`, against the manifest of the nearest
// folder above it (up to three levels: the deepest asset is two folders down) that has one.
// Throws SceneError naming the file and both hashes when they differ, or the manifest when
// the file is not listed or the manifest is malformed. Nothing to check without a manifest.
void checkAssetAgainstManifest(const std::string& path, std::string_view data);

}  // namespace scenes
