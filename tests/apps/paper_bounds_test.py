#!/usr/bin/env python3
"""bench/paper_bounds.py, issue 69's frames against their paper bounds: a real run sets a
scene's frame and passes beside its bounds (scaled to the clock it is given), --replot
reproduces the committed bench/results/bounds/bounds.md that BENCHMARKS.md quotes, a scene
with no bound is listed as such (exit 1), and a bounds file that no longer matches the
scene's passes, or is not a bounds file, is refused with exit 2 and a line naming it, no
traceback and nothing written.

Usage: paper_bounds_test.py RASTER_BINARY SOURCE_DIR
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

raster, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
script = os.path.join(source, "bench", "paper_bounds.py")
committed = os.path.join(source, "bench", "results", "bounds")
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message, file=sys.stderr)


def run(*args):
    return subprocess.run([sys.executable, script, "--raster", raster, *map(str, args)], capture_output=True, text=True,
                          timeout=120)


def expect_refused(args, naming, out):
    done = run(*args)
    lines = done.stderr.strip().splitlines()
    # (after the progress lines of the runs made before the refusal)
    check(done.returncode == 2 and "Traceback" not in done.stderr and bool(lines) and naming in lines[-1],
          f"paper_bounds.py {' '.join(map(str, args))}: not exit 2 with a last line naming {naming!r}: "
          f"exit {done.returncode}, {done.stderr[-1500:]}")
    check(not os.path.exists(os.path.join(out, "bounds.md")), f"paper_bounds.py {' '.join(map(str, args))} wrote bounds.md")


with tempfile.TemporaryDirectory() as tmp:
    with open(os.path.join(source, "bench", "paper_bounds.json")) as f:
        bounds = json.load(f)
    # One real run of shadow at one thread, at a given clock: half the counted FMA latency
    # halves the arithmetic row's bound and leaves the store-bound row as counted.
    out = os.path.join(tmp, "run")
    done = run("--scenes", "shadow", "--threads", "1", "--runs", "1", "--frames", "1", "--fma-ns",
               bounds["fma_ns"] / 2, "--out", out)
    check(done.returncode in (0, 1), f"a run of shadow exited {done.returncode}: {done.stderr[-1500:]}")
    if done.returncode in (0, 1):
        with open(os.path.join(out, "bounds.json")) as f:
            result = json.load(f)
        with open(os.path.join(out, "bounds.md")) as f:
            table = f.read()
        shadow = bounds["scenes"]["shadow"]
        expected = 2 * (shadow[0]["ms"] + shadow[1]["ms"] / 2)   # one core: twice the 2-core bound
        check(f"| shadow | 1 | {expected:.3f} | " in table, f"the shadow row does not read a bound of {expected:.3f}:\n{table}")
        check(len(result["runs"]) == 1 and len(result["runs"][0]["passes_ms"]) == len(shadow),
              "bounds.json does not hold the run and its passes")
        check(done.stdout == table, "the table printed is not bounds.md")
        check(" UTC; a dependent FMA" in table.splitlines()[0], "bounds.md does not give the runs' hour")
        with open(os.path.join(out, "bounds.png"), "rb") as f:
            check(f.read(8) == b"\x89PNG\r\n\x1a\n", "bounds.png is not a PNG")

    # --replot redraws the committed table from the committed runs.
    replot = os.path.join(tmp, "replot")
    os.makedirs(replot)
    shutil.copy(os.path.join(committed, "bounds.json"), replot)
    done = run("--replot", "--out", replot)
    with open(os.path.join(replot, "bounds.md")) as mine, open(os.path.join(committed, "bounds.md")) as theirs:
        check(done.returncode in (0, 1) and mine.read() == theirs.read(),
              f"paper_bounds.py --replot no longer writes bench/results/bounds/bounds.md ({done.stderr[-800:]})")

    # A scene with no bound in the file (one added since) is listed as such and fails the criterion.
    with open(os.path.join(committed, "bounds.json")) as f:
        doc = json.load(f)
    for run_record in doc["runs"]:
        if run_record["scene"] == "hdr":
            run_record["scene"] = "forest"
    with open(os.path.join(replot, "bounds.json"), "w") as f:
        json.dump(doc, f)
    done = run("--replot", "--out", replot)
    check(done.returncode == 1 and "| forest | 2 | no bound counted |" in done.stdout,
          f"a scene without a bound is not listed as such (exit {done.returncode}): {done.stdout[-800:]}{done.stderr[-800:]}")

    # A scene whose passes are not those counted (a pass added since), a bound that is not a
    # time, and a bounds.json whose run lost a pass: refused.
    broken = os.path.join(tmp, "broken.json")
    for change, naming in ((lambda b: b["scenes"]["shadow"].pop(), "shadow's bounds count 1 passes (shadow/shadow) where "
                            "raster bench ran 2"),
                           (lambda b: b["scenes"]["shadow"][0].update(ms=-1), "shadow pass 0: 'ms' must be above 0")):
        doc = json.loads(json.dumps(bounds))
        change(doc)
        with open(broken, "w") as f:
            json.dump(doc, f)
        expect_refused(["--scenes", "shadow", "--threads", "1", "--runs", "1", "--frames", "1", "--bounds", broken,
                        "--out", os.path.join(tmp, "refused")], naming, os.path.join(tmp, "refused"))
    with open(os.path.join(committed, "bounds.json")) as f:
        doc = json.load(f)
    doc["runs"][0]["passes_ms"].pop()
    lost = os.path.join(tmp, "lost")
    os.makedirs(lost)
    with open(os.path.join(lost, "bounds.json"), "w") as f:
        json.dump(doc, f)
    expect_refused(["--replot", "--out", lost], "run 0: 1 passes where the bounds count 2", lost)

if failures:
    print(f"{len(failures)} failure(s)", file=sys.stderr)
    sys.exit(1)
print("paper_bounds: every check passed")
