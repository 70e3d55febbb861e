#!/usr/bin/python3
"""Random frames against llvmpipe: `raster compare` at scenes, times, sizes, thread counts and
scene parameters that no test names, every target required bit for bit (`max 0`).

Each frame draws a scene (every scene of `raster scenes` by default), a time in
[0, --max-time] (three decimals; with --time-spread log, its magnitude log-uniform from 1e-3
to --max-time, six significant digits, so that --max-time 1e30 reaches every decade of
`raster`'s range and not only its last two), a size up to --max-size, a thread count from
--threads, --float-final with probability --float-final, --scalar (this pipeline's plain
lanes: the readable instantiation of every port, the SIMD paths off) with probability
--scalar, and with probability --params one of the scene's own parameters (`raster params
SCENE`; with --max-params K, 1 to K distinct ones, so that parameters meet: a near plane of
1e-7 far from the origin) at a random value of its range: uniform where the range spans at
most three decades, else its magnitude log-uniform up to the range's end (so 1e-3 to 1e20
for a world offset, either sign). A frame raster refuses (exit 2: a value another parameter
rules out, such as a cascade split past the next) is counted as refused. A frame that
differs prints the `raster compare` line that shows it again.

Presets: with --preset P (`raster methods` lists them and what each promises) the frames are
drawn with that method set, and --min-psnr X states what each must hold instead of the bytes:
the final image's PSNR against llvmpipe at least X dB (a frame holds or is below). So
`--preset fast --min-psnr 40 --params 0 --min-size 320x240 --max-size 1920x1080
--float-final 0` checks fast's promise at times no test names.

Threads: llvmpipe is not stable against itself past its host's cores (STABILITY.md, "Where gl
is not bit-identical": a thread that drew no half-float tile still flushes denormals), so
the default is 1,2; a frame that differs only at more threads than cores is llvmpipe's.

Writes --json FILE (every frame: its arguments, status and each target's largest difference,
read from the compare.json `raster compare` writes) when asked, and prints a summary. Exit
status: 0 when every frame matched (or held) or was refused, 1 when one differed (or was
below), failed or ran past --timeout, 2 for bad arguments.

Usage: bench/random_frames.py [--frames N | --minutes 10] [--seed 1] [--scenes NAME,...]
                              [--threads 1,2] [--max-size 720x480] [--max-time 30]
                              [--time-spread uniform|log] [--min-size 1x1]
                              [--float-final 0.5] [--params 0.5] [--max-params 1]
                              [--scalar 0] [--preset gl --min-psnr DB] [--timeout 600]
                              [--raster build/raster] [--json FILE] [--quiet]
(Found, on 2026-12-06: deferred's denormals and pbr's smoothstep order, both fixed;
docs/notes/2026-12-06-random-frames-denormals-and-smoothstep.md.)
"""
import argparse
import json
import math
import os
import random
import shlex
import subprocess
import sys
import tempfile
import time

from chart_files import write_text_atomically
from input_checks import (RASTER_MAX_THREADS, check_output_path, check_raster, fail, parse_counts, parse_sizes,
                          split_list)
from raster_scenes import checked_names, preset_names, scene_rows

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROG = "random_frames.py"
# A frame's statuses, with --min-psnr and without, and those that make the run fail (printed
# as they happen).
STATUSES_EXACT = ("same", "differs", "refused", "failed", "timeout")
STATUSES_PSNR = ("holds", "below", "refused", "failed", "timeout")
NOT_SAME = ("differs", "below", "failed", "timeout")


