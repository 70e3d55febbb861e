"""The registries as the bench/ runners see them: `raster scenes --json`, one row per scene
(name, description, seed, params, programs, assets, sweeps), and `raster methods --json`, the
method sets. The runners take their scene and preset lists from here, so a scene or preset
added to its registry is run with no line changed here.

A binary that cannot be run, or is not raster (it prints no such listing), is bad input to
the script that was given it: exit 2 naming --raster (input_checks.fail), no traceback."""
import json
import os
import subprocess
import sys

from input_checks import fail


def _prog():
    return os.path.basename(sys.argv[0]) or "bench"


def _listing(raster, command, required=True):
    """`raster COMMAND --json`, parsed; exits 2 naming the binary when it cannot be run or
    prints no JSON. With required=False, a binary that runs but refuses the command (an
    older raster, without the registry) gives None instead."""
    try:
        done = subprocess.run([raster, command, "--json"], capture_output=True, text=True)
    except OSError as error:
        fail(_prog(), f"--raster {raster}: cannot be run ({error.strerror}): run ./setup.sh first")
    if done.returncode != 0:
        if not required:
            return None
        fail(_prog(), f"--raster {raster}: `{command} --json` exited {done.returncode}: "
                      f"{done.stderr.strip()[-500:] or 'no message'}")
    try:
        return json.loads(done.stdout)
    except (ValueError, RecursionError):
        fail(_prog(), f"--raster {raster}: `{command} --json` printed no JSON (is it the raster binary?)")


def _names(raster, command, rows):
    """The "name" of every row, or exit 2: the listing is not the one raster prints."""
    if not isinstance(rows, list) or not rows or not all(
            isinstance(row, dict) and isinstance(row.get("name"), str) for row in rows):
        fail(_prog(), f"--raster {raster}: `{command} --json` is not raster's listing (is it the raster binary?)")
    return [row["name"] for row in rows]


def scene_rows(raster):
    """Every registry row of the `raster` binary, in its order."""
    rows = _listing(raster, "scenes")
    _names(raster, "scenes", rows)
    return rows


def scene_names(raster, required=True):
    """The registry's scene names; with required=False, None for a binary without the registry."""
    rows = _listing(raster, "scenes", required)
    return None if rows is None else _names(raster, "scenes", rows)


def preset_names(raster):
    """The presets of the binary's method registry (gl first), in its order."""
    listing = _listing(raster, "methods")
    return _names(raster, "methods", listing.get("presets") if isinstance(listing, dict) else None)


def checked_names(prog, option, given, known):
    """The names `option` chose: `given` (split by input_checks.split_list), or every one of
    `known` (the registry's, in its order) when it is None. A name not in `known` exits 2
    naming the valid ones, in one wording for every runner. With `known` None (an older
    binary without the registry) the given names are taken as they are: raster refuses an
    unknown one itself."""
    if given is None:
        return list(known)
    for name in given if known is not None else ():
        if name not in known:
            fail(prog, f"{option}: unknown '{name}' (valid: {', '.join(known)})")
    return given
