#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer: the whole suite, GL comparisons and the
# command-line tests (which run the instrumented program) included. Any report fails the run:
# UBSan traps on its first finding (below), ASan always halts, and LeakSanitizer checks at exit
# with the suppressions in tests/sanitizers/lsan.supp (leaks inside Mesa and LLVM, each commented).
set -euo pipefail
cd "$(dirname "$0")/../.."
# -O1 and line tables only: the sanitizers' own advice, and half the compile time of -O2 -g.
# Two checks are left out, each measured on the sources that cost the most (GCC 12, CPU
# seconds to compile one file; docs/notes/2026-12-02-ci-minutes.md):
# - use-after-scope (-fno-sanitize-address-use-after-scope): it poisons and unpoisons the
#   stack slot of every local at its scope's ends, and a port's pipeline inlines thousands
#   of short-lived lane values: deferred's G-buffer port 30 -> 17 s, the test programs 52 ->
#   33 s, the command line's largest unity file 63 -> 54 s. Heap and stack overflows,
#   use-after-free and leaks are still found; a dangling reference to an ended scope is what
#   goes unseen here (the libFuzzer build, clang's ASan, keeps the check on its parsers).
# - object-size: UBSan's bounds check against __builtin_object_size, a subset of what ASan
#   checks on every access anyway: the G-buffer port 17 -> 12 s, the test programs 33 -> 21 s.
# UBSan's findings trap (-fsanitize-undefined-trap-on-error) rather than call its runtime:
# every check stays, but its failure path is one ud2 instruction instead of a call with the
# source location and type descriptors it would print, and those paths were half the code of
# a port (docs/notes/2026-12-03-ci-minutes-3.md: deferred's lighting port 23.4 -> 14.4 CPU s and 1.48 -> 0.74 MB
# of text, the test programs 27.6 -> 16.3 s). What a finding prints instead: doctest's
# "test case CRASHED: SIGILL" with the test's name, then ASan's report of the signal
# (handle_sigill=1, below) with the stack down to the file and line of the check; rebuilding
# without the flag names the check, when that line does not.
# The command line's own code (apps/, tests/apps/: RASTER_COMMAND_LINE_OPTIONS) at -O0: its
# nlohmann::json and CLI11 templates compile in about half the time (CPU seconds, GCC 12:
# apps/' largest unity file 66 -> 36, the command-line tests' two 75 -> 36), while what it
# runs at length, the pipeline and the image files, is in the libraries at -O1.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -g1" -DRASTER_SANITIZE=address,undefined \
  -DRASTER_SANITIZE_OPTIONS="-fno-sanitize-address-use-after-scope;-fno-sanitize=object-size;-fsanitize-undefined-trap-on-error" \
  -DRASTER_COMMAND_LINE_OPTIONS=-O0 > /dev/null
# raster_tests brings the programs its suites run (raster, raster_extra_scene); the
# microbenchmarks (raster_micro) are measuring code, smoke-tested in the other builds.
cmake --build build-asan -j"$(nproc)" --target raster_tests
# (detect_stack_use_after_return stays off: its fake stack frames do not keep the 32-byte
# alignment of the lane types' locals, and the first aligned AVX store faults.)
# intercept_tls_get_addr=0: GCC 12's sanitizer runtime takes a dynamic TLS block that a
# malloc happens to place at offset 16 of a page for a pre-2.25 glibc header and reads
# garbage through it, and LeakSanitizer's tracer then dies at exit ("Tracer caught signal
# 11") after every test passed; libOSMesa's TLS makes the GL suites hit it depending on heap
# layout (fixed upstream after GCC 13 / LLVM 16; Mudlet/Mudlet#9809 has the mechanism).
# handle_sigill=1: UBSan's traps (above) reported with their stack.
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:intercept_tls_get_addr=0:handle_sigill=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
# Both cores: the suites are independent (development runs them two at a time too).
# Left out (by their labels, tests/suites.cmake): the microbenchmarks' smoke test (micro: not
# built here), and the tests of the Python and Chromium harnesses (harness: goal_runs,
# dask_sweep, report_chromium). What those run of this program (bench --passes, sweep
# shards, report) the cli, sweep and report suites run here too; the rest is Python and
# Chromium, which these sanitizers do not instrument.
# And one case, determinism's plain lanes against SIMD lanes on every scene (34 of the
# suites' 395 seconds here): what it adds to the cases kept is bytes, which the default
# build holds, and the plain lanes on 640x480's interior tiles. Their memory accesses at the
# frame's edges, under every method, are checked here by determinism_paths' every-method
# case (97x61: SIMD lanes on one thread and three, plain lanes on one).
# And the command line's every-scene comparison (cli): it is there for the optimized build's
# program (tests/apps/cli_test.cpp says why); here the scene suites hold the same bytes.
export RASTER_TEST_CASE_EXCLUDE="every scene: scalar lanes*,compare --exact: the built program*"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -LE '^(micro|harness)$'
