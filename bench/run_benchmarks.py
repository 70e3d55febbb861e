#!/usr/bin/python3
"""Side-by-side benchmarks of this pipeline against llvmpipe (and softpipe), all scenes.

For every scene, size and thread count it runs `raster bench` (this pipeline and the GL
driver alternating frame by frame in one process, medians compared), reads the
machine-readable lines it prints, measures each backend's peak memory at 1920x1080 in
separate processes, and writes:
  bench/results/results.json   every figure
  bench/results/results.md     the table
  bench/results/frame_time.png frame time against pixel count, a line per backend, per scene
Usage: bench/run_benchmarks.py [--quick] [--frames N] [--scenes NAME,...] [--raster build/raster] [--replot] [--dry-run]
(--scenes: every scene of `raster scenes` by default; --dry-run prints the runs and runs none)
(Debian's /usr/bin/python3, which has python3-matplotlib from ./setup.sh.)
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

from chart_files import write_atomically, write_text_atomically
from input_checks import (NUMBER, RASTER_MAX_FRAMES, BadInput, check_range, check_raster, check_record, fail, read_json,
                          split_list)
from raster_scenes import checked_names, scene_names

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RASTER = os.path.join(ROOT, "build", "raster")
OUT = os.path.join(ROOT, "bench", "results")
SIZES = ["640x480", "1280x720", "1920x1080", "3840x2160"]
SIZE = re.compile(r"([1-9][0-9]*)x([1-9][0-9]*)")
LINE = re.compile(r"scene=(\S+) backend=(\S+) threads=(\d+) size=(\S+) median_ms=([\d.]+)")


def bench_command(raster, scene, size, threads, frames, driver="llvmpipe"):
    return [raster, "bench", scene, "--size", size, "--threads", str(threads), "--frames", str(frames),
            "--warmup", "2", "--gl-driver", driver]


def run_bench(raster, scene, size, threads, frames, driver="llvmpipe"):
    """One `raster bench` run; returns {backend: median_ms} and the breakdown text."""
    cmd = bench_command(raster, scene, size, threads, frames, driver)
    result = subprocess.run(cmd, capture_output=True, text=True, check=True)
    medians = {m.group(2): float(m.group(5)) for m in LINE.finditer(result.stdout)}
    breakdown = "\n".join(l for l in result.stdout.splitlines() if l.startswith("  ") or l.startswith("per frame"))
    return medians, breakdown


def peak_memory_mb(raster, scene, size, backend):
    """Peak resident memory of one `raster render` process (this pipeline or GL)."""
    # The PNG goes to a folder of its own: "/dev/null.png" made a file in /dev as root and was
    # refused (exit 2, a few MB measured) for anyone else.
    with tempfile.TemporaryDirectory() as folder:
        cmd = [raster, "render", scene, "--size", size, "--backend", backend, "--out", os.path.join(folder, "peak.png")]
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(proc.pid, 0)
    if status != 0:
        sys.exit(f"run_benchmarks.py: {' '.join(cmd)} failed (exit status {os.waitstatus_to_exitcode(status)})")
    return usage.ru_maxrss / 1024.0   # ru_maxrss is in KiB on Linux


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="640x480 and 1920x1080 only, fewer frames")
    parser.add_argument("--frames", type=int, default=15, help="timed frames per backend and configuration")
    parser.add_argument("--scenes", help="comma-separated scene names (default: every scene of `raster scenes`)")
    parser.add_argument("--raster", default=RASTER, help="the raster binary (default: build/raster)")
    parser.add_argument("--replot", action="store_true", help="only rewrite the table and chart from results.json")
    parser.add_argument("--dry-run", action="store_true", help="print the `raster bench` command lines, run none")
    args = parser.parse_args()
    if args.frames < 1:
        parser.error(f"--frames {args.frames}: at least 1")
    # raster bench's own limit, before the first run (--quick halves the count; --dry-run
    # printed command lines raster would refuse).
    if args.frames > RASTER_MAX_FRAMES:
        parser.error(f"--frames {args.frames}: at most {RASTER_MAX_FRAMES} (raster bench's limit)")
    if args.replot:
        results = load_results(os.path.join(OUT, "results.json"))
        write_table(results)
        # The scenes in the order the runs first name them.
        write_chart(results, list(dict.fromkeys(r["scene"] for r in results["runs"])))
        return
    # --scenes "" is refused, not read as every scene.
    given = None if args.scenes is None else split_list("run_benchmarks.py", "--scenes", args.scenes)
    check_raster("run_benchmarks.py", "--raster", args.raster)
    sizes = ["640x480", "1920x1080"] if args.quick else SIZES
    frames = max(3, args.frames // 2) if args.quick else args.frames
    scenes = checked_names("run_benchmarks.py", "--scenes", given, scene_names(args.raster))
    jobs = [(s, size, t) for s in scenes for size in sizes for t in (1, 2)]
    if args.dry_run:
        for scene, size, threads in jobs:
            print(" ".join(bench_command(args.raster, scene, size, threads, frames)))
        for scene in scenes:
            print(" ".join(bench_command(args.raster, scene, "640x480", 2, max(3, frames // 3), "softpipe")))
        return
    os.makedirs(OUT, exist_ok=True)

    results = {"frames": frames, "machine": os.uname().machine, "cores": os.cpu_count(), "runs": [], "memory_mb": {}}
    started = time.time()
    for i, (scene, size, threads) in enumerate(jobs, 1):
        print(f"[{i}/{len(jobs)}] {scene} {size} threads={threads} ({time.time() - started:.0f} s)", flush=True)
        medians, breakdown = run_bench(args.raster, scene, size, threads, frames)
        results["runs"].append({"scene": scene, "size": size, "threads": threads, "medians_ms": medians,
                                "breakdown": breakdown})
    for scene in scenes:   # softpipe for scale, at 640x480
        print(f"softpipe {scene} 640x480", flush=True)
        medians, _ = run_bench(args.raster, scene, "640x480", 2, max(3, frames // 3), driver="softpipe")
        results["runs"].append({"scene": scene, "size": "640x480", "threads": 2, "medians_ms": medians,
                                "driver": "softpipe"})
        for backend in ("raster", "gl"):
            results["memory_mb"].setdefault(scene, {})[backend] = peak_memory_mb(args.raster, scene, "1920x1080", backend)

    write_text_atomically(json.dumps(results, indent=1), os.path.join(OUT, "results.json"))
    write_table(results)
    write_chart(results, scenes)
    print(f"wrote {OUT}/results.json, results.md, frame_time.png")


def load_results(path):
    """results.json for --replot, with the fields the table and the chart read checked."""
    results = read_json("run_benchmarks: --replot", path, "a results.json")
    try:
        check_record(results, {"runs": list, "memory_mb": dict}, "")
        for i, run in enumerate(results["runs"]):
            check_record(run, {"scene": str, "size": str, "threads": int, "medians_ms": dict}, f"run {i}")
            if not SIZE.fullmatch(run["size"]):
                raise BadInput(f"run {i}: 'size' is not WxH")
            other = "softpipe" if run.get("driver") == "softpipe" else "llvmpipe"
            check_record(run["medians_ms"], {"raster": NUMBER, other: NUMBER}, f"run {i}: 'medians_ms'")
            # Above 0: the table divides by raster's median, and the chart's log axes take
            # nothing at or below 0 (1e9 ms, eleven days a frame, is no measurement either).
            for backend in ("raster", other):
                check_range(run["medians_ms"], backend, 0, 1e9, f"run {i}: 'medians_ms'", above=True)
        for scene, memory in results["memory_mb"].items():
            check_record(memory, {"raster": NUMBER, "gl": NUMBER}, f"memory_mb: {scene}")
    except BadInput as e:
        fail("run_benchmarks: --replot", f"{path}: not a results.json ({e})")
    return results


def megapixels(size):
    width, height = SIZE.fullmatch(size).groups()
    return int(width) * int(height) / 1e6


def write_table(results):
    lines = ["| scene | size | threads | raster ms | llvmpipe ms | llvmpipe / raster | softpipe ms |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for run in results["runs"]:
        m = run["medians_ms"]
        if run.get("driver") == "softpipe":
            lines.append(f"| {run['scene']} | {run['size']} | {run['threads']} | {m['raster']:.2f} | | | {m['softpipe']:.2f} |")
        else:
            lines.append(f"| {run['scene']} | {run['size']} | {run['threads']} | {m['raster']:.2f} | "
                         f"{m['llvmpipe']:.2f} | {m['llvmpipe'] / m['raster']:.2f} | |")
    lines += ["", "Peak resident memory of one `raster render` process at 1920x1080 (MiB):", "",
              "| scene | raster | GL (llvmpipe) |", "| --- | --- | --- |"]
    for scene, mem in results["memory_mb"].items():
        lines.append(f"| {scene} | {mem['raster']:.0f} | {mem['gl']:.0f} |")
    write_text_atomically("\n".join(lines) + "\n", os.path.join(OUT, "results.md"))


def write_chart(results, scenes):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for backend, style in (("raster", "-o"), ("llvmpipe", "--s")):
            for threads in (1, 2):
                runs = [r for r in results["runs"] if r["scene"] == scene and r["threads"] == threads
                        and r.get("driver") != "softpipe"]
                pixels = [megapixels(r["size"]) for r in runs]
                ax.plot(pixels, [r["medians_ms"][backend] for r in runs], style, label=f"{backend}, {threads} thr")
        ax.set_title(scene)
        ax.set_xlabel("megapixels")
        ax.set_ylabel("median frame time (ms)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    write_atomically(fig, os.path.join(OUT, "frame_time.png"))


if __name__ == "__main__":
    main()
