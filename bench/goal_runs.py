#!/usr/bin/python3
"""The speed goals of issues 21, 26 and 69, measured the way they are stated.

For every size, method preset and scene it runs `raster bench` (this pipeline and llvmpipe
alternating frame by frame in one process) --runs times, the runs of all configurations
interleaved so that a slow minute of the shared host spreads over all of them, and reads
each run's ratio of medians (llvmpipe / this pipeline). A configuration meets the goal when
the median of its runs is at least --goal and no run is below --floor. The defaults are issue
69's (4.0, no run below 3.6, at 640x480 and 1920x1080, 2 threads); issues 21 and 26 asked for
--goal 3.0 --floor 2.7 --pass-goal 2.0. With --passes every run also times each pass,
finished before the next, and the table lists the passes whose median ratio is below
--pass-goal (2.5).

Writes OUT/goals.json (every run, with the host's CPU model: ratios differ between the
hosts these machines draw, AMD and Intel alike; and the latency of a dependent FMA before and
after the runs, from build/raster_micro where it is built: the same host runs at different
clocks, 1.09-1.10 ns on 2026-12-05 and 0.94 on 12-07's evening; and the UTC times the runs
began and ended, the host's hour), OUT/goals.md (the table) and OUT/goals.png
(a panel per size: each configuration's median as a bar, its runs as dots, the goal and the
floor as lines), and prints the table. --replot rewrites the table and the chart from an
existing goals.json without running anything. Exit status: 0 when every configuration meets
the goal, 1 when one does not, 2 for bad arguments or a failed run.

Usage: bench/goal_runs.py [--runs 3] [--frames 9] [--threads 2] [--sizes 640x480,1920x1080]
                          [--presets gl,fast] [--scenes NAME,...] [--passes]
                          [--raster build/raster] [--out bench/results] [--replot] [--dry-run]
(--scenes: every scene of `raster scenes` by default; --dry-run prints the runs and runs none)
(Debian's /usr/bin/python3, which has python3-matplotlib from ./setup.sh.)
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

from chart_files import write_atomically, write_text_atomically
from input_checks import (NUMBER, OPTIONAL, RASTER_MAX_FRAMES, RASTER_MAX_THREADS, BadInput, check_output_folder,
                          check_raster, check_record, fail, is_number, parse_sizes, read_json, split_list)
from raster_scenes import checked_names, preset_names, scene_names

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROG = "goal_runs.py"


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def fma_latency_ns(args):
    """The core's clock as the latency of a dependent FMA, ns (`raster_micro`'s peak/fma/chains:1
    on one core, about a second), or None where raster_micro is not built beside --raster or
    does not run that benchmark (a build without AVX2)."""
    micro = os.path.join(os.path.dirname(os.path.abspath(args.raster)), "raster_micro")
    if not os.access(micro, os.X_OK):
        return None
    core = min(os.sched_getaffinity(0))
    try:
        done = subprocess.run([micro, "--benchmark_filter=peak/fma/chains:1$", "--benchmark_format=json"],
                              capture_output=True, text=True, timeout=60,
                              preexec_fn=lambda: os.sched_setaffinity(0, {core}))
        value = json.loads(done.stdout)["benchmarks"][0]["ns_per_fma"]
    except (OSError, subprocess.TimeoutExpired, ValueError, KeyError, IndexError, TypeError):
        return None
    return value if done.returncode == 0 and is_number(value) and value > 0 else None


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=3, help="runs per configuration (default 3)")
    parser.add_argument("--frames", type=int, default=9, help="timed frames per backend and run (default 9)")
    parser.add_argument("--threads", type=int, default=2, help="threads for both backends (default 2)")
    parser.add_argument("--sizes", default="640x480,1920x1080", help="comma-separated WxH list")
    parser.add_argument("--presets", default="gl,fast", help="comma-separated presets (`raster methods` lists them)")
    parser.add_argument("--scenes", help="comma-separated scene names (default: every scene of `raster scenes`)")
    parser.add_argument("--goal", type=float, default=4.0, help="median ratio a configuration needs (default 4.0, issue 69)")
    parser.add_argument("--floor", type=float, default=3.6, help="lowest ratio any run may read (default 3.6, issue 69)")
    parser.add_argument("--passes", action="store_true", help="also time each pass and list those below --pass-goal")
    parser.add_argument("--pass-goal", type=float, default=2.5, help="median ratio every pass needs (default 2.5, issue 69)")
    parser.add_argument("--raster", default=os.path.join(ROOT, "build", "raster"), help="the raster binary")
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "results"), help="folder for goals.json, .md and .png")
    parser.add_argument("--replot", action="store_true", help="no runs: rewrite goals.md and goals.png from OUT/goals.json")
    parser.add_argument("--dry-run", action="store_true", help="print the `raster bench` command lines, run none")
    args = parser.parse_args(argv)
    try:   # the chart needs it; found missing only after minutes of runs would lose them
        import matplotlib  # noqa: F401
    except ImportError:
        parser.error(f"matplotlib is missing from {sys.executable}: run ./setup.sh, or use /usr/bin/python3")
    if args.replot:   # reads OUT/goals.json, rewrites the three files there
        args.out = check_output_folder(PROG, "--out", args.out, files=("goals.json", "goals.md", "goals.png"))
        return args
    if args.runs < 1 or args.frames < 1 or args.threads < 1:
        parser.error("--runs, --frames and --threads must be at least 1")
    # raster bench's own limits, checked before the first run rather than at it.
    for option, value, limit in (("--frames", args.frames, RASTER_MAX_FRAMES),
                                 ("--threads", args.threads, RASTER_MAX_THREADS)):
        if value > limit:
            parser.error(f"{option} {value}: at most {limit} (raster bench's limit)")
    # A goal is a finite ratio, 0 or more (0: any ratio): a NaN goal compares false with every
    # ratio, so nothing was met, and the table read "nan".
    for option, value in (("--goal", args.goal), ("--floor", args.floor), ("--pass-goal", args.pass_goal)):
        if not (math.isfinite(value) and value >= 0):
            parser.error(f"{option} {value}: not a ratio (a finite number, 0 or more)")
    # The floor is the least any run may read, at most the median's goal: above it, the goal
    # would say nothing (every run at least the floor puts the median there too).
    if args.floor > args.goal:
        parser.error(f"--floor {args.floor:g} is above --goal {args.goal:g} (the floor is the lowest a run may read, "
                     "at most the goal)")
    check_raster(PROG, "--raster", args.raster)
    # Each list's items once, in order; "" or an empty item is refused (--scenes "" once meant
    # every scene).
    args.sizes = parse_sizes(PROG, "--sizes", args.sizes)
    args.presets = split_list(PROG, "--presets", args.presets)
    args.scenes = None if args.scenes is None else split_list(PROG, "--scenes", args.scenes)
    args.presets = checked_names(PROG, "--presets", args.presets, preset_names(args.raster))
    args.scenes = checked_names(PROG, "--scenes", args.scenes, scene_names(args.raster))
    # Before any rendering: a run of many minutes must not end on an unwritable folder. The
    # folder must take files (and goals.json, .md and .png in it not be folders), or, not made
    # yet, the folder above it (a mistyped path is refused, not made parents and all);
    # --dry-run makes nothing.
    args.out = check_output_folder(PROG, "--out", args.out, files=("goals.json", "goals.md", "goals.png"))
    if not args.dry_run:
        os.makedirs(args.out, exist_ok=True)
    return args


def bench_command(args, scene, size, preset, json_path):
    cmd = [args.raster, "bench", scene, "--size", size, "--threads", str(args.threads), "--frames",
           str(args.frames), "--preset", preset, "--quiet", "--json", json_path]
    return cmd + ["--passes"] if args.passes else cmd


def run_once(args, scene, size, preset):
    """One `raster bench` run; returns its JSON record."""
    with tempfile.TemporaryDirectory() as folder:
        json_path = os.path.join(folder, "bench.json")
        cmd = bench_command(args, scene, size, preset, json_path)
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            sys.stderr.write(f"goal_runs: {' '.join(cmd)} exited {done.returncode}:\n{done.stderr[-2000:]}")
            sys.exit(2)
        with open(json_path) as f:
            return json.load(f)


def summarize(args, runs):
    """Per configuration: the runs' ratios, their median and minimum, whether the goal is met,
    and (with --passes) each pass's median ratio."""
    rows = []
    for size in args.sizes:
        for preset in args.presets:
            for scene in args.scenes:
                mine = [r for r in runs if (r["size"], r["preset"], r["scene"]) == (size, preset, scene)]
                ratios = [r["ratio"] for r in mine]
                row = {"size": size, "preset": preset, "scene": scene, "ratios": ratios,
                       "median": statistics.median(ratios), "min": min(ratios)}
                row["met"] = row["median"] >= args.goal and row["min"] >= args.floor
                if args.passes:
                    count = len(mine[0]["passes"])
                    row["passes"] = [{"pass": i + 1, "program": mine[0]["passes"][i]["program"],
                                      "median_ratio": statistics.median(
                                          r["passes"][i]["llvmpipe_ms"] / r["passes"][i]["raster_ms"] for r in mine),
                                      "median_raster_ms": statistics.median(r["passes"][i]["raster_ms"] for r in mine)}
                                     for i in range(count)]
                rows.append(row)
    return rows


