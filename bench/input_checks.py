"""What the bench scripts share for bad input: a message naming the file and the problem, and
exit status 2 (as `raster` gives), before any work; never a Python traceback.

    doc = read_json("sweep_chart.py", path, "a sweep.json")
    check_record(doc, {"points": list, "scene": str}, where="")   # raises BadInput
"""
import numbers
import os
import sys


class BadInput(Exception):
    """A file or argument that is not what the script reads; the message says what and where."""


def fail(prog, message):
    """Prints `prog: message` on stderr and exits 2."""
    print(f"{prog}: {message}", file=sys.stderr)
    sys.exit(2)


def read_json(prog, path, what):
    """The JSON document in path; a missing, unreadable or malformed file exits 2 naming it."""
    import json
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, UnicodeDecodeError, ValueError) as e:
        fail(prog, f"{path}: not {what} ({e})")


# Field types: a Python type, a tuple of them, NUMBER (int or float, not bool), or OPTIONAL(t)
# (t or null). bool is not accepted where a number is asked for, nor a number for a bool.
NUMBER = "number"


def OPTIONAL(kind):  # noqa: N802 (reads as a type in the field tables)
    return ("optional", kind)


def is_number(value):
    """An int or float (JSON's number), not a bool."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


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
            raise BadInput(f"{prefix}'{field}' is not {_name(kind)}")


def check_each(records, fields, name):
    """Raises BadInput unless records holds at least one record and each has fields (the
    message counts them from 0: `point 3: no 'value'`)."""
    if not records:
        raise BadInput(f"no {name}s")
    for i, record in enumerate(records):
        check_record(record, fields, f"{name} {i}")


def check_output_path(prog, option, path):
    """An output file's path (or the PREFIX of PREFIX.png and PREFIX.svg), given as `option`:
    its folder must exist and take files, checked before any work (a probe file made and
    removed: root's access() says yes of /proc)."""
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
