#!/usr/bin/env python3
"""bench/goal_runs.py judges each configuration by its runs' ratios as the issues state the
goal (median at least --goal, no run below --floor), exits 0 only when all meet it and 1 when
one does not, writes goals.json and goals.md that agree with each other and a goals.png
chart, and exits 2 on bad
input before any run, leaving no file behind.

Usage: goal_runs_test.py RASTER_BINARY SOURCE_DIR
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

raster, source = sys.argv[1], sys.argv[2]
runner = os.path.join(source, "bench", "goal_runs.py")
small = ["--raster", raster, "--runs", "2", "--frames", "2", "--threads", "2", "--sizes", "48x32,17x9",
         "--scenes", "shadow,hdr", "--presets", "gl,fast"]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message, file=sys.stderr)


def goal_runs(*extra):
    return subprocess.run([sys.executable, runner, *small, *extra], capture_output=True, text=True)


with tempfile.TemporaryDirectory(prefix="goal-runs-test-") as tmp:
    # Every ratio is above 0: all met, exit 0; the table and the JSON hold the same rows.
    out = os.path.join(tmp, "all-met")
    done = goal_runs("--goal", "0", "--floor", "0", "--passes", "--out", out)
    check(done.returncode == 0, f"a goal of 0 exited {done.returncode}: {done.stderr[-2000:]}")
    with open(os.path.join(out, "goals.json")) as f:
        result = json.load(f)
    rows = result["configurations"]
    check(len(rows) == 8, f"{len(rows)} configurations, not 2 sizes x 2 presets x 2 scenes")
    check(len(result["runs"]) == 16, f"{len(result['runs'])} runs, not 8 configurations x 2")
    for row in rows:
        check(len(row["ratios"]) == 2 and all(r > 0 for r in row["ratios"]), f"ratios of {row}")
        check(row["median"] == statistics.median(row["ratios"]) and row["min"] == min(row["ratios"]),
              f"median or lowest of {row}")
        check(row["met"], f"not met at a goal of 0: {row}")
        programs = [p["program"] for p in row["passes"]]
        expected = ["shadow/shadow", "shadow/main"] if row["scene"] == "shadow" else None
        check(programs == expected if expected else programs[0] == "hdr/scene" and len(programs) > 2,
              f"passes of {row['scene']}: {programs}")
    with open(os.path.join(out, "goals.md")) as f:
        table = f.read()
    body = [line for line in table.splitlines() if line.startswith("| 48x32") or line.startswith("| 17x9")]
    check(len(body) == 8, f"the table has {len(body)} rows, not 8:\n{table}")
    check(all("| yes |" in line for line in body), f"a row of the table is not met:\n{table}")
    with open(os.path.join(out, "goals.png"), "rb") as f:
        check(f.read(8) == b"\x89PNG\r\n\x1a\n", "goals.png is not a PNG")
    check(sorted(os.listdir(out)) == ["goals.json", "goals.md", "goals.png"], f"left in --out: {os.listdir(out)}")

    # --replot rebuilds the same table from goals.json, with no run.
    os.remove(os.path.join(out, "goals.png"))
    done = subprocess.run([sys.executable, runner, "--replot", "--out", out], capture_output=True, text=True)
    check(done.returncode == 0 and "[1/" not in done.stderr, f"--replot exited {done.returncode}: {done.stderr}")
    with open(os.path.join(out, "goals.md")) as f:
        check(f.read() == table, "--replot wrote a different table")
    check(os.path.exists(os.path.join(out, "goals.png")), "--replot wrote no chart")
    # A median just under the goal is not printed rounded onto it: 2.996 against 3, not "3.00 | no".
    result["goal"], result["configurations"][0]["median"], result["configurations"][0]["met"] = 3.0, 2.996, False
    with open(os.path.join(out, "goals.json"), "w") as f:
        json.dump(result, f)
    done = subprocess.run([sys.executable, runner, "--replot", "--out", out], capture_output=True, text=True)
    with open(os.path.join(out, "goals.md")) as f:
        first = next(line for line in f.read().splitlines() if line.startswith("| 48x32"))
    check(done.returncode == 0 and "| 2.996 |" in first and "| no |" in first,
          f"a median of 2.996 against a goal of 3 reads: {first}")
    done = subprocess.run([sys.executable, runner, "--replot", "--out", os.path.join(tmp, "nothing-here")],
                          capture_output=True, text=True)
    check(done.returncode == 2 and "goals.json" in done.stderr, f"--replot without goals.json exited {done.returncode}")

    # No ratio reaches 10^9: none met, exit 1.
    out = os.path.join(tmp, "none-met")
    done = goal_runs("--goal", "1e9", "--out", out)
    check(done.returncode == 1, f"a goal of 10^9 exited {done.returncode}, not 1: {done.stderr[-2000:]}")
    with open(os.path.join(out, "goals.json")) as f:
        check(not any(row["met"] for row in json.load(f)["configurations"]), "a configuration met a goal of 10^9")

    # A median at the goal with one run below the floor is not met (the rule itself, on set
    # ratios: a floor above the goal, the way a run could once test it, is refused below).
    sys.dont_write_bytecode = True   # no __pycache__ left in bench/
    sys.path.insert(0, os.path.join(source, "bench"))
    import goal_runs as goal_runs_module  # noqa: E402
    rule = argparse.Namespace(sizes=["8x8"], presets=["gl"], scenes=["shadow"], goal=4.0, floor=3.6, passes=False)
    for ratios, met in (([5.0, 3.0], False), ([5.0, 3.6], True), ([3.9, 4.0, 4.1], True), ([3.9, 3.9, 4.5], False)):
        rows = goal_runs_module.summarize(rule, [{"size": "8x8", "preset": "gl", "scene": "shadow", "ratio": r}
                                                 for r in ratios])
        check(rows[0]["met"] == met, f"ratios {ratios} against goal 4 and floor 3.6: met is {rows[0]['met']}")

    # Bad input: exit 2, an error that names the problem (after argparse's usage lines, where
    # argparse refuses it), no run started.
    blocker = os.path.join(tmp, "a-file")
    open(blocker, "w").close()
    goals_png_folder = os.path.join(tmp, "png-folder")   # an --out whose goals.png is a folder
    os.makedirs(os.path.join(goals_png_folder, "goals.png"))
    # The presets are the binary's (`raster methods --json`), draft included.
    for extra, says in ((["--presets", "gl,slow"], "gl, precise, fast, draft"),
                        (["--scenes", "forest"], "shadow, deferred, hdr"),
                        (["--sizes", "640"], "WxH"), (["--sizes", "0x480"], "WxH"), (["--runs", "0"], "--runs"),
                        (["--out", os.path.join(blocker, "under")], f"the folder {blocker} does not exist"),
                        (["--out", blocker], "not a folder"),
                        (["--out", os.path.join(tmp, "no", "such")],
                         f"the folder {os.path.join(tmp, 'no')} does not exist"),
                        # "" once meant every scene; NaN compares false with every ratio; a floor
                        # above the goal makes the goal say nothing; raster bench takes at most
                        # 10000 frames; --out "" names no folder; /bin/true prints no scene list.
                        (["--scenes", ""], "--scenes '': empty"), (["--scenes", "shadow,"], "an empty item"),
                        (["--goal", "nan"], "--goal nan: not a ratio"), (["--pass-goal", "inf"], "--pass-goal inf"),
                        (["--floor", "10", "--goal", "1"], "--floor 10 is above --goal 1"),
                        (["--frames", "10001"], "--frames 10001: at most 10000"),
                        (["--out", ""], "--out '': names no folder"),
                        (["--raster", "/bin/true"], "--raster /bin/true"),
                        (["--raster", "/nonexistent/raster"], "--raster /nonexistent/raster: does not exist"),
                        (["--out", goals_png_folder], "goals.png is a folder")):
        bad = os.path.join(tmp, "bad")
        args = extra if "--out" in extra else extra + ["--out", bad]
        done = goal_runs(*args)
        check(done.returncode == 2, f"{extra} exited {done.returncode}, not 2")
        check(says in done.stderr, f"{extra}: the error does not say '{says}': {done.stderr}")
        check("[1/" not in done.stderr, f"{extra}: a run started before the error")
        check(not os.path.exists(os.path.join(bad, "goals.json")), f"{extra} left a goals.json")
    check(not os.path.exists(os.path.join(tmp, "no")), "a refused --out made the folders above it")
    dry = os.path.join(tmp, "dry")
    done = goal_runs("--presets", "draft", "--dry-run", "--out", dry)
    check(done.returncode == 0 and "--preset draft" in done.stdout, f"--presets draft --dry-run: {done.stderr}")
    check(not os.path.exists(dry), "--dry-run made its --out")

print("goal_runs_test: " + ("passed" if not failures else f"{len(failures)} failed"))
sys.exit(1 if failures else 0)
