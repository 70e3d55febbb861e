#!/usr/bin/python3
"""Runs the microbenchmarks (build/raster_micro, Google Benchmark) and prints a short table.

The JSON Google Benchmark writes (--benchmark_format=json) goes to --out, by default
bench/results/micro.json; it is written beside the target and renamed into place only when
the run succeeded, so a failed run leaves no half-written file. Each row is one benchmark:
its per-item time (ns per lane lookup, texel, triangle, gathered element or FMA) and what
the peaks report (gathers per ns, GFLOP/s).

  bench/run_micro.py                          everything, 0.5 s a benchmark (about 40 s)
  bench/run_micro.py --filter texture/ --repetitions 3
  bench/run_micro.py --check --min-time 0.001 the smoke test (ctest -R micro_smoke): every
                                              family must be in the JSON with sane numbers
Exit status: 0 ok, 1 a check failed, 2 bad input (no binary, unreadable output).
"""
import argparse
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Every family the smoke test requires (name prefixes), and the peaks' (AVX2 builds only).
FAMILIES = ["texture/rgba8_bilinear_x16/", "texture/rgba16f_bilinear_x16/", "pcf/3x3_x16/", "pcf/5x5_x16/",
            "clear/depth24_1024", "clear/depth24_tile64", "clear/rgba8_1920x1080", "tile_walk/walk/",
            "tile_walk/walk_depth/", "coarse/full_rate/", "coarse/2x1/", "coarse/2x2/", "coarse/4x4/"]
PEAK_FAMILIES = ["peak/gather_dword/", "peak/gather_qword/", "peak/fma/"]
PER_ITEM = ["ns_per_lookup", "ns_per_texel", "ns_per_triangle", "ns_per_element", "ns_per_fma", "ns_per_pixel"]


def fail(message, status):
    print(f"run_micro: {message}", file=sys.stderr)
    sys.exit(status)


def run(binary, out, args):
    """Runs the binary with JSON output into `out` (atomically); returns the parsed JSON."""
    if not os.path.isfile(binary) or not os.access(binary, os.X_OK):
        fail(f"{binary}: no such executable (build it: cmake --build build --target raster_micro)", 2)
    folder = os.path.dirname(os.path.abspath(out))
    if not os.path.isdir(folder):
        fail(f"{out}: its folder {folder} does not exist", 2)
    partial = out + ".partial"
    cmd = [binary, "--benchmark_format=console", "--benchmark_out_format=json", f"--benchmark_out={partial}",
           f"--benchmark_min_time={args.min_time}", "--benchmark_counters_tabular=false"]
    if args.filter:
        cmd.append(f"--benchmark_filter={args.filter}")
    if args.repetitions > 1:
        cmd += [f"--benchmark_repetitions={args.repetitions}", "--benchmark_report_aggregates_only=true"]
    result = subprocess.run(cmd, stdout=subprocess.DEVNULL if not args.verbose else None)
    if result.returncode != 0:
        if os.path.exists(partial):
            os.remove(partial)
        fail(f"{binary} exited with status {result.returncode}", 1)
    try:
        with open(partial) as f:
            data = json.load(f)
    except (OSError, ValueError) as error:
        fail(f"{partial}: not readable as Google Benchmark JSON ({error})", 2)
    os.replace(partial, out)
    return data


def per_item(bench):
    for key in PER_ITEM:
        if key in bench:
            return key, bench[key]
    return None, None


def table(data):
    context = data.get("context", {})
    print(f"{context.get('host_name', '?')}: {context.get('num_cpus', '?')} cpus at {context.get('mhz_per_cpu', '?')} MHz "
          f"(TSC), load {context.get('load_avg', '?')}")
    print("| benchmark | per item | ns | items/ns | peak figure |")
    print("| --- | --- | --- | --- | --- |")
    for bench in data["benchmarks"]:
        key, value = per_item(bench)
        rate = bench.get("items_per_second", 0.0) * 1e-9
        extra = ""
        if "gathers_per_ns" in bench:
            extra = f"{bench['gathers_per_ns']:.3f} gathers/ns"
        elif "gflops" in bench:
            extra = f"{bench['gflops']:.1f} GFLOP/s"
        elif "groups_per_triangle" in bench:
            extra = f"{bench['groups_per_triangle']:.2f} groups/triangle"
        name = bench["name"]
        unit = key[len("ns_per_"):] if key else "?"
        print(f"| {name} | {unit} | {value:.3f} | {rate:.3f} | {extra} |" if value is not None else f"| {name} | ? | | | |")


def check(data, families):
    """The smoke test: every family present, every run without error and with finite, positive rates."""
    problems = []
    benches = data.get("benchmarks")
    if not isinstance(benches, list) or not benches:
        return ["no benchmarks in the JSON"]
    for family in families:
        if not any(b.get("name", "").startswith(family) for b in benches):
            problems.append(f"family {family} missing")
    for b in benches:
        name = b.get("name", "?")
        if b.get("error_occurred"):
            problems.append(f"{name}: {b.get('error_message', 'error')}")
            continue
        key, value = per_item(b)
        rate = b.get("items_per_second")
        if key is None or not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
            problems.append(f"{name}: no positive per-item time")
        if not (isinstance(rate, (int, float)) and math.isfinite(rate) and rate > 0):
            problems.append(f"{name}: no positive items_per_second")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "raster_micro"))
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "micro.json"))
    parser.add_argument("--filter", default="", help="Google Benchmark's --benchmark_filter (a regex; '-' negates)")
    parser.add_argument("--min-time", default="0.5", help="seconds per benchmark (--benchmark_min_time)")
    parser.add_argument("--repetitions", type=int, default=1, help="repetitions; the table then shows mean, median, stddev")
    parser.add_argument("--check", action="store_true", help="fail unless every family ran with sane numbers")
    parser.add_argument("--no-peaks", action="store_true", help="with --check: a build without AVX2 has no peak/ family")
    parser.add_argument("--verbose", action="store_true", help="show Google Benchmark's own console output")
    args = parser.parse_args()
    try:
        float(args.min_time)
    except ValueError:
        fail(f"--min-time {args.min_time!r}: not a number of seconds", 2)
    data = run(args.binary, args.out, args)
    table(data)
    if args.check:
        problems = check(data, FAMILIES + ([] if args.no_peaks else PEAK_FAMILIES))
        for p in problems:
            print(f"run_micro: check failed: {p}", file=sys.stderr)
        if problems:
            sys.exit(1)
        print(f"run_micro: {len(data['benchmarks'])} benchmarks, every family present")


if __name__ == "__main__":
    main()
