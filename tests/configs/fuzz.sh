#!/usr/bin/env bash
# The libFuzzer targets (fuzz/): built with clang, AddressSanitizer and UBSan, each run from
# its seed corpus (fuzz/corpus/NAME) for a bounded time; any crash, hang (over 10 s on one
# input), leak or sanitizer report fails the run and leaves the input in build-fuzz/.
# RASTER_FUZZ_SECONDS sets the time per target (default 25, about two minutes for the five,
# to keep CI short; until 2026-12-02 it was 45, and no CI run at 45 found an input).
set -euo pipefail
cd "$(dirname "$0")/../.."
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DRASTER_FUZZ=ON > /dev/null
cmake --build build-fuzz -j"$(nproc)"
seconds=${RASTER_FUZZ_SECONDS:-25}
for target in obj image hdr cli geometry; do
  found=build-fuzz/found-$target
  mkdir -p "$found"
  echo "== fuzzing $target for ${seconds}s"
  # New inputs go to $found; the seed corpus in the repository is only read.
  (cd build-fuzz && "./${target}_fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="found-$target/" -print_final_stats=1 "found-$target" "../fuzz/corpus/$target" 2>&1 |
      grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)" || true)
  if ls "$found"/crash-* "$found"/leak-* "$found"/timeout-* "$found"/oom-* > /dev/null 2>&1; then
    echo "fuzz: $target found a failing input: $(ls "$found"/crash-* "$found"/leak-* "$found"/timeout-* "$found"/oom-* 2>/dev/null | head -1)"
    exit 1
  fi
done
echo "fuzz: 5 passed, 0 failed"
