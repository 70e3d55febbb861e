"""What the bench scripts share for bad input: a message naming the file and the problem, and
exit status 2 (as `raster` gives), before any work; never a Python traceback.

    doc = read_json("sweep_chart.py", path, "a sweep.json")
    check_record(doc, {"points": list, "scene": str}, where="")   # raises BadInput
    check_range(doc["points"][0], "value", 0, 1e100, "point 0", above=True)

Arguments too: check_output_path (a file, or a PREFIX of files), check_output_folder,
check_raster, and the comma-separated lists (split_list, parse_counts, parse_sizes), these
against raster's own limits.
"""
import math
import numbers
import os
import re
import stat
import sys


class BadInput(Exception):
    """A file or argument that is not what the script reads; the message says what and where."""


def fail(prog, message):
    """Prints `prog: message` on stderr and exits 2."""
    print(f"{prog}: {message}", file=sys.stderr)
    sys.exit(2)


def _shown(text):
    """An argument as a message shows it: quoted where it is empty or holds spaces."""
    return text if text and not any(c.isspace() for c in text) else repr(text)


# The largest JSON file a script reads: the committed results are under 1 MiB each, and a
# whole file is read into memory. The cap also ends a read of something endless that passed
# for a file.
MAX_JSON_BYTES = 64 << 20


def read_json(prog, path, what):
    """The JSON document in path; a missing, unreadable or malformed file exits 2 naming it, as
    does one that is not a regular file (a folder; a device or a pipe, read from for ever, or
    blocking its open), one over MAX_JSON_BYTES, or one nested too deeply for Python's parser
    (a RecursionError)."""
    import json
    shown = _shown(path)
    try:
        # stat before open: opening a FIFO waits for a writer that may never come.
        info = os.stat(path)
        if not stat.S_ISREG(info.st_mode):
            fail(prog, f"{shown}: not {what} ({'a folder' if stat.S_ISDIR(info.st_mode) else 'not a regular file'})")
        with open(path, "rb") as f:
            data = f.read(MAX_JSON_BYTES + 1)   # at most one byte past the cap: the file may grow
        if len(data) > MAX_JSON_BYTES:
            fail(prog, f"{shown}: not {what} (larger than {MAX_JSON_BYTES >> 20} MiB)")
        return json.loads(data)   # bytes: UTF-8 (or -16, -32), as JSON is
    except RecursionError:
        fail(prog, f"{shown}: not {what} (nested too deeply)")
    except (OSError, UnicodeDecodeError, ValueError) as e:
        fail(prog, f"{shown}: not {what} ({e})")


# Field types: a Python type, a tuple of them, NUMBER (a finite int or float, not bool), or OPTIONAL(t)
# (t or null). bool is not accepted where a number is asked for, nor a number for a bool.
NUMBER = "number"


def OPTIONAL(kind):  # noqa: N802 (reads as a type in the field tables)
    return ("optional", kind)