def ratio_text(value, line):
    """Two decimals, or three where two would round a ratio onto the other side of `line`
    (2.996 against a 3.0 goal reads 2.996, not a 3.00 that failed)."""
    text = f"{value:.2f}"
    return text if (float(text) >= line) == (value >= line) else f"{value:.3f}"


def clock_text(fma):
    """The clock line of the table: the dependent FMA's latency before and after the runs."""
    if fma is None:
        return ""
    return f"; a dependent FMA {fma['before']:.3f} ns before the runs, {fma['after']:.3f} after (the clock)"


def utc_now():
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())


def when_text(utc):
    """The runs' hour on the table's first line ("; 2026-12-07 21:41-21:45 UTC"): the host's
    speed changes with it. Nothing for a record made before it was kept."""
    if utc is None:
        return ""
    start, end = (time.strptime(utc[k], "%Y-%m-%dT%H:%M:%SZ") for k in ("start", "end"))
    last = time.strftime("%H:%M" if start[:3] == end[:3] else "%Y-%m-%d %H:%M", end)
    return f"; {time.strftime('%Y-%m-%d %H:%M', start)}-{last} UTC"


def check_utc(utc):
    """Raises BadInput unless utc is {"start": T, "end": T}, T as utc_now() writes it."""
    check_record(utc, {"start": str, "end": str}, "utc")
    for key in ("start", "end"):
        try:
            time.strptime(utc[key], "%Y-%m-%dT%H:%M:%SZ")
        except ValueError:
            raise BadInput(f"utc: '{key}' is not a time such as 2026-12-07T21:41:00Z") from None


