#!/usr/bin/env python3
"""The SHA-256 of every target this pipeline renders, over scenes, sizes, thread counts and
with and without --scalar: the check that a restructuring changed no byte.

    python3 bench/target_hashes.py --out before.json              # on the old tree
    python3 bench/target_hashes.py --against before.json          # on the new one: exit 1 on any change

Each run is `raster render SCENE --dump DIR`; a target is hashed from its lossless dump (the
EXR where the target is float or depth, else the PNG). The scenes are the registry's
(`raster scenes --json`) unless --scenes names them, so an older binary without the
registry can be hashed too. Output is a JSON object {"scene size threads scalar target": sha256}.
"""
import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from chart_files import write_text_atomically  # noqa: E402
from input_checks import (RASTER_MAX_THREADS, check_output_path, check_raster, fail, parse_counts,  # noqa: E402
                          parse_sizes, read_json, split_list)
from raster_scenes import checked_names, scene_names  # noqa: E402

PROG = "target_hashes.py"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--raster", default=os.path.join(ROOT, "build", "raster"),
                        help="the raster binary (default: the repository's build/raster)")
    parser.add_argument("--scenes", help="comma-separated scenes (default: every registry scene)")
    parser.add_argument("--sizes", default="640x480,333x197,64x48", help="comma-separated WxH")
    parser.add_argument("--threads", default="1,2,3,4,5",
                        help=f"comma-separated thread counts (0..{RASTER_MAX_THREADS}; 0: every core)")
    parser.add_argument("--out", help="write the hashes here (JSON)")
    parser.add_argument("--against", help="compare with this earlier --out; exit 1 on any difference")
    return parser.parse_args()


def target_hashes(dump_dir):
    """{target: sha256} of one dump folder: the EXR of a target when there is one, else its PNG."""
    files = {}
    for name in sorted(os.listdir(dump_dir)):
        stem, ext = os.path.splitext(name)
        if ext == ".exr" or (ext == ".png" and stem not in files):
            files[stem] = name
    hashes = {}
    for stem, name in files.items():
        with open(os.path.join(dump_dir, name), "rb") as f:
            hashes[stem] = hashlib.sha256(f.read()).hexdigest()
    return hashes


def check_render_options(raster):
    """The binary renders with the options every run passes: `render --help` names them (a
    binary that is not raster, such as /bin/true, would "render" nothing, found only once the
    runs began)."""
    try:
        done = subprocess.run([raster, "render", "--help"], capture_output=True, text=True)
    except OSError as error:
        fail(PROG, f"--raster {raster}: cannot be run ({error.strerror})")
    if done.returncode != 0:
        fail(PROG, f"--raster {raster}: `render --help` exited {done.returncode} (is it the raster binary?)")
    missing = [option for option in ("--dump", "--scalar", "--threads", "--size") if option not in done.stdout]
    if missing:
        fail(PROG, f"--raster {raster}: `render --help` names no {', '.join(missing)} (is it the raster binary?)")


def main():
    args = parse_args()
    # Every argument, and what the end of the run reads or writes, is checked before its
    # minutes of renders.
    check_raster(PROG, "--raster", args.raster)
    sizes = parse_sizes(PROG, "--sizes", args.sizes)
    threads = [str(n) for n in parse_counts(PROG, "--threads", args.threads, 0, RASTER_MAX_THREADS, "raster's limit")]
    given = None if args.scenes is None else split_list(PROG, "--scenes", args.scenes)
    before = None
    if args.against is not None:   # "" too: a file name, refused by read_json
        before = read_json(PROG, args.against, "an earlier --out of this script")
        if not isinstance(before, dict) or not all(isinstance(v, str) for v in before.values()):
            fail(PROG, f"{args.against}: not an earlier --out of this script (an object of target hashes)")
    if args.out is not None:   # "" too: refused by check_output_path, not skipped
        check_output_path(PROG, "--out", args.out)
    check_render_options(args.raster)
    # The registry's scenes; --scenes is checked against it where the binary has one (an older
    # binary without it is hashed with the names given: raster refuses an unknown one).
    scenes = checked_names(PROG, "--scenes", given, scene_names(args.raster, required=given is None))
    runs = [(s, z, t, scalar) for s in scenes for z in sizes for t in threads for scalar in (False, True)]
    hashes = {}
    with tempfile.TemporaryDirectory() as work:
        for index, (scene, size, thread_count, scalar) in enumerate(runs, 1):
            dump = os.path.join(work, f"run{index}")
            command = [args.raster, "render", scene, "--size", size, "--threads", thread_count,
                       "--dump", dump, "--out", os.path.join(work, "final.png"), "--quiet"]
            if scalar:
                command.append("--scalar")
            done = subprocess.run(command, capture_output=True, text=True)
            if done.returncode == 2:   # raster refused the input (a size, a scene): so does this script
                fail(PROG, f"{' '.join(command)}: {done.stderr.strip()}")
            if done.returncode != 0:
                sys.exit(f"{' '.join(command)} exited {done.returncode}: {done.stderr.strip()}")
            if not os.path.isdir(dump):
                sys.exit(f"{' '.join(command)} exited 0 but wrote no --dump folder")
            for target, digest in target_hashes(dump).items():
                hashes[f"{scene} {size} {thread_count} {'scalar' if scalar else 'simd'} {target}"] = digest
            print(f"\r{index}/{len(runs)} runs, {len(hashes)} target hashes", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)
    if args.out is not None:
        write_text_atomically(json.dumps(hashes, indent=1, sort_keys=True), args.out)
    per_config = {}
    for key, digest in hashes.items():
        scene, size, _, _, target = key.split(" ")
        per_config.setdefault((scene, size, target), set()).add(digest)
    varying = [k for k, v in per_config.items() if len(v) > 1]
    print(f"{len(hashes)} target hashes over {len(runs)} runs; "
          f"{len(varying)} targets differ between thread counts or --scalar")
    for scene, size, target in varying:
        print(f"  varies: {scene} {size} {target}")
    if before is not None:
        changed = sorted(k for k in hashes if k in before and before[k] != hashes[k])
        missing = sorted(set(before) ^ set(hashes))
        print(f"against {args.against}: {len(hashes) - len(changed) - len(set(hashes) - set(before))} same, "
              f"{len(changed)} changed, {len(missing)} present on one side only")
        for key in changed[:20] + missing[:20]:
            print(f"  {key}")
        if changed or missing:
            return 1
    return 1 if varying else 0


if __name__ == "__main__":
    sys.exit(main())