def is_number(value):
    """An int or float (JSON's number), not a bool, and finite: Python's json reads NaN and
    Infinity, which are not JSON, and which raster never writes (nlohmann's writer puts null
    where a value is not finite; a PSNR of identical images is null, not Infinity)."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool) and math.isfinite(value)


def _non_finite(value):
    return isinstance(value, float) and not math.isfinite(value)


def _matches(value, kind):
    if isinstance(kind, tuple) and len(kind) == 2 and kind[0] == "optional":
        return value is None or _matches(value, kind[1])
    if kind == NUMBER:
        return is_number(value)
    if kind is int:
        return isinstance(value, int) and not isinstance(value, bool)
    return isinstance(value, kind)


def _name(kind):
    if isinstance(kind, tuple) and len(kind) == 2 and kind[0] == "optional":
        return f"{_name(kind[1])} or null"
    if kind == NUMBER:
        return "a number"
    return {list: "a list", dict: "an object", str: "a string", bool: "true or false", int: "an integer"}.get(
        kind, getattr(kind, "__name__", str(kind)))


def check_record(record, fields, where):
    """Raises BadInput unless record is an object holding every field with its type."""
    prefix = f"{where}: " if where else ""
    if not isinstance(record, dict):
        raise BadInput(f"{prefix}an object was expected")
    for field, kind in fields.items():
        if field not in record:
            raise BadInput(f"{prefix}no '{field}'")
        if not _matches(record[field], kind):
            if _non_finite(record[field]):   # named as the file spells it: NaN, Infinity, -Infinity
                import json
                raise BadInput(f"{prefix}'{field}' is {json.dumps(record[field])}, not a finite number "
                               "(not JSON; raster writes null for a value that is not finite)")
            raise BadInput(f"{prefix}'{field}' is not {_name(kind)}")


def check_range(record, field, low, high, where, above=False, why=""):
    """Raises BadInput unless record[field] (already checked a number; null passes) lies in
    low..high, or above low and at most high where `above`. For values the writer cannot give:
    matplotlib's axes overflow near 1e308 (a warning and a broken chart, or a traceback), and a
    log axis takes nothing at or below 0. `why` ends the message: what the range is."""
    value = record[field]
    if value is None:
        return
    if (value <= low if above else value < low) or value > high:
        prefix = f"{where}: " if where else ""
        span = f"above {low:g} and at most {high:g}" if above else f"within {low:g}..{high:g}"
        raise BadInput(f"{prefix}'{field}' is {value:g}, not {span}" + (f" ({why})" if why else ""))


def check_each(records, fields, name):
    """Raises BadInput unless records holds at least one record and each has fields (the
    message counts them from 0: `point 3: no 'value'`)."""
    if not records:
        raise BadInput(f"no {name}s")
    for i, record in enumerate(records):
        check_record(record, fields, f"{name} {i}")


def check_output_path(prog, option, path, suffixes=("",)):
    """An output file's path, given as `option`, or the PREFIX of the files PREFIX + each of
    `suffixes` (e.g. (".png", ".svg")): it must name a file (not "", nor end in a folder: the
    files would be hidden ones such as ".png" in it), no file written may be a folder or other
    than a regular file where it is already there (a rename onto a folder fails once the work is
    done; onto /dev/null, as root, it would replace the device), and its folder must exist and
    take files; checked before any work (a probe file made and removed: root's access() says
    yes of /proc)."""
    if os.path.basename(path) in ("", ".", ".."):
        fail(prog, f"{option} {_shown(path)}: names no file ({'it is empty' if not path else 'it names a folder'})")
    for written in (path + suffix for suffix in suffixes):
        if os.path.exists(written) and not os.path.isfile(written):   # a dangling link is replaced: fine
            kind = "a folder" if os.path.isdir(written) else "not a regular file"
            fail(prog, f"{option} {path}: {written} is {kind}")
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        fail(prog, f"{option} {path}: the folder {folder} does not exist")
    probe = os.path.join(folder, f".write-probe-{os.getpid()}")
    try:
        with open(probe, "w"):
            pass
        os.remove(probe)
    except OSError as e:
        fail(prog, f"{option} {path}: cannot write in {folder} ({e.strerror})")


def check_output_folder(prog, option, path, files=()):
    """An output folder given as `option`, made later by the script: a folder already there
    must take files, and none of `files` (the names the script writes in it) be a folder; one
    not made yet must have a folder above it that takes files (a mistyped path is refused, not
    made parents and all). Returns the path without a trailing slash."""
    if not path:
        fail(prog, f"{option} '': names no folder (it is empty)")
    path = os.path.normpath(path)
    if os.path.exists(path) and not os.path.isdir(path):
        fail(prog, f"{option} {path}: not a folder")
    if os.path.isdir(path):
        for name in files or ("probe",):
            check_output_path(prog, option, os.path.join(path, name))
    else:
        check_output_path(prog, option, path)   # the folder above takes files (and so this one)
    return path


# raster's own limits (`raster render --help`, `raster bench --help`, `raster params SCENE`):
# checked here too, so that a list of runs is refused before its first run, not at the run
# that reaches the value, minutes later.
RASTER_MAX_SIDE = 16384      # --size, each side (GL_MAX_TEXTURE_SIZE of llvmpipe)
RASTER_MAX_THREADS = 1024    # --threads (0: every core)
RASTER_MAX_FRAMES = 10000    # bench --frames


def check_raster(prog, option, path):
    """The raster binary given as `option`: a regular file this user may run."""
    if not os.path.isfile(path) or not os.access(path, os.X_OK):
        why = "does not exist" if not os.path.exists(path) else "is not an executable file"
        fail(prog, f"{option} {path}: {why} (build it with ./setup.sh)")


def split_list(prog, option, text):
    """The items of a comma-separated `option`, each once, in order: an empty list or item
    ("", "a,", "a,,b") is refused, not read as the default or as a name "". Spaces around an
    item are refused too: they would travel into raster's arguments and the output's keys."""
    items = text.split(",")
    for item in items:
        if not item:
            fail(prog, f"{option} {_shown(text)}: " + ("empty" if not text else "an empty item") +
                 " (a comma-separated list is needed)")
        if item != item.strip():
            fail(prog, f"{option} {_shown(text)}: {item!r} has spaces around it")
    return list(dict.fromkeys(items))


def parse_counts(prog, option, text, low, high, why=""):
    """A comma-separated list of whole numbers from low to high (why: where the limit is
    from), each once, in order; the numbers' text normalised ("02" is 2)."""
    counts = []
    for item in split_list(prog, option, text):
        if not re.fullmatch(r"[0-9]+", item):
            fail(prog, f"{option} {_shown(text)}: {item!r} is not a whole number")
        if not low <= int(item) <= high:
            limit = f"{low}..{high}" + (f"; {why}" if why else "")
            fail(prog, f"{option} {_shown(text)}: {int(item)} is out of range ({limit})")
        counts.append(int(item))
    return list(dict.fromkeys(counts))


def parse_sizes(prog, option, text):
    """A comma-separated list of WxH image sizes, each side 1..RASTER_MAX_SIDE, each once."""
    sizes = []
    for size in split_list(prog, option, text):
        match = re.fullmatch(r"([0-9]+)x([0-9]+)", size)
        if not match:
            fail(prog, f"{option} {_shown(text)}: {size!r} is not WxH (e.g. 640x480)")
        width, height = map(int, match.groups())
        if not (1 <= width <= RASTER_MAX_SIDE and 1 <= height <= RASTER_MAX_SIDE):
            fail(prog, f"{option} {_shown(text)}: {size} is not a WxH of sides 1..{RASTER_MAX_SIDE} (raster's limit)")
        sizes.append(f"{width}x{height}")   # "0640x480" is 640x480: one key, as raster reads it
    return list(dict.fromkeys(sizes))
