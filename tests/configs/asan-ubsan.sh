#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer: the whole suite, GL comparisons and the
# command-line tests (which run the instrumented program) included. Any report fails the run:
# UBSan halts on its first finding, ASan always does, and LeakSanitizer checks at exit with
# the suppressions in tests/sanitizers/lsan.supp (leaks inside Mesa and LLVM, each commented).
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRASTER_SANITIZE=address,undefined > /dev/null
cmake --build build-asan -j"$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
ctest --test-dir build-asan --output-on-failure
