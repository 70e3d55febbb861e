// The dump of a frame's targets (`raster render --dump DIR`), and loading it back: how a
// frame rendered in a child process (softpipe, another Gallium driver) reaches this one.
//
// DIR holds, per target in the scene's order:
//   NAME.png   every target, to look at (io/image_io.h's preview); lossless for RGBA8
//   NAME.exr   depth and float targets, lossless (io/exr_io.h)
// and DIR/targets.txt, one "NAME KIND" line per target, KIND one of rgba8, half (RGBA16F),
// float (RGBA32F), depth16, depth24. Loading gives the targets back bit for bit: the same
// formats, sizes, channels, depth bits and payload bytes.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace compare {

// The names of the files above for these targets, in the order they are written (the
// manifest last). Throws std::runtime_error for a target name that cannot be a file name.
std::vector<std::string> targetDumpFiles(const std::vector<scenes::Target>& targets);

// Writes the files above into folder (created if missing; its parent must exist), each
// whole or not at all, calling wrote(PATH) after each (the manifest last). Every path is
// checked before the first is written (checkOutputPath), so a name taken by a folder or a
// link stops the dump with nothing written.
void writeTargetDump(const std::string& folder, const std::vector<scenes::Target>& targets,
                     const std::function<void(const std::string&)>& wrote = {});

// Loads a folder written by writeTargetDump, in the same order. Throws std::runtime_error
// naming the file for a missing or bad manifest or image, or an image of another kind than
// the manifest says.
std::vector<scenes::Target> loadTargetDump(const std::string& folder);

}  // namespace compare
