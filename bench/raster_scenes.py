"""The scene registry as the bench/ runners see it: `raster scenes --json`, one row per
scene (name, description, seed, params, programs, assets, sweeps). The runners take their
scene lists from here, so a scene added to the registry is run with no line changed here."""
import json
import subprocess
import sys


def scene_rows(raster):
    """Every registry row of the `raster` binary, in its order; exits 2 naming the binary
    when it cannot be run."""
    try:
        done = subprocess.run([raster, "scenes", "--json"], capture_output=True, text=True)
    except OSError as error:
        sys.exit(f"{raster} cannot be run ({error.strerror}): run ./setup.sh first")
    if done.returncode != 0:
        sys.exit(f"{raster} scenes --json exited {done.returncode}: {done.stderr.strip()}")
    return json.loads(done.stdout)


def scene_names(raster):
    return [row["name"] for row in scene_rows(raster)]