def table(args, rows, host, fma, utc=None):
    lines = [f"Host: {host}{when_text(utc)}{clock_text(fma)}; {args.threads} threads, {args.runs} runs of {args.frames} frames per row "
             f"(`bench/goal_runs.py`). Goal: median >= {args.goal}, no run below {args.floor}.", "",
             "| size | preset | scene | runs (llvmpipe / raster) | median | lowest | goal met |"
             + (f" passes below {args.pass_goal}x |" if args.passes else ""),
             "| --- | --- | --- | --- | ---: | ---: | :---: |" + (" --- |" if args.passes else "")]
    for row in rows:
        line = (f"| {row['size']} | {row['preset']} | {row['scene']} | {', '.join(f'{r:.2f}' for r in row['ratios'])} | "
                f"{ratio_text(row['median'], args.goal)} | {ratio_text(row['min'], args.floor)} | "
                f"{'yes' if row['met'] else 'no'} |")
        if args.passes:
            weak = [f"{p['pass']} `{p['program']}` {ratio_text(p['median_ratio'], args.pass_goal)}" for p in row["passes"]
                    if p["median_ratio"] < args.pass_goal]
            line += f" {'; '.join(weak) if weak else 'none'} |"
        lines.append(line)
    if args.passes:
        lines += ["", *pass_table(args, rows)]
    return "\n".join(lines) + "\n"


