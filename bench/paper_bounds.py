#!/usr/bin/python3
"""Each scene's frame against its paper bound (issue 69), measured the way the issue states it.

bench/paper_bounds.json holds every scene's bound at 640x480, pass by pass: the least time the
work a pass must do can take on the counted machine's cores (its arithmetic at the cores' peak,
its fetches at the gather rate of their working set, whichever binds; the counts are in
docs/notes/2026-12-02-paper-bounds-and-scaling.md). For every scene and thread count this runs
`raster bench SCENE --size 640x480 --threads T --passes` --runs times (all runs interleaved, so
that a slow minute of the shared host spreads over all of them) and sets the frame's median
beside the bound on min(T, cores) cores. A frame meets issue 69's criterion when it is at most
--factor (2) times its bound.

The bounds were counted at one clock (a dependent FMA's latency, fma_ns in the file); the host
runs at others. The rows bound by arithmetic or setup are scaled to the clock of the hour,
measured with build/raster_micro before and after the runs (the faster of the two: the lower
bound), or given with --fma-ns; rows bound by fetches or stores from level 3 and memory are not.
On fewer cores than counted a bound grows in proportion (on one core it doubles); on more it
shrinks so, which assumes every peak grows with the cores.

Writes OUT/bounds.json (every run, the host, its UTC hour, the clock), OUT/bounds.md (a table of frames, then
each pass) and OUT/bounds.png (per scene, the bound's passes and ours as stacked bars in
multiples of the bound), and prints the table. --replot rewrites bounds.md and bounds.png from
bounds.json. Exit status:
0 when every scene is within --factor of its bound at every thread count, 1 when one is not or
has no bound in the file, 2 for bad arguments, a failed run, or a file that does not match the
scene (its passes counted differently from those `raster bench` runs).

Usage: bench/paper_bounds.py [--runs 3] [--frames 9] [--threads 2,1] [--scenes NAME,...]
                             [--factor 2] [--fma-ns NS] [--bounds bench/paper_bounds.json]
                             [--raster build/raster] [--out bench/results/bounds] [--replot] [--dry-run]
"""
import argparse
import json
import math
import os
import statistics
import sys
import time

from goal_runs import bench_command, check_utc, cpu_model, fma_latency_ns, run_once, utc_now, when_text
from chart_files import write_atomically, write_text_atomically
from input_checks import (NUMBER, OPTIONAL, RASTER_MAX_FRAMES, RASTER_MAX_THREADS, BadInput, check_each,
                          check_output_folder, check_raster, check_record, fail, is_number, parse_counts, read_json,
                          split_list)
from raster_scenes import checked_names, scene_names

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROG = "paper_bounds.py"
SCALED = ("arithmetic", "setup")   # the kinds of bound that move with the clock


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=3, help="runs per scene and thread count (default 3)")
    parser.add_argument("--frames", type=int, default=9, help="timed frames per backend and run (default 9)")
    parser.add_argument("--threads", default="2,1", help="comma-separated thread counts (default 2,1)")
    parser.add_argument("--scenes", help="comma-separated scene names (default: every scene of `raster scenes`)")
    parser.add_argument("--factor", type=float, default=2.0, help="how far above its bound a frame may be (default 2)")
    parser.add_argument("--fma-ns", type=float, help="the clock as a dependent FMA's latency, ns (default: measured)")
    parser.add_argument("--bounds", default=os.path.join(ROOT, "bench", "paper_bounds.json"), help="the bounds file")
    parser.add_argument("--raster", default=os.path.join(ROOT, "build", "raster"), help="the raster binary")
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "bounds"),
                        help="folder for bounds.json, .md and .png")
    parser.add_argument("--replot", action="store_true", help="no runs: rewrite bounds.md and .png from OUT/bounds.json")
    parser.add_argument("--dry-run", action="store_true", help="print the `raster bench` command lines, run none")
    args = parser.parse_args(argv)
    args.out = check_output_folder(PROG, "--out", args.out, files=("bounds.json", "bounds.md", "bounds.png"))
    if args.replot:
        return args
    if not (1 <= args.runs and 1 <= args.frames <= RASTER_MAX_FRAMES):
        parser.error(f"--runs must be at least 1 and --frames 1..{RASTER_MAX_FRAMES}")
    if not (math.isfinite(args.factor) and args.factor >= 1):
        parser.error(f"--factor {args.factor}: not a factor of 1 or more")
    if args.fma_ns is not None and not (math.isfinite(args.fma_ns) and args.fma_ns > 0):
        parser.error(f"--fma-ns {args.fma_ns}: not a latency (a number above 0)")
    check_raster(PROG, "--raster", args.raster)
    args.threads = parse_counts(PROG, "--threads", args.threads, 1, RASTER_MAX_THREADS, "raster bench's limit")
    args.scenes = None if args.scenes is None else split_list(PROG, "--scenes", args.scenes)
    args.scenes = checked_names(PROG, "--scenes", args.scenes, scene_names(args.raster))
    args.bounds_doc = read_bounds(args.bounds)
    if not args.dry_run:
        os.makedirs(args.out, exist_ok=True)
    return args


