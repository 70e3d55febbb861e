#!/usr/bin/env bash
# The libFuzzer targets (fuzz/): built with clang, AddressSanitizer and UBSan, each run from
# its seed corpus (fuzz/corpus/NAME) for a bounded time; any crash, hang (over 10 s on one
# input), leak or sanitizer report fails the run and leaves the input in build-fuzz/.
# RASTER_FUZZ_SECONDS sets the processor time per target (default 15: it was 45 until
# 2026-12-02 and 25 until 2026-12-03, and no CI run at any of them found an input; each run
# starts from the seed corpus in the repository, so CI's fuzzing is a check that the seeds'
# neighbourhood stays clean, and a long search is `RASTER_FUZZ_SECONDS=600 tests/configs/fuzz.sh`):
# the five run at once, each for that time times five over the number of cores (38 s on two
# cores).
set -euo pipefail
cd "$(dirname "$0")/../.."
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DRASTER_FUZZ=ON > /dev/null
cmake --build build-fuzz -j"$(nproc)"
seconds=${RASTER_FUZZ_SECONDS:-15}
targets=(obj image hdr cli geometry)
# libFuzzer runs one process per target here; all five share the cores for the same wall
# time, which gives each the processor time of RASTER_FUZZ_SECONDS on its own core, with no
# core left idle at the end. (A hang is still an input over 10 s of wall time, which at
# about 0.4 of a core is now some 4 s of its processor time.)
wall=$(( (seconds * ${#targets[@]} + $(nproc) - 1) / $(nproc) ))
fuzz_one() {   # fuzz_one TARGET: runs it, its summary lines to build-fuzz/TARGET.log
  local target=$1 found=build-fuzz/found-$1
  mkdir -p "$found"
  # New inputs go to $found; the seed corpus in the repository is only read.
  (cd build-fuzz && "./${target}_fuzz" -max_total_time="$wall" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="found-$target/" -print_final_stats=1 "found-$target" "../fuzz/corpus/$target" 2>&1 |
      grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)" || true) > "build-fuzz/$target.log"
}
echo "== fuzzing ${targets[*]} at once for ${wall}s each (${seconds}s of a core each on $(nproc))"
for target in "${targets[@]}"; do
  fuzz_one "$target" &
done
wait
failed=0
for target in "${targets[@]}"; do
  found=build-fuzz/found-$target
  echo "== $target"
  cat "build-fuzz/$target.log"
  if ls "$found"/crash-* "$found"/leak-* "$found"/timeout-* "$found"/oom-* > /dev/null 2>&1; then
    echo "fuzz: $target found a failing input: $(ls "$found"/crash-* "$found"/leak-* "$found"/timeout-* "$found"/oom-* 2>/dev/null | head -1)"
    failed=$((failed + 1))
  elif ! grep -q "^stat::number_of_executed_units" "build-fuzz/$target.log"; then
    echo "fuzz: $target did not run to its end (no final stats)"
    failed=$((failed + 1))
  fi
done
echo "fuzz: $(( ${#targets[@]} - failed )) passed, $failed failed"
((failed == 0))