def pass_table(args, rows):
    """Pass by pass: each pass's median ratio in every size and preset, then this pipeline's
    median ms for it in the first preset at every size (where the runs recorded them)."""
    by_config = {(row["size"], row["preset"], row["scene"]): row for row in rows}
    first = args.presets[0]
    ms_sizes = [size for size in args.sizes
                if all("median_raster_ms" in p for s in args.scenes for p in by_config[(size, first, s)]["passes"])]
    lines = ["Pass by pass: each pass's median ratio (llvmpipe / raster), then ours in ms (median of the runs).", "",
             "| scene | pass | program | " + " | ".join(f"{z} `{p}`" for z in args.sizes for p in args.presets)
             + "".join(f" | ours, {z} `{first}`, ms" for z in ms_sizes) + " |",
             "| --- | ---: | --- |" + " ---: |" * (len(args.sizes) * len(args.presets) + len(ms_sizes))]
    for scene in args.scenes:
        reference = by_config[(args.sizes[0], first, scene)]["passes"]
        for i, p in enumerate(reference):
            def cell(size, preset, key, text):
                passes = by_config[(size, preset, scene)]["passes"]
                return text(passes[i][key]) if i < len(passes) else "-"
            ratios = [cell(z, q, "median_ratio", lambda v: ratio_text(v, args.pass_goal)) for z in args.sizes
                      for q in args.presets]
            times = [cell(z, first, "median_raster_ms", lambda v: f"{v:.3f}") for z in ms_sizes]
            lines.append(f"| {scene} | {p['pass']} | `{p['program']}` | " + " | ".join(ratios + times) + " |")
    return lines


def chart(args, rows, host, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(args.sizes), figsize=(4.5 * len(args.sizes), 4), squeeze=False, sharey=True)
    width = 0.8 / len(args.presets)
    for ax, size in zip(axes[0], args.sizes):
        for p, preset in enumerate(args.presets):
            mine = [next(r for r in rows if (r["size"], r["preset"], r["scene"]) == (size, preset, scene))
                    for scene in args.scenes]
            x = [i + (p - (len(args.presets) - 1) / 2) * width for i in range(len(args.scenes))]
            ax.bar(x, [r["median"] for r in mine], width * 0.9, label=f"{preset} (median)", alpha=0.75)
            for xi, row in zip(x, mine):
                ax.plot([xi] * len(row["ratios"]), row["ratios"], "k.", markersize=4)
                # The median above its bar and its runs' dots, not under them.
                ax.annotate(f"{row['median']:.2f}", (xi, max([row["median"]] + row["ratios"])),
                            textcoords="offset points", xytext=(0, 3), ha="center", fontsize=7)
        ax.axhline(args.goal, color="#2ca02c", linestyle="--", linewidth=1, label=f"goal {args.goal:g}x")
        ax.axhline(args.floor, color="#d62728", linestyle=":", linewidth=1, label=f"floor {args.floor:g}x")
        ax.set_xticks(range(len(args.scenes)), args.scenes)
        ax.set_title(f"{size}, {args.threads} threads", fontsize=10)
        ax.grid(True, axis="y", alpha=0.3)
    axes[0][0].set_ylabel("llvmpipe time / this pipeline's (runs as dots)")
    axes[0][-1].legend(fontsize=7, loc="lower right")
    fig.suptitle(f"Speed goals, {args.runs} runs each ({host})", fontsize=10)
    fig.tight_layout()
    write_atomically(fig, path)
    plt.close(fig)