def read_bounds(path, prog=PROG):
    """The bounds file, checked (check_bounds); anything else exits 2, `prog` naming the script."""
    doc = read_json(prog, path, "a paper bounds file")
    try:
        check_bounds(doc)
    except BadInput as error:
        fail(prog, f"{path}: not a paper bounds file ({error})")
    return doc


def check_bounds(doc):
    """Raises BadInput unless every scene's passes each have a name, a target (its label in
    bench/tile_costs output), a program, a bound in ms above 0, what binds it (one of the
    file's `binds`) and the work counted."""
    check_record(doc, {"size": str, "cores": int, "fma_ns": NUMBER, "binds": dict, "scenes": dict}, "")
    if doc["cores"] < 1 or doc["fma_ns"] <= 0:
        raise BadInput("'cores' and 'fma_ns' must be above 0")
    for scene, passes in doc["scenes"].items():
        if not isinstance(passes, list):
            raise BadInput(f"scene {scene}: a list of passes was expected")
        check_each(passes, {"name": str, "target": str, "program": str, "ms": NUMBER, "binds": str, "work": str},
                   f"{scene} pass")
        for i, p in enumerate(passes):
            if p["ms"] <= 0 or p["binds"] not in doc["binds"]:
                raise BadInput(f"{scene} pass {i}: 'ms' must be above 0 and 'binds' one of {', '.join(doc['binds'])}")


def bound_ms(doc, passes, threads, fma_ns, host_cores):
    """Each pass's bound on min(threads, host cores) cores at the clock `fma_ns` (None: as counted)."""
    cores = min(threads, host_cores)
    clock = 1.0 if fma_ns is None else fma_ns / doc["fma_ns"]
    return [p["ms"] * doc["cores"] / cores * (clock if p["binds"] in SCALED else 1.0) for p in passes]


def check_passes(args, scene, record):
    """Exit 2 when the scene's passes are not those the bounds file counted."""
    ran = [p["program"] for p in record.get("passes", [])]
    counted = [p["program"] for p in args.bounds_doc["scenes"][scene]]
    if ran != counted:
        fail(PROG, f"{args.bounds}: {scene}'s bounds count {len(counted)} passes ({', '.join(counted)}) where "
                   f"raster bench ran {len(ran)} ({', '.join(ran)}): count the scene's passes again")


def measure(args):
    configs = [(scene, t) for t in args.threads for scene in args.scenes]
    if args.dry_run:
        for _ in range(args.runs):
            for scene, threads in configs:
                print(" ".join(bench_command(BenchArgs(args, threads), scene, args.bounds_doc["size"], "gl", "RUN.json")))
        return None
    before = args.fma_ns if args.fma_ns is not None else fma_latency_ns(args)
    runs, started, start = [], time.time(), utc_now()
    for run in range(args.runs):
        for scene, threads in configs:
            print(f"[{len(runs) + 1}/{args.runs * len(configs)}] run {run + 1}: {scene}, {threads} threads "
                  f"({time.time() - started:.0f} s)", file=sys.stderr, flush=True)
            record = run_once(BenchArgs(args, threads), scene, args.bounds_doc["size"], "gl")
            if scene in args.bounds_doc["scenes"]:
                check_passes(args, scene, record)
            ms = {b["name"]: b["median_ms"] for b in record["backends"]}
            runs.append({"run": run + 1, "scene": scene, "threads": threads, "frame_ms": ms["raster"],
                         "llvmpipe_ms": ms["llvmpipe"], "passes_ms": [p["raster_ms"] for p in record["passes"]]})
    after = args.fma_ns if args.fma_ns is not None else fma_latency_ns(args)
    clock = None if before is None or after is None else min(before, after)
    return {"host": cpu_model(), "utc": {"start": start, "end": utc_now()}, "host_cores": len(os.sched_getaffinity(0)), "fma_ns": clock, "frames": args.frames,
            "factor": args.factor, "size": args.bounds_doc["size"], "bounds": args.bounds_doc, "runs": runs}


