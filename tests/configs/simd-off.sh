#!/usr/bin/env bash
# The build with every SIMD option off (-DRASTER_AVX2=OFF): no *_avx2 / *_avx512 sibling is
# compiled, FastLanes is the plain-C++ Lanes<8>, and the compiler targets baseline x86-64.
# The suites of the pipeline run against it (not the two determinism ones: below), GL
# comparisons included: its bytes must be the default build's, and llvmpipe's. It checks
# bytes, not speed, so it is compiled at -O1 (-ffp-contract=off and no fast-math keep every
# float operation what the source says at any level): 2.3 times faster to compile than
# Release's -O3 (deferred's lighting port, 9.3 -> 4.1 CPU seconds).
set -euo pipefail
cd "$(dirname "$0")/../.."
# The command line at -O0, as in the ASan + UBSan configuration (asan-ubsan.sh says why): it
# runs here only inside the pipeline suites (softpipe's renders, the views and stability
# suites' runs of the program), where the pipeline it calls is the libraries' -O1 code.
cmake -S . -B build-simd-off -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -DNDEBUG" -DRASTER_AVX2=OFF \
  -DRASTER_COMMAND_LINE_OPTIONS=-O0 > /dev/null
# raster_tests brings the programs its suites run (raster, raster_extra_scene); the measuring
# programs (raster_micro, tile_costs: 18 of 89 build steps) are smoke-tested in the release step.
cmake --build build-simd-off -j"$(nproc)" --target raster_tests
# Left out (by their labels, tests/suites.cmake): the suites of the command line
# (command_line: its options, files and messages, the same code with SIMD on or off; the
# program itself still runs here, in the suites that compare its images) and the Python and
# Chromium harnesses (harness), which check scripts, not bytes, and the microbenchmarks'
# smoke test (micro: not built here). And by name: the two
# determinism suites, whose subject is thread counts, lane types and draw splits, while
# here both lane types are the plain one and the thread counts and splits are the same code
# in every build (the other three configurations run them); and the suites of code no lane
# type reaches (bad input refused, the scene registry's rows, image files and assets: 19 of
# this configuration's 151 suite-seconds). This build's bytes are held to llvmpipe's by
# every scene suite and the feature suites.
ctest --test-dir build-simd-off --output-on-failure -j"$(nproc)" -LE '^(command_line|harness|micro)$' \
  -E '^(determinism.*|hostile|registry|image_io|assets)$'
