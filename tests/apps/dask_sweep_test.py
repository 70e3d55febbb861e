#!/usr/bin/env python3
"""A sweep sharded on a 2-worker Dask LocalCluster equals the single-machine sweep, byte for
byte, even when a worker dies under a shard (the task is rescheduled); bad input (an unknown
parameter, too many shards, an --out in a folder that does not exist, a --scheduler that is
no address or has no valid port, more local workers than a few a core) exits 2 before any
cluster starts.

Usage: dask_sweep_test.py RASTER_BINARY SOURCE_DIR
"""
import filecmp
import os
import subprocess
import sys
import tempfile

raster, source = sys.argv[1], sys.argv[2]
runner = os.path.join(source, "bench", "dask_sweep.py")
sweep = ["shadow", "--param", "light_elevation=5:80:5"]
options = ["--size", "96x72", "--methods", "gl,fast", "--threads", "1"]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message, file=sys.stderr)


with tempfile.TemporaryDirectory(prefix="dask-sweep-test-") as tmp:
    single = os.path.join(tmp, "single")
    done = subprocess.run([raster, "sweep"] + sweep + options + ["--out", single, "--quiet"], capture_output=True, text=True)
    check(done.returncode == 0, f"raster sweep exited {done.returncode}: {done.stderr}")

    dask = os.path.join(tmp, "dask")
    done = subprocess.run([sys.executable, runner] + sweep + ["--shards", "3", "--local-workers", "2", "--out", dask,
                          "--raster", raster, "--test-kill-worker-on-shard", "2", "--"] + options,
                          capture_output=True, text=True)
    check(done.returncode == 0, f"dask_sweep.py exited {done.returncode}: {done.stderr[-3000:]}")
    check(os.path.exists(os.path.join(dask, ".killed-a-worker")), "the worker of shard 2 was not killed")
    same = os.path.exists(os.path.join(dask, "sweep.json")) and filecmp.cmp(
        os.path.join(single, "sweep.json"), os.path.join(dask, "sweep.json"), shallow=False)
    check(same, "the Dask sweep.json differs from raster sweep's")
    check(os.path.getsize(os.path.join(dask, "sweep.png")) > 0 if os.path.exists(os.path.join(dask, "sweep.png")) else False,
          "no merged chart")

    done = subprocess.run([sys.executable, runner, "shadow", "--param", "no_such=1:2:3", "--shards", "2",
                           "--local-workers", "2", "--out", os.path.join(tmp, "bad"), "--raster", raster],
                          capture_output=True, text=True)
    check(done.returncode == 2, f"an unknown parameter exited {done.returncode}, not 2")
    check("no_such" in done.stderr and "light_elevation" in done.stderr, f"the error does not list the parameters: {done.stderr}")
    check(not os.path.exists(os.path.join(tmp, "bad", "sweep.json")), "bad input left a sweep.json")

    # A shard that raster refuses on its worker (exit 2; here a wrapper that passes --check and
    # refuses the run itself) is not retried: Dask retries a task on any exception it raises,
    # so the task returns the refusal. One attempt for the one shard, despite --retries 2.
    attempts = os.path.join(tmp, "attempts")
    wrapper = os.path.join(tmp, "refusing-raster")
    with open(wrapper, "w") as f:
        f.write(f'#!/bin/sh\ncase " $* " in *" --check "*) exec "{raster}" "$@";; esac\n'
                f'echo attempt >> "{attempts}"\necho "raster: refused on the worker" >&2\nexit 2\n')
    os.chmod(wrapper, 0o755)
    done = subprocess.run([sys.executable, runner] + sweep + ["--shards", "1", "--local-workers", "1", "--retries", "2",
                          "--out", os.path.join(tmp, "refusing"), "--raster", wrapper, "--"] + options,
                          capture_output=True, text=True)
    check(done.returncode == 2 and "refused on the worker" in done.stderr,
          f"a refused shard exited {done.returncode}: {done.stderr[-2000:]}")
    tries = open(attempts).read().count("attempt") if os.path.exists(attempts) else 0
    check(tries == 1, f"a refused shard ran {tries} times, not once")

    # More shards than raster takes, and an --out whose parent folder does not exist: refused
    # by raster's check before any cluster starts, and nothing made (the folder once was).
    for shards, out, naming in (("20000", os.path.join(tmp, "many"), "--shard"),
                                ("2", os.path.join(tmp, "no", "such"), "--out")):
        done = subprocess.run([sys.executable, runner] + sweep + ["--shards", shards, "--local-workers", "2",
                               "--out", out, "--raster", raster], capture_output=True, text=True)
        check(done.returncode == 2, f"--shards {shards} --out {out} exited {done.returncode}, not 2: {done.stderr[-2000:]}")
        check(naming in done.stderr and "Traceback" not in done.stderr, f"the refusal does not name {naming}: {done.stderr[-2000:]}")
        check(not os.path.exists(out), f"the refused run made {out}")

    # A --scheduler that is no address (distributed's ValueError was a traceback) or has a port
    # past 65535 (a 30 s connect timeout), and more local workers than a few a core (100000
    # hung without a word): exit 2 naming the option, nothing made, no cluster started.
    for where, naming in ((["--scheduler", "garbage"], "--scheduler garbage"),
                          (["--scheduler", "tcp://[::1"], "--scheduler tcp://[::1"),
                          (["--scheduler", "tcp://127.0.0.1:99999"], "port 99999 is not 1..65535"),
                          (["--local-workers", "100000"], "--local-workers: 100000 is more than")):
        out = os.path.join(tmp, "refused")
        try:
            done = subprocess.run([sys.executable, runner] + sweep + ["--shards", "2", "--out", out, "--raster", raster]
                                  + where, capture_output=True, text=True, timeout=25)
        except subprocess.TimeoutExpired:   # killed: a refusal takes a second or two
            done = subprocess.CompletedProcess(where, "timeout", "", "killed after 25 s")
        check(done.returncode == 2, f"{where} exited {done.returncode}, not 2: {done.stderr[-2000:]}")
        check(naming in done.stderr and "Traceback" not in done.stderr,
              f"{where}: the refusal does not name {naming!r}: {done.stderr[-2000:]}")
        check(not os.path.exists(out), f"{where}: the refused run made {out}")

print("dask_sweep_test: " + ("passed" if not failures else f"{len(failures)} failed"))
sys.exit(1 if failures else 0)