def parse_args(argv):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames", type=int, default=0, help="frames to compare (default: as many as --minutes allow)")
    parser.add_argument("--minutes", type=float, default=10.0, help="time to spend when --frames is not given (default 10)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the draws: the same seed draws the same frames (default 1)")
    parser.add_argument("--scenes", help="comma-separated scene names (default: every scene of `raster scenes`)")
    parser.add_argument("--threads", default="1,2", help="comma-separated thread counts to draw from (default 1,2)")
    parser.add_argument("--max-size", default="720x480", help="largest WxH drawn (default 720x480)")
    parser.add_argument("--min-size", default="1x1", help="smallest WxH drawn (default 1x1)")
    parser.add_argument("--max-time", type=float, default=30.0, help="latest time drawn, seconds (default 30)")
    parser.add_argument("--time-spread", choices=("uniform", "log"), default="uniform",
                        help="how times are drawn: uniform in [0, --max-time], or log-uniform in magnitude (default uniform)")
    parser.add_argument("--float-final", type=float, default=0.5, help="share of frames with --float-final (default 0.5)")
    parser.add_argument("--params", type=float, default=0.5, help="share of frames that set a scene parameter (default 0.5)")
    parser.add_argument("--scalar", type=float, default=0.0,
                        help="share of frames with --scalar: this pipeline's plain lanes, every SIMD path off (default 0)")
    parser.add_argument("--max-params", type=int, default=1,
                        help="most parameters such a frame sets, 1 to this many distinct ones (default 1)")
    parser.add_argument("--preset", default="gl", help="the method set compared (default gl: every target bit for bit)")
    parser.add_argument("--min-psnr", type=float,
                        help="instead of the bytes: the final image's PSNR against llvmpipe, at least this many dB")
    parser.add_argument("--timeout", type=float, default=600.0, help="seconds one compare may take (default 600)")
    parser.add_argument("--raster", default=os.path.join(ROOT, "build", "raster"), help="the raster binary")
    parser.add_argument("--json", help="write every frame and the summary here")
    parser.add_argument("--quiet", action="store_true", help="no progress on stderr")
    args = parser.parse_args(argv)
    if args.frames < 0 or args.frames > 10**7:
        fail(PROG, f"--frames {args.frames}: out of range (0..10000000; 0: as many as --minutes allow)")
    if not (math.isfinite(args.minutes) and 0 < args.minutes <= 7 * 24 * 60):
        fail(PROG, f"--minutes {args.minutes}: out of range (above 0, at most a week)")
    if not (math.isfinite(args.max_time) and 0 <= args.max_time <= 1e30):
        fail(PROG, f"--max-time {args.max_time}: out of range (0..1e30, raster's)")
    for option, share in (("--float-final", args.float_final), ("--params", args.params), ("--scalar", args.scalar)):
        if not 0 <= share <= 1:   # NaN fails too
            fail(PROG, f"{option} {share}: not a share (0..1)")
    if not 1 <= args.max_params <= 100:
        fail(PROG, f"--max-params {args.max_params}: out of range (1..100)")
    if not (math.isfinite(args.timeout) and args.timeout > 0):
        fail(PROG, f"--timeout {args.timeout}: must be a positive number of seconds")
    args.threads = parse_counts(PROG, "--threads", args.threads, 1, RASTER_MAX_THREADS, "raster's --threads; 0 is not one count")
    for option in ("--max-size", "--min-size"):
        attribute = option[2:].replace("-", "_")
        if "," in getattr(args, attribute):
            fail(PROG, f"{option} {getattr(args, attribute)}: one WxH, not a list")
        setattr(args, attribute, parse_sizes(PROG, option, getattr(args, attribute))[0])
    # The two sizes as (width, height), parsed once for every frame's draw.
    args.size_bounds = [tuple(map(int, size.split("x"))) for size in (args.min_size, args.max_size)]
    (min_w, min_h), (max_w, max_h) = args.size_bounds
    if min_w > max_w or min_h > max_h:
        fail(PROG, f"--min-size {args.min_size}: larger than --max-size {args.max_size} on a side")
    if args.min_psnr is not None:
        if not (math.isfinite(args.min_psnr) and 0 <= args.min_psnr <= 200):
            fail(PROG, f"--min-psnr {args.min_psnr}: out of range (0..200 dB)")
        if args.float_final > 0:
            fail(PROG, f"--min-psnr reads the final RGBA8 image's PSNR: give --float-final 0, not {args.float_final}")
    check_raster(PROG, "--raster", args.raster)
    args.preset = checked_names(PROG, "--preset", [args.preset], preset_names(args.raster))[0]
    if args.preset != "gl" and args.min_psnr is None:
        fail(PROG, f"--preset {args.preset}: say what its frames must hold with --min-psnr DB "
                   "(`raster methods` gives each preset's promise); only gl is held to the bytes")
    if args.json:
        check_output_path(PROG, "--json", args.json)
    rows = {row["name"]: row for row in scene_rows(args.raster)}
    given = split_list(PROG, "--scenes", args.scenes) if args.scenes is not None else None
    names = checked_names(PROG, "--scenes", given, list(rows))
    args.rows = {name: rows[name] for name in names}
    return args


