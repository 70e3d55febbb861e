// Reading an asset file whole, with the checks and the words every loader of io/assets.h
// shares: the file is there, is a regular file, can be read and is not empty, and (in a
// checked asset folder) holds the bytes its manifest lists. Every failure throws
// SceneError("asset <path>: <what is wrong>").
#pragma once

#include <string>

namespace scenes {

[[noreturn]] void failAsset(const std::string& path, const std::string& what);

// Throws SceneError ("asset PATH: no such file", "is a directory, not a file", ...) unless
// `path` names a regular file: the first checks every loader makes, with their words, for a
// caller that must know up front (sweep --check) and reads the file only later.
void checkAssetFileExists(const std::string& path);

// The whole file, after checkAssetFileExists, an open that tells "permission denied" from
// other failures, and a refusal of an empty file; then checked against the asset folder's
// manifest (io/asset_manifest.h) where it has one.
std::string readAssetFile(const std::string& path);

}  // namespace scenes
