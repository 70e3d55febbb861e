// The stage views the report shows are those `raster render --view` offers, read from what
// `raster render SCENE --view help` prints: when it succeeds, one view a line (its first
// word); when it fails, the valid names its error line lists ("... (valid views: a, b, c)"
// or "...: a, b, c"). The report never keeps a list of its own.
#pragma once

#include <string>
#include <vector>

namespace report {

// The view names in a child's exit status and output, in order, each once; empty when none
// can be read.
std::vector<std::string> parseViewNames(int status, const std::string& output);

}  // namespace report
