"""The registries as the bench/ runners see them: `raster scenes --json`, one row per scene
(name, description, seed, params, programs, assets, sweeps), and `raster methods --json`, the
method sets. The runners take their scene and preset lists from here, so a scene or preset
added to its registry is run with no line changed here."""
import json
import subprocess
import sys


def _listing(raster, command):
    """`raster COMMAND --json`, parsed; exits naming the binary when it cannot be run."""
    try:
        done = subprocess.run([raster, command, "--json"], capture_output=True, text=True)
    except OSError as error:
        sys.exit(f"{raster} cannot be run ({error.strerror}): run ./setup.sh first")
    if done.returncode != 0:
        sys.exit(f"{raster} {command} --json exited {done.returncode}: {done.stderr.strip()}")
    return json.loads(done.stdout)


def scene_rows(raster):
    """Every registry row of the `raster` binary, in its order."""
    return _listing(raster, "scenes")


def scene_names(raster):
    return [row["name"] for row in scene_rows(raster)]


def preset_names(raster):
    """The presets of the binary's method registry (gl first), in its order."""
    return [preset["name"] for preset in _listing(raster, "methods")["presets"]]
