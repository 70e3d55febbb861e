#!/usr/bin/env bash
# The build with every SIMD option off (-DRASTER_AVX2=OFF): no *_avx2 / *_avx512 sibling is
# compiled, FastLanes is the plain-C++ Lanes<8>, and the compiler targets baseline x86-64.
# Every suite of the pipeline runs against it, GL comparisons included: its bytes must be the
# default build's, and llvmpipe's. It checks bytes, not speed, so it is compiled at -O1
# (-ffp-contract=off and no fast-math keep every float operation what the source says at any
# level): 2.3 times faster to compile than Release's -O3 (deferred's lighting port, 9.3 ->
# 4.1 CPU seconds).
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build-simd-off -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -DNDEBUG" -DRASTER_AVX2=OFF > /dev/null
cmake --build build-simd-off -j"$(nproc)"
# Left out (by their labels, tests/suites.cmake): the suites of the command line
# (command_line: its options, files and messages, the same code with SIMD on or off; the
# program itself still runs here, in the suites that compare its images) and the Python and
# Chromium harnesses (harness), which check scripts, not bytes.
ctest --test-dir build-simd-off --output-on-failure -j"$(nproc)" -LE '^(command_line|harness)$'
