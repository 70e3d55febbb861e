// The reproducer file of `raster soup`: one soup (scenes/soup/soup.h) as JSON, bit exact.
//
//   {"format": "raster-soup-1", "seed": 7, "width": 64, "height": 64,
//    "triangles": [{"kind": "sliver", "clip": [[X, Y, Z, W], [...], [...]]}, ...],
//    "meshes": [{"kind": "fan", "note": "on screen", "clip": [[X, Y, Z, W], ...],
//                "indices": [0, 1, 2, ...], "outline": [1, 2, ...]}, ...],
//    "differences": ["main pass pixel ...", ...]}
//
// Every coordinate is its float's IEEE-754 bit pattern as 8 hex digits ("3f800000" is 1.0),
// so NaNs, infinities, -0 and denormals come back exactly. Triangle i (0-based) is drawn in
// the ID colour of i + 1. "differences" (what the run that wrote it saw) is informative and
// not read back.
#pragma once

#include <string>
#include <vector>

#include "scenes/soup/soup.h"

namespace cli {

std::string soupToJson(const scenes::soup::Soup& soup, const std::vector<std::string>& differences);

// Reads a reproducer; throws UsageError "--replay PATH: ..." naming what is wrong (the file
// cannot be read, is not JSON, or a field is missing, of the wrong type or out of range).
scenes::soup::Soup readSoupFile(const std::string& path);

}  // namespace cli