def parameter_value(rng, param):
    """A value in the parameter's [min, max]: uniform over at most three decades, else the
    magnitude log-uniform from 1e-3 (or min) to the end, either sign where the range has both."""
    low, high = float(param["min"]), float(param["max"])
    if high <= low:
        return low
    magnitude_top = max(abs(low), abs(high))
    if (low > 0 and high / low <= 1e3) or (low <= 0 and magnitude_top <= 1e3):
        value = rng.uniform(low, high)
    else:
        bottom = low if low > 0 else min(1e-3, magnitude_top)
        value = math.exp(rng.uniform(math.log(bottom), math.log(magnitude_top)))
        if low < 0 and rng.random() < 0.5:
            value = -value
        value = min(max(value, low), high)
    return round(value) if param.get("integer") else float(f"{value:.6g}")


def draw_time(rng, args):
    """A time in [0, --max-time]: uniform (three decimals), or with --time-spread log its
    magnitude log-uniform from 1e-3 (or --max-time, if smaller) to --max-time."""
    if args.time_spread == "uniform" or args.max_time <= 0:
        return round(rng.uniform(0, args.max_time), 3)
    bottom = min(1e-3, args.max_time)
    value = math.exp(rng.uniform(math.log(bottom), math.log(args.max_time)))
    return min(float(f"{value:.6g}"), args.max_time)


def draw_frame(rng, args):
    """One frame's compare arguments, and what was drawn."""
    scene = rng.choice(sorted(args.rows))
    (width_min, height_min), (width_max, height_max) = args.size_bounds
    frame = {"scene": scene, "time": draw_time(rng, args),
             "size": f"{rng.randint(width_min, width_max)}x{rng.randint(height_min, height_max)}",
             "threads": rng.choice(args.threads), "float_final": rng.random() < args.float_final, "set": {}}
    params = [p for p in args.rows[scene].get("params", []) if p["name"] not in ("time", "size")]
    if params and rng.random() < args.params:
        if args.max_params == 1:   # the draws of the seeds quoted before --max-params existed
            chosen = [rng.choice(params)]
        else:
            chosen = rng.sample(params, rng.randint(1, min(args.max_params, len(params))))
            chosen.sort(key=params.index)   # --set in the order `raster params` lists them
        for param in chosen:
            frame["set"][param["name"]] = parameter_value(rng, param)
    if args.preset != "gl":
        frame["preset"] = args.preset
    if args.scalar > 0:   # drawn only when asked, so that the seeds quoted before keep their frames
        frame["scalar"] = rng.random() < args.scalar
    return frame


def compare_words(frame):
    words = ["compare", frame["scene"], "--time", str(frame["time"]), "--size", frame["size"],
             "--threads", str(frame["threads"])]
    for name, value in frame["set"].items():
        words += ["--set", f"{name}={value}"]
    if frame["float_final"]:
        words.append("--float-final")
    if "preset" in frame:
        words += ["--preset", frame["preset"]]
    if frame.get("scalar"):
        words.append("--scalar")
    return words