class BenchArgs:
    """What goal_runs.run_once reads of its arguments, for one thread count."""
    def __init__(self, args, threads):
        self.raster, self.threads, self.frames, self.passes = args.raster, threads, args.frames, True


def summarize(result):
    """Per scene and thread count: the frame's and each pass's median against the bounds."""
    doc, rows = result["bounds"], []
    for scene, threads in dict.fromkeys((r["scene"], r["threads"]) for r in result["runs"]):
        mine = [r for r in result["runs"] if (r["scene"], r["threads"]) == (scene, threads)]
        row = {"scene": scene, "threads": threads, "frames_ms": [r["frame_ms"] for r in mine],
               "frame_ms": statistics.median(r["frame_ms"] for r in mine),
               "passes_ms": [statistics.median(r["passes_ms"][i] for r in mine) for i in range(len(mine[0]["passes_ms"]))]}
        passes = doc["scenes"].get(scene)
        if passes:
            row["bounds_ms"] = bound_ms(doc, passes, threads, result["fma_ns"], result["host_cores"])
            row["bound_ms"] = sum(row["bounds_ms"])
            row["over"] = row["frame_ms"] / row["bound_ms"]
            row["met"] = row["over"] <= result["factor"]
        rows.append(row)
    return rows


def table(result, rows):
    doc, factor = result["bounds"], result["factor"]
    clock = (f"a dependent FMA {result['fma_ns']:.3f} ns (the bounds were counted at {doc['fma_ns']:.3f}: rows bound by "
             f"arithmetic or setup scaled by {result['fma_ns'] / doc['fma_ns']:.3f})" if result["fma_ns"] is not None
             else "clock not measured (raster_micro not built): the bounds as counted")
    lines = [f"Host: {result['host']}, {result['host_cores']} cores{when_text(result.get('utc'))}; {clock}; {result['size']}, "
             f"{len(rows[0]['frames_ms'])} runs of {result['frames']} frames (`bench/paper_bounds.py`). "
             f"Criterion: a frame at most {factor:g}x its bound.", "",
             "| scene | threads | bound, ms | frame, ms (runs) | frame / bound | within |",
             "| --- | ---: | ---: | --- | ---: | :---: |"]
    for row in rows:
        runs = ", ".join(f"{ms:.3f}" for ms in row["frames_ms"])
        if "bound_ms" in row:
            lines.append(f"| {row['scene']} | {row['threads']} | {row['bound_ms']:.3f} | {row['frame_ms']:.3f} ({runs}) | "
                         f"{row['over']:.2f} | {'yes' if row['met'] else 'no'} |")
        else:
            lines.append(f"| {row['scene']} | {row['threads']} | no bound counted | {row['frame_ms']:.3f} ({runs}) | - | no |")
    lines += ["", "Pass by pass (medians; ours / bound):", "",
              "| scene | threads | pass | program | binds | bound, ms | ours, ms | ours / bound |",
              "| --- | ---: | ---: | --- | --- | ---: | ---: | ---: |"]
    for row in (r for r in rows if "bound_ms" in r):
        for i, (p, bound, ours) in enumerate(zip(doc["scenes"][row["scene"]], row["bounds_ms"], row["passes_ms"])):
            lines.append(f"| {row['scene']} | {row['threads']} | {i + 1} | `{p['program']}` | {p['binds']} | {bound:.3f} | "
                         f"{ours:.3f} | {ours / bound:.1f} |")
    return "\n".join(lines) + "\n"


