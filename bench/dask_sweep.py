#!/usr/bin/env python3
"""`raster sweep` on a Dask cluster: one task per shard, merged into the single-machine result.

Each task runs `raster sweep ... --shard K/N` in a scratch folder of the worker it lands on
and returns that shard's sweep.json as text, so workers need the raster binary (and the
assets) at the same path, but no shared file system. The client writes the shards under
OUT/shards/ and runs `raster sweep-merge`, which checks that every shard is there exactly
once and each holds exactly its points; its OUT/sweep.json is byte for byte the one
`raster sweep` writes without --shard (the file holds no timing).

A task that fails, or whose worker dies under it, is run again (--retries, and Dask's own
rescheduling of a lost worker's tasks); a shard that still fails stops the run with its
error. Bad input (raster's exit status 2) is not retried: it would fail the same way, so the
task returns raster's refusal rather than raising (Dask retries a task on any exception).

Usage:
  dask_sweep.py SCENE --param NAME=FROM:TO:STEPS[:log] --shards N --out DIR
                (--scheduler tcp://HOST:PORT | --local-workers W) [raster sweep options]
Every option after `--` goes to `raster sweep` unchanged, e.g.
  dask_sweep.py shadow --param near=0.1:1e-5:16:log --shards 8 --local-workers 2 --out sw \\
      -- --methods gl,fast --size 320x240 --threads 1
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

from chart_files import write_text_atomically
from input_checks import check_raster

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_RASTER = os.path.join(HERE, "..", "build", "raster")


# The most --local-workers a core: each worker is a process that runs one `raster sweep`
# shard at a time, which keeps a core busy (more with raster's --threads). Workers past the
# cores only queue on them, each a Python process of ~100 MB that takes a while to start: 64
# on 2 cores crawled, 100000 hung without a word. A few a core leaves room for shards that
# wait on I/O.
WORKERS_PER_CORE = 4


def usable_cores():
    """The cores this process may run on (its affinity: a container's or taskset's share)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:   # not Linux
        return os.cpu_count() or 1


def scheduler_problem(address):
    """What is wrong with a --scheduler address, or None, found before anything is made or
    started: distributed's own parser (Client() raised its ValueError as a traceback for
    "garbage" or "tcp://[::1"), a protocol it has, a host, and a port in 1..65535 (Client
    waited out its 30 s connect timeout on tcp://127.0.0.1:99999)."""
    try:
        from distributed.comm.addressing import parse_address, parse_host_port
        from distributed.comm.registry import backends
    except ImportError:
        return None   # main() says that python3-distributed is missing
    try:
        scheme, location = parse_address(address)   # HOST:PORT alone is tcp://HOST:PORT
        host, port = parse_host_port(location)
    except ValueError as e:
        return f"not PROTOCOL://HOST:PORT ({e})"
    if scheme not in backends or scheme == "inproc":   # inproc: within one process only
        return f"unknown protocol {scheme}:// (tcp, tls, ws, wss or ucx)"
    if not host:
        return "no host"
    if not 1 <= port <= 65535:
        return f"port {port} is not 1..65535"
    return None


def run_shard(raster, scene, param, index, count, extra, kill_marker=None):
    """Runs one shard in a scratch folder. Runs on a worker. Returns (its sweep.json text,
    None), or (None, raster's refusal) when raster exits 2: returned, not raised, so that
    Dask does not retry what would fail the same way."""
    if kill_marker and not os.path.exists(kill_marker):
        # Test hook (--test-kill-worker-on-shard): the first attempt takes its worker down
        # for real, as a machine lost mid-run would; the retry finds the marker and runs.
        open(kill_marker, "w").close()
        os._exit(1)
    with tempfile.TemporaryDirectory(prefix=f"sweep-shard-{index}-") as folder:
        out = os.path.join(folder, "out")
        command = [raster, "sweep", scene, "--param", param, "--shard", f"{index}/{count}", "--out", out, "--quiet"]
        done = subprocess.run(command + list(extra), capture_output=True, text=True)
        if done.returncode == 2:
            return None, done.stderr.strip() or f"raster sweep exited 2 for shard {index}/{count}"
        if done.returncode != 0:
            raise RuntimeError(f"shard {index}/{count} failed (exit {done.returncode}): {done.stderr.strip()[-2000:]}")
        with open(os.path.join(out, "sweep.json")) as f:
            return f.read(), None


