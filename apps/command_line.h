// The command line as a library: everything `raster` does, behind one call.
#pragma once

namespace cli {

// Parses and runs one command line; returns the exit status (0 success, 1 internal
// failure or a compare threshold exceeded, 2 bad input). The scenes are those of the
// registry at the time of the call (scenes/registry.h).
int run(int argc, char** argv);

}  // namespace cli
