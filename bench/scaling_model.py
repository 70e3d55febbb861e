#!/usr/bin/python3
"""Each scene's frame against its paper bound, and a model of its speed-up beyond 2 cores.

Reads `raster bench SCENE --passes --json` runs (and `bench/tile_costs` per-tile costs) that
a shell loop wrote into folders, and prints two Markdown tables per scene:

  1. pass by pass, the paper bound (bench/paper_bounds.json; docs/notes/
     2026-12-07-paper-bounds-recounted.md derives each), scaled to the runs' clock (--fma-ns),
     beside the measured pass at 1 and 2 threads, and their ratio;
  2. the scaling model at 1, 2, 4, 8, 16 and 32 threads: ours and llvmpipe's.

The model, from medians of the runs:
  e     the frame's serial share, Karp-Flatt from its 1- and 2-thread medians:
        e = 2 T2 / T1 - 1 (clamped at 0): everything that did not halve (work no loop
        runs in parallel, waits at the loops' ends and pass boundaries, binning's in-order
        steps, the host's calls).
  f_p   pass p's share of the frame's tile work, and its tiles' costs, from a warm
        frame's per-tile cycles at 1 thread (--tiles: bench/tile_costs.cpp, each tile's
        least over several frames).
  L_p(N) the makespan of pass p's tiles on N workers, as a share of their sum: tiles cut
        into 16-row bands where the renderer cuts them (more than one thread, fewer tiles
        than 8 x threads, a tile of at most 16 triangles), and a depth-only pass's heavy
        tile into triangle ranges (depth_ranges.h), each from the tile costs' record of
        the tiles' bins, handed in the renderer's order to whichever worker is free first.
        A pass of few tiles, or one heavy tile of a pass that draws colour, cannot use N.
  T_N   T1 (e + (1 - e) sum_p f_p L_p(N) / sum_p f_p L_p(2) / 2): Amdahl with the
        measured e, the parallel part slowed by each pass's tile limit relative to 2
        threads (where e was measured; at N = 2 the model gives T2).
Amdahl's line beside it has no tile limit: T1 (e + (1 - e) / N).
The serial work alone (--tiny, optional): the frame at 16x16 less that frame's tile work
(--tiles-tiny), a lower bound on e's serial part; the rest of e is waits.

llvmpipe (Mesa): the draw module (vertex shading) and setup/binning run on the
application's thread; only rasterization and shading run on its rasterizer threads,
LP_NUM_THREADS capped at LP_MAX_THREADS = 32 (lp_limits.h), a task per 64x64 tile. Per pass
its frame's Karp-Flatt share stays serial, the rest splits over min(N, 32) threads in whole
64x64 tiles (no bands), weighted by llvmpipe's own pass times (--passes) and with this
pipeline's per-tile costs standing in for its tiles' (the same geometry in the same tiles).

Usage:
  for r in 1 2 3; do for s in shadow deferred hdr pbr; do for t in 1 2; do
    build/raster bench $s --threads $t --frames 9 --passes --quiet --json runs/full/${s}_t${t}_r$r.json
    build/raster bench $s --size 16x16 --threads $t --frames 9 --passes --quiet --json runs/tiny/${s}_t${t}_r$r.json
  done; build/tile_costs $s 640x480 1 2 5 > runs/tiles/${s}_r$r.json
  build/tile_costs $s 16x16 1 2 5 > runs/tiles-tiny/${s}_r$r.json; done; done
  bench/scaling_model.py --runs runs/full --tiny runs/tiny --tiles runs/tiles --tiles-tiny runs/tiles-tiny
"""
import argparse
import glob
import json
import math
import os
import re
import statistics
import sys

from chart_files import write_text_atomically
from input_checks import (NUMBER, RASTER_MAX_SIDE, RASTER_MAX_THREADS, BadInput, check_each, check_output_path,
                          check_range, check_record, fail, is_number, parse_counts, read_json, split_list)
from paper_bounds import bound_ms, read_bounds

PROG = "scaling_model.py"

# The paper bound of each pass at 640x480 on 2 cores (its arithmetic at the cores' peak, its
# divisions at the divider's rate, or its texel fetches at the gather rate of their working
# set, the largest; on 1 core each bound doubles), from the one file that holds them, scaled
# to the runs' clock (--fma-ns) as bench/paper_bounds.py scales them. Per scene, per pass:
# (label: the pass's target as bench/tile_costs names it, kind, bound_ms, what binds it).
BOUNDS_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paper_bounds.json")