def parse_args(argv):
    if "--" in argv:
        split = argv.index("--")
        argv, extra = argv[:split], argv[split + 1:]
    else:
        extra = []
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("scene")
    parser.add_argument("--param", required=True, help="NAME=FROM:TO:STEPS[:log], as raster sweep takes it")
    parser.add_argument("--shards", type=int, required=True, help="number of tasks (values are dealt out round-robin)")
    parser.add_argument("--out", required=True, help="folder for sweep.json/.md/.png/.svg and shards/")
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--scheduler", help="address of a running Dask scheduler, e.g. tcp://10.0.0.5:8786")
    where.add_argument("--local-workers", type=int, help="start a LocalCluster of this many single-threaded workers")
    parser.add_argument("--raster", default=DEFAULT_RASTER, help="the raster binary, at the same path on every worker")
    parser.add_argument("--retries", type=int, default=2, help="extra attempts for a failed shard (default 2)")
    parser.add_argument("--test-kill-worker-on-shard", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    args.extra = extra
    if args.shards < 1:
        parser.error(f"--shards: {args.shards} is not 1 or more")
    if args.local_workers is not None and args.local_workers < 1:
        parser.error(f"--local-workers: {args.local_workers} is not 1 or more")
    cores = usable_cores()
    if args.local_workers is not None and args.local_workers > WORKERS_PER_CORE * cores:
        parser.error(f"--local-workers: {args.local_workers} is more than {WORKERS_PER_CORE * cores} "
                     f"({WORKERS_PER_CORE} for each of this machine's {cores} cores: more would only queue on them)")
    if args.scheduler is not None:
        problem = scheduler_problem(args.scheduler)
        if problem:
            parser.error(f"--scheduler {args.scheduler}: {problem}")
    if args.retries < 0:
        parser.error("--retries: must be 0 or more")
    args.raster = os.path.abspath(args.raster)
    check_raster("dask_sweep.py", "--raster", args.raster)   # a file, not a folder (access() says yes of one)
    return args


def check_arguments(args):
    """Lets raster check everything before any task runs; --check makes nothing. Twice: as a
    shard (the range, methods, size, the shard count, the output folder the merge writes),
    and whole, which also checks the Python and matplotlib that the merge's chart needs here
    (a shard, drawing nothing, skips that)."""
    common = [args.raster, "sweep", args.scene, "--param", args.param, "--out", args.out, "--check"]
    for shard in (["--shard", f"1/{args.shards}"], []):
        done = subprocess.run(common + shard + args.extra, capture_output=True, text=True)
        if done.returncode != 0:
            print(done.stderr.strip() or f"raster sweep refused the arguments (exit {done.returncode})", file=sys.stderr)
            sys.exit(2 if done.returncode == 2 else 1)


def main(argv):
    args = parse_args(argv)
    check_arguments(args)
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        sys.exit("dask_sweep.py: python3-distributed is missing (Debian: apt install python3-distributed)")

    # The cluster first: a scheduler that cannot be reached leaves no --out folder behind.
    cluster = None
    if args.local_workers:
        cluster = LocalCluster(n_workers=args.local_workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    else:
        try:
            client = Client(args.scheduler)
        except OSError as e:   # no scheduler there, or not reachable: one line, not a traceback
            print(f"dask_sweep.py: --scheduler: cannot reach {args.scheduler}: {e}", file=sys.stderr)
            return 1
    shard_root = os.path.join(args.out, "shards")
    try:
        os.makedirs(args.out, exist_ok=True)
        shutil.rmtree(shard_root, ignore_errors=True)
        kill_marker = None
        if args.test_kill_worker_on_shard:
            kill_marker = os.path.join(args.out, ".killed-a-worker")
            if os.path.exists(kill_marker):
                os.remove(kill_marker)
        futures = {}
        for k in range(1, args.shards + 1):
            marker = kill_marker if k == args.test_kill_worker_on_shard else None
            futures[k] = client.submit(run_shard, args.raster, args.scene, args.param, k, args.shards, args.extra,
                                       marker, key=f"sweep-shard-{k}-of-{args.shards}", retries=args.retries,
                                       pure=False)
        print(f"dask_sweep: {args.shards} shards on {len(client.scheduler_info()['workers'])} workers", file=sys.stderr)
        done = 0
        for k, future in futures.items():
            try:
                text, refusal = future.result()
            except Exception as e:   # failed on every attempt (or its worker lost each time)
                print(f"dask_sweep.py: shard {k}/{args.shards} failed after {args.retries} retries: {e}", file=sys.stderr)
                return 1
            if refusal is not None:
                print(f"dask_sweep.py: shard {k}/{args.shards}: {refusal}", file=sys.stderr)
                return 2
            folder = os.path.join(shard_root, f"shard-{k}")
            os.makedirs(folder, exist_ok=True)
            write_text_atomically(text, os.path.join(folder, "sweep.json"))
            done += 1
            print(f"dask_sweep: shard {k}/{args.shards} done ({done}/{args.shards})", file=sys.stderr)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()

    shards = [os.path.join(shard_root, f"shard-{k}") for k in range(1, args.shards + 1)]
    merged = subprocess.run([args.raster, "sweep-merge"] + shards + ["--out", args.out])
    return merged.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