def run_frame(args, frame, out_dir):
    """Compares one frame; sets its status (same, differs, refused, failed, timeout; with
    --min-psnr holds or below instead of same or differs) and the largest difference of each
    target in the target's own unit (compare.json's max_in_unit: 8-bit steps, depth LSBs,
    half or float ULPs), and with --min-psnr the final image's PSNR (None: identical)."""
    command = [args.raster, *compare_words(frame), "--out", out_dir, "--quiet"]
    numbers = os.path.join(out_dir, "compare.json")
    if os.path.exists(numbers):   # the last frame's: this one must write its own
        os.remove(numbers)
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        frame["status"] = "timeout"
        return
    targets, final_psnr = {}, None
    if done.returncode == 0 and os.path.exists(numbers):
        try:
            with open(numbers) as f:
                listed = json.load(f)["targets"]
            targets = {t["name"]: t["max_in_unit"] for t in listed}
            if args.min_psnr is not None:
                final_psnr = next(t["psnr_db"] for t in listed if t["name"] == "final")
        except (OSError, ValueError, KeyError, TypeError, StopIteration) as error:
            targets = {}
            frame["message"] = f"{numbers} unreadable: {error!r}"
    frame["targets"] = targets
    if done.returncode == 2:
        frame["status"] = "refused"
        frame["message"] = done.stderr.strip()[-500:]
    elif done.returncode != 0 or not targets:
        frame["status"] = "failed"
        frame.setdefault("message", done.stderr.strip()[-500:] or f"exit {done.returncode}, no target compared")
    elif args.min_psnr is not None:
        frame["final_psnr_db"] = final_psnr   # null in compare.json: identical, no finite PSNR
        frame["status"] = "holds" if final_psnr is None or final_psnr >= args.min_psnr else "below"
    else:
        frame["status"] = "same" if all(v == 0 for v in targets.values()) else "differs"


def main(argv):
    args = parse_args(argv)
    rng = random.Random(args.seed)
    deadline = time.monotonic() + args.minutes * 60
    frames, last_progress = [], time.monotonic()
    with tempfile.TemporaryDirectory(prefix="random-frames-") as out_dir:
        while (len(frames) < args.frames) if args.frames else (time.monotonic() < deadline):
            frame = draw_frame(rng, args)
            run_frame(args, frame, out_dir)
            frames.append(frame)
            if frame["status"] in NOT_SAME:
                if frame["status"] == "below":
                    shown = f"final {frame['final_psnr_db']:.2f} dB, under {args.min_psnr:g}"
                else:
                    shown = ", ".join(f"{k} max {v:g}" for k, v in frame.get("targets", {}).items() if v != 0)
                print(f"{frame['status']}: raster {shlex.join(compare_words(frame))}"
                      + (f" ({shown})" if shown else "") + (f": {frame['message']}" if "message" in frame else ""),
                      flush=True)
            if not args.quiet and time.monotonic() - last_progress > 10:
                last_progress = time.monotonic()
                bad = sum(f["status"] in NOT_SAME for f in frames)
                print(f"{PROG}: {len(frames)} frames, {bad} not the same", file=sys.stderr, flush=True)
    statuses = STATUSES_EXACT if args.min_psnr is None else STATUSES_PSNR
    counts = {status: sum(f["status"] == status for f in frames) for status in statuses}
    print(f"{len(frames)} frames (seed {args.seed}): " + ", ".join(f"{n} {status}" for status, n in counts.items()))
    if args.json:
        summary = {"seed": args.seed, "raster": os.path.abspath(args.raster), "threads": args.threads,
                   "min_size": args.min_size, "max_size": args.max_size, "max_time": args.max_time,
                   "time_spread": args.time_spread,
                   "preset": args.preset, "min_psnr_db": args.min_psnr, "counts": counts, "frames": frames}
        write_text_atomically(json.dumps(summary, indent=1) + "\n", args.json)
    return 1 if any(counts.get(status) for status in NOT_SAME) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