def load_bounds(path, fma_ns):
    """Per scene: (label, kind, bound_ms on 2 cores at the clock `fma_ns`, what binds it) a pass;
    None: at the clock the file was counted at (paper_bounds.bound_ms scales its rows)."""
    doc = read_bounds(path, PROG)
    return {scene: [(p["target"], p["name"], ms, f"{p['binds']}: {p['work']}")
                    for p, ms in zip(passes, bound_ms(doc, passes, doc["cores"], fma_ns, doc["cores"]))]
            for scene, passes in doc["scenes"].items()}


# How the renderer cuts a pass into work items, from what the tile costs record of it (each
# tile's bin, whether its heavy tiles may be walked in ranges): raster/renderer.cpp cuts a
# tile of at most BANDED_TILE_MAX_TRIANGLES triangles into 16-row bands where the pass has
# fewer than 8 x threads tiles; raster/tile/depth_ranges.cpp (depthRangeCount) walks a
# depth-only pass's tile holding more than 1 / (2 x threads) of its bin entries in as many
# ranges as the threads, at most MAX_DEPTH_RANGES and one per MIN_DEPTH_RANGE_TRIANGLES.
BANDED_TILE_MAX_TRIANGLES, MAX_DEPTH_RANGES, MIN_DEPTH_RANGE_TRIANGLES = 16, 4, 64
TILE, REGION, LP_MAX_THREADS = 64, 16, 32


RUN_FIELDS = {"passes": list, "backends": list}
RUN_PASS_FIELDS = {"raster_ms": NUMBER, "llvmpipe_ms": NUMBER}
TILES_FIELDS = {"passes": list, "tsc_ghz": NUMBER}
TILES_PASS_FIELDS = {"label": str, "tile_cycles": list, "tile_triangles": list, "depth_ranges": bool, "tiles_x": int,
                     "tiles_y": int, "height": int}


def read_checked(path, what, fields, pass_fields, check=None):
    """One JSON file, its fields and each pass's checked, and then check(doc) (raising
    BadInput); anything else exits 2 naming it."""
    doc = read_json(PROG, path, what)
    try:
        check_record(doc, fields, "")
        check_each(doc["passes"], pass_fields, "pass")
        if check:
            check(doc)
    except BadInput as e:
        fail(PROG, f"{path}: not {what} ({e})")
    return doc


# What a run's and a tile file's numbers can be. A pass's time and a frame's median are above
# 0 (the model divides by them: a median of 0 printed "0.00 ms" and speed-ups of 0.0x, all of
# them 0 a ZeroDivisionError); a tile's cycles 0 or more (a tile may do nothing), the counter's
# rate and a pass's shape above 0 (they divide), its tiles and rows no more than raster's
# largest side has pixels. 1e9 ms is eleven days a frame: past it a file is not a measurement.
MAX_MS = 1e9


def check_run(run):
    for i, p in enumerate(run["passes"]):
        for field in RUN_PASS_FIELDS:
            check_range(p, field, 0, MAX_MS, f"pass {i}", above=True, why="a pass takes time")
    for i, backend in enumerate(run["backends"]):
        if isinstance(backend, dict) and backend.get("name") in ("raster", "llvmpipe"):
            check_record(backend, {"median_ms": NUMBER}, f"backend {i}")
            check_range(backend, "median_ms", 0, MAX_MS, f"backend {i}", above=True, why="a frame takes time")


def check_tiles(tiles):
    check_range(tiles, "tsc_ghz", 0, 1e3, "", above=True)
    for i, p in enumerate(tiles["passes"]):
        for field in ("tiles_x", "tiles_y", "height"):
            check_range(p, field, 1, RASTER_MAX_SIDE, f"pass {i}")
        if not p["tile_cycles"] or not all(is_number(c) and c >= 0 for c in p["tile_cycles"]):
            raise BadInput(f"pass {i}: 'tile_cycles' is not a list of cycle counts (numbers, 0 or more)")
        if len(p["tile_triangles"]) != len(p["tile_cycles"]) or not all(
                isinstance(n, int) and not isinstance(n, bool) and n >= 0 for n in p["tile_triangles"]):
            raise BadInput(f"pass {i}: 'tile_triangles' is not a count of triangles (a whole number, 0 or more) a tile")


