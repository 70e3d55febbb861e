#!/usr/bin/env bash
# The build with every SIMD option off (-DRASTER_AVX2=OFF): no *_avx2 / *_avx512 sibling is
# compiled, FastLanes is the plain-C++ Lanes<8>, and the compiler targets baseline x86-64.
# The whole suite runs against it, GL comparisons included: its bytes must be the default
# build's, and llvmpipe's.
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build-simd-off -DCMAKE_BUILD_TYPE=Release -DRASTER_AVX2=OFF > /dev/null
cmake --build build-simd-off -j"$(nproc)"
# Left out: the suites of the Python and Chromium harnesses (goal_runs, dask_sweep,
# report_chromium), which check scripts, not bytes; the sweep and report suites run here.
ctest --test-dir build-simd-off --output-on-failure -j"$(nproc)" -E '^(goal_runs|dask_sweep|report_chromium)$'
