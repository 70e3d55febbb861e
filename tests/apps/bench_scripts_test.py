#!/usr/bin/env python3
"""The bench scripts that read files a person hands them (sweep_chart.py, tradeoff_chart.py,
scaling_model.py, goal_runs.py --replot, target_hashes.py) draw the repository's own
results, and refuse anything else with exit 2 and one line naming the file and what is
wrong: no Python traceback, no half-written output, and for target_hashes.py no minutes of
renders before the refusal. scaling_model.py on the committed runs reproduces
bench/results/scaling/model.md, and goal_runs.py --replot bench/results/issue69/goals.md:
the tables BENCHMARKS.md quotes. random_frames.py's frames match llvmpipe, a difference is
caught, and its bad arguments are refused.

Usage: bench_scripts_test.py RASTER_BINARY SOURCE_DIR
"""
import contextlib
import glob
import io
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import warnings

raster, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
bench = os.path.join(source, "bench")
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message, file=sys.stderr)


def run(script, *args, cwd=None, timeout=60):
    """The script's exit; a run past `timeout` seconds (a read that never ends) is killed and
    reads as exit status "timeout"."""
    command = [sys.executable, os.path.join(bench, script), *map(str, args)]
    try:
        return subprocess.run(command, capture_output=True, text=True, cwd=cwd, timeout=timeout)
    except subprocess.TimeoutExpired:
        return subprocess.CompletedProcess(command, "timeout", "", f"killed after {timeout} s")


def expect_refused(script, args, naming, outputs=(), cwd=None, usage=False):
    """Exit 2, one line on stderr holding `naming` (after argparse's usage lines where `usage`),
    no traceback, none of `outputs` written."""
    done = run(script, *args, cwd=cwd)
    what = f"{script} {' '.join(map(str, args))}"
    check(done.returncode == 2, f"{what} exited {done.returncode}, not 2: {done.stderr[-1500:]}")
    check("Traceback" not in done.stderr, f"{what} printed a traceback: {done.stderr[-1500:]}")
    lines = done.stderr.strip().splitlines()
    check(bool(lines) and naming in lines[-1] and (usage or len(lines) == 1),
          f"{what}: stderr is not one line naming {naming!r}: {done.stderr[-1500:]}")
    for path in outputs:
        check(not os.path.exists(path), f"{what} left {path} behind")


def expect_refused_in_process(what, call, naming, usage=False):
    """call(), a bench script's own function run in this process (no interpreter and matplotlib
    start a case: the test's time is budgeted), exits 2 with one line on stderr naming `naming`
    (after argparse's usage lines where `usage`); no other exception, no warning."""
    stderr, status = io.StringIO(), None
    with contextlib.redirect_stderr(stderr), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            call()
        except SystemExit as e:
            status = e.code
        except Exception as e:   # what a script without the check raised: a traceback
            status = f"{type(e).__name__}: {e}"
    text = stderr.getvalue()
    check(status == 2, f"{what} exited {status}, not 2: {text[-1500:]}")
    lines = text.strip().splitlines()
    check(bool(lines) and naming in lines[-1] and (usage or len(lines) == 1),
          f"{what}: stderr is not one line naming {naming!r}: {text[-1500:]}")
    check(not caught, f"{what} warned: {[str(w.message) for w in caught]}")


def main_with(module, *args):
    """A call of module.main() as `module.py args` would make it."""
    def call():
        saved = sys.argv
        sys.argv = [module.__name__ + ".py", *map(str, args)]
        try:
            module.main()
        finally:
            sys.argv = saved
    return call