def load_runs(folder, scene, threads):
    pattern = os.path.join(folder, f"{scene}_t{threads}_r*.json")
    paths = sorted(glob.glob(pattern))
    if not paths:
        fail(PROG, f"no run matches {pattern} (see --help's Usage for the names)")
    runs = [read_checked(path, "a `raster bench --passes --json` run", RUN_FIELDS, RUN_PASS_FIELDS, check_run)
            for path in paths]
    for path, run in zip(paths, runs):
        names = {b.get("name") for b in run["backends"] if isinstance(b, dict) and "median_ms" in b}
        if not {"raster", "llvmpipe"} <= names:
            fail(PROG, f"{path}: not a `raster bench` run against llvmpipe (its backends: {sorted(map(str, names))})")
    return runs


def median_passes(runs, backend):
    """Per pass index: the median over runs of the pass's time, ms."""
    key = "raster_ms" if backend == "raster" else "llvmpipe_ms"
    count = min(len(r["passes"]) for r in runs)
    return [statistics.median(r["passes"][i][key] for r in runs) for i in range(count)]


def median_frame(runs, backend):
    return statistics.median(next(b["median_ms"] for b in r["backends"] if b["name"] == backend) for r in runs)


def load_tiles(folder, scene):
    """Per pass label: per-tile cost, the median over runs of each tile's cycles; and the pass's shape."""
    pattern = os.path.join(folder, f"{scene}_r*.json")
    paths = sorted(glob.glob(pattern))
    if not paths:
        fail(PROG, f"no tile costs match {pattern} (see --help's Usage for the names)")
    runs = [read_checked(path, "`bench/tile_costs` output", TILES_FIELDS, TILES_PASS_FIELDS, check_tiles)
            for path in paths]
    shape = [(p["label"], len(p["tile_cycles"])) for p in runs[0]["passes"]]
    for path, r in zip(paths[1:], runs[1:]):
        if [(p["label"], len(p["tile_cycles"])) for p in r["passes"]] != shape:
            fail(PROG, f"{path}: its passes or tiles differ from {paths[0]}'s (another size?)")
    passes = {}
    for i, p in enumerate(runs[0]["passes"]):
        costs = [statistics.median(r["passes"][i]["tile_cycles"][t] for r in runs) for t in range(len(p["tile_cycles"]))]
        passes[p["label"]] = {"costs": costs, "tile_triangles": p["tile_triangles"], "depth_ranges": p["depth_ranges"],
                              "tiles_x": p["tiles_x"], "tiles_y": p["tiles_y"], "height": p["height"], "index": i,
                              "ghz": statistics.median(r["tsc_ghz"] for r in runs)}
    return passes