def chart(result, rows, path):
    """A panel per thread count; per scene two stacked bars in units of the scene's bound: the
    bound's passes (1 in all) and ours (the passes' medians), each pass one colour in both, a
    pass wider than a quarter named; the criterion's line at --factor, the frame's median a tick."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    doc, factor = result["bounds"], result["factor"]
    counts = list(dict.fromkeys(row["threads"] for row in rows))
    bounded = [row for row in rows if "bound_ms" in row]
    scenes = list(dict.fromkeys(row["scene"] for row in bounded))
    fig, axes = plt.subplots(1, len(counts), figsize=(6.5 * len(counts), 0.9 + 0.9 * len(scenes)), squeeze=False,
                             sharey=True)
    colours = plt.get_cmap("tab20").colors
    for ax, threads in zip(axes[0], counts):
        for k, scene in enumerate(scenes):
            row = next((r for r in bounded if (r["scene"], r["threads"]) == (scene, threads)), None)
            if row is None:
                continue
            for bar, (widths, y) in enumerate(((row["bounds_ms"], k - 0.2), (row["passes_ms"], k + 0.2))):
                left = 0.0
                for i, (p, ms) in enumerate(zip(doc["scenes"][scene], widths)):
                    width = ms / row["bound_ms"]
                    ax.barh(y, width, 0.36, left=left, color=colours[i % len(colours)], edgecolor="white", linewidth=0.5)
                    if width > 0.25:
                        ax.text(left + width / 2, y, p["name"], ha="center", va="center", fontsize=6)
                    left += width
                if bar == 1:
                    ax.text(max(left, row["over"]), y, f" {row['over']:.2f}x", va="center", fontsize=7)
            ax.plot([row["over"]] * 2, [k, k + 0.4], color="black", linewidth=1.5)
        ax.axvline(factor, color="#d62728", linestyle="--", linewidth=1, label=f"{factor:g}x its bound")
        ax.axvline(1.0, color="#2ca02c", linestyle=":", linewidth=1, label="the bound")
        ax.set_yticks([y for k in range(len(scenes)) for y in (k - 0.2, k + 0.2)],
                      [label for scene in scenes for label in (f"{scene}: bound", f"{scene}: ours")], fontsize=7)
        ax.set_xlabel("multiples of the scene's bound (each pass a colour; the frame's median a tick)", fontsize=7)
        ax.set_title(f"{result['size']}, {threads} thread{'s' if threads > 1 else ''}", fontsize=9)
        ax.grid(True, axis="x", alpha=0.3)
    axes[0][0].invert_yaxis()   # the first scene on top (the axes share it: once)
    axes[0][-1].legend(fontsize=7, loc="lower right")
    fig.suptitle(f"Each frame against its paper bound ({result['host']})", fontsize=9)
    fig.tight_layout()
    write_atomically(fig, path)
    plt.close(fig)


def replot(args):
    """The runs of OUT/bounds.json, checked."""
    path = os.path.join(args.out, "bounds.json")
    result = read_json(PROG, path, "a bounds.json")
    try:
        check_record(result, {"host": str, "host_cores": int, "fma_ns": OPTIONAL(NUMBER), "frames": int, "factor": NUMBER,
                              "size": str, "bounds": dict, "runs": list}, "")
        if result["host_cores"] < 1 or (result["fma_ns"] is not None and result["fma_ns"] <= 0):
            raise BadInput("'host_cores' and 'fma_ns' must be above 0")
        check_bounds(result["bounds"])
        if result.get("utc") is not None:
            check_utc(result["utc"])
        check_each(result["runs"], {"scene": str, "threads": int, "frame_ms": NUMBER, "passes_ms": list}, "run")
        for i, run in enumerate(result["runs"]):
            counted = result["bounds"]["scenes"].get(run["scene"])
            if run["threads"] < 1 or not all(is_number(ms) and ms > 0 for ms in [run["frame_ms"], *run["passes_ms"]]):
                raise BadInput(f"run {i}: 'threads' and every time must be above 0")
            if counted is not None and len(counted) != len(run["passes_ms"]):
                raise BadInput(f"run {i}: {len(run['passes_ms'])} passes where the bounds count {len(counted)}")
            first = next(r for r in result["runs"] if r["scene"] == run["scene"])
            if len(run["passes_ms"]) != len(first["passes_ms"]):
                raise BadInput(f"run {i}: {len(run['passes_ms'])} passes where {run['scene']}'s first run has "
                               f"{len(first['passes_ms'])}")
    except BadInput as error:
        fail(PROG, f"{path}: not a bounds.json ({error})")
    return result


def main(argv):
    args = parse_args(argv)
    result = replot(args) if args.replot else measure(args)
    if result is None:   # --dry-run
        return 0
    rows = summarize(result)
    text = table(result, rows)
    if not args.replot:
        write_text_atomically(json.dumps(result, indent=1) + "\n", os.path.join(args.out, "bounds.json"))
    write_text_atomically(text, os.path.join(args.out, "bounds.md"))
    chart(result, rows, os.path.join(args.out, "bounds.png"))
    sys.stdout.write(text)
    return 0 if all(row.get("met", False) for row in rows) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