with tempfile.TemporaryDirectory(prefix="bench-scripts-test-") as tmp:
    def write(name, text):
        path = os.path.join(tmp, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    malformed = write("malformed.json", '{"points": [')
    a_list = write("list.json", "[1, 2]")
    missing = os.path.join(tmp, "missing.json")
    sweep = sorted(glob.glob(os.path.join(source, "docs", "stability", "*", "sweep.json")))[0]
    with open(sweep) as f:
        sweep_doc = json.load(f)
    tradeoff = os.path.join(source, "docs", "tradeoff", "640x480", "tradeoff.json")
    with open(tradeoff) as f:
        tradeoff_doc = json.load(f)

    # The charts draw the repository's own results, under both metrics.
    for script, result in (("sweep_chart.py", sweep), ("tradeoff_chart.py", tradeoff)):
        for metric in ("psnr", "flip"):
            prefix = os.path.join(tmp, f"{script}-{metric}")
            done = run(script, result, "--out", prefix, "--metric", metric)
            check(done.returncode == 0, f"{script} {result} --metric {metric} exited {done.returncode}: {done.stderr}")
            for ext, magic in (("png", b"\x89PNG"), ("svg", b"<?xml")):
                with open(f"{prefix}.{ext}", "rb") as f:
                    check(f.read(5).startswith(magic), f"{prefix}.{ext} is not a {ext}")
        # Same inputs, same bytes: a chart drawn again (an SVG once held its date and random ids).
        again = os.path.join(tmp, f"{script}-again")
        done = run(script, result, "--out", again)
        for ext in ("png", "svg"):
            with open(f"{again}.{ext}", "rb") as f, open(os.path.join(tmp, f"{script}-psnr.{ext}"), "rb") as g:
                check(f.read() == g.read(), f"{script}: the {ext} drawn twice differs")

    # What the sweep chart says where lines or labels would lie on one another (matplotlib
    # keeps each text as a comment in the SVG): hdr's time sweep, where precise and softpipe
    # first fail at one value, and shadow's near sweep, where draft is fast (no post pass).
    def sweep_svg_texts(name):
        prefix = os.path.join(tmp, name)
        done = run("sweep_chart.py", os.path.join(source, "docs", "stability", name, "sweep.json"), "--out", prefix)
        check(done.returncode == 0, f"sweep_chart.py {name} exited {done.returncode}: {done.stderr}")
        with open(prefix + ".svg") as f:
            return f.read()
    hdr_time = sweep_svg_texts("hdr-time")
    check("<!-- precise, softpipe fail -->" in hdr_time, "hdr-time: precise and softpipe not named in one label")
    check("each value's time" in hdr_time and "t=1" not in hdr_time, "hdr-time: the title names a base time")
    shadow_near = sweep_svg_texts("shadow-near")
    check("<!-- draft (the same as fast at every value) -->" in shadow_near, "shadow-near: draft's line not told apart")
    check("<!-- gl (identical at every value) -->" in shadow_near, "shadow-near: gl's line not told apart")

    # The tradeoff chart of each committed result, under both metrics: no label covers
    # another in any panel (the chart's clusters of methods at one speed and accuracy are
    # what it is read for), and every point is named in one.
    sys.dont_write_bytecode = True   # no __pycache__ left in bench/
    sys.path.insert(0, bench)
    import matplotlib.text  # noqa: E402
    import tradeoff_chart  # noqa: E402
    current = [path for path in sorted(glob.glob(os.path.join(source, "docs", "tradeoff", "*", "tradeoff.json")))
               if re.fullmatch(r"[0-9]+x[0-9]+", os.path.basename(os.path.dirname(path)))]   # not dated runs
    check(len(current) >= 2, f"{len(current)} current tradeoff results in docs/tradeoff/")
    for result_path in current:
        # (FLIP's panels place their labels with the same code: one size of them is enough.)
        for metric in ("psnr", "flip") if result_path == current[-1] else ("psnr",):
            results = tradeoff_chart.load_results([result_path], metric)
            fig = tradeoff_chart.figure(results, metric)
            renderer = fig.canvas.get_renderer()
            what = f"{os.path.relpath(result_path, source)} ({metric})"
            panels = [ax for ax in fig.axes if ax.axison]
            check(len(panels) == 2 * len(results), f"{what}: {len(panels)} panels for {len(results)} scenes")
            for ax in panels:
                texts = [t for t in ax.texts if t.get_text()]
                # The text's own box (an annotation's extent would take in its leader line),
                # once the annotation has placed its text.
                for t in texts:
                    if isinstance(t, matplotlib.text.Annotation):
                        t.update_positions(renderer)
                boxes = [matplotlib.text.Text.get_window_extent(t, renderer) for t in texts]
                for a in range(len(texts)):
                    for b in range(a):
                        check(not boxes[a].overlaps(boxes[b]), f"{what}, {ax.get_title()}: "
                              f"{texts[a].get_text()!r} covers {texts[b].get_text()!r}")
                named = ", ".join(t.get_text().replace("\n", " ") for t in texts)
                scene = next(r for r in results if ax.get_title().startswith(r["scene"] + " "))
                for point in scene["points"]:
                    check(point["name"] in named, f"{what}, {ax.get_title()}: {point['name']} is not named")
            tradeoff_chart.plt.close(fig)

    # A point with a field gone, of the wrong type, or a sweep without FLIP charted by FLIP.
    point_gone = dict(sweep_doc, points=[{k: v for k, v in p.items() if k != "value_index"} for p in sweep_doc["points"]])
    wrong_type = dict(sweep_doc, points=[dict(p, value="high") for p in sweep_doc["points"]])
    no_flip = dict(sweep_doc, points=[{k: v for k, v in p.items() if k != "flip_vs_llvmpipe"} for p in sweep_doc["points"]])
    out = os.path.join(tmp, "refused")
    outputs = [out + ".png", out + ".svg"]
    for path, naming in ((malformed, "malformed.json: not a sweep.json"), (a_list, "list.json: not a sweep.json"),
                         (missing, "missing.json: not a sweep.json"),
                         (write("gone.json", json.dumps(point_gone)), "point 0: no 'value_index'"),
                         (write("type.json", json.dumps(wrong_type)), "point 0: 'value' is not a number"),
                         (write("empty.json", json.dumps(dict(sweep_doc, points=[]))), "no points")):
        expect_refused("sweep_chart.py", [path, "--out", out], naming, outputs)
    expect_refused("sweep_chart.py", [write("noflip.json", json.dumps(no_flip)), "--out", out, "--metric", "flip"],
                   "the sweep has no FLIP", outputs)
    expect_refused("sweep_chart.py", [sweep, "--out", "/proc/chart"], "--out /proc/chart: cannot write in /proc")
    expect_refused("sweep_chart.py", [sweep, "--out", os.path.join(tmp, "no", "chart")], "does not exist")

    first = tradeoff_doc[0] if isinstance(tradeoff_doc, list) else tradeoff_doc
    slow = dict(first, points=[dict(p, speedup_vs_llvmpipe=0) for p in first["points"]])
    nameless = dict(first, points=[{k: v for k, v in p.items() if k != "name"} for p in first["points"]])
    for path, naming in ((malformed, "malformed.json: not a tradeoff result"), (a_list, "an object was expected"),
                         (write("slow.json", json.dumps(slow)), "'speedup_vs_llvmpipe' is not above 0"),
                         (write("nameless.json", json.dumps(nameless)), "point 0: no 'name'")):
        expect_refused("tradeoff_chart.py", [path, "--out", out], naming, outputs)
    expect_refused("tradeoff_chart.py", [tradeoff, "--out", "/proc/chart"], "cannot write in /proc")

    # What the charts read, refused with a line naming the file and field, and an --out that
    # names no file or whose .png is a folder, before any drawing (the scripts' own functions,
    # in this process: one start of matplotlib for them all; one real process below).
    import sweep_chart  # noqa: E402
    deep = write("deep.json", "[" * 100000)   # past Python's parser: a RecursionError
    side = next(p["method"] for p in sweep_doc["points"] if p["method"] != "llvmpipe")

    def sweep_with(name, **fields):
        """sweep_doc with the fields of its first point of `side` replaced ("threshold_db": the sweep's)."""
        doc = json.loads(json.dumps(sweep_doc))
        doc.update({k: v for k, v in fields.items() if k in doc})
        point = next(p for p in doc["points"] if p["method"] == side)
        point.update({k: v for k, v in fields.items() if k not in doc})
        return write(name, json.dumps(doc))   # NaN and Infinity written as Python's json does

    log_sweep = sweep_doc["range"]["log"]
    check(log_sweep, f"{sweep} is not a log sweep, which the cases below need")
    for path, naming in ((deep, "deep.json: not a sweep.json (nested too deeply)"),
                         (sweep_with("nan.json", psnr_vs_llvmpipe_db=float("nan")), "'psnr_vs_llvmpipe_db' is NaN"),
                         (sweep_with("inf.json", threshold_db=float("inf")), "'threshold_db' is Infinity"),
                         (sweep_with("infvalue.json", value=float("inf")), "'value' is Infinity"),
                         (sweep_with("huge.json", psnr_vs_llvmpipe_db=1e308), "'psnr_vs_llvmpipe_db' is 1e+308"),
                         (sweep_with("negative.json", value=-1.0), "'value' is -1, not above 0")):
        expect_refused_in_process(f"sweep_chart {path}", lambda: sweep_chart.load(path, False), naming)
    expect_refused_in_process("sweep_chart --metric flip, a FLIP of 2",
                              lambda: sweep_chart.load(sweep_with("flip2.json", flip_vs_llvmpipe=2.0), True),
                              "'flip_vs_llvmpipe' is 2, not within 0..1")
    for doc, metric, naming in ((dict(first, points=[dict(first["points"][0], speedup_vs_llvmpipe=float("inf"))]),
                                 "psnr", "'speedup_vs_llvmpipe' is Infinity"),
                                (dict(first, points=[dict(first["points"][0], speedup_vs_llvmpipe=1e308)]),
                                 "psnr", "'speedup_vs_llvmpipe' is 1e+308"),
                                (dict(first, points=[dict(first["points"][0], flip_vs_llvmpipe=float("nan"))]),
                                 "flip", "'flip_vs_llvmpipe' is NaN")):
        path = write("point.json", json.dumps(doc))
        expect_refused_in_process(f"tradeoff_chart {naming}", lambda: tradeoff_chart.load_results([path], metric),
                                  naming)
    expect_refused_in_process("tradeoff_chart deep.json", lambda: tradeoff_chart.load_results([deep], "psnr"),
                              "nested too deeply")
    os.makedirs(os.path.join(tmp, "folder.png"))
    for module, result in ((sweep_chart, sweep), (tradeoff_chart, tradeoff)):
        expect_refused_in_process(f"{module.__name__} --out DIR/", main_with(module, result, "--out", tmp + "/"),
                                  "names no file")
        expect_refused_in_process(f"{module.__name__} --out PREFIX (PREFIX.png a folder)",
                                  main_with(module, result, "--out", os.path.join(tmp, "folder")), "is a folder")
    expect_refused("sweep_chart.py", [sweep, "--out", ""], "--out '': names no file",
                   [os.path.join(tmp, ".png"), os.path.join(tmp, ".svg")], cwd=tmp)
    # A PSNR below 0 (a float image's can be) is drawn, the axis reaching down to it; a
    # threshold past any PSNR (raster sweep takes any finite --threshold) is named, not drawn at
    # 1e308 (where matplotlib's axis overflowed with a warning).
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        fig = sweep_chart.draw(sweep_chart.load(sweep_with("below0.json", psnr_vs_llvmpipe_db=-20.0), False))
        check(fig.axes[0].get_ylim()[0] < -20, f"a PSNR of -20 dB lies below the y axis {fig.axes[0].get_ylim()}")
        sweep_chart.plt.close(fig)
        fig = sweep_chart.draw(sweep_chart.load(sweep_with("far.json", threshold_db=1e308), False))
        check(fig.axes[0].get_ylim()[1] < 1e4 and any("1e+308 dB (above the axis)" in t.get_text()
                                                       for t in fig.axes[0].texts),
              f"a threshold of 1e308 dB: y axis {fig.axes[0].get_ylim()}, not named above it")
        fig.canvas.draw()   # where the overflow was
        sweep_chart.plt.close(fig)
    check(not caught, f"sweep_chart warned: {[str(w.message) for w in caught]}")

    # The paper bounds and the scaling model from the committed runs: model.md's tables, by the
    # command its first line names (the runs' clock among its arguments).
    runs, tiles = os.path.join(bench, "results", "scaling", "runs"), os.path.join(bench, "results", "scaling", "tiles")
    with open(os.path.join(bench, "results", "scaling", "model.md")) as f:
        header, *body = f.read().splitlines()
    made_by = header.split("bench/scaling_model.py", 1)[1].split("(", 1)[0].split()
    done = run("scaling_model.py", *(os.path.join(source, a) if a.startswith("bench/") else a for a in made_by))
    check(done.returncode == 0, f"scaling_model.py exited {done.returncode}: {done.stderr[-1500:]}")
    committed = [line for line in body if line]
    check([line for line in done.stdout.splitlines() if line] == committed,
          "scaling_model.py on bench/results/scaling no longer prints model.md's tables")
    # The model cuts a pass's items as the renderer does, from each tile's bin: a few-tile pass's
    # tiles of at most 16 triangles into 16-row bands, a depth-only pass's heavy tile into ranges
    # (its second range halfway down the list).
    import scaling_model  # noqa: E402
    few = {"costs": [4.0, 2.0], "tile_triangles": [1, 17], "depth_ranges": False, "tiles_x": 2, "height": 64}
    check(scaling_model.work_items(few, 2) == [1.0] * 4 + [2.0], "the model's bands are not the renderer's")
    heavy = {**few, "costs": [6.0, 2.0], "tile_triangles": [300, 100], "depth_ranges": True}
    check(scaling_model.work_items(heavy, 2) == [3.0, 2.0, 3.0], "the model's depth ranges are not the renderer's")
    broken_runs = os.path.join(tmp, "runs")
    shutil.copytree(runs, broken_runs)
    with open(os.path.join(broken_runs, "hdr_t2_r2.json"), "w") as f:
        json.dump({"passes": [{"raster_ms": 1.0}], "backends": []}, f)
    expect_refused("scaling_model.py", ["--runs", broken_runs, "--tiles", tiles, "--scenes", "hdr"],
                   "hdr_t2_r2.json: not a `raster bench --passes --json` run (pass 0: no 'llvmpipe_ms')")
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", runs], "no tile costs match")
    expect_refused("scaling_model.py", ["--runs", os.path.join(tmp, "none"), "--tiles", tiles], "not a folder")
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", tiles, "--scenes", "cat"], "'cat' has no paper bound")
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", tiles, "--threads", "1,x"], "--threads 1,x")
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", tiles, "--frames", "hdr=1,2,3"], "--frames hdr=1,2,3")
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", tiles, "--json", "/proc/model.json"],
                   "cannot write in /proc")
    # --threads: past raster's 1024 (10^8 ran for ever), or without 1 and 2 (--help: the
    # model is measured at them); --tiny without --tiles-tiny; a frame's median of 0.
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", tiles, "--threads", "1,2,100000000"],
                   "100000000 is out of range")
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", tiles, "--threads", "4,8"], "must hold 1 and 2")
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", tiles, "--tiny", runs], "--tiles-tiny")
    expect_refused("scaling_model.py", ["--runs", runs, "--tiles", tiles, "--json", ""], "--json '': names no file")
    zero_runs = os.path.join(tmp, "zero-runs")
    shutil.copytree(runs, zero_runs)
    with open(os.path.join(runs, "hdr_t1_r1.json")) as f:
        zero = json.load(f)
    for backend in zero["backends"]:
        backend["median_ms"] = 0
    with open(os.path.join(zero_runs, "hdr_t1_r1.json"), "w") as f:
        json.dump(zero, f)
    expect_refused("scaling_model.py", ["--runs", zero_runs, "--tiles", tiles, "--scenes", "hdr"],
                   "hdr_t1_r1.json: not a `raster bench --passes --json` run (backend 0: 'median_ms' is 0, not above 0")

    # goal_runs.py --replot redraws the committed goal run's table from its goals.json, and
    # refuses a goals.json whose configurations are not what it wrote.
    replot = os.path.join(tmp, "replot")
    os.makedirs(replot)
    committed_goals = os.path.join(bench, "results", "issue69")
    shutil.copy(os.path.join(committed_goals, "goals.json"), replot)
    done = run("goal_runs.py", "--replot", "--out", replot)
    check(done.returncode == 0, f"goal_runs.py --replot exited {done.returncode}: {done.stderr[-1500:]}")
    with open(os.path.join(replot, "goals.md")) as mine, open(os.path.join(committed_goals, "goals.md")) as theirs:
        written = mine.read()
        check(written == theirs.read(), "goal_runs.py --replot no longer writes bench/results/issue69/goals.md")
    # A run with --passes also tabulates every pass: its ratios and our ms (BENCHMARKS' pass by pass).
    check("| hdr | 11 | `hdr/post+composite` | " in written and "ours, 640x480 `gl`, ms |" in written,
          "goal_runs.py --replot does not tabulate each pass's ratios and times")
    with open(os.path.join(committed_goals, "goals.json")) as f:
        goals = json.load(f)
    for broken, naming in ((dict(goals, configurations=[1]), "configuration 0: an object was expected"),
                           (dict(goals, configurations=goals["configurations"][1:]), "no configuration for size"),
                           (dict(goals, configurations=[dict(goals["configurations"][0], passes=[
                               dict(goals["configurations"][0]["passes"][0], median_raster_ms="fast")])]
                                 + goals["configurations"][1:]), "configuration 0 pass 0: 'median_raster_ms'")):
        with open(os.path.join(replot, "goals.json"), "w") as f:
            json.dump(broken, f)
        expect_refused("goal_runs.py", ["--replot", "--out", replot], naming)
    # A goal run states the clock it ran at (a dependent FMA's latency before and after its
    # runs; the host's hours differ by it) on its table's first line, and refuses a clock that
    # is not two numbers.
    with open(os.path.join(replot, "goals.json"), "w") as f:
        json.dump(dict(goals, fma_ns={"before": 0.938, "after": 1.093},
                       utc={"start": "2026-12-07T21:41:07Z", "end": "2026-12-07T21:45:50Z"}), f)
    done = run("goal_runs.py", "--replot", "--out", replot)
    with open(os.path.join(replot, "goals.md")) as f:
        check(done.returncode == 0 and "; 2026-12-07 21:41-21:45 UTC; a dependent FMA 0.938 ns before the runs, 1.093 after "
              "(the clock);" in f.readline(), "goal_runs.py --replot does not state the goal run's hour and clock")
    with open(os.path.join(replot, "goals.json"), "w") as f:
        json.dump(dict(goals, utc={"start": "21:41", "end": "2026-12-07T21:45:50Z"}), f)
    expect_refused("goal_runs.py", ["--replot", "--out", replot], "utc: 'start' is not a time")
    with open(os.path.join(replot, "goals.json"), "w") as f:
        json.dump(dict(goals, fma_ns={"before": 0.938}), f)
    expect_refused("goal_runs.py", ["--replot", "--out", replot], "fma_ns: no 'after'")

    expect_refused("run_benchmarks.py", ["--frames", "0", "--dry-run"], "--frames 0: at least 1", usage=True)
    # raster bench takes at most 10000 frames: --quick's half of 10^8 was printed as a command.
    expect_refused("run_benchmarks.py", ["--dry-run", "--quick", "--frames", "100000000"], "at most 10000", usage=True)
    expect_refused("run_benchmarks.py", ["--raster", raster, "--dry-run", "--scenes", ""], "--scenes '': empty")
    # Every runner names an unknown scene or preset in one wording (raster_scenes.checked_names).
    expect_refused("run_benchmarks.py", ["--raster", raster, "--dry-run", "--scenes", "shadow,forest"],
                   "--scenes: unknown 'forest' (valid: shadow, ")
    expect_refused("goal_runs.py", ["--raster", raster, "--dry-run", "--scenes", "forest"], "--scenes: unknown 'forest'")
    expect_refused("goal_runs.py", ["--raster", raster, "--dry-run", "--presets", "gl,warp"],
                   "--presets: unknown 'warp' (valid: gl, ")
    # --replot's results.json (run in this process: the script reads it from bench/results): a
    # median of 0 divided the table by 0, and NaN is not JSON.
    import run_benchmarks  # noqa: E402
    results_doc = {"runs": [{"scene": "shadow", "size": "640x480", "threads": 1,
                             "medians_ms": {"raster": 0, "llvmpipe": 1.0}}], "memory_mb": {}}
    path = write("results.json", json.dumps(results_doc))
    expect_refused_in_process("run_benchmarks --replot, a median of 0", lambda: run_benchmarks.load_results(path),
                              "run 0: 'medians_ms': 'raster' is 0, not above 0")
    results_doc["runs"][0]["medians_ms"]["raster"] = float("nan")
    path = write("results.json", json.dumps(results_doc))
    expect_refused_in_process("run_benchmarks --replot, a NaN median", lambda: run_benchmarks.load_results(path),
                              "'raster' is NaN")

    # target_hashes.py reads --against and tries --out before its renders, from any folder.
    expect_refused("target_hashes.py", ["--raster", raster, "--against", malformed], "not an earlier --out", cwd=tmp)
    expect_refused("target_hashes.py", ["--raster", raster, "--out", "/proc/hashes.json"], "cannot write in /proc",
                   cwd=tmp)
    # Files that are not regular are refused, not read for ever (/dev/zero: /dev/null here, which
    # a script without the check reads as empty, not until memory runs out) or waited on (a FIFO
    # with no writer); every argument is checked before the first render, each list's items and
    # the binary too (a traceback, a silent default, or an error after all the renders).
    fifo = os.path.join(tmp, "fifo")
    os.mkfifo(fifo)
    for against in ("/dev/null", fifo):
        expect_refused("target_hashes.py", ["--raster", raster, "--against", against], "not a regular file", cwd=tmp)
    expect_refused("target_hashes.py", ["--raster", raster, "--against", deep], "nested too deeply", cwd=tmp)
    for option, value, naming in (("--threads", "1, 2", "' 2' has spaces around it"),
                                  ("--threads", "", "--threads '': empty"), ("--threads", "1,", "an empty item"),
                                  ("--threads", "1025", "1025 is out of range"), ("--scenes", "", "--scenes '': empty"),
                                  ("--scenes", "shadow,forest", "unknown 'forest'"),
                                  ("--sizes", "24x16,99999x2", "99999x2 is not a WxH"),
                                  ("--out", os.path.join(tmp, "folder.png"), "is a folder")):
        expect_refused("target_hashes.py", ["--raster", raster, "--scenes", "shadow", "--sizes", "24x16",
                                            "--threads", "1", option, value], naming, cwd=tmp)
    for binary in ("/nonexistent/raster", "/bin/true"):
        for scenes in ([], ["--scenes", "shadow"]):   # with --scenes, no `raster scenes` is needed
            expect_refused("target_hashes.py", ["--raster", binary, *scenes, "--sizes", "24x16", "--threads", "1"],
                           f"--raster {binary}", cwd=tmp)
    hashes = os.path.join(tmp, "hashes.json")
    done = run("target_hashes.py", "--raster", raster, "--scenes", "shadow", "--sizes", "24x16", "--threads", "1,3",
               "--out", hashes, cwd=tmp)
    check(done.returncode == 0, f"target_hashes.py exited {done.returncode}: {done.stderr[-1500:]}")
    done = run("target_hashes.py", "--raster", raster, "--scenes", "shadow", "--sizes", "24x16", "--threads", "2",
               "--against", hashes, cwd=tmp)
    check(done.returncode == 1 and "present on one side only" in done.stdout,
          f"another thread count against --out: exit {done.returncode}, {done.stdout[-500:]}")
    done = run("target_hashes.py", "--raster", raster, "--scenes", "shadow", "--sizes", "24x16", "--threads", "3,1",
               "--against", hashes, cwd=tmp)
    check(done.returncode == 0 and " 0 changed" in done.stdout, f"the same runs again: {done.stdout[-500:]}")

    # random_frames.py: random frames against llvmpipe, every target bit for bit. Real frames
    # match; a raster that reports a difference is caught (exit 1, the reproducing line); a
    # refused frame is counted, not failed; bad arguments exit 2 before any frame.
    frames_json = os.path.join(tmp, "frames.json")
    done = run("random_frames.py", "--raster", raster, "--frames", "4", "--max-size", "40x30", "--max-time", "3",
               "--json", frames_json, "--quiet", timeout=120)
    check(done.returncode == 0, f"random_frames.py exited {done.returncode}: {done.stdout[-800:]} {done.stderr[-800:]}")
    if os.path.exists(frames_json):
        with open(frames_json) as f:
            frames = json.load(f)
        check(frames["counts"]["same"] == 4 and len(frames["frames"]) == 4, f"random_frames.py counts: {frames['counts']}")
        check(all(fr["targets"].get("final") == 0 and set(fr["targets"].values()) == {0} for fr in frames["frames"]),
              f"random_frames.py targets: {[fr.get('targets') for fr in frames['frames']]}")
    fake = os.path.join(tmp, "fake-raster")
    # The fake's compare writes compare.json where --out says, as raster's does.
    numbers = 'while [ $# -gt 0 ] && [ "$1" != --out ]; do shift; done; echo \'{"targets": [{"name": "final", "max_in_unit": 3}]}\' > "$2/compare.json"'
    for compare, expected, shows in ((numbers, 1, "differs: raster compare "),
                                     ("echo 'raster: --set: a value out of range' >&2; exit 2", 0, " 1 refused"),
                                     ("echo 'final  rgba8 8x8  max 0'", 1, "failed: raster compare ")):
        with open(fake, "w") as f:
            f.write(f'#!/bin/sh\nif [ "$1" = compare ]; then {compare}; exit 0; fi\nexec {shlex.quote(raster)} "$@"\n')
        os.chmod(fake, 0o755)
        done = run("random_frames.py", "--raster", fake, "--frames", "1", "--quiet")
        check(done.returncode == expected and shows in done.stdout,
              f"random_frames.py with `{compare}`: exit {done.returncode}, {done.stdout[-500:]} {done.stderr[-500:]}")
    # --max-params K: each frame that sets parameters sets 1 to K distinct ones; --scalar S:
    # that share of the frames with the plain lanes (a fake whose compare finds no difference).
    same = numbers.replace('"max_in_unit": 3', '"max_in_unit": 0')
    with open(fake, "w") as f:
        f.write(f'#!/bin/sh\nif [ "$1" = compare ]; then {same}; exit 0; fi\nexec {shlex.quote(raster)} "$@"\n')
    done = run("random_frames.py", "--raster", fake, "--frames", "30", "--scenes", "shadow", "--params", "1",
               "--max-params", "3", "--scalar", "0.5", "--json", frames_json, "--quiet")
    with open(frames_json) as f:
        drawn = json.load(f)["frames"]
    counts = [len(fr["set"]) for fr in drawn]
    check(done.returncode == 0 and min(counts) >= 1 and max(counts) == 3 and 2 in counts,
          f"random_frames.py --max-params 3: exit {done.returncode}, parameters a frame {counts}")
    check(0 < sum(fr["scalar"] for fr in drawn) < 30, f"random_frames.py --scalar 0.5: {[fr.get('scalar') for fr in drawn]}")
    # --time-spread log: times across the decades up to --max-time, where uniform draws put
    # nearly all of them in its last two.
    decades = {}
    for spread in ("uniform", "log"):
        done = run("random_frames.py", "--raster", fake, "--frames", "40", "--scenes", "shadow", "--max-time", "1e30",
                   "--time-spread", spread, "--json", frames_json, "--quiet")
        with open(frames_json) as f:
            times = [fr["time"] for fr in json.load(f)["frames"]]
        check(done.returncode == 0 and all(0 <= t <= 1e30 for t in times), f"random_frames.py --time-spread {spread}: {times}")
        decades[spread] = {math.floor(math.log10(t)) for t in times if t > 0}
    check(len(decades["uniform"]) <= 4 and len(decades["log"]) >= 15 and min(decades["log"]) < 0,
          f"random_frames.py --time-spread: decades drawn {decades}")
    with open(fake, "w") as f:   # a difference: its reproducing line carries --scalar
        f.write(f'#!/bin/sh\nif [ "$1" = compare ]; then {numbers}; exit 0; fi\nexec {shlex.quote(raster)} "$@"\n')
    done = run("random_frames.py", "--raster", fake, "--frames", "1", "--scalar", "1", "--quiet")
    check(done.returncode == 1 and " --scalar (final max 3)" in done.stdout, f"random_frames.py --scalar 1: {done.stdout[-500:]}")
    # --preset P --min-psnr X: a frame holds when the final image's PSNR is at least X (null in
    # compare.json: identical), and the preset reaches compare; below X fails the run.
    for psnr, expected, shows in (("35.5", 1, "--preset fast (final 35.50 dB, under 40)"), ("45", 0, " 1 holds, 0 below"),
                                  ("null", 0, " 1 holds, 0 below")):
        with_psnr = numbers.replace('"max_in_unit": 3}', f'"max_in_unit": 3, "psnr_db": {psnr}}}')
        with open(fake, "w") as f:
            f.write(f'#!/bin/sh\nif [ "$1" = compare ]; then {with_psnr}; exit 0; fi\nexec {shlex.quote(raster)} "$@"\n')
        done = run("random_frames.py", "--raster", fake, "--frames", "1", "--preset", "fast", "--min-psnr", "40",
                   "--float-final", "0", "--quiet")
        check(done.returncode == expected and shows in done.stdout,
              f"random_frames.py --preset fast, final at {psnr} dB: exit {done.returncode}, {done.stdout[-500:]} {done.stderr[-500:]}")
    for option, value, naming in (("--threads", "0", "0 is out of range"), ("--max-size", "0x30", "0x30 is not a WxH"),
                                  ("--max-size", "8x8,9x9", "one WxH"), ("--float-final", "1.5", "not a share"),
                                  ("--params", "nan", "not a share"), ("--max-params", "0", "out of range (1..100)"), ("--scalar", "2", "not a share"),
                                  ("--preset", "fast", "say what its frames must hold with --min-psnr"),
                                  ("--min-psnr", "40", "give --float-final 0"), ("--min-size", "800x10", "larger than --max-size"),
                                  ("--scenes", "forest", "unknown 'forest'"), ("--scenes", "", "--scenes '': empty"),
                                  ("--minutes", "-1", "out of range"), ("--json", tmp, "is a folder")):
        expect_refused("random_frames.py", ["--raster", raster, "--frames", "1", option, value], naming, cwd=tmp)

if failures:
    print(f"{len(failures)} failure(s)", file=sys.stderr)
    sys.exit(1)
print("bench scripts: every check passed")