def replot(args):
    """The table and the chart again from goals.json, with the settings it was measured with."""
    path = os.path.join(args.out, "goals.json")
    result = read_json("goal_runs: --replot", path, "a goals.json")
    try:
        check_record(result, {"configurations": list, "threads": int, "frames": int, "goal": NUMBER, "floor": NUMBER,
                              "pass_goal": OPTIONAL(NUMBER), "host": str}, "")
        rows = result["configurations"]
        if not rows:
            raise BadInput("no configurations")
        for i, row in enumerate(rows):
            where = f"configuration {i}"
            check_record(row, {"size": str, "preset": str, "scene": str, "ratios": list, "median": NUMBER,
                               "min": NUMBER, "met": bool}, where)
            if not row["ratios"] or len(row["ratios"]) != len(rows[0]["ratios"]) or not all(
                    map(is_number, row["ratios"])):
                raise BadInput(f"{where}: 'ratios' is not as many numbers as the first configuration's")
            if result["pass_goal"] is not None:
                check_record(row, {"passes": list}, where)
                for k, p in enumerate(row["passes"]):
                    check_record(p, {"pass": int, "program": str, "median_ratio": NUMBER}, f"{where} pass {k}")
                    if "median_raster_ms" in p:   # absent from the runs before it was recorded
                        check_record(p, {"median_raster_ms": NUMBER}, f"{where} pass {k}")
        fma = result.get("fma_ns")   # absent from the runs before it was recorded (history/*.json)
        if fma is not None:
            check_record(fma, {"before": NUMBER, "after": NUMBER}, "fma_ns")
        utc = result.get("utc")   # the same
        if utc is not None:
            check_utc(utc)
        ordered = lambda key: list(dict.fromkeys(row[key] for row in rows))
        args.sizes, args.presets, args.scenes = ordered("size"), ordered("preset"), ordered("scene")
        present = {(row["size"], row["preset"], row["scene"]) for row in rows}
        for config in ((z, p, s) for z in args.sizes for p in args.presets for s in args.scenes):
            if config not in present:   # the chart has a bar for every size, preset and scene
                raise BadInput(f"no configuration for size {config[0]}, preset {config[1]}, scene {config[2]}")
    except BadInput as error:
        fail("goal_runs: --replot", f"{path}: not a goals.json ({error})")
    args.runs = len(rows[0]["ratios"])
    args.threads, args.frames, args.goal, args.floor = result["threads"], result["frames"], result["goal"], result["floor"]
    args.passes, args.pass_goal = result["pass_goal"] is not None, result["pass_goal"]
    write_outputs(args, rows, result["host"], fma, json.dumps(result, indent=1) + "\n", utc)
    return 0


def write_outputs(args, rows, host, fma, json_text, utc=None):
    """goals.json, goals.md and goals.png, each written whole under a temporary name and renamed:
    never a half-written file. Returns the table."""
    text = table(args, rows, host, fma, utc)
    chart(args, rows, host, os.path.join(args.out, "goals.png"))
    write_text_atomically(json_text, os.path.join(args.out, "goals.json"))
    write_text_atomically(text, os.path.join(args.out, "goals.md"))
    return text


def main(argv):
    args = parse_args(argv)
    if args.replot:
        return replot(args)
    configs = [(size, preset, scene) for size in args.sizes for preset in args.presets for scene in args.scenes]
    if args.dry_run:
        for run in range(args.runs):
            for size, preset, scene in configs:
                print(" ".join(bench_command(args, scene, size, preset, "RUN.json")))
        return 0
    runs, started, total = [], time.time(), args.runs * len(configs)
    before, start = fma_latency_ns(args), utc_now()
    for run in range(args.runs):
        for size, preset, scene in configs:
            print(f"[{len(runs) + 1}/{total}] run {run + 1}: {scene} {size} {preset} "
                  f"({time.time() - started:.0f} s)", file=sys.stderr, flush=True)
            record = run_once(args, scene, size, preset)
            runs.append({"run": run + 1, "size": size, "preset": preset, "scene": scene, "ratio": record["ratio"],
                         "median_ms": {b["name"]: b["median_ms"] for b in record["backends"]},
                         "passes": record.get("passes", [])})
    after = fma_latency_ns(args)
    fma = {"before": before, "after": after} if before is not None and after is not None else None
    host = cpu_model()
    rows = summarize(args, runs)
    utc = {"start": start, "end": utc_now()}
    result = {"host": host, "utc": utc, "fma_ns": fma, "threads": args.threads, "frames": args.frames, "goal": args.goal,
              "floor": args.floor, "pass_goal": args.pass_goal if args.passes else None, "configurations": rows,
              "runs": runs}
    sys.stdout.write(write_outputs(args, rows, host, fma, json.dumps(result, indent=1) + "\n", utc))
    return 0 if all(row["met"] for row in rows) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
