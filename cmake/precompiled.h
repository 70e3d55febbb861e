// The standard and third-party headers that most sources of the libraries and the tests
// include, parsed once per target (CMake's target_precompile_headers, CMakeLists.txt) rather
// than once per source: parsing them was 0.6-0.9 of the 1-2 CPU seconds each source spent
// before its own code (GCC 12; docs/notes/2026-12-03-ci-minutes-3.md). Only headers that are
// not this project's: one of ours here would hide a source's missing #include. Each source
// still includes what it uses, so the build is the same without it (-DRASTER_PCH=OFF).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

// Not <immintrin.h>: raster/simd/intrinsics.h includes it between pragmas that silence a
// GCC 12 warning at the sites its functions are inlined into, and a precompiled header does
// not carry that state to them (thousands of -Wmaybe-uninitialized warnings in the AVX-512 build).