def depth_range_count(bin_size, entries, threads):
    """raster/tile/depth_ranges.cpp's depthRangeCount."""
    if threads < 2 or bin_size * 2 * threads <= entries:
        return 1
    return min(threads, MAX_DEPTH_RANGES, max(bin_size // MIN_DEPTH_RANGE_TRIANGLES, 1))


def work_items(tiles, threads):
    """The renderer's work items for `threads`: whole tiles, 16-row bands of equal cost, or a
    depth-only pass's heavy tile in equal triangle ranges (the first range where the tile was,
    the others k / ranges of the way down the list, as raster/tile/depth_ranges.cpp places them)."""
    costs, triangles, tx, height = tiles["costs"], tiles["tile_triangles"], tiles["tiles_x"], tiles["height"]
    if tiles["depth_ranges"] and threads > 1:
        entries = sum(triangles)
        placed = []
        for i, c in enumerate(costs):
            ranges = depth_range_count(triangles[i], entries, threads)
            for k in range(ranges):
                placed.append((2 * i if k == 0 else 2 * (len(costs) * k // ranges) + 1, c / ranges))
        return [c for _, c in sorted(placed, key=lambda item: item[0])]
    few = threads > 1 and len(costs) < 8 * threads
    items = []
    for t, c in enumerate(costs):
        bands = math.ceil(min(TILE, height - (t // tx) * TILE) / REGION) if few and triangles[t] <= BANDED_TILE_MAX_TRIANGLES else 1
        items.extend([c / bands] * bands)
    return items


def makespan(items, workers):
    """Items handed in order to whichever worker is free first (TBB's loop with grain 1)."""
    free = [0.0] * max(1, workers)
    for c in items:
        i = free.index(min(free))
        free[i] += c
    return max(free)


def tile_ms(tiles):
    """A pass's per-tile costs in ms (the counter's rate from the same run)."""
    return [c / tiles["ghz"] / 1e6 for c in tiles["costs"]]


def stage_breakdown(folder, scene, threads):
    """The median over runs of `raster bench`'s per-frame stage times (its text output), ms."""
    stages = {}
    for path in sorted(glob.glob(os.path.join(folder, f"{scene}_t{threads}_r*.txt"))):
        with open(path) as f:
            for line in f:
                m = re.match(r"\s+(vertex shading|clip \+ setup|binning|rasterization|fragment shading|output merge)\s+([0-9.]+) ms", line)
                if m:
                    stages.setdefault(m.group(1), []).append(float(m.group(2)))
    return {k: statistics.median(v) for k, v in stages.items()}


def karp_flatt(t1, t2):
    return min(max(2.0 * t2 / t1 - 1.0, 0.0), 1.0)


def model_scene(bounds, scene, full, tiny, tiles, tiles_tiny, thread_list, frames=None):
    r1, r2 = load_runs(full, scene, 1), load_runs(full, scene, 2)
    t1, t2 = median_passes(r1, "raster"), median_passes(r2, "raster")
    l1, l2 = median_passes(r1, "llvmpipe"), median_passes(r2, "llvmpipe")
    T1, T2 = median_frame(r1, "raster"), median_frame(r2, "raster")
    LT1, LT2 = median_frame(r1, "llvmpipe"), median_frame(r2, "llvmpipe")
    if frames:   # --frames: frame medians measured elsewhere (a quieter hour) in place of the runs'
        T1, T2, LT1, LT2 = frames
    passes_note = " (the runs' passes, not the hour of --frames)" if frames else ""
    tile_passes = load_tiles(tiles, scene)
    labels = [label for label, _, _, _ in bounds[scene]]
    missing = [label for label in labels if label not in tile_passes]
    if missing:
        fail(PROG, f"--tiles {tiles}: {scene}'s tile costs have no pass {', '.join(missing)} (passes: "
                   f"{', '.join(tile_passes)})")
    for name, got in (("--runs at 1 thread", t1), ("--runs at 2 threads", t2)):
        if len(got) != len(labels):
            fail(PROG, f"{name}: {scene}'s runs time {len(got)} passes, its bound has {len(labels)}")
    passes = []
    for i, (label, kind, bound, why) in enumerate(bounds[scene]):
        tp = tile_passes[label]
        costs = tile_ms(tp)
        share = {n: makespan(work_items({**tp, "costs": costs}, n), n) / (sum(costs) or 1.0)
                 for n in thread_list}
        lp_share = {n: makespan(costs, min(n, LP_MAX_THREADS)) / (sum(costs) or 1.0) for n in thread_list}
        passes.append({"label": label, "kind": kind, "bound_ms": bound, "binds": why, "t1_ms": t1[i], "t2_ms": t2[i],
                       "llvmpipe_t1_ms": l1[i], "llvmpipe_t2_ms": l2[i], "tile_work_ms": sum(costs),
                       "tiles": len(costs), "largest_tile_share": max(costs) / (sum(costs) or 1.0),
                       "makespan_share": share, "llvmpipe_makespan_share": lp_share})
    if not any(p["tile_work_ms"] for p in passes):   # the model's parallel part would be 0 / 0
        fail(PROG, f"--tiles {tiles}: {scene}'s tile costs are all 0 cycles")
    work = sum(p["tile_work_ms"] for p in passes)
    lwork = sum(p["llvmpipe_t1_ms"] for p in passes) or 1.0
    e, le = karp_flatt(T1, T2), karp_flatt(LT1, LT2)

    def parallel(n, key, weight, total):
        return sum(p[weight] / total * p[key][n] for p in passes)

    model = {}
    for n in thread_list:
        ours = parallel(n, "makespan_share", "tile_work_ms", work) / (2 * parallel(2, "makespan_share", "tile_work_ms", work))
        theirs = parallel(n, "llvmpipe_makespan_share", "llvmpipe_t1_ms", lwork) / (
            2 * parallel(2, "llvmpipe_makespan_share", "llvmpipe_t1_ms", lwork))
        tn = T1 if n == 1 else T1 * (e + (1 - e) * ours)
        ln = LT1 if n == 1 else LT1 * (le + (1 - le) * theirs)
        model[n] = {"raster_ms": tn, "speedup": T1 / tn, "amdahl": 1.0 / (e + (1 - e) / n),
                    "tile_limit": 1.0 / ours if n > 1 else 1.0,
                    "llvmpipe_ms": ln, "llvmpipe_speedup": LT1 / ln}
    result = {"scene": scene, "passes": passes, "frame_1t_ms": T1, "frame_2t_ms": T2, "llvmpipe_frame_1t_ms": LT1,
              "llvmpipe_frame_2t_ms": LT2, "bound_2c_ms": sum(p["bound_ms"] for p in passes), "serial_share": e,
              "llvmpipe_serial_share": le, "stages_1t_ms": stage_breakdown(full, scene, 1),
              "stages_2t_ms": stage_breakdown(full, scene, 2), "runs": {"1t": len(r1), "2t": len(r2)}, "model": model,
              "passes_note": passes_note}
    if tiny and tiles_tiny:
        s1 = median_frame(load_runs(tiny, scene, 1), "raster")
        tiny_tiles = load_tiles(tiles_tiny, scene)
        tiny_work = sum(sum(tile_ms(tp)) for tp in tiny_tiles.values())
        result["serial_work_ms"] = max(s1 - tiny_work, 0.0)
        result["serial_work_share"] = result["serial_work_ms"] / T1
    return result


def print_scene(m, thread_list):
    s = m["scene"]
    print(f"\n### {s}: frame {m['frame_1t_ms']:.2f} ms (1 thread), {m['frame_2t_ms']:.2f} ms (2 threads); "
          f"bound {2 * m['bound_2c_ms']:.2f} ms on 1 core, {m['bound_2c_ms']:.2f} on 2; "
          f"frame / bound {m['frame_1t_ms'] / (2 * m['bound_2c_ms']):.1f}x (1), {m['frame_2t_ms'] / m['bound_2c_ms']:.1f}x (2)\n")
    print(f"| pass | bound, 1 / 2 cores, ms | measured{m['passes_note']}, 1 / 2 threads, ms | measured / bound, 1 / 2 | binds |")
    print("| --- | ---: | ---: | ---: | --- |")
    for p in m["passes"]:
        b = p["bound_ms"]
        print(f"| {p['kind']} | {2 * b:.3g} / {b:.3g} | {p['t1_ms']:.3f} / {p['t2_ms']:.3f} | "
              f"{p['t1_ms'] / (2 * b):.1f} / {p['t2_ms'] / b:.1f} | {p['binds']} |")
    st1, st2 = m["stages_1t_ms"], m["stages_2t_ms"]
    if st1:
        print("\nstages per frame, 1 / 2 threads (tile stages summed over threads), ms: " + ", ".join(
            f"{k} {st1.get(k, 0):.3f} / {st2.get(k, 0):.3f}" for k in st1))
    extra = ""
    if "serial_work_ms" in m:
        extra = f"; serial work alone (16x16 frame less its tiles) {m['serial_work_ms']:.3f} ms, {100 * m['serial_work_share']:.1f}%"
    print(f"\nserial share (Karp-Flatt, 1 and 2 threads): ours {100 * m['serial_share']:.1f}%, "
          f"llvmpipe's {100 * m['llvmpipe_serial_share']:.1f}%{extra}\n")
    ns = [n for n in thread_list if n > 1]
    print("| pass | tile work, 1 thread, ms | tiles | largest tile | " + " | ".join(f"speed-up of its tiles at {n}" for n in ns) + " |")
    print("| --- | ---: | ---: | ---: | " + " | ".join("---:" for n in ns) + " |")
    for p in m["passes"]:
        print(f"| {p['kind']} | {p['tile_work_ms']:.3f} | {p['tiles']} | {100 * p['largest_tile_share']:.1f}% | " +
              " | ".join(f"{1 / p['makespan_share'][n]:.1f}" for n in ns) + " |")
    print("\n| threads | ours ms | speed-up | Amdahl alone | llvmpipe ms | llvmpipe speed-up | llvmpipe / ours |")
    print("| ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for n in thread_list:
        x = m["model"][n]
        print(f"| {n} | {x['raster_ms']:.2f} | {x['speedup']:.2f} | {x['amdahl']:.2f} | {x['llvmpipe_ms']:.2f} | "
              f"{x['llvmpipe_speedup']:.2f} | {x['llvmpipe_ms'] / x['raster_ms']:.2f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", required=True, help="folder of full-size runs: SCENE_t{1,2}_rR.json")
    parser.add_argument("--tiny", help="folder of --size 16x16 runs, the same names (optional: serial work alone)")
    parser.add_argument("--tiles", required=True, help="folder of bench/tile_costs output at the full size: SCENE_rR.json")
    parser.add_argument("--tiles-tiny", help="the same at the tiny size (16x16), with --tiny")
    parser.add_argument("--scenes", help="comma-separated scenes (default: every scene of --bounds)")
    parser.add_argument("--bounds", default=BOUNDS_FILE, help="the paper bounds file (default bench/paper_bounds.json)")
    parser.add_argument("--fma-ns", type=float,
                        help="the runs' clock as a dependent FMA's latency, ns (raster_micro's peak/fma/chains:1), to "
                             "scale the bounds to (default: the bounds file's own clock)")
    parser.add_argument("--threads", default="1,2,4,8,16,32",
                        help=f"thread counts to model (must hold 1 and 2; at most {RASTER_MAX_THREADS}, as raster)")
    parser.add_argument("--frames", action="append", default=[], metavar="SCENE=T1,T2,LT1,LT2",
                        help="the frame medians (ms: ours at 1 and 2 threads, llvmpipe's at 1 and 2) to take the serial "
                             "shares from, in place of --runs' (e.g. a quieter hour's run_benchmarks.py); repeatable")
    parser.add_argument("--json", help="also write every figure to this file")
    args = parser.parse_args()
    for option, folder in (("--runs", args.runs), ("--tiny", args.tiny), ("--tiles", args.tiles),
                           ("--tiles-tiny", args.tiles_tiny)):
        if folder is not None and not os.path.isdir(folder):
            fail(PROG, f"{option} {folder}: not a folder")
    # The serial work alone needs both: the tiny frame, less its tile work (one alone was
    # read as neither, silently).
    if (args.tiny is None) != (args.tiles_tiny is None):
        fail(PROG, "--tiny and --tiles-tiny go together (the 16x16 runs and their tile costs)")
    if args.fma_ns is not None and not (math.isfinite(args.fma_ns) and args.fma_ns > 0):
        fail(PROG, f"--fma-ns {args.fma_ns}: not a latency (a number above 0)")
    bounds = load_bounds(args.bounds, args.fma_ns)
    scenes = list(bounds) if args.scenes is None else split_list(PROG, "--scenes", args.scenes)
    for scene in scenes:
        if scene not in bounds:
            fail(PROG, f"--scenes: {scene!r} has no paper bound in {args.bounds} (scenes: {', '.join(bounds)})")
    # The model is measured at 1 and 2 threads (--help: the list must hold them). A count past
    # raster's limit is no machine it runs on, and each takes the makespan of a list that long:
    # 100000000 ran for ever.
    thread_list = sorted(parse_counts(PROG, "--threads", args.threads, 1, RASTER_MAX_THREADS, "raster's limit"))
    if not {1, 2} <= set(thread_list):
        fail(PROG, f"--threads {args.threads}: must hold 1 and 2 (the model is measured at them)")
    frames = {}
    for item in args.frames:
        name, _, values = item.partition("=")
        try:
            frames[name] = [float(v) for v in values.split(",")]
        except ValueError:
            frames[name] = []
        if name not in bounds or len(frames[name]) != 4 or not all(0 < v <= MAX_MS for v in frames[name]):
            fail(PROG, f"--frames {item}: not SCENE=T1,T2,LT1,LT2 (a scene and four times in ms, above 0 and at "
                       f"most {MAX_MS:g})")
    if args.json is not None:   # "" too: refused by check_output_path, not skipped
        check_output_path(PROG, "--json", args.json)
    models = [model_scene(bounds, s, args.runs, args.tiny, args.tiles, args.tiles_tiny, thread_list, frames.get(s))
              for s in scenes]
    for m in models:
        print_scene(m, thread_list)
    if args.json is not None:
        write_text_atomically(json.dumps(models, indent=1), args.json)
    return 0


if __name__ == "__main__":
    sys.exit(main())
